//! Collision shapes by mesh content: a shape is a pure function of the mesh and the
//! [`ShapeOptions`], so a conversion that meets a mesh it has seen before (a re-export, a new CAD
//! version with unchanged parts) takes the shape from a [`ShapeCache`] instead of computing it.
//! No IO here: [`MemoryShapeCache`] is a bounded in-memory LRU for the service and the CLI.

use std::collections::{BTreeMap, HashMap};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Mutex;

use sha2::{Digest, Sha256};

use super::shape::{BodyShape, ShapeOptions};
use crate::pipeline::ir::Mesh;

/// Bumped whenever [`super::body_shape`] (or what is done to its result before caching) changes
/// what it returns for the same input, so that a cache never serves shapes of another algorithm.
const ALGORITHM: &[u8] = b"cad2mo collision shape v2";

/// SHA-256 of everything a body's shape depends on: the mesh's vertex and triangle bytes (as
/// [`super::body_shape`] reads them) and every field of the [`ShapeOptions`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ShapeKey(pub [u8; 32]);

impl ShapeKey {
    pub fn of(mesh: &Mesh, opts: &ShapeOptions) -> ShapeKey {
        let mut h = Sha256::new();
        h.update(ALGORITHM);
        // Every field, by name: a new option fails to compile here until it is hashed.
        let ShapeOptions {
            primitive_abs_tolerance,
            primitive_rel_tolerance,
            primitive_volume_tolerance,
            decompose_ratio,
            max_parts,
            vhacd_resolution,
            decomposition_budget,
            cylinder_sides,
            max_triangles,
            simplify_cells,
            max_hull_vertices,
            thin_thickness,
        } = opts;
        for x in
            [primitive_abs_tolerance, primitive_rel_tolerance, primitive_volume_tolerance, decompose_ratio, simplify_cells, thin_thickness]
        {
            h.update(x.to_bits().to_le_bytes());
        }
        for n in [
            u64::from(*max_parts),
            u64::from(*vhacd_resolution),
            *decomposition_budget,
            *cylinder_sides as u64,
            *max_triangles as u64,
            *max_hull_vertices as u64,
        ] {
            h.update(n.to_le_bytes());
        }
        h.update((mesh.vertices.len() as u64).to_le_bytes());
        let mut buf = Vec::with_capacity(64 * 1024);
        for chunk in mesh.vertices.chunks(4096) {
            buf.clear();
            for v in chunk {
                for c in v {
                    buf.extend_from_slice(&c.to_bits().to_le_bytes());
                }
            }
            h.update(&buf);
        }
        h.update((mesh.triangles.len() as u64).to_le_bytes());
        for chunk in mesh.triangles.chunks(4096) {
            buf.clear();
            for t in chunk {
                for i in t {
                    buf.extend_from_slice(&i.to_le_bytes());
                }
            }
            h.update(&buf);
        }
        ShapeKey(h.finalize().into())
    }
}

/// Where computed shapes are kept between conversions. Implementations must return exactly the
/// shape that was put under a key (or nothing): the output of a conversion must not depend on
/// whether a shape came from the cache.
pub trait ShapeCache: Send + Sync + std::fmt::Debug {
    fn get(&self, key: &ShapeKey) -> Option<BodyShape>;
    fn put(&self, key: ShapeKey, shape: &BodyShape);
}

/// Counters of a [`MemoryShapeCache`] since it was made.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CacheStats {
    /// Lookups that found a shape.
    pub hits: u64,
    /// Lookups that found none (the shape was then computed).
    pub misses: u64,
    /// Shapes dropped to stay within the byte budget.
    pub evictions: u64,
    pub entries: usize,
    /// Approximate bytes held.
    pub bytes: usize,
}

struct Entry {
    shape: BodyShape,
    bytes: usize,
    /// Last use (a counter, larger is newer).
    used: u64,
}

#[derive(Default)]
struct Lru {
    map: HashMap<ShapeKey, Entry>,
    /// Last use → key, oldest first.
    order: BTreeMap<u64, ShapeKey>,
    bytes: usize,
    clock: u64,
}

/// A bounded in-memory LRU of shapes by approximate size. One per process, shared by every
/// conversion (`Arc<MemoryShapeCache>`).
pub struct MemoryShapeCache {
    max_bytes: usize,
    lru: Mutex<Lru>,
    hits: AtomicU64,
    misses: AtomicU64,
    evictions: AtomicU64,
}

impl std::fmt::Debug for MemoryShapeCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MemoryShapeCache").field("max_bytes", &self.max_bytes).field("stats", &self.stats()).finish()
    }
}

/// The default budget of [`MemoryShapeCache`]: 256 MB.
pub const DEFAULT_CACHE_BYTES: usize = 256 << 20;

impl Default for MemoryShapeCache {
    fn default() -> Self {
        MemoryShapeCache::new(DEFAULT_CACHE_BYTES)
    }
}

/// Approximate heap and inline size of a shape.
pub fn shape_bytes(s: &BodyShape) -> usize {
    let parts: usize = s.parts.iter().map(|p| std::mem::size_of_val(p) + p.vertices.capacity() * 24 + p.faces.capacity() * 12).sum();
    let warnings: usize = s.warnings.iter().map(|w| std::mem::size_of_val(w) + w.capacity()).sum();
    std::mem::size_of::<BodyShape>() + std::mem::size_of::<Entry>() + parts + warnings + 64
}

impl MemoryShapeCache {
    /// A cache holding at most about `max_bytes` of shapes (0: holds nothing).
    pub fn new(max_bytes: usize) -> MemoryShapeCache {
        MemoryShapeCache {
            max_bytes,
            lru: Mutex::new(Lru::default()),
            hits: AtomicU64::new(0),
            misses: AtomicU64::new(0),
            evictions: AtomicU64::new(0),
        }
    }

    pub fn stats(&self) -> CacheStats {
        let (entries, bytes) = match self.lru.lock() {
            Ok(l) => (l.map.len(), l.bytes),
            Err(p) => {
                let l = p.into_inner();
                (l.map.len(), l.bytes)
            }
        };
        CacheStats {
            hits: self.hits.load(Ordering::Relaxed),
            misses: self.misses.load(Ordering::Relaxed),
            evictions: self.evictions.load(Ordering::Relaxed),
            entries,
            bytes,
        }
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Lru> {
        // A panic while holding the lock leaves a consistent map (every update is completed
        // before anything can panic), so a poisoned lock is still usable.
        self.lru.lock().unwrap_or_else(|p| p.into_inner())
    }
}

impl ShapeCache for MemoryShapeCache {
    fn get(&self, key: &ShapeKey) -> Option<BodyShape> {
        let mut guard = self.lock();
        let l = &mut *guard;
        l.clock += 1;
        let now = l.clock;
        let found = l.map.get_mut(key).map(|e| {
            let old = e.used;
            e.used = now;
            (old, e.shape.clone())
        });
        match found {
            Some((old, shape)) => {
                l.order.remove(&old);
                l.order.insert(now, *key);
                drop(guard);
                self.hits.fetch_add(1, Ordering::Relaxed);
                Some(shape)
            }
            None => {
                drop(guard);
                self.misses.fetch_add(1, Ordering::Relaxed);
                None
            }
        }
    }

    fn put(&self, key: ShapeKey, shape: &BodyShape) {
        let bytes = shape_bytes(shape);
        if bytes > self.max_bytes {
            return;
        }
        let mut guard = self.lock();
        let l = &mut *guard;
        l.clock += 1;
        let now = l.clock;
        if let Some(old) = l.map.insert(key, Entry { shape: shape.clone(), bytes, used: now }) {
            l.order.remove(&old.used);
            l.bytes -= old.bytes;
        }
        l.order.insert(now, key);
        l.bytes += bytes;
        let mut evicted = 0;
        while l.bytes > self.max_bytes {
            let Some((_, k)) = l.order.pop_first() else { break };
            if let Some(e) = l.map.remove(&k) {
                l.bytes -= e.bytes;
                evicted += 1;
            }
        }
        drop(guard);
        if evicted > 0 {
            self.evictions.fetch_add(evicted, Ordering::Relaxed);
        }
    }
}

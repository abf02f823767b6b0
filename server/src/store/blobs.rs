//! Content-addressed files: bundles, packages, reports and result files, named by the SHA-256 of
//! their bytes, kept in one of two backends chosen by configuration (`--blob-url`):
//!
//! - **the local folder** (default): `<data_dir>/blobs/<first two hex digits>/<sha256>`, written
//!   atomically (temporary file in the same folder, fsync, rename), so nothing half-written is ever
//!   visible. A crash between the write and the rename leaves a `.<hash>.<uuid>.tmp` file behind:
//!   [`Blobs::new`] removes those older than [`PARTIAL_AGE`] (younger ones may be the writes of
//!   another instance sharing the folder).
//! - **an S3-compatible object store** (`s3://bucket/prefix`, through the `object_store` crate):
//!   the same layout under the prefix (`<prefix>/<first two>/<sha256>`), so a local folder can be
//!   copied to a bucket as it is. A PUT is atomic (an object is visible whole or not at all), so no
//!   temporary objects exist.
//!
//! In both: a put of bytes already stored does nothing (idempotent), and every read checks the
//! bytes against their name: a corrupt blob is an error ([`std::io::ErrorKind::InvalidData`]),
//! never served.
//!
//! The API is blocking (it is called from blocking contexts: `spawn_blocking` tasks, the
//! conversion workers). The object store's futures run on the runtime that opened the store,
//! through its handle, from the calling blocking thread: never on an async worker thread.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use futures_util::StreamExt;
use object_store::path::Path as ObjectPath;
use object_store::{ObjectStore, PutPayload};
use sha2::{Digest, Sha256};

/// The blob store (cheap to clone).
#[derive(Clone, Debug)]
pub struct Blobs {
    backend: Arc<Backend>,
}

#[derive(Debug)]
enum Backend {
    Local { root: PathBuf },
    Object { store: Arc<dyn ObjectStore>, prefix: String, handle: tokio::runtime::Handle, url: String },
}

/// Where blobs go and how to reach an S3-compatible store (see `config::ServeArgs`).
#[derive(Clone, Debug, Default)]
pub struct BlobSettings {
    /// `None`: `<data_dir>/blobs`; `s3://bucket/prefix`: an S3-compatible store.
    pub url: Option<String>,
    /// The S3 endpoint for stores other than AWS (`http://` allowed), e.g. `http://minio:9000`.
    pub s3_endpoint: Option<String>,
    /// Credentials and region; `None` leaves them to the standard `AWS_*` variables, read by
    /// `object_store`'s `AmazonS3Builder::from_env` (tests set them here instead).
    pub s3_access_key_id: Option<String>,
    pub s3_secret_access_key: Option<String>,
    pub s3_region: Option<String>,
}

/// Hex SHA-256 of `bytes`.
pub fn sha256_hex(bytes: &[u8]) -> String {
    hex::encode(Sha256::digest(bytes))
}

/// Whether `hash` is a blob name: 64 lowercase hex digits.
pub fn is_hash(hash: &str) -> bool {
    hash.len() == 64 && hash.bytes().all(|b| b.is_ascii_hexdigit() && !b.is_ascii_uppercase())
}

/// `<prefix>/<dir>/<name>` (no leading slash; the prefix may be empty).
fn key(prefix: &str, dir: &str, name: &str) -> ObjectPath {
    let key = if prefix.is_empty() { format!("{dir}/{name}") } else { format!("{prefix}/{dir}/{name}") };
    ObjectPath::from(key)
}

/// The error of a blob whose bytes do not hash to its name.
fn corrupt(hash: &str, actual: &str) -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidData, format!("blob {hash} is corrupt: its bytes hash to {actual}"))
}

fn object_error(e: object_store::Error) -> std::io::Error {
    std::io::Error::other(e)
}

impl Blobs {
    /// Opens (creating) `<data_dir>/blobs` and removes the partial files a crash left behind.
    /// Call at start-up, before anything writes blobs.
    pub fn new(data_dir: &Path) -> std::io::Result<Blobs> {
        let root = data_dir.join("blobs");
        std::fs::create_dir_all(&root)?;
        let removed = remove_partial_files(&root)?;
        if removed > 0 {
            tracing::warn!(removed, "partial blob files left by a stop were removed");
        }
        Ok(Blobs { backend: Arc::new(Backend::Local { root }) })
    }

    /// Opens the store `settings` name: the local folder under `data_dir` when no URL is given,
    /// else an S3-compatible store, checked reachable (one request) before returning. Call inside
    /// a tokio runtime, at start-up: the object store's requests run on this runtime.
    pub async fn open(settings: &BlobSettings, data_dir: &Path) -> std::io::Result<Blobs> {
        let Some(url) = settings.url.as_deref().map(str::trim).filter(|u| !u.is_empty()) else {
            return Blobs::new(data_dir);
        };
        let Some(rest) = url.strip_prefix("s3://") else {
            return Err(std::io::Error::other(format!("blob URL {url}: only s3://bucket/prefix is supported (or none: the local folder)")));
        };
        let (bucket, prefix) = rest.split_once('/').unwrap_or((rest, ""));
        if bucket.is_empty() {
            return Err(std::io::Error::other(format!("blob URL {url}: no bucket")));
        }
        let mut builder = object_store::aws::AmazonS3Builder::from_env().with_bucket_name(bucket).with_retry(object_store::RetryConfig {
            max_retries: 4,
            retry_timeout: std::time::Duration::from_secs(60),
            backoff: Default::default(),
        });
        if let Some(endpoint) = &settings.s3_endpoint {
            builder = builder.with_endpoint(endpoint).with_allow_http(endpoint.starts_with("http://"));
        }
        if let Some(k) = &settings.s3_access_key_id {
            builder = builder.with_access_key_id(k);
        }
        if let Some(k) = &settings.s3_secret_access_key {
            builder = builder.with_secret_access_key(k);
        }
        if let Some(r) = &settings.s3_region {
            builder = builder.with_region(r);
        }
        let store = builder.build().map_err(object_error)?;
        let blobs = Blobs::in_object_store(Arc::new(store), prefix, url);
        // Fail at start, not at the first upload: one listing of the prefix's top level (an
        // error for a bucket that does not exist, bad credentials or no server).
        let Backend::Object { store, prefix, .. } = &*blobs.backend else { return Err(std::io::Error::other("not an object store")) };
        let under = (!prefix.is_empty()).then(|| ObjectPath::from(prefix.as_str()));
        match store.list_with_delimiter(under.as_ref()).await {
            Ok(_) => Ok(blobs),
            Err(e) => Err(std::io::Error::other(format!("blob store {url} is not reachable: {e}"))),
        }
    }

    /// Blobs in `store` under `prefix` (`url` names it in messages). Call inside a tokio runtime:
    /// requests run on it.
    pub fn in_object_store(store: Arc<dyn ObjectStore>, prefix: &str, url: &str) -> Blobs {
        let prefix = prefix.trim_matches('/').to_string();
        let handle = tokio::runtime::Handle::current();
        Blobs { backend: Arc::new(Backend::Object { store, prefix, handle, url: url.to_string() }) }
    }

    /// Where the blobs are, for logs: a folder or a URL.
    pub fn location(&self) -> String {
        match &*self.backend {
            Backend::Local { root } => root.display().to_string(),
            Backend::Object { url, .. } => url.clone(),
        }
    }

    /// The key of a blob in an object store: `<prefix>/<first two>/<hash>`.
    fn object_path(&self, hash: &str) -> Result<ObjectPath, String> {
        let Backend::Object { prefix, .. } = &*self.backend else { return Err("not an object store".into()) };
        if !is_hash(hash) {
            return Err("bad hash".into());
        }
        Ok(key(prefix, &hash[..2], hash))
    }

    fn local_path(root: &Path, hash: &str) -> Option<PathBuf> {
        is_hash(hash).then(|| root.join(&hash[..2]).join(hash))
    }

    /// Runs an object store request from a blocking thread on the store's runtime.
    fn block_on<F: std::future::Future>(handle: &tokio::runtime::Handle, f: F) -> F::Output {
        handle.block_on(f)
    }

    /// Stores `bytes` (blocking: call from a blocking context) and returns its hash. Bytes already
    /// stored are not written again.
    pub fn put(&self, bytes: &[u8]) -> std::io::Result<String> {
        let hash = sha256_hex(bytes);
        match &*self.backend {
            Backend::Local { root } => {
                let path = Self::local_path(root, &hash).ok_or_else(|| std::io::Error::other("bad hash"))?;
                if path.exists() {
                    return Ok(hash);
                }
                let dir = path.parent().ok_or_else(|| std::io::Error::other("no parent"))?;
                std::fs::create_dir_all(dir)?;
                let tmp = dir.join(format!(".{hash}.{}.tmp", uuid::Uuid::new_v4()));
                let result = (|| {
                    let mut f = std::fs::File::create(&tmp)?;
                    f.write_all(bytes)?;
                    f.sync_all()?;
                    std::fs::rename(&tmp, &path)
                })();
                if result.is_err() {
                    let _ = std::fs::remove_file(&tmp);
                }
                result.map(|_| hash)
            }
            Backend::Object { store, handle, .. } => {
                let path = self.object_path(&hash).map_err(std::io::Error::other)?;
                Self::block_on(handle, async {
                    // Present with the right size: already stored (a PUT is atomic, so a present
                    // object is whole; a corrupt one of the same size is caught on read).
                    match store.head(&path).await {
                        Ok(meta) if meta.size == bytes.len() as u64 => return Ok(()),
                        Ok(_) | Err(object_store::Error::NotFound { .. }) => {}
                        Err(e) => return Err(object_error(e)),
                    }
                    store.put(&path, PutPayload::from(bytes.to_vec())).await.map(|_| ()).map_err(object_error)
                })?;
                Ok(hash)
            }
        }
    }

    /// Reads a blob (blocking); `Ok(None)` when absent (or `hash` is not a blob name), an
    /// [`std::io::ErrorKind::InvalidData`] error when its bytes do not match its name.
    pub fn get(&self, hash: &str) -> std::io::Result<Option<Vec<u8>>> {
        let bytes = match &*self.backend {
            Backend::Local { root } => {
                let Some(path) = Self::local_path(root, hash) else { return Ok(None) };
                match std::fs::read(path) {
                    Ok(b) => b,
                    Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
                    Err(e) => return Err(e),
                }
            }
            Backend::Object { store, handle, .. } => {
                let Ok(path) = self.object_path(hash) else { return Ok(None) };
                let got = Self::block_on(handle, async {
                    match store.get(&path).await {
                        Ok(r) => r.bytes().await.map(Some),
                        Err(object_store::Error::NotFound { .. }) => Ok(None),
                        Err(e) => Err(e),
                    }
                });
                match got.map_err(object_error)? {
                    Some(b) => b.to_vec(),
                    None => return Ok(None),
                }
            }
        };
        let actual = sha256_hex(&bytes);
        if actual != hash {
            return Err(corrupt(hash, &actual));
        }
        Ok(Some(bytes))
    }

    /// Every stored blob's hash, sorted (blocking). Names that are not blobs (another tool's
    /// files, a local folder's partial files) are left out.
    pub fn list(&self) -> std::io::Result<Vec<String>> {
        let mut hashes = Vec::new();
        match &*self.backend {
            Backend::Local { root } => {
                for dir in std::fs::read_dir(root)? {
                    let dir = dir?;
                    if !dir.file_type()?.is_dir() {
                        continue;
                    }
                    let dir_name = dir.file_name().to_string_lossy().to_string();
                    for entry in std::fs::read_dir(dir.path())? {
                        let name = entry?.file_name().to_string_lossy().to_string();
                        if is_hash(&name) && name[..2] == dir_name {
                            hashes.push(name);
                        }
                    }
                }
            }
            Backend::Object { store, prefix, handle, .. } => {
                let under = (!prefix.is_empty()).then(|| ObjectPath::from(prefix.as_str()));
                let keys: Vec<String> = Self::block_on(handle, async {
                    let mut stream = store.list(under.as_ref());
                    let mut keys = Vec::new();
                    while let Some(meta) = stream.next().await {
                        keys.push(meta?.location.to_string());
                    }
                    Ok::<_, object_store::Error>(keys)
                })
                .map_err(object_error)?;
                for key in keys {
                    let rel = if prefix.is_empty() {
                        Some(key.as_str())
                    } else {
                        key.strip_prefix(prefix.as_str()).and_then(|k| k.strip_prefix('/'))
                    };
                    if let Some((dir, name)) = rel.and_then(|r| r.split_once('/')) {
                        if is_hash(name) && name[..2] == *dir {
                            hashes.push(name.to_string());
                        }
                    }
                }
            }
        }
        hashes.sort();
        Ok(hashes)
    }
}

/// Partial files at least this old are removed at start: no write takes that long, so they were
/// left by a stop, not being written by another process sharing the folder.
pub const PARTIAL_AGE: std::time::Duration = std::time::Duration::from_secs(600);

/// Whether `name` is a temporary file of [`Blobs::put`]: `.<64 hex>.<anything>.tmp`.
fn is_partial(name: &str) -> bool {
    name.strip_prefix('.')
        .and_then(|n| n.strip_suffix(".tmp"))
        .and_then(|n| n.split_once('.'))
        .is_some_and(|(hash, _)| hash.len() == 64 && hash.bytes().all(|b| b.is_ascii_hexdigit()))
}

/// Removes the temporary files of interrupted writes in the blob folders (one level deep, as
/// [`Blobs::put`] writes them) last modified [`PARTIAL_AGE`] ago or earlier. Returns how many
/// were removed.
fn remove_partial_files(root: &Path) -> std::io::Result<usize> {
    let mut removed = 0;
    for dir in std::fs::read_dir(root)? {
        let dir = dir?;
        if !dir.file_type()?.is_dir() {
            continue;
        }
        for entry in std::fs::read_dir(dir.path())? {
            let entry = entry?;
            let partial = entry.file_name().to_str().is_some_and(is_partial);
            let old = || -> std::io::Result<bool> {
                let modified = entry.metadata()?.modified()?;
                Ok(modified.elapsed().is_ok_and(|age| age >= PARTIAL_AGE))
            };
            if partial && entry.file_type()?.is_file() && old()? {
                match std::fs::remove_file(entry.path()) {
                    Ok(()) => removed += 1,
                    Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
                    Err(e) => return Err(e),
                }
            }
        }
    }
    Ok(removed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn put_get_idempotent() {
        let dir = tempfile::tempdir().unwrap();
        let b = Blobs::new(dir.path()).unwrap();
        let h = b.put(b"hello").unwrap();
        assert_eq!(h, sha256_hex(b"hello"));
        assert_eq!(b.put(b"hello").unwrap(), h);
        assert_eq!(b.get(&h).unwrap().as_deref(), Some(&b"hello"[..]));
        assert_eq!(b.get(&"0".repeat(64)).unwrap(), None);
        assert_eq!(b.get("../../etc/passwd").unwrap(), None);
        assert_eq!(b.list().unwrap(), vec![h]);
    }

    #[test]
    fn partial_files_are_removed_at_start() {
        let dir = tempfile::tempdir().unwrap();
        let b = Blobs::new(dir.path()).unwrap();
        let h = b.put(b"kept").unwrap();
        let folder = dir.path().join("blobs").join(&h[..2]);
        // What a crash between write and rename leaves, in this folder and a fresh one.
        let partial = folder.join(format!(".{h}.{}.tmp", uuid::Uuid::new_v4()));
        std::fs::write(&partial, b"half").unwrap();
        let other = dir.path().join("blobs/ff");
        std::fs::create_dir_all(&other).unwrap();
        let partial2 = other.join(format!(".{}.x.tmp", "f".repeat(64)));
        std::fs::write(&partial2, b"half").unwrap();
        // Files that are not ours stay.
        let foreign = folder.join("notes.tmp");
        std::fs::write(&foreign, b"mine").unwrap();
        // Stops happened long ago; a write of another process sharing the folder is under way.
        let long_ago = std::time::SystemTime::now() - PARTIAL_AGE - std::time::Duration::from_secs(1);
        for p in [&partial, &partial2, &foreign] {
            std::fs::File::options().write(true).open(p).unwrap().set_modified(long_ago).unwrap();
        }
        let in_progress = folder.join(format!(".{h}.{}.tmp", uuid::Uuid::new_v4()));
        std::fs::write(&in_progress, b"being written").unwrap();

        let b = Blobs::new(dir.path()).unwrap();
        assert!(!partial.exists() && !partial2.exists());
        assert!(foreign.exists() && in_progress.exists());
        assert_eq!(b.get(&h).unwrap().as_deref(), Some(&b"kept"[..]));
        // Listing names blobs only, not the foreign file.
        assert_eq!(b.list().unwrap(), vec![h]);
    }

    /// A blob folder written before object stores existed still reads: the layout is unchanged.
    #[test]
    fn existing_local_layout_reads() {
        let dir = tempfile::tempdir().unwrap();
        let h = sha256_hex(b"old data");
        std::fs::create_dir_all(dir.path().join("blobs").join(&h[..2])).unwrap();
        std::fs::write(dir.path().join("blobs").join(&h[..2]).join(&h), b"old data").unwrap();
        let b = Blobs::new(dir.path()).unwrap();
        assert_eq!(b.get(&h).unwrap().as_deref(), Some(&b"old data"[..]));
    }

    /// A local blob whose bytes changed on disk is an error, never returned.
    #[test]
    fn corrupt_local_blob_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        let b = Blobs::new(dir.path()).unwrap();
        let h = b.put(b"the package").unwrap();
        std::fs::write(dir.path().join("blobs").join(&h[..2]).join(&h), b"the pockage").unwrap();
        let e = b.get(&h).unwrap_err();
        assert_eq!(e.kind(), std::io::ErrorKind::InvalidData, "{e}");
        assert!(e.to_string().contains(&h), "{e}");
    }

    /// The object store backend (here in memory; on S3 in tests/blobs_s3.rs): the same
    /// semantics, the same key layout under the prefix, reached from blocking threads.
    #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
    async fn object_store_backend() {
        let mem = Arc::new(object_store::memory::InMemory::new());
        let b = Blobs::in_object_store(mem.clone(), "/some/prefix/", "memory://");
        let store: Arc<dyn ObjectStore> = mem.clone();
        tokio::task::spawn_blocking(move || {
            let h = b.put(b"hello").unwrap();
            assert_eq!(h, sha256_hex(b"hello"));
            let key = ObjectPath::from(format!("some/prefix/{}/{h}", &h[..2]));
            let handle = tokio::runtime::Handle::current();
            let etag = |k: &ObjectPath| handle.block_on(store.head(k)).unwrap().e_tag;
            let first = etag(&key);
            // Idempotent: the object is not written again.
            assert_eq!(b.put(b"hello").unwrap(), h);
            assert_eq!(etag(&key), first, "a second put rewrote the object");
            assert_eq!(b.get(&h).unwrap().as_deref(), Some(&b"hello"[..]));
            assert_eq!(b.get(&"0".repeat(64)).unwrap(), None);
            assert_eq!(b.get("../x").unwrap(), None);
            // Other keys under the prefix are not blobs.
            handle.block_on(store.put(&ObjectPath::from("some/prefix/notes.txt"), PutPayload::from_static(b"x"))).unwrap();
            handle
                .block_on(store.put(&ObjectPath::from("elsewhere/aa/".to_string() + &"a".repeat(64)), PutPayload::from_static(b"x")))
                .unwrap();
            assert_eq!(b.list().unwrap(), vec![h.clone()]);
            // Overwritten with other bytes (same size): an error on read, never served.
            handle.block_on(store.put(&key, PutPayload::from_static(b"jello"))).unwrap();
            let e = b.get(&h).unwrap_err();
            assert_eq!(e.kind(), std::io::ErrorKind::InvalidData, "{e}");
            // Overwritten with bytes of another size: the next put repairs it.
            handle.block_on(store.put(&key, PutPayload::from_static(b"hell"))).unwrap();
            assert_eq!(b.put(b"hello").unwrap(), h);
            assert_eq!(b.get(&h).unwrap().as_deref(), Some(&b"hello"[..]));
        })
        .await
        .unwrap();
    }
}

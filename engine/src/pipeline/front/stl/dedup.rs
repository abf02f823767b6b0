//! Exact vertex welding: corners whose `f32` coordinates are bitwise equal become one vertex.
//!
//! An open-addressing hash table (linear probing, load factor at most 1/2) keyed by the three
//! coordinate bit patterns. Bitwise equality is the rule: `0.0` and `-0.0` stay distinct, nothing
//! is merged by tolerance.

use crate::pipeline::ir;

/// Key bits and `index + 1` of the vertex (0 marks an empty slot).
type Slot = [u32; 4];

pub(crate) struct MeshBuilder {
    slots: Vec<Slot>,
    shift: u32,
    pub(crate) vertices: Vec<[f32; 3]>,
    pub(crate) triangles: Vec<[u32; 3]>,
}

#[inline]
fn hash(k: [u32; 3], shift: u32) -> usize {
    const M: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut h = u64::from(k[0]).wrapping_mul(M);
    h = (h.rotate_left(26) ^ u64::from(k[1])).wrapping_mul(M);
    h = (h.rotate_left(26) ^ u64::from(k[2])).wrapping_mul(M);
    (h >> shift) as usize
}

impl MeshBuilder {
    /// `triangles`: expected triangle count (a hint; everything grows as needed).
    pub(crate) fn with_capacity(triangles: usize) -> Self {
        // Closed meshes have about half as many vertices as triangles: a table of `triangles`
        // slots keeps the load near 1/2 without growing.
        let slots = triangles.max(16).next_power_of_two();
        MeshBuilder {
            slots: vec![[0; 4]; slots],
            shift: 64 - slots.trailing_zeros(),
            vertices: Vec::with_capacity(triangles / 2 + 16),
            triangles: Vec::with_capacity(triangles),
        }
    }

    /// Index of the vertex at `v`, adding it when new.
    #[inline]
    pub(crate) fn vertex(&mut self, v: [f32; 3]) -> u32 {
        if 2 * (self.vertices.len() + 1) > self.slots.len() {
            self.grow();
        }
        let key = [v[0].to_bits(), v[1].to_bits(), v[2].to_bits()];
        let mask = self.slots.len() - 1;
        let mut i = hash(key, self.shift);
        loop {
            let s = self.slots[i];
            if s[3] == 0 {
                let index = self.vertices.len() as u32;
                self.slots[i] = [key[0], key[1], key[2], index + 1];
                self.vertices.push(v);
                return index;
            }
            if s[0] == key[0] && s[1] == key[1] && s[2] == key[2] {
                return s[3] - 1;
            }
            i = (i + 1) & mask;
        }
    }

    fn grow(&mut self) {
        let len = self.slots.len() * 2;
        let shift = 64 - len.trailing_zeros();
        let mut slots = vec![[0u32; 4]; len];
        let mask = len - 1;
        for s in self.slots.iter().filter(|s| s[3] != 0) {
            let mut i = hash([s[0], s[1], s[2]], shift);
            while slots[i][3] != 0 {
                i = (i + 1) & mask;
            }
            slots[i] = *s;
        }
        self.slots = slots;
        self.shift = shift;
    }

    #[inline]
    pub(crate) fn triangle(&mut self, corners: [[f32; 3]; 3]) {
        let t = [self.vertex(corners[0]), self.vertex(corners[1]), self.vertex(corners[2])];
        self.triangles.push(t);
    }

    pub(crate) fn finish(mut self) -> ir::Mesh {
        self.vertices.shrink_to_fit();
        self.triangles.shrink_to_fit();
        ir::Mesh { vertices: self.vertices, triangles: self.triangles }
    }
}

#[cfg(test)]
mod tests {
    use super::MeshBuilder;

    #[test]
    fn welds_bitwise_equal_corners_only() {
        let mut b = MeshBuilder::with_capacity(1);
        b.triangle([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
        b.triangle([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-0.0, 0.0, 0.0]]);
        let m = b.finish();
        assert_eq!(m.vertices.len(), 4);
        assert_eq!(m.triangles, vec![[0, 1, 2], [1, 2, 3]]);
    }

    #[test]
    fn grows_past_initial_capacity() {
        let mut b = MeshBuilder::with_capacity(0);
        for i in 0..10_000u32 {
            let f = i as f32;
            b.triangle([[f, 0.0, 0.0], [f, 1.0, 0.0], [f + 1.0, 0.0, 0.0]]);
        }
        let m = b.finish();
        assert_eq!(m.vertices.len(), 20_001);
        for (i, t) in m.triangles.iter().enumerate() {
            for (k, &v) in t.iter().enumerate() {
                let want = [[i as f32, 0.0, 0.0], [i as f32, 1.0, 0.0], [i as f32 + 1.0, 0.0, 0.0]][k];
                assert_eq!(m.vertices[v as usize], want);
            }
        }
    }
}

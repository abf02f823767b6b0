//! Content-addressed files: bundles, packages and reports, stored under
//! `<data_dir>/blobs/<first two hex digits>/<sha256>`, written atomically (temporary file in the
//! same folder, fsync, rename), so nothing half-written is ever visible.

use std::io::Write;
use std::path::{Path, PathBuf};

use sha2::{Digest, Sha256};

/// The blob folder.
#[derive(Clone, Debug)]
pub struct Blobs {
    root: PathBuf,
}

/// Hex SHA-256 of `bytes`.
pub fn sha256_hex(bytes: &[u8]) -> String {
    hex::encode(Sha256::digest(bytes))
}

impl Blobs {
    pub fn new(data_dir: &Path) -> std::io::Result<Blobs> {
        let root = data_dir.join("blobs");
        std::fs::create_dir_all(&root)?;
        Ok(Blobs { root })
    }

    fn path(&self, hash: &str) -> Option<PathBuf> {
        let valid = hash.len() == 64 && hash.bytes().all(|b| b.is_ascii_hexdigit() && !b.is_ascii_uppercase());
        valid.then(|| self.root.join(&hash[..2]).join(hash))
    }

    /// Stores `bytes` (blocking IO: call from a blocking context) and returns its hash.
    pub fn put(&self, bytes: &[u8]) -> std::io::Result<String> {
        let hash = sha256_hex(bytes);
        let path = self.path(&hash).ok_or_else(|| std::io::Error::other("bad hash"))?;
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

    /// Reads a blob; `Ok(None)` when absent.
    pub fn get(&self, hash: &str) -> std::io::Result<Option<Vec<u8>>> {
        let Some(path) = self.path(hash) else { return Ok(None) };
        match std::fs::read(path) {
            Ok(b) => Ok(Some(b)),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
            Err(e) => Err(e),
        }
    }
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
    }
}

//! Content-addressed files: bundles, packages and reports, stored under
//! `<data_dir>/blobs/<first two hex digits>/<sha256>`, written atomically (temporary file in the
//! same folder, fsync, rename), so nothing half-written is ever visible. A crash between the
//! write and the rename leaves a `.<hash>.<uuid>.tmp` file behind: [`Blobs::new`] removes them.

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
    /// Opens (creating) `<data_dir>/blobs` and removes the partial files a crash left behind.
    /// Call at start-up, before anything writes blobs.
    pub fn new(data_dir: &Path) -> std::io::Result<Blobs> {
        let root = data_dir.join("blobs");
        std::fs::create_dir_all(&root)?;
        let removed = remove_partial_files(&root)?;
        if removed > 0 {
            tracing::warn!(removed, "partial blob files left by a stop were removed");
        }
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

/// Whether `name` is a temporary file of [`Blobs::put`]: `.<64 hex>.<anything>.tmp`.
fn is_partial(name: &str) -> bool {
    name.strip_prefix('.')
        .and_then(|n| n.strip_suffix(".tmp"))
        .and_then(|n| n.split_once('.'))
        .is_some_and(|(hash, _)| hash.len() == 64 && hash.bytes().all(|b| b.is_ascii_hexdigit()))
}

/// Removes the temporary files of interrupted writes in the blob folders (one level deep, as
/// [`Blobs::put`] writes them). Returns how many were removed.
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
            if partial && entry.file_type()?.is_file() {
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

        let b = Blobs::new(dir.path()).unwrap();
        assert!(!partial.exists() && !partial2.exists());
        assert!(foreign.exists());
        assert_eq!(b.get(&h).unwrap().as_deref(), Some(&b"kept"[..]));
    }
}

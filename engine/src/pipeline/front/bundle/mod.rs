//! Input bundles: the files of one CAD export, held in memory.
//!
//! A bundle comes from a `.zip` ([`Bundle::from_zip`], read defensively: no absolute paths, no
//! `..`, caps on size, entry count and compression ratio; an entry is inflated at most one byte
//! past its declared size, so a header that lies is a `CorruptEntry` at the cost it declares)
//! or from a directory that the caller has read ([`Bundle::from_files`]; the pipeline itself
//! never touches the file system).
//!
//! Paths inside a bundle are relative, `/`-separated and normalised. Exports come from Windows and
//! real bundles keep meshes in sub-folders, so [`Bundle::resolve`] looks a referenced name up
//! exactly, then case-insensitively, then by file name anywhere in the bundle.

use std::collections::BTreeMap;
use std::io::Read;

/// Safety limits for reading a zip.
#[derive(Clone, Debug)]
pub struct Limits {
    /// Total uncompressed bytes.
    pub max_total_bytes: u64,
    /// Number of entries.
    pub max_entries: usize,
    /// Uncompressed / compressed size of one entry.
    pub max_ratio: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits { max_total_bytes: 1 << 30, max_entries: 20_000, max_ratio: 1_000 }
    }
}

/// Why a bundle could not be read or a file in it not found.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum BundleError {
    #[error("{bundle}: not a readable zip archive: {reason}")]
    NotZip { bundle: String, reason: String },
    #[error("{bundle}: entry \"{entry}\" has an unsafe path (absolute or with \"..\")")]
    UnsafePath { bundle: String, entry: String },
    #[error("{bundle}: more than {limit} entries")]
    TooManyEntries { bundle: String, limit: usize },
    #[error("{bundle}: uncompressed content exceeds {limit} bytes")]
    TooLarge { bundle: String, limit: u64 },
    #[error("{bundle}: entry \"{entry}\" expands {ratio}x (limit {limit}x): refusing a likely zip bomb")]
    CompressionRatio { bundle: String, entry: String, ratio: u64, limit: u64 },
    #[error("{bundle}: entry \"{entry}\" is corrupt: {reason}")]
    CorruptEntry { bundle: String, entry: String, reason: String },
    #[error("{bundle}: two entries map to the same path \"{entry}\"")]
    DuplicateEntry { bundle: String, entry: String },
    #[error("{bundle}: no model source found: expected a first-generation SimMechanics XML (root PhysicalModelingXMLFile), a second-generation Simscape Multibody XML (root SimscapeMultibodyImportXML) or a URDF (.urdf, root robot){hint}")]
    NoXml { bundle: String, hint: String },
    #[error("{bundle}: two model sources in one bundle: \"{first}\" ({first_kind}) and \"{second}\" ({second_kind}); a bundle holds one model: put each in its own bundle")]
    TwoSources { bundle: String, first: String, first_kind: &'static str, second: String, second_kind: &'static str },
    #[error("{bundle}: two model sources in one bundle: \"{first}\" and \"{second}\"; put each model in its own bundle")]
    TwoXml { bundle: String, first: String, second: String },
    #[error("{referenced_from}: \"{name}\" matches more than one file in the bundle: {}", candidates.join(", "))]
    Ambiguous { referenced_from: String, name: String, candidates: Vec<String> },
}

/// The files of one export, keyed by normalised relative path.
#[derive(Clone, Debug, Default)]
pub struct Bundle {
    /// A name for messages (the zip's or directory's name).
    pub name: String,
    files: BTreeMap<String, Vec<u8>>,
}

/// Normalises a relative path: `\` to `/`, no `.` segments, no empty segments. `None` when the path
/// is absolute, has a drive letter, or climbs with `..`.
pub fn normalise(path: &str) -> Option<String> {
    let p = path.replace('\\', "/");
    if p.starts_with('/') || p.as_bytes().get(1) == Some(&b':') {
        return None;
    }
    let mut parts = Vec::new();
    for seg in p.split('/') {
        match seg {
            "" | "." => {}
            ".." => return None,
            s => parts.push(s),
        }
    }
    if parts.is_empty() {
        return None;
    }
    Some(parts.join("/"))
}

impl Bundle {
    /// A bundle from files the caller read (paths relative to the bundle's root).
    /// Unsafe paths are rejected like zip entries.
    pub fn from_files(name: &str, files: impl IntoIterator<Item = (String, Vec<u8>)>) -> Result<Bundle, BundleError> {
        let mut b = Bundle { name: name.to_string(), files: BTreeMap::new() };
        for (path, bytes) in files {
            let norm = normalise(&path).ok_or_else(|| BundleError::UnsafePath { bundle: name.into(), entry: path.clone() })?;
            if b.files.insert(norm.clone(), bytes).is_some() {
                return Err(BundleError::DuplicateEntry { bundle: name.into(), entry: norm });
            }
        }
        Ok(b)
    }

    /// Reads a zip archive held in memory, enforcing `limits`. Entry names are UTF-8 when their
    /// bytes are valid UTF-8, flag or not (Info-ZIP 3.0, Linux `zip`, writes UTF-8 names without
    /// the flag), else what the archive says (CP437, or its Unicode path field).
    pub fn from_zip(name: &str, bytes: &[u8], limits: &Limits) -> Result<Bundle, BundleError> {
        let bundle = name.to_string();
        let mut archive = zip::ZipArchive::new(std::io::Cursor::new(bytes))
            .map_err(|e| BundleError::NotZip { bundle: bundle.clone(), reason: e.to_string() })?;
        if archive.len() > limits.max_entries {
            return Err(BundleError::TooManyEntries { bundle, limit: limits.max_entries });
        }
        let mut files = BTreeMap::new();
        let mut total: u64 = 0;
        for i in 0..archive.len() {
            let mut entry = archive.by_index(i).map_err(|e| BundleError::NotZip { bundle: bundle.clone(), reason: e.to_string() })?;
            let raw_name = entry_name(entry.name_raw(), entry.name());
            if entry.is_dir() {
                continue;
            }
            let path = normalise(&raw_name).ok_or_else(|| BundleError::UnsafePath { bundle: bundle.clone(), entry: raw_name.clone() })?;
            let declared = entry.size();
            let compressed = entry.compressed_size().max(1);
            if declared / compressed > limits.max_ratio {
                return Err(BundleError::CompressionRatio {
                    bundle,
                    entry: raw_name,
                    ratio: declared / compressed,
                    limit: limits.max_ratio,
                });
            }
            if total.saturating_add(declared) > limits.max_total_bytes {
                return Err(BundleError::TooLarge { bundle, limit: limits.max_total_bytes });
            }
            // Never trust the declared size: inflate at most one byte past it (and past what
            // the limits still allow), so a header that lies costs no more than it declares.
            let budget = (limits.max_total_bytes - total).min(compressed.saturating_mul(limits.max_ratio)).min(declared).saturating_add(1);
            let mut data = Vec::with_capacity(declared.min(budget) as usize);
            (&mut entry).take(budget).read_to_end(&mut data).map_err(|e| BundleError::CorruptEntry {
                bundle: bundle.clone(),
                entry: raw_name.clone(),
                reason: e.to_string(),
            })?;
            if data.len() as u64 >= budget {
                return Err(if data.len() as u64 > declared {
                    BundleError::CorruptEntry {
                        bundle,
                        entry: raw_name,
                        reason: format!("inflates to more than the {declared} bytes its header declares"),
                    }
                } else if total + data.len() as u64 > limits.max_total_bytes {
                    BundleError::TooLarge { bundle, limit: limits.max_total_bytes }
                } else {
                    BundleError::CompressionRatio {
                        bundle,
                        entry: raw_name,
                        ratio: data.len() as u64 / compressed,
                        limit: limits.max_ratio,
                    }
                });
            }
            total += data.len() as u64;
            if files.insert(path.clone(), data).is_some() {
                return Err(BundleError::DuplicateEntry { bundle, entry: path });
            }
        }
        Ok(Bundle { name: name.to_string(), files })
    }

    /// Every file path, sorted.
    pub fn paths(&self) -> impl Iterator<Item = &str> {
        self.files.keys().map(String::as_str)
    }

    pub fn get(&self, path: &str) -> Option<&[u8]> {
        self.files.get(path).map(Vec::as_slice)
    }

    pub fn len(&self) -> usize {
        self.files.len()
    }

    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }

    /// Total bytes held.
    pub fn total_bytes(&self) -> u64 {
        self.files.values().map(|v| v.len() as u64).sum()
    }

    /// The one model source in the bundle: each file is asked of `kind_of` (its path and
    /// bytes; `None` when it is no source). Two sources of one kind are [`BundleError::TwoXml`],
    /// of two kinds [`BundleError::TwoSources`], none [`BundleError::NoXml`].
    pub fn find_source<K: Copy + PartialEq>(
        &self,
        kind_of: impl Fn(&str, &[u8]) -> Option<K>,
        describe: impl Fn(K) -> &'static str,
    ) -> Result<(K, &str), BundleError> {
        let mut found: Option<(K, &str)> = None;
        for (path, bytes) in &self.files {
            let Some(kind) = kind_of(path, bytes) else { continue };
            if let Some((k, first)) = found {
                return Err(if k == kind {
                    BundleError::TwoXml { bundle: self.name.clone(), first: first.to_string(), second: path.clone() }
                } else {
                    BundleError::TwoSources {
                        bundle: self.name.clone(),
                        first: first.to_string(),
                        first_kind: describe(k),
                        second: path.clone(),
                        second_kind: describe(kind),
                    }
                });
            }
            found = Some((kind, path));
        }
        found.ok_or_else(|| {
            let xmls: Vec<&str> = self
                .paths()
                .filter(|p| {
                    let l = p.to_ascii_lowercase();
                    l.ends_with(".xml") || l.ends_with(".urdf") || l.ends_with(".xacro")
                })
                .collect();
            let hint = if xmls.is_empty() {
                " (the bundle holds no .xml or .urdf file)".to_string()
            } else {
                format!(" (XML files present but of another kind: {})", crate::pipeline::ir::bounded_list(&xmls, 10))
            };
            BundleError::NoXml { bundle: self.name.clone(), hint }
        })
    }

    /// The one file for which `is_export` holds (e.g. the XML sniffer). Two is an error naming both.
    pub fn find_export(&self, is_export: impl Fn(&[u8]) -> bool) -> Result<&str, BundleError> {
        let mut found: Option<&str> = None;
        for (path, bytes) in &self.files {
            let looks_xml = path.to_ascii_lowercase().ends_with(".xml");
            if looks_xml && is_export(bytes) {
                if let Some(first) = found {
                    return Err(BundleError::TwoXml { bundle: self.name.clone(), first: first.to_string(), second: path.clone() });
                }
                found = Some(path);
            }
        }
        found.ok_or_else(|| {
            let xmls: Vec<&str> = self.paths().filter(|p| p.to_ascii_lowercase().ends_with(".xml")).collect();
            let hint = if xmls.is_empty() {
                " (the bundle holds no .xml file)".to_string()
            } else {
                format!(" (XML files present but of another kind: {})", xmls.join(", "))
            };
            BundleError::NoXml { bundle: self.name.clone(), hint }
        })
    }

    /// Finds the file a reference names, as seen from `referenced_from` (a bundle path).
    ///
    /// Order: the path relative to the referencing file's folder, exactly; then the same
    /// case-insensitively; then any file in the bundle with that file name (case-insensitive).
    /// `Ok(None)` when nothing matches; an error when a step finds two candidates.
    pub fn resolve(&self, referenced_from: &str, name: &str) -> Result<Option<&str>, BundleError> {
        let dir = referenced_from.rsplit_once('/').map(|(d, _)| d).unwrap_or("");
        let joined = if dir.is_empty() { name.to_string() } else { format!("{dir}/{name}") };
        let Some(wanted) = normalise(&joined).or_else(|| normalise(name)) else {
            return Ok(None);
        };
        if let Some((k, _)) = self.files.get_key_value(&wanted) {
            return Ok(Some(k.as_str()));
        }
        let lower = wanted.to_lowercase();
        let by_path: Vec<&str> = self.paths().filter(|p| p.to_lowercase() == lower).collect();
        if let Some(found) = self.one(referenced_from, name, by_path)? {
            return Ok(Some(found));
        }
        let file_name = lower.rsplit('/').next().unwrap_or(&lower).to_string();
        let by_name: Vec<&str> = self.paths().filter(|p| p.rsplit('/').next().unwrap_or(p).to_lowercase() == file_name).collect();
        self.one(referenced_from, name, by_name)
    }

    fn one<'a>(&self, referenced_from: &str, name: &str, candidates: Vec<&'a str>) -> Result<Option<&'a str>, BundleError> {
        match candidates.len() {
            0 => Ok(None),
            1 => Ok(Some(candidates[0])),
            _ => Err(BundleError::Ambiguous {
                referenced_from: referenced_from.to_string(),
                name: name.to_string(),
                candidates: candidates.into_iter().map(String::from).collect(),
            }),
        }
    }
}

/// An entry's name: the raw bytes when they are non-ASCII valid UTF-8 (a CP437 name that
/// happens to be valid UTF-8 is vanishingly rare: its high bytes would have to form exact
/// UTF-8 sequences), else the archive's decoding (`decoded`: CP437 without the UTF-8 flag, the
/// Unicode path extra field where present).
fn entry_name(raw: &[u8], decoded: &str) -> String {
    match std::str::from_utf8(raw) {
        Ok(s) if !raw.is_ascii() => s.to_string(),
        _ => decoded.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    fn zip_of(entries: &[(&str, &[u8])]) -> Vec<u8> {
        let mut out = Vec::new();
        {
            let mut w = zip::ZipWriter::new(std::io::Cursor::new(&mut out));
            let opts = zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Deflated);
            for (name, data) in entries {
                w.start_file(*name, opts).unwrap();
                w.write_all(data).unwrap();
            }
            w.finish().unwrap();
        }
        out
    }

    #[test]
    fn normalise_rejects_escapes() {
        assert_eq!(normalise("a\\b/./c.stl").as_deref(), Some("a/b/c.stl"));
        assert_eq!(normalise("../x"), None);
        assert_eq!(normalise("a/../../x"), None);
        assert_eq!(normalise("/etc/passwd"), None);
        assert_eq!(normalise("C:/x"), None);
        assert_eq!(normalise(""), None);
    }

    #[test]
    fn zip_round_trip_and_lookup() {
        let z = zip_of(&[("model/ARM.xml", b"<PhysicalModelingXMLFile/>"), ("model/meshes/simmechanics/arm_prt.stl", b"solid x")]);
        let b = Bundle::from_zip("b.zip", &z, &Limits::default()).unwrap();
        assert_eq!(b.len(), 2);
        let xml = b.find_export(|bytes| bytes.starts_with(b"<Phys")).unwrap();
        assert_eq!(xml, "model/ARM.xml");
        assert_eq!(b.resolve(xml, "ARM_PRT.STL").unwrap(), Some("model/meshes/simmechanics/arm_prt.stl"));
        assert_eq!(b.resolve(xml, "missing.stl").unwrap(), None);
    }

    #[test]
    fn utf8_names_without_the_flag_are_utf8_and_others_cp437() {
        // Info-ZIP 3.0 stores "gehäuse_prt.stl" as UTF-8 bytes with general-purpose bit 11
        // clear. Written here as a same-length ASCII name (no flag), then patched in place.
        let z = zip_of(&[("gehXXuse_prt.stl", b"solid x\nendsolid x\n"), ("m\u{e9}.txt", b"y")]);
        let mut bytes = z.clone();
        let (from, to) = (b"gehXXuse_prt.stl", "geh\u{e4}use_prt.stl".as_bytes());
        assert_eq!(from.len(), to.len());
        let mut patched = 0;
        while let Some(i) = bytes.windows(from.len()).position(|w| w == from) {
            bytes[i..i + from.len()].copy_from_slice(to);
            patched += 1;
        }
        assert_eq!(patched, 2, "local and central headers");
        let b = Bundle::from_zip("b.zip", &bytes, &Limits::default()).unwrap();
        assert!(b.get("geh\u{e4}use_prt.stl").is_some(), "{:?}", b.paths().collect::<Vec<_>>());
        assert_eq!(b.resolve("M.xml", "GEH\u{c4}USE_PRT.STL").unwrap(), Some("geh\u{e4}use_prt.stl"));
        // A flagged UTF-8 name (the zip crate sets the flag) reads the same.
        assert!(b.get("m\u{e9}.txt").is_some());
        // Bytes that are not UTF-8 are CP437: 0x84 is "ä" there.
        assert_eq!(entry_name(b"geh\x84use", "geh\u{e4}use"), "geh\u{e4}use");
    }

    #[test]
    fn zip_slip_is_refused() {
        let z = zip_of(&[("../evil.txt", b"x")]);
        assert!(matches!(Bundle::from_zip("b.zip", &z, &Limits::default()), Err(BundleError::UnsafePath { .. })));
    }

    #[test]
    fn zip_bomb_is_refused() {
        let zeros = vec![0u8; 5_000_000];
        let z = zip_of(&[("bomb.bin", &zeros)]);
        let err = Bundle::from_zip("b.zip", &z, &Limits::default()).unwrap_err();
        assert!(matches!(err, BundleError::CompressionRatio { .. }), "{err}");
        let small = Limits { max_total_bytes: 1000, max_entries: 10, max_ratio: 1_000_000 };
        let err = Bundle::from_zip("b.zip", &z, &small).unwrap_err();
        assert!(matches!(err, BundleError::TooLarge { .. }), "{err}");
    }

    /// A deflated entry of `len` zeros whose local and central headers declare `declared`
    /// uncompressed bytes.
    fn lying_zip(len: usize, declared: u32) -> Vec<u8> {
        let mut z = zip_of(&[("m/lie.bin", &vec![0u8; len])]);
        let patch = |z: &mut Vec<u8>, sig: &[u8; 4], offset: usize| {
            let at = z.windows(4).position(|w| w == sig).unwrap() + offset;
            z[at..at + 4].copy_from_slice(&declared.to_le_bytes());
        };
        patch(&mut z, b"PK\x03\x04", 22);
        patch(&mut z, b"PK\x01\x02", 24);
        z
    }

    #[test]
    fn entry_larger_than_its_header_declares_is_refused_at_the_declared_size() {
        // 200 KB of zeros (a ratio under the limit) declared as 100 bytes.
        let z = lying_zip(200_000, 100);
        let err = Bundle::from_zip("b.zip", &z, &Limits::default()).unwrap_err();
        assert_eq!(
            err,
            BundleError::CorruptEntry {
                bundle: "b.zip".into(),
                entry: "m/lie.bin".into(),
                reason: "inflates to more than the 100 bytes its header declares".into()
            }
        );
        // A declared size over the ratio limit is refused before inflating.
        let z = lying_zip(200_000, 100_000_000);
        let err = Bundle::from_zip("b.zip", &z, &Limits::default()).unwrap_err();
        assert!(matches!(err, BundleError::CompressionRatio { .. }), "{err}");
        // The truth is accepted.
        let z = lying_zip(200_000, 200_000);
        assert_eq!(Bundle::from_zip("b.zip", &z, &Limits::default()).unwrap().total_bytes(), 200_000);
    }

    #[test]
    fn not_a_zip() {
        let err = Bundle::from_zip("b.zip", b"hello", &Limits::default()).unwrap_err();
        assert!(err.to_string().starts_with("b.zip: not a readable zip"), "{err}");
    }

    #[test]
    fn ambiguous_and_two_xml() {
        let b = Bundle::from_files(
            "dir",
            [
                ("m.xml".to_string(), b"X".to_vec()),
                ("n.xml".to_string(), b"X".to_vec()),
                ("a/PART.stl".to_string(), vec![]),
                ("b/part.STL".to_string(), vec![]),
            ],
        )
        .unwrap();
        let err = b.resolve("m.xml", "part.stl").unwrap_err();
        assert!(err.to_string().contains("a/PART.stl, b/part.STL"), "{err}");
        let err = b.find_export(|x| x == b"X").unwrap_err();
        assert!(err.to_string().contains("\"m.xml\" and \"n.xml\""), "{err}");
    }
}

//! The output bundle: one zip holding the package and `report.json`.
//!
//! Entries are stored in the order given, with a fixed timestamp, so the same conversion gives
//! byte-identical zips.

use std::io::Write;

/// Zips `files` (paths relative to the zip root) into memory.
pub fn write_zip(files: &[(String, Vec<u8>)]) -> Result<Vec<u8>, std::io::Error> {
    write_zip_observed(files, &mut |_, _| {})
}

/// [`write_zip`], calling `done(i, n)` before each of the `n` files is deflated.
pub fn write_zip_observed(files: &[(String, Vec<u8>)], done: &mut dyn FnMut(usize, usize)) -> Result<Vec<u8>, std::io::Error> {
    let mut out = std::io::Cursor::new(Vec::new());
    {
        let mut zip = zip::ZipWriter::new(&mut out);
        let opts = zip::write::SimpleFileOptions::default()
            .compression_method(zip::CompressionMethod::Deflated)
            .last_modified_time(zip::DateTime::default())
            .large_file(false);
        for (i, (path, bytes)) in files.iter().enumerate() {
            done(i, files.len());
            zip.start_file(path.as_str(), opts).map_err(std::io::Error::other)?;
            zip.write_all(bytes)?;
        }
        zip.finish().map_err(std::io::Error::other)?;
    }
    Ok(out.into_inner())
}

#[cfg(test)]
mod tests {
    #[test]
    fn deterministic() {
        let files = vec![("P/a.mo".to_string(), b"model a end a;".to_vec())];
        let a = super::write_zip(&files).unwrap();
        let b = super::write_zip(&files).unwrap();
        assert_eq!(a, b);
        let mut z = zip::ZipArchive::new(std::io::Cursor::new(a)).unwrap();
        assert_eq!(z.by_index(0).unwrap().name(), "P/a.mo");
    }
}

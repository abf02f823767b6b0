//! The output bundle: one zip holding the package and `report.json`.
//!
//! Entries are stored in the order given, with a fixed timestamp, so the same conversion gives
//! byte-identical zips.

use std::io::Write;

/// Zips `files` (paths relative to the zip root) into memory.
pub fn write_zip(files: &[(String, Vec<u8>)]) -> Result<Vec<u8>, std::io::Error> {
    write_zip_observed(files, &mut |_, _| {})
}

/// Below this many bytes in all, files are deflated on one thread.
const PARALLEL_BYTES: usize = 4 << 20;
/// Pieces a large zip is deflated in (on as many threads; a fixed number, so that the zip's bytes
/// do not depend on the machine's cores).
const PIECES: usize = 4;

/// [`write_zip`], calling `done(i, n)` as the `n` files are deflated. A large set of files is
/// deflated in [`PIECES`] runs of consecutive files on as many threads, each into a zip of its
/// own, whose entries are then copied verbatim into one: the same bytes as deflating them in
/// turn.
pub fn write_zip_observed(files: &[(String, Vec<u8>)], done: &mut dyn FnMut(usize, usize)) -> Result<Vec<u8>, std::io::Error> {
    let total: usize = files.iter().map(|(_, b)| b.len()).sum();
    if total < PARALLEL_BYTES || files.len() < PIECES {
        return zip_run(files, done);
    }
    // Consecutive runs of about equal bytes.
    let mut bounds = vec![0usize];
    let mut acc = 0usize;
    for (i, (_, b)) in files.iter().enumerate() {
        acc += b.len();
        if acc * PIECES >= total * bounds.len() && bounds.len() < PIECES && i + 1 < files.len() {
            bounds.push(i + 1);
        }
    }
    bounds.push(files.len());
    let pieces: Vec<Result<Vec<u8>, std::io::Error>> = std::thread::scope(|scope| {
        let handles: Vec<_> = bounds
            .windows(2)
            .map(|w| {
                let part = &files[w[0]..w[1]];
                scope.spawn(move || zip_run(part, &mut |_, _| {}))
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap_or_else(|e| std::panic::resume_unwind(e))).collect()
    });
    let mut out = std::io::Cursor::new(Vec::new());
    {
        let mut zip = zip::ZipWriter::new(&mut out);
        for (k, piece) in pieces.into_iter().enumerate() {
            done(bounds[k], files.len());
            let archive = zip::ZipArchive::new(std::io::Cursor::new(piece?)).map_err(std::io::Error::other)?;
            zip.merge_archive(archive).map_err(std::io::Error::other)?;
        }
        zip.finish().map_err(std::io::Error::other)?;
    }
    Ok(out.into_inner())
}

/// Zips `files` in turn, calling `done(i, n)` before each of the `n`.
fn zip_run(files: &[(String, Vec<u8>)], done: &mut dyn FnMut(usize, usize)) -> Result<Vec<u8>, std::io::Error> {
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

    /// A large set of files deflated in pieces on several threads gives the same bytes as one
    /// run, and every file reads back.
    #[test]
    fn pieces_give_the_bytes_of_one_run() {
        let files: Vec<(String, Vec<u8>)> =
            (0..40).map(|i| (format!("P/f{i}.txt"), (0..200_000u32).map(|k| ((k * 7 + i) % 251) as u8).collect())).collect();
        let total: usize = files.iter().map(|(_, b)| b.len()).sum();
        assert!(total >= super::PARALLEL_BYTES);
        let parallel = super::write_zip(&files).unwrap();
        let serial = super::zip_run(&files, &mut |_, _| {}).unwrap();
        assert_eq!(parallel, serial);
        let mut z = zip::ZipArchive::new(std::io::Cursor::new(parallel)).unwrap();
        assert_eq!(z.len(), 40);
        let mut back = Vec::new();
        std::io::Read::read_to_end(&mut z.by_name("P/f39.txt").unwrap(), &mut back).unwrap();
        assert_eq!(back, files[39].1);
    }
}

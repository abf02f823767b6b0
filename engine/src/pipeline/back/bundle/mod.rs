//! The output bundle: one zip holding the package and `report.json`.
//!
//! Entries are stored in the order given, with a fixed timestamp, so the same conversion gives
//! byte-identical zips. A file may come already deflated ([`FileData`]): the conversion deflates
//! the large shape files (DXF and STL per body) as it writes them, so it never holds them all as
//! plain bytes (issue 26, peak memory); the zip lays them out as they are.

use std::borrow::Cow;
use std::io::Write;

/// One file of the output: its bytes, or its bytes deflated for the zip (the same entry either
/// way: [`write_files`] deflates plain files exactly as [`Deflater`] does).
#[derive(Clone, Debug)]
pub struct FileData(Data);

#[derive(Clone, Debug)]
enum Data {
    Plain(Vec<u8>),
    /// Deflated bytes (`method` 8) of `len` plain bytes whose CRC-32 is `crc`.
    Deflated {
        len: usize,
        crc: u32,
        data: Vec<u8>,
    },
}

impl FileData {
    /// The plain bytes' length.
    pub fn len(&self) -> usize {
        match &self.0 {
            Data::Plain(b) => b.len(),
            Data::Deflated { len, .. } => *len,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Whether the bytes are held deflated.
    pub fn is_deflated(&self) -> bool {
        matches!(self.0, Data::Deflated { .. })
    }

    /// The plain bytes (inflated when held deflated: a copy, for readers and tests).
    pub fn bytes(&self) -> Cow<'_, [u8]> {
        match &self.0 {
            Data::Plain(b) => Cow::Borrowed(b),
            Data::Deflated { len, data, .. } => {
                let mut out = vec![0; *len];
                // Our own deflate of exactly `len` bytes: it inflates to them.
                match libdeflater::Decompressor::new().deflate_decompress(data, &mut out) {
                    Ok(n) if n == *len => Cow::Owned(out),
                    _ => Cow::Owned(Vec::new()),
                }
            }
        }
    }

    /// The plain bytes, by value.
    pub fn into_bytes(self) -> Vec<u8> {
        match self.0 {
            Data::Plain(b) => b,
            d @ Data::Deflated { .. } => FileData(d).bytes().into_owned(),
        }
    }
}

impl From<Vec<u8>> for FileData {
    fn from(bytes: Vec<u8>) -> FileData {
        FileData(Data::Plain(bytes))
    }
}

/// Files are equal when their plain bytes are, however they are held.
impl PartialEq for FileData {
    fn eq(&self, other: &FileData) -> bool {
        match (&self.0, &other.0) {
            (Data::Plain(a), Data::Plain(b)) => a == b,
            (Data::Deflated { len: la, crc: ca, data: da }, Data::Deflated { len: lb, crc: cb, data: db }) => {
                la == lb && ca == cb && da == db
            }
            _ => self.len() == other.len() && self.bytes() == other.bytes(),
        }
    }
}

/// Deflates files for the zip ahead of it, with one reused compressor.
pub struct Deflater(libdeflater::Compressor);

impl Default for Deflater {
    fn default() -> Deflater {
        Deflater(compressor())
    }
}

impl Deflater {
    /// `bytes` as the zip will hold them: deflated, or plain when deflating does not shrink them
    /// (the zip then stores them). The plain bytes are dropped once deflated.
    pub fn file(&mut self, bytes: Vec<u8>) -> FileData {
        match pack(&mut self.0, &bytes) {
            (crc, Some(data)) => FileData(Data::Deflated { len: bytes.len(), crc, data }),
            (_, None) => FileData(Data::Plain(bytes)),
        }
    }
}

fn compressor() -> libdeflater::Compressor {
    libdeflater::Compressor::new(libdeflater::CompressionLvl::new(LEVEL).unwrap_or_default())
}

/// Zips `files` (paths relative to the zip root) into memory. They are copied first: a package
/// is zipped by [`write_files`], which frees each file as it goes.
pub fn write_zip(files: &[(String, Vec<u8>)]) -> Result<Vec<u8>, std::io::Error> {
    write_files(files.iter().map(|(p, b)| (p.clone(), FileData::from(b.clone()))).collect())
}

/// Zips `files` (paths relative to the zip root) into memory.
pub fn write_files(files: Vec<(String, FileData)>) -> Result<Vec<u8>, std::io::Error> {
    write_files_observed(files, &mut |_, _| {})
}

/// Deflate level (libdeflate's 1 to 12). Measured on the 2,000-body package with meshes (6,040
/// files, 63 MB): level 1 (libdeflate's fastest matcher) deflates it in 1.78 G instructions for a
/// zip of 10.1 MB; level 3 took 2.79 G for 8.9 MB (a third of the whole conversion's work), zlib's
/// default level 6 through the `zip` crate about twice that for 7.6 MB (callgrind, 2026-11-29;
/// README, Speed). The package is written once per conversion and fetched a few times: time wins.
const LEVEL: i32 = 1;
/// The classic zip format's limits (no zip64): entries, and sizes and offsets below 4 GiB. A
/// package beyond them is written by the `zip` crate (zip64), slower.
const MAX_ENTRIES: usize = 0xFFFE;
const MAX_SIZE: u64 = 0xFFFF_FFFE;
/// DOS date of every entry: 1980-01-01 00:00 (the zip format's epoch), so that the same
/// conversion gives the same bytes.
const DOS_DATE: u16 = (1 << 5) | 1;
/// Unix regular file, rw-r--r--, in the external attributes' upper half.
const UNIX_FILE: u32 = 0o100644 << 16;

/// `bytes`' CRC-32 and their deflated bytes, when deflating shrinks them (else the zip stores
/// them as they are).
fn pack(compressor: &mut libdeflater::Compressor, bytes: &[u8]) -> (u32, Option<Vec<u8>>) {
    let crc = crc32fast::hash(bytes);
    let mut data = vec![0; compressor.deflate_compress_bound(bytes.len())];
    match compressor.deflate_compress(bytes, &mut data) {
        Ok(n) if n < bytes.len() => {
            // The bound is above the input's size: keeping it would hold as much memory again
            // as the files (issue 26, peak memory).
            data.truncate(n);
            data.shrink_to_fit();
            (crc, Some(data))
        }
        _ => (crc, None),
    }
}

/// [`write_files`], calling `done(i, n)` as the `n` plain files are deflated. Each file is deflated
/// on its own (libdeflate, one compressor per thread, reused), on all cores, and the entries are
/// then laid out in the order given: the bytes do not depend on the number of threads, nor on
/// which files came deflated (a [`Deflater`] deflates exactly as this does). Each file is freed
/// once laid out.
///
/// The `zip` crate gave no way to write an entry deflated elsewhere and made a fresh deflate
/// state per entry (about 0.5 MB cleared each time, most of the cost for a package of thousands
/// of small shape files); the container itself is a few headers, read back by the `zip` crate
/// and Python's `zipfile` in the tests.
pub fn write_files_observed(files: Vec<(String, FileData)>, done: &mut dyn FnMut(usize, usize)) -> Result<Vec<u8>, std::io::Error> {
    let mut out = Vec::new();
    write_zip_to(files, done, Sink::Memory(&mut out))?;
    Ok(out)
}

/// Where [`write_zip_to`] writes: memory (reserved once, to the zip's size) or a stream.
enum Sink<'a> {
    Memory(&'a mut Vec<u8>),
    Stream(&'a mut dyn Write),
}

impl Sink<'_> {
    fn reserve(&mut self, n: usize) {
        if let Sink::Memory(v) = self {
            v.reserve_exact(n);
        }
    }
    fn write_all(&mut self, bytes: &[u8]) -> Result<(), std::io::Error> {
        match self {
            Sink::Memory(v) => {
                v.extend_from_slice(bytes);
                Ok(())
            }
            Sink::Stream(w) => w.write_all(bytes),
        }
    }
}

/// [`write_files_observed`] into `sink` (a file: the zip is never held whole in memory, and its
/// bytes are copied once, into the file). What is written is the same as
/// [`write_files_observed`]'s bytes; on an error, part of it may have been written.
pub fn write_files_into(
    files: Vec<(String, FileData)>,
    done: &mut dyn FnMut(usize, usize),
    sink: &mut dyn Write,
) -> Result<(), std::io::Error> {
    write_zip_to(files, done, Sink::Stream(sink))
}

fn write_zip_to(files: Vec<(String, FileData)>, done: &mut dyn FnMut(usize, usize), mut sink: Sink<'_>) -> Result<(), std::io::Error> {
    let total: u64 = files.iter().map(|(p, b)| (b.len() + 2 * p.len() + 76) as u64).sum::<u64>() + 22;
    if files.len() > MAX_ENTRIES || total > MAX_SIZE {
        return sink.write_all(&zip_crate(&files, done)?);
    }
    let n_files = files.len();
    // The plain files, deflated here.
    let plain: Vec<usize> = (0..n_files).filter(|&i| !files[i].1.is_deflated()).collect();
    let n = plain.len();
    let next = std::sync::atomic::AtomicUsize::new(0);
    let finished = std::sync::atomic::AtomicUsize::new(0);
    let work = |report: &mut dyn FnMut(usize)| {
        let mut compressor = compressor();
        let mut mine = Vec::new();
        loop {
            let k = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            let Some(&i) = plain.get(k) else { break };
            if let (_, FileData(Data::Plain(bytes))) = &files[i] {
                mine.push((i, pack(&mut compressor, bytes)));
            }
            report(finished.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1);
        }
        mine
    };
    let threads = std::thread::available_parallelism().map_or(1, |t| t.get()).min(n.max(1)).min(8);
    let mut packed: Vec<Option<(u32, Option<Vec<u8>>)>> = (0..n_files).map(|_| None).collect();
    // Progress is reported from this thread only (`done` need not be `Send`): the files it
    // deflates, then the end, which the other threads may reach first (on a busy machine they
    // can deflate every file before this thread takes one).
    let mut last = 0;
    std::thread::scope(|scope| {
        let helpers: Vec<_> = (1..threads).map(|_| scope.spawn(|| work(&mut |_| {}))).collect();
        for (i, p) in work(&mut |k| {
            last = k;
            done(k, n);
        }) {
            packed[i] = Some(p);
        }
        for h in helpers {
            for (i, p) in h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)) {
                packed[i] = Some(p);
            }
        }
    });
    if last < n {
        done(n, n);
    }
    // Each entry: (method, CRC, the bytes the zip holds), from the file or from its deflate here.
    let entry = |file: &FileData, p: Option<&(u32, Option<Vec<u8>>)>| -> Option<(u16, u32, usize)> {
        match (&file.0, p) {
            (Data::Deflated { crc, data, .. }, _) => Some((8, *crc, data.len())),
            (Data::Plain(_), Some((crc, Some(d)))) => Some((8, *crc, d.len())),
            (Data::Plain(b), Some((crc, None))) => Some((0, *crc, b.len())),
            (Data::Plain(_), None) => None,
        }
    };
    let mut size = 22;
    for ((path, file), p) in files.iter().zip(&packed) {
        let (_, _, len) = entry(file, p.as_ref()).ok_or_else(|| std::io::Error::other("a zip entry was not deflated"))?;
        size += len + 2 * path.len() + 76;
    }
    sink.reserve(size);
    // Headers are gathered and written with the data before them, so the sink sees few writes.
    let mut out = Vec::with_capacity(size.min(1 << 16));
    let mut written = 0usize;
    let mut central = Vec::new();
    // Each file and its deflated bytes are freed once copied.
    for ((path, file), p) in files.into_iter().zip(packed) {
        let (method, crc, _) = entry(&file, p.as_ref()).ok_or_else(|| std::io::Error::other("a zip entry was not deflated"))?;
        let len = file.len();
        let data: Vec<u8> = match (file.0, p) {
            (Data::Deflated { data, .. }, _) | (Data::Plain(_), Some((_, Some(data)))) => data,
            (Data::Plain(b), _) => b,
        };
        let name = path.as_bytes();
        let flags: u16 = if path.is_ascii() { 0 } else { 1 << 11 };
        let needed: u16 = if method == 8 { 20 } else { 10 };
        let offset = (written + out.len()) as u32;
        // The fields a local header and a central directory entry share, from the version needed on.
        let mut common = Vec::with_capacity(26);
        for v in [needed, flags, method, 0, DOS_DATE] {
            common.extend_from_slice(&v.to_le_bytes());
        }
        for v in [crc, data.len() as u32, len as u32] {
            common.extend_from_slice(&v.to_le_bytes());
        }
        common.extend_from_slice(&(name.len() as u16).to_le_bytes());
        common.extend_from_slice(&0u16.to_le_bytes());
        out.extend_from_slice(&0x0403_4b50u32.to_le_bytes());
        out.extend_from_slice(&common);
        out.extend_from_slice(name);
        if out.len() + data.len() > 1 << 16 {
            written += out.len() + data.len();
            sink.write_all(&out)?;
            sink.write_all(&data)?;
            out.clear();
        } else {
            out.extend_from_slice(&data);
        }
        central.extend_from_slice(&0x0201_4b50u32.to_le_bytes());
        central.extend_from_slice(&((3u16 << 8) | 20).to_le_bytes());
        central.extend_from_slice(&common);
        for v in [0u16, 0, 0] {
            central.extend_from_slice(&v.to_le_bytes());
        }
        central.extend_from_slice(&UNIX_FILE.to_le_bytes());
        central.extend_from_slice(&offset.to_le_bytes());
        central.extend_from_slice(name);
    }
    let (cd_offset, cd_size) = ((written + out.len()) as u32, central.len() as u32);
    out.extend_from_slice(&central);
    out.extend_from_slice(&0x0605_4b50u32.to_le_bytes());
    for v in [0u16, 0, n_files as u16, n_files as u16] {
        out.extend_from_slice(&v.to_le_bytes());
    }
    out.extend_from_slice(&cd_size.to_le_bytes());
    out.extend_from_slice(&cd_offset.to_le_bytes());
    out.extend_from_slice(&0u16.to_le_bytes());
    sink.write_all(&out)
}

/// Zips `files` in turn with the `zip` crate (zip64 where needed), calling `done(i, n)` before
/// each of the `n`.
fn zip_crate(files: &[(String, FileData)], done: &mut dyn FnMut(usize, usize)) -> Result<Vec<u8>, std::io::Error> {
    let mut out = std::io::Cursor::new(Vec::new());
    {
        let mut zip = zip::ZipWriter::new(&mut out);
        let opts = zip::write::SimpleFileOptions::default()
            .compression_method(zip::CompressionMethod::Deflated)
            .last_modified_time(zip::DateTime::default())
            .large_file(true);
        for (i, (path, bytes)) in files.iter().enumerate() {
            done(i, files.len());
            zip.start_file(path.as_str(), opts).map_err(std::io::Error::other)?;
            zip.write_all(&bytes.bytes())?;
        }
        zip.finish().map_err(std::io::Error::other)?;
    }
    Ok(out.into_inner())
}

#[cfg(test)]
mod tests {
    /// A deflated entry keeps only its bytes, not the compressor's bound (about the input's size):
    /// the entries of a package are all held until laid out (issue 26, peak memory).
    #[test]
    fn a_deflated_entry_holds_only_its_bytes() {
        let mut c = super::compressor();
        let text = b"0 0 0\n".repeat(100_000);
        let (_, data) = super::pack(&mut c, &text);
        let data = data.expect("deflated");
        assert!(data.len() < text.len() / 100 && data.capacity() == data.len(), "{} of {}", data.len(), data.capacity());
    }

    /// Streamed into a writer (the command line's file), the zip is the one made in memory:
    /// small entries gathered, large ones (beyond the 64 KB batch) written through, plain,
    /// deflated and stored entries alike.
    #[test]
    fn a_streamed_zip_is_the_one_made_in_memory() {
        let big: Vec<u8> = (0..300_000u32).flat_map(|i| (i % 251).to_le_bytes()).collect();
        let mix = |i: u64| {
            let x = (i ^ 0x9e37_79b9_7f4a_7c15).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            let x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            (x ^ (x >> 31)) as u8
        };
        // Not shrunk by deflating: stored, and larger than a batch.
        let random: Vec<u8> = (0..100_000u64).map(mix).collect();
        let files = || {
            vec![
                ("P/a.mo".to_string(), super::FileData::from(b"model a end a;".to_vec())),
                ("P/big.txt".to_string(), super::Deflater::default().file(big.clone())),
                ("P/random.bin".to_string(), super::FileData::from(random.clone())),
                ("P/b.mo".to_string(), super::FileData::from(b"model b end b;".to_vec())),
            ]
        };
        let mut streamed: Vec<u8> = Vec::new();
        super::write_files_into(files(), &mut |_, _| {}, &mut streamed as &mut dyn std::io::Write).unwrap();
        let memory = super::write_files(files()).unwrap();
        assert!(memory.len() > random.len(), "the random entry is stored");
        assert_eq!(streamed, memory);
        let back = read_back(&streamed);
        let names: Vec<&str> = back.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, ["P/a.mo", "P/big.txt", "P/random.bin", "P/b.mo"]);
        assert_eq!(back[0].1, b"model a end a;");
        assert_eq!(back[1].1, big);
        assert_eq!(back[2].1, random);
        assert_eq!(back[3].1, b"model b end b;");
        // Python's zipfile reads each entry at its local header's offset.
        let mut z = zip::ZipArchive::new(std::io::Cursor::new(&streamed)).unwrap();
        for i in 0..z.len() {
            let f = z.by_index(i).unwrap();
            let at = f.header_start() as usize;
            assert_eq!(&streamed[at..at + 4], b"PK\x03\x04", "{}", f.name());
            let name_len = u16::from_le_bytes([streamed[at + 26], streamed[at + 27]]) as usize;
            assert_eq!(&streamed[at + 30..at + 30 + name_len], f.name().as_bytes());
        }
    }

    #[test]
    fn deterministic() {
        let files = vec![("P/a.mo".to_string(), b"model a end a;".to_vec())];
        let a = super::write_zip(&files).unwrap();
        let b = super::write_zip(&files).unwrap();
        assert_eq!(a, b);
        let mut z = zip::ZipArchive::new(std::io::Cursor::new(a)).unwrap();
        assert_eq!(z.by_index(0).unwrap().name(), "P/a.mo");
    }

    fn read_back(zip: &[u8]) -> Vec<(String, Vec<u8>)> {
        let mut z = zip::ZipArchive::new(std::io::Cursor::new(zip)).unwrap();
        (0..z.len())
            .map(|i| {
                let mut f = z.by_index(i).unwrap();
                let mut back = Vec::new();
                std::io::Read::read_to_end(&mut f, &mut back).unwrap();
                (f.name().to_string(), back)
            })
            .collect()
    }

    /// Compressible, incompressible, empty and non-ASCII-named files come back from the `zip`
    /// crate's reader as given, in order (it checks each entry's CRC as it reads); the same
    /// files give the same bytes; the `zip` crate's path (zip64, for packages beyond the
    /// classic format's limits) reads back the same.
    #[test]
    fn every_entry_reads_back() {
        let mut noise = crate::mechanism::XorShift::new(7);
        let mut files: Vec<(String, Vec<u8>)> =
            (0..40).map(|i| (format!("P/f{i}.txt"), (0..20_000u32).map(|k| ((k * 7 + i) % 251) as u8).collect())).collect();
        files.push(("P/noise.bin".into(), (0..50_000).map(|_| noise.next_u64() as u8).collect()));
        files.push(("P/empty.txt".into(), Vec::new()));
        files.push(("P/Gelenk_\u{fc}ber_\u{e4}u\u{df}eres.mo".into(), "model X end X;".repeat(50).into_bytes()));
        let zip = super::write_zip(&files).unwrap();
        assert_eq!(read_back(&zip), files);
        assert_eq!(zip, super::write_zip(&files).unwrap());
        let held: Vec<(String, super::FileData)> = files.iter().map(|(p, b)| (p.clone(), b.clone().into())).collect();
        assert_eq!(read_back(&super::zip_crate(&held, &mut |_, _| {}).unwrap()), files);
        // Files deflated ahead (as the conversion deflates its shape files) read back as given
        // and give the same zip, on either path.
        let mut d = super::Deflater::default();
        let ahead: Vec<(String, super::FileData)> = files.iter().map(|(p, b)| (p.clone(), d.file(b.clone()))).collect();
        assert_eq!(ahead.iter().filter(|(_, f)| f.is_deflated()).count(), 41, "all but the noise and the empty file");
        assert!(ahead.iter().zip(&files).all(|((_, f), (_, b))| f.len() == b.len() && *f.bytes() == **b));
        assert!(ahead.iter().zip(&held).all(|((_, a), (_, b))| a == b), "equal however held");
        assert_eq!(super::write_files(ahead.clone()).unwrap(), zip);
        assert_eq!(read_back(&super::zip_crate(&ahead, &mut |_, _| {}).unwrap()), files);
        // Deflated where that shrinks, stored where not.
        let mut z = zip::ZipArchive::new(std::io::Cursor::new(&zip)).unwrap();
        assert_eq!(z.by_name("P/f3.txt").unwrap().compression(), zip::CompressionMethod::Deflated);
        assert_eq!(z.by_name("P/noise.bin").unwrap().compression(), zip::CompressionMethod::Stored);
        assert!(zip.len() < 50_000 + 40 * 2_000, "{} bytes", zip.len());
    }

    /// `done` counts up, never beyond the number of files.
    #[test]
    fn progress_counts_up() {
        let files: Vec<(String, Vec<u8>)> = (0..300).map(|i| (format!("P/f{i}.txt"), vec![b'a'; 1000 + i])).collect();
        let mut seen = Vec::new();
        super::write_files_observed(files.into_iter().map(|(p, b)| (p, b.into())).collect(), &mut |k, n| seen.push((k, n))).unwrap();
        assert!(!seen.is_empty());
        assert_eq!(seen.last(), Some(&(300, 300)), "the end is reported");
        assert!(seen.iter().all(|&(k, n)| n == 300 && (1..=300).contains(&k)));
        assert!(seen.windows(2).all(|w| w[0].0 < w[1].0));
    }
}

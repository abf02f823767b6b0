//! The `cad2mo` command line: the only part of the converter that touches the file system.
//!
//! Exit codes: 0 success, 1 conversion error (message on stderr), 2 bad usage.
//! An output file is written atomically (temporary file + rename): an error never leaves a
//! partial file behind.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use cad2mo_engine::pipeline::front::bundle::{Bundle, Limits};
use cad2mo_engine::pipeline::{self, Options};

#[derive(Parser, Debug)]
#[command(name = "cad2mo", version, about = "Converts CAD assembly exports into Modelica packages")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Convert a bundle (a .zip or a directory with the XML export and its meshes) into a zip
    /// holding the Modelica package and report.json.
    Convert {
        /// The input bundle: a .zip file or a directory.
        bundle: PathBuf,
        /// The output zip.
        #[arg(short, long)]
        output: PathBuf,
        /// Name of the Modelica package (default: from the assembly's name).
        #[arg(long)]
        package_name: Option<String>,
        /// Gravity vector in world coordinates, m/s^2, as X,Y,Z (default: 0,-9.81,0 for
        /// SimMechanics XML, whose CAD "up" is y; 0,0,-9.81 for URDF and Simscape XML).
        #[arg(long, value_parser = parse_gravity, allow_hyphen_values = true)]
        gravity: Option<[f64; 3]>,
        /// Merge bodies joined by welds into single bodies.
        #[arg(long)]
        lump_welds: bool,
        /// VRML matching: position tolerance in metres (default: 1e-4 of the assembly's size).
        #[arg(long)]
        match_tolerance: Option<f64>,
        /// VRML matching: orientation tolerance in radians (default 1e-3).
        #[arg(long)]
        match_angle: Option<f64>,
    },
    /// Run the HTTP service (SQLite database created and migrated on start).
    Serve(cad2mo_server::config::ServeArgs),
    /// Regenerate the latest version of models with the current motor library and drives.
    Reexport {
        /// Every model.
        #[arg(long, conflicts_with = "model", required_unless_present = "model")]
        all: bool,
        /// One model, by id.
        #[arg(long)]
        model: Option<String>,
        #[command(flatten)]
        service: cad2mo_server::config::ServeArgs,
    },
    /// Manage API tokens (required when the service listens beyond loopback).
    Token {
        #[command(subcommand)]
        command: TokenCommand,
    },
    /// Check the blob store against the database: read and verify every stored blob, list
    /// referenced blobs that are missing or corrupt, and blobs no row refers to (orphans,
    /// harmless). Exit code 1 when a referenced blob is missing or corrupt.
    CheckBlobs {
        #[command(flatten)]
        service: cad2mo_server::config::ServeArgs,
    },
    /// Print the conversion report (JSON) of a bundle without writing a package.
    Inspect {
        bundle: PathBuf,
        #[arg(long)]
        lump_welds: bool,
    },
}

#[derive(Subcommand, Debug)]
enum TokenCommand {
    /// Create a token and print it (only its hash is stored: keep it). Says on stderr which
    /// database it was stored in.
    Create {
        /// A name to recognise the token by.
        #[arg(long, default_value = "cli")]
        name: String,
        /// Validity, e.g. 30d, 12h, 90m, 2w (default: no expiry).
        #[arg(long, value_parser = parse_duration)]
        expires_in: Option<u64>,
        #[command(flatten)]
        service: cad2mo_server::config::ServeArgs,
    },
    /// List tokens: id, name, created, expiry and the last 8 hex digits of the stored hash
    /// (never the token).
    List {
        #[command(flatten)]
        service: cad2mo_server::config::ServeArgs,
    },
    /// Revoke (delete) a token by id, or by name when one token has it.
    Revoke {
        /// The token's id or name.
        name_or_id: String,
        #[command(flatten)]
        service: cad2mo_server::config::ServeArgs,
    },
}

/// `30d`, `12h`, `90m`, `45s`, `2w` (a positive whole number and a unit) in seconds.
fn parse_duration(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let split = t.find(|c: char| !c.is_ascii_digit()).unwrap_or(t.len());
    let (n, unit) = t.split_at(split);
    let n: u64 = n.parse().map_err(|_| format!("expected a number and a unit (s, m, h, d, w), e.g. 30d; got \"{s}\""))?;
    let scale = match unit {
        "s" => 1,
        "m" => 60,
        "h" => 3600,
        "d" => 86_400,
        "w" => 604_800,
        _ => return Err(format!("unknown unit in \"{s}\": use s, m, h, d or w (e.g. 30d)")),
    };
    match n.checked_mul(scale) {
        Some(secs) if secs > 0 && secs <= 100 * 365 * 86_400 => Ok(secs),
        _ => Err(format!("\"{s}\" must be more than 0 and at most 100 years")),
    }
}

fn parse_gravity(s: &str) -> Result<[f64; 3], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(format!("expected three numbers X,Y,Z, got \"{s}\""));
    }
    let mut g = [0.0; 3];
    for (k, p) in parts.iter().enumerate() {
        g[k] = p.parse::<f64>().map_err(|_| format!("\"{p}\" is not a number"))?;
        if !g[k].is_finite() {
            return Err(format!("\"{p}\" is not finite"));
        }
    }
    Ok(g)
}

/// Reads a bundle from a zip file or a directory tree.
pub fn read_bundle(path: &Path, limits: &Limits) -> Result<Bundle, String> {
    read_bundle_ahead(path, limits, false).map(|(b, _)| b)
}

/// [`read_bundle`]; with `parse`, a directory's model source (its one `.xml` or `.urdf` file
/// that is one) is read first and parsed while the other files are read
/// ([`pipeline::parse_ahead`]; issue 23: the parse no longer waits for thousands of meshes).
pub fn read_bundle_ahead(path: &Path, limits: &Limits, parse: bool) -> Result<(Bundle, Option<pipeline::ParsedAhead>), String> {
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| path.display().to_string());
    let meta = std::fs::metadata(path).map_err(|e| format!("{}: {e}", path.display()))?;
    if !meta.is_dir() && !meta.is_file() {
        // A FIFO, socket or device could block forever or never end.
        return Err(format!("{}: not a regular file or a directory", path.display()));
    }
    if meta.is_dir() {
        // The files are listed (with their sizes, so the limits are checked before anything is
        // read), then read on up to four threads into their places in the list (issue 23: the
        // kernel's copies of a bundle's thousands of files are most of a large conversion's
        // start). The bundle does not depend on the threads.
        let mut listed: Vec<(PathBuf, String, u64)> = Vec::new();
        let mut total = 0u64;
        let mut stack = vec![path.to_path_buf()];
        while let Some(dir) = stack.pop() {
            let entries = std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
            for entry in entries {
                let entry = entry.map_err(|e| format!("{}: {e}", dir.display()))?;
                let p = entry.path();
                let ft = entry.file_type().map_err(|e| format!("{}: {e}", p.display()))?;
                if ft.is_dir() {
                    stack.push(p);
                } else if ft.is_file() {
                    let len = entry.metadata().map_err(|e| format!("{}: {e}", p.display()))?.len();
                    total = total.saturating_add(len);
                    if total > limits.max_total_bytes || listed.len() >= limits.max_entries {
                        return Err(format!(
                            "{}: bundle exceeds {} bytes or {} files",
                            path.display(),
                            limits.max_total_bytes,
                            limits.max_entries
                        ));
                    }
                    let rel = p.strip_prefix(path).map_err(|e| e.to_string())?;
                    let rel = rel.components().map(|c| c.as_os_str().to_string_lossy()).collect::<Vec<_>>().join("/");
                    listed.push((p, rel, len));
                }
            }
        }
        let (read, ahead) = read_listed(&listed, parse)?;
        let files = listed.into_iter().zip(read).map(|((_, rel, _), bytes)| (rel, bytes));
        Ok((Bundle::from_files(&name, files).map_err(|e| e.to_string())?, ahead))
    } else {
        let bytes = read_bounded(path, limits.max_total_bytes)?;
        Ok((Bundle::from_zip(&name, &bytes, limits).map_err(|e| e.to_string())?, None))
    }
}

/// Reads the listed files (path, relative path, size when listed), each at most its listed size
/// (a file that grew since is refused: the limits were checked on the sizes), on up to four
/// threads; the first failure in list order is reported. With `parse`, this thread reads the
/// `.xml` and `.urdf` files while the other threads start on the rest and, when exactly one of
/// them is a model source, parses it before it joins them ([`pipeline::parse_ahead`]).
fn read_listed(listed: &[(PathBuf, String, u64)], parse: bool) -> Result<(Vec<Vec<u8>>, Option<pipeline::ParsedAhead>), String> {
    use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
    let mut read: Vec<Option<Result<Vec<u8>, String>>> = (0..listed.len()).map(|_| None).collect();
    let is_source = |rel: &str| {
        let lower = rel.to_ascii_lowercase();
        lower.ends_with(".xml") || lower.ends_with(".urdf")
    };
    let (first, queue): (Vec<usize>, Vec<usize>) = (0..listed.len()).partition(|&i| parse && is_source(&listed[i].1));
    let next = AtomicUsize::new(0);
    let failed = AtomicBool::new(false);
    let work = || {
        let mut mine = Vec::new();
        while !failed.load(Ordering::Relaxed) {
            let Some(&i) = queue.get(next.fetch_add(1, Ordering::Relaxed)) else { break };
            let (p, _, len) = &listed[i];
            let r = read_bounded(p, *len);
            failed.fetch_or(r.is_err(), Ordering::Relaxed);
            mine.push((i, r));
        }
        mine
    };
    let threads = std::thread::available_parallelism().map_or(1, |t| t.get()).min(4).min(queue.len()).max(1);
    let mut ahead = None;
    std::thread::scope(|scope| {
        let helpers: Vec<_> = (1..threads).map(|_| scope.spawn(work)).collect();
        // The sources, read here while the other threads start on the rest.
        for &i in &first {
            let r = read_bounded(&listed[i].0, listed[i].2);
            failed.fetch_or(r.is_err(), Ordering::Relaxed);
            read[i] = Some(r);
        }
        let sources: Vec<(&str, &[u8])> = first
            .iter()
            .filter_map(|&i| match &read[i] {
                Some(Ok(bytes)) => pipeline::SourceKind::of(&listed[i].1, bytes).map(|_| (listed[i].1.as_str(), bytes.as_slice())),
                _ => None,
            })
            .collect();
        if let [(rel, bytes)] = sources[..] {
            ahead = pipeline::parse_ahead(rel, bytes);
        }
        let mut done = work();
        for h in helpers {
            done.extend(h.join().unwrap_or_else(|e| std::panic::resume_unwind(e)));
        }
        for (i, r) in done {
            read[i] = Some(r);
        }
    });
    // A failure stops the threads, so other files may be unread: the first failure in list
    // order is reported.
    if let Some(Some(Err(e))) = read.iter().find(|r| matches!(r, Some(Err(_)))) {
        return Err(e.clone());
    }
    let read =
        read.into_iter().map(|r| r.unwrap_or_else(|| Err("a file of the bundle was not read".to_string()))).collect::<Result<_, _>>()?;
    Ok((read, ahead))
}

/// Reads a regular file of at most `max` bytes (a file that grows while read, or that was swapped
/// for something else after the check, is refused rather than read without end).
fn read_bounded(path: &Path, max: u64) -> Result<Vec<u8>, String> {
    use std::io::Read;
    let err = |e: std::io::Error| format!("{}: {e}", path.display());
    let file = std::fs::File::open(path).map_err(err)?;
    let meta = file.metadata().map_err(err)?;
    if !meta.is_file() {
        return Err(format!("{}: not a regular file", path.display()));
    }
    let mut bytes = Vec::with_capacity(usize::try_from(meta.len().min(max)).unwrap_or(0));
    file.take(max.saturating_add(1)).read_to_end(&mut bytes).map_err(err)?;
    if bytes.len() as u64 > max {
        return Err(format!("{}: larger than the limit of {max} bytes", path.display()));
    }
    Ok(bytes)
}

/// Whether writing `output` would replace `input` (or a file of an input folder): the same
/// file by canonical path, symlinks followed.
fn output_overwrites_input(input: &Path, output: &Path) -> bool {
    let Ok(input) = std::fs::canonicalize(input) else { return false };
    // The output may not exist yet: then its folder decides.
    let resolved = std::fs::canonicalize(output).ok().or_else(|| {
        let dir = output.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
        Some(std::fs::canonicalize(dir).ok()?.join(output.file_name()?))
    });
    resolved.is_some_and(|out| out == input || (out.starts_with(&input) && out.exists()))
}

/// Writes `bytes` to `path` through a temporary file in the same folder and a rename.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    write_atomic_with(path, |f| f.write_all(bytes))
}

/// Writes what `write` writes to `path` through a temporary file in the same folder and a
/// rename: `path` is the whole output or untouched.
pub fn write_atomic_with(path: &Path, write: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>) -> std::io::Result<()> {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let file_name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let tmp = dir.join(format!(".{file_name}.{}.tmp", std::process::id()));
    let result = std::fs::File::create(&tmp).and_then(|mut f| write(&mut f)).and_then(|_| std::fs::rename(&tmp, path));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Warnings printed per code before the rest of that code is counted in one line (every one
/// stays in report.json).
const WARNINGS_PER_CODE: usize = 20;

fn print_warnings(warnings: &[pipeline::ir::Warning]) {
    for line in warning_lines(warnings) {
        eprintln!("{line}");
    }
}

/// The lines [`print_warnings`] prints: each warning up to [`WARNINGS_PER_CODE`] of its code,
/// then one line per code for the rest.
fn warning_lines(warnings: &[pipeline::ir::Warning]) -> Vec<String> {
    let mut seen: std::collections::BTreeMap<&str, usize> = std::collections::BTreeMap::new();
    let mut lines = Vec::new();
    for w in warnings {
        let n = seen.entry(w.code).or_default();
        *n += 1;
        if *n <= WARNINGS_PER_CODE {
            lines.push(format!("warning[{}]: {}: {}", w.code, w.location, w.message));
        }
    }
    for (code, n) in seen.into_iter().filter(|(_, n)| *n > WARNINGS_PER_CODE) {
        lines.push(format!("warning[{code}]: {} more like these (every one is in report.json)", n - WARNINGS_PER_CODE));
    }
    lines
}

pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let _ = e.print();
            return if e.use_stderr() { ExitCode::from(2) } else { ExitCode::SUCCESS };
        }
    };
    let limits = Limits::default();
    match cli.command {
        Command::Serve(args) => serve(cad2mo_server::config::Settings::from_args(args)),
        Command::Reexport { all: _, model, service } => reexport(cad2mo_server::config::Settings::from_args(service), model),
        Command::Token { command } => token(command),
        Command::CheckBlobs { service } => check_blobs(cad2mo_server::config::Settings::from_args(service)),
        Command::Convert { bundle, output, package_name, gravity, lump_welds, match_tolerance, match_angle } => {
            if let Some(p) = &package_name {
                if pipeline::back::modelica::sanitize(p, "P") != *p {
                    eprintln!("error: --package-name \"{p}\" is not a Modelica identifier ([A-Za-z_][A-Za-z0-9_]*, not a keyword)");
                    return ExitCode::from(2);
                }
            }
            if output_overwrites_input(&bundle, &output) {
                eprintln!(
                    "error: the output {} is the input bundle {} (or inside it): choose another -o path",
                    output.display(),
                    bundle.display()
                );
                return ExitCode::from(2);
            }
            let (b, ahead) = match read_bundle_ahead(&bundle, &limits, true) {
                Ok(b) => b,
                Err(e) => {
                    eprintln!("error: {e}");
                    return ExitCode::from(1);
                }
            };
            let matching = pipeline::passes::geometry_match::MatchOptions { tolerance_m: match_tolerance, angle_tolerance: match_angle };
            let opts = Options { package_name, gravity, lump_welds, write_shapes: true, matching, ..Options::default() };
            let out = match pipeline::convert_owned_ahead(b, ahead, &opts) {
                Ok(o) => o,
                Err(e) => {
                    eprintln!("error: {e}");
                    return ExitCode::from(1);
                }
            };
            print_warnings(&out.report.warnings);
            // The zip goes straight into the file (never held whole in memory).
            if let Err(e) = write_atomic_with(&output, |f| pipeline::back::bundle::write_files_into(out.files, &mut |_, _| {}, f)) {
                eprintln!("error: writing {}: {e}", output.display());
                return ExitCode::from(1);
            }
            eprintln!(
                "wrote {} (package {}, {} bodies, {} joints, {} warnings)",
                output.display(),
                out.report.package_name,
                out.report.bodies.len(),
                out.report.joints.len(),
                out.report.warnings.len()
            );
            ExitCode::SUCCESS
        }
        Command::Inspect { bundle, lump_welds } => {
            let b = match read_bundle(&bundle, &limits) {
                Ok(b) => b,
                Err(e) => {
                    eprintln!("error: {e}");
                    return ExitCode::from(1);
                }
            };
            let opts = Options { lump_welds, write_shapes: false, ..Options::default() };
            match pipeline::convert(&b, &opts) {
                Ok(out) => match cad2mo_engine::jsontext::to_string(&out.report) {
                    Ok(s) => {
                        println!("{s}");
                        ExitCode::SUCCESS
                    }
                    Err(e) => {
                        eprintln!("error: {e}");
                        ExitCode::from(1)
                    }
                },
                Err(e) => {
                    eprintln!("error: {e}");
                    ExitCode::from(1)
                }
            }
        }
    }
}

/// `cad2mo check-blobs`: [`cad2mo_server::store::integrity::check`] on the service's database and blob
/// store; the findings on stdout, one per line, then a summary.
fn check_blobs(settings: cad2mo_server::config::Settings) -> ExitCode {
    let result = runtime().map_err(anyhow::Error::from).and_then(|rt| {
        rt.block_on(async {
            let store = cad2mo_server::store::Store::open(&settings.database_url).await?;
            let blobs = cad2mo_server::store::blobs::Blobs::open(&settings.blobs, &settings.data_dir).await?;
            let report = cad2mo_server::store::integrity::check(&store, &blobs).await?;
            Ok::<_, anyhow::Error>((blobs.location(), report))
        })
    });
    match result {
        Ok((location, r)) => {
            for (kind, hashes) in [("missing", &r.missing), ("corrupt", &r.corrupt), ("orphan", &r.orphans)] {
                for h in hashes {
                    println!("{kind} {h}");
                }
            }
            println!(
                "{location}: {} blobs stored, {} referenced; {} missing, {} corrupt, {} orphans",
                r.stored,
                r.referenced,
                r.missing.len(),
                r.corrupt.len(),
                r.orphans.len()
            );
            if r.is_consistent() {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(1)
            }
        }
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(2)
        }
    }
}

/// Opens the database the service would use with `service`'s settings (the data folder made
/// absolute, so messages say exactly which file).
async fn open_store(service: cad2mo_server::config::ServeArgs) -> anyhow::Result<(cad2mo_server::store::Store, String)> {
    let mut service = service;
    service.data_dir = std::path::absolute(&service.data_dir)?;
    let settings = cad2mo_server::config::Settings::from_args(service);
    std::fs::create_dir_all(&settings.data_dir)?;
    let store = cad2mo_server::store::Store::open(&settings.database_url).await?;
    let url = settings.database_url.split('?').next().unwrap_or_default();
    // A PostgreSQL URL is shown without its user and password.
    let shown = match url.split_once("://") {
        Some((scheme, rest)) if scheme.starts_with("postgres") => format!("{scheme}://{}", rest.rsplit_once('@').map_or(rest, |(_, h)| h)),
        _ => url.trim_start_matches("sqlite://").to_string(),
    };
    Ok((store, shown))
}

/// `cad2mo token create|list|revoke`.
fn token(command: TokenCommand) -> ExitCode {
    use cad2mo_server::store::tokens::{self, Revoked, TokenInfo};
    let line = |t: &TokenInfo| {
        let expiry = match (&t.expires_at, t.expired) {
            (None, _) => "never".to_string(),
            (Some(e), true) => format!("{e} (expired)"),
            (Some(e), false) => e.clone(),
        };
        let tail = &t.sha256[t.sha256.len().saturating_sub(8)..];
        format!("{}  {}  created {}  expires {}  sha256 …{}", t.id, t.name, t.created_at, expiry, tail)
    };
    let result = runtime().map_err(anyhow::Error::from).and_then(|rt| {
        rt.block_on(async {
            match command {
                TokenCommand::Create { name, expires_in, service } => {
                    let (store, db) = open_store(service).await?;
                    let token = tokens::create(&store, &name, expires_in).await?;
                    println!("{token}");
                    let until = if expires_in.is_some() { " (it expires: see `cad2mo token list`)" } else { "" };
                    eprintln!("token \"{name}\" stored in {db}{until}");
                    Ok(ExitCode::SUCCESS)
                }
                TokenCommand::List { service } => {
                    let (store, db) = open_store(service).await?;
                    let all = tokens::list(&store).await?;
                    for t in &all {
                        println!("{}", line(t));
                    }
                    eprintln!("{} tokens in {db}", all.len());
                    Ok(ExitCode::SUCCESS)
                }
                TokenCommand::Revoke { name_or_id, service } => {
                    let (store, db) = open_store(service).await?;
                    match tokens::revoke(&store, &name_or_id).await? {
                        Revoked::One(t) => {
                            eprintln!("revoked {}", line(&t));
                            Ok(ExitCode::SUCCESS)
                        }
                        Revoked::NotFound => {
                            eprintln!("error: no token with id or name \"{name_or_id}\" in {db}");
                            Ok(ExitCode::from(1))
                        }
                        Revoked::Ambiguous(many) => {
                            eprintln!("error: {} tokens are named \"{name_or_id}\"; revoke one by id:", many.len());
                            for t in &many {
                                eprintln!("  {}", line(t));
                            }
                            Ok(ExitCode::from(2))
                        }
                    }
                }
            }
        })
    });
    result.unwrap_or_else(|e| {
        eprintln!("error: {e:#}");
        ExitCode::from(1)
    })
}

fn runtime() -> std::io::Result<tokio::runtime::Runtime> {
    tokio::runtime::Builder::new_multi_thread().enable_all().build()
}

fn serve(settings: cad2mo_server::config::Settings) -> ExitCode {
    cad2mo_server::telemetry::init();
    let result = runtime().map_err(anyhow::Error::from).and_then(|rt| {
        rt.block_on(async {
            let app = cad2mo_server::app::App::build(settings).await?;
            tracing::info!(address = %app.local_addr(), "cad2mo listening");
            app.run_until_stopped().await
        })
    });
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(1)
        }
    }
}

/// `cad2mo reexport`: queues re-export jobs and runs them with the service's own worker pool,
/// drawing a progress bar on stderr. A failing model does not stop the others; the exit code is
/// 1 when any failed.
fn reexport(settings: cad2mo_server::config::Settings, model: Option<String>) -> ExitCode {
    use cad2mo_server::store::models;
    let result = runtime().map_err(anyhow::Error::from).and_then(|rt| {
        rt.block_on(async {
            std::fs::create_dir_all(&settings.data_dir)?;
            let store = cad2mo_server::store::Store::open(&settings.database_url).await?;
            let blobs = cad2mo_server::store::blobs::Blobs::open(&settings.blobs, &settings.data_dir).await?;
            let ids: Vec<(String, String)> = match &model {
                Some(id) => match models::get_model(&store.pool, id).await? {
                    Some(m) => vec![(m.id, m.name)],
                    None => anyhow::bail!("no model {id}"),
                },
                None => models::list_models(&store.pool).await?.into_iter().map(|m| (m.id, m.name)).collect(),
            };
            let mut jobs = Vec::new();
            let mut failed = Vec::new();
            for (id, name) in &ids {
                match models::queue_reexport(&store.pool, id).await? {
                    Some((version, job)) => jobs.push((name.clone(), version, job)),
                    None => failed.push(format!("{name} ({id}): no version to re-export")),
                }
            }
            let live = settings.live_bind.map(|a| (settings.live_host(), a.port()));
            let pool = cad2mo_server::app::start_jobs(store.clone(), blobs, &settings, live).await?;
            pool.notify();
            let total = jobs.len();
            let mut done = 0;
            let mut pending = jobs;
            while !pending.is_empty() {
                tokio::time::sleep(std::time::Duration::from_millis(100)).await;
                let mut still = Vec::new();
                for (name, version, job) in pending {
                    match models::get_job(&store.pool, &job).await? {
                        Some(j) if j.status == "succeeded" => done += 1,
                        Some(j) if j.status == "failed" => {
                            done += 1;
                            let detail = j.error_json.and_then(|e| serde_json::from_str::<serde_json::Value>(&e).ok());
                            let detail = detail.and_then(|d| d["detail"].as_str().map(String::from)).unwrap_or_default();
                            failed.push(format!("{name} v{version}: {detail}"));
                        }
                        _ => still.push((name, version, job)),
                    }
                }
                pending = still;
                progress(done, total);
            }
            eprintln!();
            Ok::<_, anyhow::Error>((total, failed))
        })
    });
    match result {
        Ok((total, failed)) => {
            for f in &failed {
                eprintln!("failed: {f}");
            }
            eprintln!("re-exported {} of {total} models", total.saturating_sub(failed.len()));
            if failed.is_empty() {
                ExitCode::SUCCESS
            } else {
                ExitCode::from(1)
            }
        }
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(1)
        }
    }
}

/// `[#########           ] 9/20` on one line of stderr.
fn progress(done: usize, total: usize) {
    let width = 30;
    let filled = (done * width).checked_div(total).unwrap_or(width);
    eprint!("\r[{}{}] {done}/{total}", "#".repeat(filled), " ".repeat(width - filled));
}

#[cfg(test)]
mod warning_tests {
    use cad2mo_engine::pipeline::ir::Warning;

    /// Routine warnings are counted after the first ones of their code; rare codes all show.
    #[test]
    fn many_warnings_of_one_code_are_counted() {
        let mut ws: Vec<Warning> =
            (0..1333).map(|i| Warning::new("joint-frames-misaligned", format!("joint {i}"), format!("t.xml:{i}"))).collect();
        ws.push(Warning::new("interference", "a and b", "collision shapes"));
        let lines = super::warning_lines(&ws);
        assert_eq!(lines.len(), super::WARNINGS_PER_CODE + 2, "{lines:?}");
        assert!(lines.iter().any(|l| l.starts_with("warning[interference]: collision shapes: a and b")));
        assert_eq!(lines.last().unwrap(), "warning[joint-frames-misaligned]: 1313 more like these (every one is in report.json)");
    }
}

#[cfg(test)]
mod read_tests {
    use cad2mo_engine::pipeline::front::bundle::Limits;
    use cad2mo_engine::pipeline::{self, Options};

    fn pendulum_files() -> Vec<(String, Vec<u8>)> {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/in/pendulum");
        ["PENDULUM.xml", "meshes/LINK_prt.stl"].iter().map(|f| (f.to_string(), std::fs::read(dir.join(f)).expect("fixture"))).collect()
    }

    fn folder(files: &[(String, Vec<u8>)]) -> tempfile::TempDir {
        let dir = tempfile::tempdir().expect("temp dir");
        for (rel, bytes) in files {
            let p = dir.path().join(rel);
            std::fs::create_dir_all(p.parent().expect("parent")).expect("mkdir");
            std::fs::write(p, bytes).expect("write");
        }
        dir
    }

    /// The source parsed while the meshes are read gives the conversion parsing it in turn
    /// gives, file for file; a broken source fails the same way either way (naming the file and
    /// line); two sources are not parsed ahead, and the bundle's error says there are two.
    #[test]
    fn a_source_parsed_ahead_converts_as_one_parsed_in_turn() {
        let opts = Options { write_shapes: true, ..Options::default() };
        let convert_both = |dir: &std::path::Path| {
            let (bundle, ahead) = super::read_bundle_ahead(dir, &Limits::default(), true).expect("reads");
            let had_ahead = ahead.is_some();
            let fast = pipeline::convert_owned_ahead(bundle, ahead, &opts).map(|o| o.files);
            let plain = pipeline::convert(&super::read_bundle(dir, &Limits::default()).expect("reads"), &opts).map(|o| o.files);
            (had_ahead, fast.map_err(|e| e.to_string()), plain.map_err(|e| e.to_string()))
        };
        let good = folder(&pendulum_files());
        let (had_ahead, fast, plain) = convert_both(good.path());
        assert!(had_ahead);
        let (fast, plain) = (fast.expect("converts"), plain.expect("converts"));
        assert_eq!(fast.len(), plain.len());
        for ((pa, fa), (pb, fb)) in fast.iter().zip(&plain) {
            assert_eq!(pa, pb);
            assert!(fa.bytes() == fb.bytes(), "{pa}");
        }

        let mut broken = pendulum_files();
        let cut = broken[0].1.len() * 2 / 3;
        broken[0].1.truncate(cut);
        let dir = folder(&broken);
        let (had_ahead, fast, plain) = convert_both(dir.path());
        assert!(had_ahead, "a truncated XML is still sniffed as the source");
        let e = fast.expect_err("truncated");
        assert_eq!(Err::<(), _>(e.clone()), plain.map(|_| ()));
        assert!(e.contains("PENDULUM.xml"), "{e}");

        let mut two = pendulum_files();
        two.push(("copy/OTHER.xml".to_string(), two[0].1.clone()));
        let dir = folder(&two);
        let (had_ahead, fast, plain) = convert_both(dir.path());
        assert!(!had_ahead);
        let e = fast.expect_err("two sources");
        assert_eq!(Err::<(), _>(e.clone()), plain.map(|_| ()));
    }

    /// A folder's files, read on several threads, land at their own paths with their own bytes;
    /// the limits are checked on the listed sizes before anything is read.
    #[test]
    fn a_folder_reads_whole_and_within_its_limits() {
        let dir = tempfile::tempdir().expect("temp dir");
        let mut want = Vec::new();
        for i in 0..64 {
            let rel = if i % 3 == 0 { format!("sub/d{}/f{i}.stl", i % 4) } else { format!("f{i}.txt") };
            let bytes: Vec<u8> = (0..(i * 37 % 500)).map(|k| (k * 31 + i) as u8).collect();
            let path = dir.path().join(&rel);
            std::fs::create_dir_all(path.parent().expect("parent")).expect("mkdir");
            std::fs::write(&path, &bytes).expect("write");
            want.push((rel, bytes));
        }
        let total: u64 = want.iter().map(|(_, b)| b.len() as u64).sum();
        let b = super::read_bundle(dir.path(), &Limits::default()).expect("reads");
        assert_eq!(b.len(), want.len());
        for (rel, bytes) in &want {
            assert_eq!(b.get(rel), Some(&bytes[..]), "{rel}");
        }
        let tight = |max_total_bytes, max_entries| Limits { max_total_bytes, max_entries, ..Limits::default() };
        assert!(super::read_bundle(dir.path(), &tight(total, 64)).is_ok());
        for limits in [tight(total - 1, 64), tight(total, 63)] {
            let e = super::read_bundle(dir.path(), &limits).expect_err("beyond the limits");
            assert!(e.contains("bundle exceeds"), "{e}");
        }
    }
}

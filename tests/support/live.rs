//! The live view's test harness: `tests/live/harness.c` compiled with the system C compiler
//! against the sender C source a package ships, and the known motions it sends.

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::common::{tools_required, workspace_root};

/// The C compiler: `$CC`, else `cc`.
fn compiler() -> String {
    std::env::var("CC").unwrap_or_else(|_| "cc".to_string())
}

/// Compiles the harness against `sender_c` (the text of a package's `cad2mo_live.c`) into
/// `dir`, with every warning an error. `None` (with a notice) when there is no C compiler and
/// the tools are not required.
pub fn build_harness(sender_c: &str, dir: &Path) -> Option<PathBuf> {
    if Command::new(compiler()).arg("--version").output().is_err() {
        assert!(!tools_required(), "the live view tests need a C compiler ({})", compiler());
        println!("NOTICE: no C compiler ({}): the live view harness is not built", compiler());
        return None;
    }
    std::fs::write(dir.join("cad2mo_live.c"), sender_c).expect("write the sender");
    let live = workspace_root().join("tests/live");
    let exe = dir.join("harness");
    let out = Command::new(compiler())
        .args(["-O2", "-Wall", "-Wextra", "-Werror", "-Wno-unused-function"])
        .arg("-I")
        .arg(&live)
        .arg("-I")
        .arg(dir)
        .arg(live.join("harness.c"))
        .arg("-o")
        .arg(&exe)
        .output()
        .expect("run the C compiler");
    assert!(out.status.success(), "the harness does not compile:\n{}", String::from_utf8_lossy(&out.stderr));
    Some(exe)
}

/// A known motion of `n` bodies: body `i` at (i, sin t, 0.1 i) turned by 0.5 t + 0.1 i about z.
/// One row per sample: the time, then per body r_0 and R.T (world to body) row by row.
pub fn spin_motion(n: usize, samples: usize, dt: f64) -> Vec<Vec<f64>> {
    (0..samples)
        .map(|k| {
            let t = k as f64 * dt;
            let mut row = vec![t];
            for i in 0..n {
                let (x, a) = (i as f64, 0.5 * t + 0.1 * i as f64);
                let (s, c) = a.sin_cos();
                // R (body to world) = Rz(a); R.T = transpose(R).
                row.extend([x, t.sin(), 0.1 * x, c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0]);
            }
            row
        })
        .collect()
}

/// The motion as the harness reads it on stdin.
pub fn motion_text(rows: &[Vec<f64>]) -> String {
    let mut s = String::new();
    for r in rows {
        let line: Vec<String> = r.iter().map(|x| format!("{x:.17e}")).collect();
        s.push_str(&line.join(" "));
        s.push('\n');
    }
    s
}

/// Where and as what the harness sends.
pub struct Stream {
    /// UDP port on 127.0.0.1.
    pub port: u16,
    pub model: String,
    pub version: i64,
    /// The version's layout id (hex).
    pub layout: String,
    pub token: Option<String>,
    /// Pace frames at simulated time.
    pub real_time: bool,
}

/// Runs the harness: sends `rows` as `s` says. Returns its stdout.
pub fn run_harness(exe: &Path, s: &Stream, rows: &[Vec<f64>]) -> String {
    use std::io::Write;
    let mut child = Command::new(exe)
        .args([
            "127.0.0.1",
            &s.port.to_string(),
            &s.model,
            &s.version.to_string(),
            &s.layout,
            s.token.as_deref().unwrap_or("-"),
            if s.real_time { "1" } else { "0" },
        ])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("start the harness");
    child.stdin.take().expect("stdin").write_all(motion_text(rows).as_bytes()).expect("feed the harness");
    let out = child.wait_with_output().expect("harness");
    assert!(out.status.success(), "harness failed: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).to_string()
}

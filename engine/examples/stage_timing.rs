//! Where a conversion's time goes: `cargo run --release -p cad2mo-engine --example stage_timing -- DIR`
//! prints the wall time from the start of each pipeline stage to the next (as the job's progress
//! reports them), then the time to zip the files, as `cad2mo convert` does.

#[path = "../benches/support/gen.rs"]
#[allow(dead_code)]
mod gen;

use cad2mo_engine::pipeline::front::bundle::Bundle;
use std::time::Instant;

use cad2mo_engine::pipeline::observe::{Observer, Stage};
use cad2mo_engine::pipeline::{self, Options};

struct Clock {
    start: Instant,
    seen: Vec<(Stage, f64)>,
}

impl Observer for Clock {
    fn progress(&mut self, stage: Stage, _done: usize, _total: usize) {
        if self.seen.last().is_none_or(|(s, _)| *s != stage) {
            self.seen.push((stage, self.start.elapsed().as_secs_f64()));
        }
    }
}

fn main() {
    let Some(dir) = std::env::args().nth(1) else {
        eprintln!("usage: stage_timing BUNDLE_DIR");
        std::process::exit(2);
    };
    let t0 = Instant::now();
    let bundle = Bundle::from_files(&dir, gen::files_under(std::path::Path::new(&dir))).expect("bundle reads");
    let read = t0.elapsed().as_secs_f64();
    let mut clock = Clock { start: Instant::now(), seen: Vec::new() };
    let out = pipeline::convert_observed(&bundle, &Options::default(), &mut clock).expect("converts");
    let total = clock.start.elapsed().as_secs_f64();
    println!("read bundle {:8.1} ms", read * 1e3);
    for (k, (stage, at)) in clock.seen.iter().enumerate() {
        let end = clock.seen.get(k + 1).map_or(total, |n| n.1);
        println!("{:<12} {:8.1} ms", format!("{stage:?}"), (end - at) * 1e3);
    }
    println!("convert      {:8.1} ms", total * 1e3);
    let t = Instant::now();
    let zip = cad2mo_engine::pipeline::back::bundle::write_files(out.files.clone()).expect("zip");
    println!("zip          {:8.1} ms ({} files, {} bytes)", t.elapsed().as_secs_f64() * 1e3, out.files.len(), zip.len());
}

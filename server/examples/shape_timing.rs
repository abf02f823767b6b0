//! Per-body collision shape timings of a bundle (a directory), for choosing the shape budgets:
//!
//! ```sh
//! cargo run --release -p cad2mo --example shape_timing -- DIR [max_hull_vertices] [decomposition_budget]
//! ```

use std::time::Instant;

use cad2mo::collision::{body_shape, ShapeOptions};
use cad2mo::pipeline::{self, Options};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let Some(dir) = args.get(1) else {
        eprintln!("usage: shape_timing DIR [max_hull_vertices] [decomposition_budget]");
        std::process::exit(2);
    };
    let mut opts = ShapeOptions::default();
    if let Some(n) = args.get(2).and_then(|n| n.parse().ok()) {
        opts.max_hull_vertices = n;
    }
    if let Some(n) = args.get(3).and_then(|n| n.parse().ok()) {
        opts.decomposition_budget = n;
    }
    let bundle = match cad2mo::cli::read_bundle(std::path::Path::new(dir), &Default::default()) {
        Ok(b) => b,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    let a = match pipeline::analyse(&bundle, &Options::default()) {
        Ok(a) => a,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    let mut total = 0.0;
    let (mut worst_fit, mut worst_ratio) = (0.0f64, 0.0f64);
    for (i, b) in a.model.bodies.iter().enumerate() {
        let Some(m) = &b.mesh else { continue };
        let t0 = Instant::now();
        let s = body_shape(m, &opts);
        let dt = t0.elapsed().as_secs_f64();
        total += dt;
        worst_fit = worst_fit.max(s.fit_error);
        worst_ratio = worst_ratio.max(s.volume_ratio);
        println!(
            "{i:3} {:>7} tris {:>13} parts {:2} verts {:5} fit {:.2} mm ratio {:.3} {:.3} s {:?}",
            m.triangles.len(),
            s.kind.name(),
            s.parts.len(),
            s.vertex_count,
            s.fit_error * 1e3,
            s.volume_ratio,
            dt,
            s.warnings
        );
    }
    println!("total {total:.3} s (one thread); worst fit {:.2} mm, worst ratio {worst_ratio:.3}", worst_fit * 1e3);
}

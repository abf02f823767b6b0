//! Per-body collision shape timings of a bundle (a directory), for choosing the shape budgets,
//! then the whole conversion three times in one process: without a shape cache, and twice with
//! one (cold, then warm):
//!
//! ```sh
//! cargo run --release -p cad2mo-engine --example shape_timing -- DIR [max_hull_vertices] [decomposition_budget]
//! ```

#[path = "../benches/support/gen.rs"]
#[allow(dead_code)]
mod gen;

use cad2mo_engine::pipeline::front::bundle::Bundle;
use std::time::Instant;

use cad2mo_engine::collision::{body_shape, ShapeOptions};
use cad2mo_engine::pipeline::{self, Options};

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
    let bundle = match Bundle::from_files(dir, gen::files_under(std::path::Path::new(dir))) {
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
    let mut shapes = vec![None; a.model.bodies.len()];
    let (mut worst_fit, mut worst_ratio) = (0.0f64, 0.0f64);
    for (i, b) in a.model.bodies.iter().enumerate() {
        let Some(m) = &b.mesh else { continue };
        let t0 = Instant::now();
        let s = body_shape(m, &opts);
        let dt = t0.elapsed().as_secs_f64();
        shapes[i] = Some(s.clone());
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
    // Contacts at the CAD pose, every pair checked, within 5 cm: the narrow phase's speed.
    let world = cad2mo_engine::collision::World::new(&shapes);
    let poses = cad2mo_engine::pipeline::back::collision_shapes::cad_poses(&a.model);
    let all = |_: usize, _: usize| true;
    let n = cad2mo_engine::collision::contacts_at(&world, &poses, &all, 0.05).len();
    let t0 = Instant::now();
    for _ in 0..200 {
        std::hint::black_box(cad2mo_engine::collision::contacts_at(&world, &poses, &all, 0.05));
    }
    println!("contacts_at, margin 5 cm: {n} pairs, {:.1} µs per call", t0.elapsed().as_secs_f64() / 200.0 * 1e6);
    let cache = std::sync::Arc::new(cad2mo_engine::collision::MemoryShapeCache::default());
    let shared: std::sync::Arc<dyn cad2mo_engine::collision::ShapeCache> = cache.clone();
    for (what, opts) in [
        ("no cache", Options::default()),
        ("cache, cold", Options { shape_cache: Some(shared.clone()), ..Options::default() }),
        ("cache, warm", Options { shape_cache: Some(shared), ..Options::default() }),
    ] {
        let t0 = Instant::now();
        match pipeline::convert(&bundle, &opts) {
            Ok(out) => println!(
                "convert ({what}): {:.3} s, shapes computed {}, from the cache {}",
                t0.elapsed().as_secs_f64(),
                out.shapes.computed,
                out.shapes.cached
            ),
            Err(e) => println!("convert ({what}): error {e}"),
        }
    }
    println!("{:?}", cache.stats());
}

//! Replays every input under `fuzz/regressions/<target>/` through the fuzz target of that name
//! (the targets' bodies are `fuzz/src/lib.rs`, included here), so crashes the fuzzers found stay
//! fixed on a normal `cargo test`. Add a crash by copying its minimised input there (README,
//! "Fuzzing").

#[allow(dead_code)]
#[path = "../../fuzz/src/lib.rs"]
mod targets;

use std::path::Path;

#[test]
fn fuzz_regressions_replay() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz/regressions");
    let mut replayed = 0;
    let mut failures = Vec::new();
    for (name, run) in targets::TARGETS {
        let dir = root.join(name);
        let Ok(entries) = std::fs::read_dir(&dir) else { continue };
        let mut files: Vec<_> = entries.flatten().map(|e| e.path()).filter(|p| p.is_file()).collect();
        files.sort();
        for f in files {
            let data = std::fs::read(&f).expect("read a regression input");
            if let Err(panic) = std::panic::catch_unwind(|| run(&data)) {
                let msg = panic
                    .downcast_ref::<String>()
                    .map(String::as_str)
                    .or_else(|| panic.downcast_ref::<&str>().copied())
                    .unwrap_or("(non-string panic)");
                failures.push(format!("{name}: {}: {msg}", f.display()));
            }
            replayed += 1;
        }
    }
    // Every target directory under fuzz/regressions must be a known target.
    if let Ok(entries) = std::fs::read_dir(&root) {
        for e in entries.flatten() {
            let n = e.file_name().to_string_lossy().into_owned();
            if e.path().is_dir() && !targets::TARGETS.iter().any(|(t, _)| *t == n) {
                failures.push(format!("fuzz/regressions/{n}: no fuzz target of that name"));
            }
        }
    }
    assert!(failures.is_empty(), "{} of {replayed} fuzz regressions fail:\n{}", failures.len(), failures.join("\n"));
}

/// The committed seed corpus runs clean too (small: the golden inputs and the hand-made bombs).
#[test]
fn fuzz_seeds_replay() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz/seeds");
    let mut replayed = 0;
    for (name, run) in targets::TARGETS {
        let Ok(entries) = std::fs::read_dir(root.join(name)) else { continue };
        for e in entries.flatten() {
            let data = std::fs::read(e.path()).expect("read a seed");
            run(&data);
            replayed += 1;
        }
    }
    assert!(replayed > 50, "only {replayed} seeds under {}", root.display());
}

/// The `convert` target's check finds non-finite numbers, and only where a number stands.
#[test]
fn convert_check_finds_non_finite_numbers() {
    let bad = "model M\n  B b(r = {inf, 0, -NaN}, m = 1);\n  P p(x = Infinity);\nend M;\n";
    assert_eq!(targets::non_finite_tokens(bad).len(), 3, "{bad}");
    let good = "model M \"inf, NaN\"\n  // = inf\n  /* = NaN */\n  Body inf(r = {1e300, 0, 0});\n  \
                equation\n  connect(inf.frame_a, nan.frame_b);\n  x = f(nan[1]);\nend M;\n";
    assert_eq!(targets::non_finite_tokens(good), Vec::<usize>::new(), "{good}");
}

/// The structure-aware URDF target reaches the whole conversion: its seeds are URDFs that
/// convert (a chain, a branching tree with prismatic and floating joints, a mimic), not only
/// inputs every front end refuses.
#[test]
fn urdf_tree_seeds_convert() {
    use cad2mo_engine::pipeline::{self, front::bundle::Bundle};
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz/seeds/urdf_tree");
    for (seed, links) in [("chain.bin", 6), ("tree.bin", 4), ("mimic.bin", 2), ("mimic_ring.bin", 3)] {
        let data = std::fs::read(root.join(seed)).expect("seed");
        let text = targets::urdf_of_bytes(&data);
        let bundle = Bundle::from_files("fuzz", [("robot.urdf".to_string(), text.clone().into_bytes())]).expect("bundle");
        let opts = pipeline::Options { write_shapes: false, ..Default::default() };
        let out = pipeline::convert(&bundle, &opts).unwrap_or_else(|e| panic!("{seed} does not convert: {e}\n{text}"));
        assert!(out.report.bodies.len() > links, "{seed}: {} bodies", out.report.bodies.len());
        if seed == "mimic_ring.bin" {
            let ring = out.report.warnings.iter().filter(|w| w.code == "mimic-not-expressible" && w.message.contains("cycle")).count();
            assert_eq!(ring, 1, "{seed}: {:?}", out.report.warnings);
        }
    }
}

//! Writes the benchmarks' generated bundles to a directory, for whole-process timings of
//! `cad2mo convert` (README, Speed):
//!
//! ```sh
//! cargo run --release -p cad2mo-engine --example gen_bundle -- tree-stl 2000 /tmp/tree2000
//! cargo run --release -p cad2mo-engine --example gen_bundle -- urdf 200 /tmp/urdf200
//! cargo run --release -p cad2mo-engine --example gen_bundle -- urdf-shared 25 /tmp/shared25
//! ```

#[path = "../benches/support/gen.rs"]
#[allow(dead_code)]
mod gen;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let (Some(kind), Some(n), Some(dir)) = (args.get(1), args.get(2).and_then(|n| n.parse::<usize>().ok()), args.get(3)) else {
        eprintln!("usage: gen_bundle tree-stl|tree|urdf|urdf-shared N DIR");
        std::process::exit(2);
    };
    let files = match kind.as_str() {
        "tree-stl" => gen::tree_with_stl(n),
        "tree" => vec![("tree.xml".to_string(), gen::tree_xml(n).into_bytes())],
        "urdf" => gen::urdf_tree(n),
        // Issue 26: one 199,712-triangle OBJ named by N links (25: the bundle's budget).
        "urdf-shared" => gen::urdf_shared_obj(n, 317),
        _ => {
            eprintln!("unknown kind {kind}: tree-stl, tree, urdf or urdf-shared");
            std::process::exit(2);
        }
    };
    let dir = std::path::Path::new(dir);
    let mut bytes = 0;
    for (path, data) in &files {
        let p = dir.join(path);
        if let Some(parent) = p.parent() {
            std::fs::create_dir_all(parent).expect("create directory");
        }
        std::fs::write(&p, data).expect("write file");
        bytes += data.len();
    }
    println!("{} files, {} bytes in {}", files.len(), bytes, dir.display());
}

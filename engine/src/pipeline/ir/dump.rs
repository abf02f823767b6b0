//! A deterministic text dump of the IR, for golden-file tests (`tests/out/<case>/ir.txt`).

use std::fmt::Write as _;

use nalgebra::Isometry3;

use super::{FrameOwner, Model};

fn pose(p: &Isometry3<f64>) -> String {
    let t = p.translation.vector;
    let m = p.rotation.to_rotation_matrix();
    let m = m.matrix();
    let c = |k: usize| format!("[{:.9}, {:.9}, {:.9}]", m[(0, k)], m[(1, k)], m[(2, k)]);
    format!("at [{:.9}, {:.9}, {:.9}] x {} y {}", t.x, t.y, t.z, c(0), c(1))
}

/// Renders the model; numbers to 9 decimals (nanometres, nanoradians).
pub fn dump(model: &Model) -> String {
    let mut s = String::new();
    let src = &model.source;
    let _ = writeln!(s, "model {:?} from {:?} ({}, {:?}, {:?})", model.name, src.file, src.container, src.created_using, src.created_from);
    let _ = writeln!(s, "length_scale {}", model.length_scale);
    for g in &model.grounds {
        let _ = writeln!(s, "ground {:?} node {:?} frame {}", g.name, g.node_id, pose(&model.frame(g.frame).pose));
    }
    for b in &model.bodies {
        let _ = writeln!(s, "body {:?} node {:?} subsystem {:?}", b.cad_name, b.node_id, b.subsystem_path);
        let _ = writeln!(s, "  mass {:.9} volume {:?} area {:?}", b.mass, b.volume, b.surface_area);
        let i = &b.inertia_cg;
        let _ = writeln!(
            s,
            "  inertia_cg [[{:.9e}, {:.9e}, {:.9e}], [{:.9e}, {:.9e}, {:.9e}], [{:.9e}, {:.9e}, {:.9e}]]",
            i[(0, 0)],
            i[(0, 1)],
            i[(0, 2)],
            i[(1, 0)],
            i[(1, 1)],
            i[(1, 2)],
            i[(2, 0)],
            i[(2, 1)],
            i[(2, 2)]
        );
        if let Some(m) = &b.material {
            let _ = writeln!(s, "  material {:?}", m.color);
        }
        let _ = writeln!(s, "  geometry {:?} mesh {}", b.geometry_file, b.mesh.as_ref().map_or(0, |m| m.triangle_count()));
        for f in &b.frames {
            let fr = model.frame(*f);
            let owner_ok = matches!(fr.owner, FrameOwner::Body(_));
            let _ = writeln!(
                s,
                "  frame {:?} {:?} node {:?} ref {:?}{} {}",
                fr.name,
                fr.display_name,
                fr.node_id,
                fr.ref_id,
                if owner_ok { "" } else { " (not owned by a body!)" },
                pose(&fr.pose)
            );
        }
    }
    for j in &model.joints {
        let prims: Vec<String> = j
            .primitives
            .iter()
            .map(|p| format!("{}[{}, {}, {}]", p.kind.as_str(), p.axis_world.x, p.axis_world.y, p.axis_world.z))
            .collect();
        let _ = writeln!(
            s,
            "joint {:?} node {:?} base {:?} follower {:?} {}",
            j.cad_name,
            j.node_id,
            model.frame(j.base).node_id,
            model.frame(j.follower).node_id,
            prims.join(" ")
        );
    }
    s
}

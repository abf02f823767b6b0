//! Contact forces in the Modelica model: `<Pkg>/Components/Collision.mo` (the `World` model with
//! the bodies' convex collision shapes in a C `ExternalObject`, GJK/EPA distances and the contact
//! law), the C source in `<Pkg>/Resources/Include/cad2mo_collision.c`, and the declarations
//! `Mechatronics` gets: `parameter Boolean collisions = false`, the conditional world fed with every
//! shaped body's pose and velocities by modifiers, and one MSL `WorldForceAndTorque` per shaped
//! body on its `frame_a`, connected to the world's outputs.
//!
//! Plain data in, text out: no IO, no panics.

use crate::pipeline::back::modelica::diagram::extend::PLACEHOLDER;
use std::fmt::Write as _;

use super::num;
use crate::collision::ConvexPart;

/// The collision C source (GJK, EPA, contact law), shipped in every package with collision shapes.
pub const C_SOURCE: &str = include_str!("cad2mo_collision.c");

/// `<Pkg>/Components/Collision.mo` and `<Pkg>/Resources/Include/cad2mo_collision.c`.
pub fn files(pkg: &str) -> Vec<(String, Vec<u8>)> {
    let include = super::include_annotation(pkg, "cad2mo_collision.c");
    let text = format!(
        r#"within {pkg}.Components;
package Collision "Contact forces between the bodies' convex collision shapes"
  extends Modelica.Icons.Package;

  model World "Contact forces between the convex collision shapes of the bodies"
    parameter Integer nBodies(min=1) "Number of bodies with collision shapes";
    parameter Integer nParts(min=1) "Number of convex parts (a body has one or more)";
    parameter Integer partBody[nParts](each min=1) "Body (1..nBodies) each part belongs to";
    parameter Integer partVertices[nParts](each min=1) "Number of vertices of each part";
    parameter Modelica.Units.SI.Length partRadius[nParts] "Radius each part's convex hull is grown by (spheres, capsules)";
    parameter Integer nVertices = sum(partVertices) "Number of vertices of all parts";
    parameter Modelica.Units.SI.Position vertices[nVertices, 3] "Vertices of the parts in turn, in their body's frame_a";
    parameter Integer checked[nBodies, nBodies] "1: contacts between the two bodies are computed, 0: they may touch";
    parameter Real stiffness(min=0) = 1e7 "Contact stiffness K of F = K*delta^exponent (N/m^exponent)"
      annotation (Dialog(group="Contact law"));
    parameter Real exponent(min=1) = 1.5 "Exponent of the penetration (1.5: Hertz)"
      annotation (Dialog(group="Contact law"));
    parameter Real restitution(min=0.01, max=1) = 0.5 "Coefficient of restitution of an impact"
      annotation (Dialog(group="Contact law"));
    parameter Real friction(min=0) = 0.3 "Coulomb friction coefficient"
      annotation (Dialog(group="Contact law"));
    parameter Modelica.Units.SI.Velocity vReg = 0.01 "Slip speed below which friction grows linearly with it"
      annotation (Dialog(group="Contact law"));
    parameter Modelica.Units.SI.Velocity vImpactMin = 0.01 "Least approach speed the damping is scaled by"
      annotation (Dialog(group="Contact law"));
    parameter Real bodyStiffness[nBodies](each min=0) = fill(stiffness, nBodies) "Stiffness per body (a pair: in series)"
      annotation (Dialog(group="Materials"));
    parameter Real bodyRestitution[nBodies](each min=0.01, each max=1) = fill(restitution, nBodies) "Restitution per body (a pair: the smaller)"
      annotation (Dialog(group="Materials"));
    parameter Real bodyFriction[nBodies](each min=0) = fill(friction, nBodies) "Friction coefficient per body (a pair: the geometric mean)"
      annotation (Dialog(group="Materials"));
    input Real r_0[nBodies, 3](each final unit="m") "Origins of the bodies' frame_a, resolved in world";
    input Real R_T[nBodies, 3, 3] "Orientations of the bodies' frame_a (R.T: world to frame_a)";
    input Real v_0[nBodies, 3](each final unit="m/s") "Velocities of the frame_a origins, resolved in world";
    input Real w_a[nBodies, 3](each final unit="rad/s") "Angular velocities of the bodies, resolved in frame_a";
    Modelica.Blocks.Interfaces.RealOutput force[nBodies, 3] "Contact force on each body at its frame_a origin, resolved in world (N)"
      annotation (Placement(transformation(extent={{{{100,30}},{{120,50}}}})));
    Modelica.Blocks.Interfaces.RealOutput torque[nBodies, 3] "Contact torque on each body about its frame_a origin, resolved in world (N.m)"
      annotation (Placement(transformation(extent={{{{100,-50}},{{120,-30}}}})));
  protected
    Internal.Shapes shapes = Internal.Shapes(nBodies, partBody, partVertices, partRadius, vertices, bodyStiffness, bodyRestitution, bodyFriction, exponent, vReg, vImpactMin) "The shapes and contact law in C";
  equation
    (force, torque) = Internal.contactForces(shapes, r_0, R_T, v_0, w_a, checked);
    annotation (Documentation(info="<html>
<p>The collision manager: one C object (<code>Resources/Include/cad2mo_collision.c</code>, plain C99, nothing to link) holds the convex parts of every body's collision shape (each the convex hull of its vertices in the body's <code>frame_a</code>, grown by a radius), and at every evaluation computes, for every pair of bodies with <code>checked</code> = 1, the distance or penetration of their parts (GJK and EPA, converged to rounding on polytopes) and the contact force at the middle of the witness points.</p>
<p>Contact law (per touching pair of parts), penetration &delta; along the contact normal n:</p>
<ul>
<li>normal force F<sub>n</sub> = K &delta;<sup>exponent</sup> (1 + &chi; d&delta;/dt / v<sub>0</sub>), never pulling (Hunt&ndash;Crossley form as Flores et al. 2011), v<sub>0</sub> the approach speed at contact onset (at least <code>vImpactMin</code>, remembered per pair of parts by the C object), &chi; computed from the coefficient of restitution so that an impact rebounds with exactly <code>restitution</code> for any mass, stiffness and speed (Flores's closed form 8(1-e)/(5e) approximates it);</li>
<li>friction F<sub>t</sub> = -&mu; F<sub>n</sub> v<sub>t</sub> / sqrt(|v<sub>t</sub>|<sup>2</sup> + vReg<sup>2</sup>) against the slip velocity v<sub>t</sub> (regularised Coulomb).</li>
</ul>
<p>Materials per body: a pair uses the series stiffness (K<sub>1</sub><sup>-1/exponent</sup> + K<sub>2</sub><sup>-1/exponent</sup>)<sup>-exponent</sup>, the smaller restitution and the geometric mean of the friction coefficients. Stiff contacts make stiff equations: lower <code>stiffness</code> when the simulation crawls.</p>
<p>Outputs: the force and torque on every body at its <code>frame_a</code> origin, resolved in world, for <code>Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque</code>.</p>
</html>"));
  end World;

  package Internal "The C collision code of World"
    extends Modelica.Icons.InternalPackage;

    class Shapes "The convex collision shapes of the bodies and the contact law"
      extends ExternalObject;

      function constructor "Builds the shapes"
        extends Modelica.Icons.Function;
        input Integer nBodies "Number of bodies";
        input Integer partBody[:] "Body of each part (1-based)";
        input Integer partVertices[size(partBody, 1)] "Vertices per part";
        input Real partRadius[size(partBody, 1)] "Radius per part";
        input Real vertices[:, 3] "All vertices, frame_a coordinates";
        input Real stiffness[nBodies] "Stiffness per body";
        input Real restitution[nBodies] "Restitution per body";
        input Real friction[nBodies] "Friction coefficient per body";
        input Real exponent "Exponent of the penetration";
        input Real vReg "Friction regularisation speed";
        input Real vImpactMin "Least approach speed";
        output Shapes shapes "The shapes";
        external "C" shapes = cad2mo_collision_open(nBodies, size(partBody, 1), partBody, partVertices, partRadius, size(vertices, 1), vertices, stiffness, restitution, friction, exponent, vReg, vImpactMin)
          annotation ({include});
      end constructor;

      function destructor "Frees the shapes"
        extends Modelica.Icons.Function;
        input Shapes shapes "The shapes";
        external "C" cad2mo_collision_close(shapes)
          annotation ({include});
      end destructor;
    end Shapes;

    function contactForces "Contact forces and torques on every body"
      extends Modelica.Icons.Function;
      input Shapes shapes "The shapes";
      input Real r_0[:, 3] "Body origins, world";
      input Real R_T[size(r_0, 1), 3, 3] "Body orientations (world to frame_a)";
      input Real v_0[size(r_0, 1), 3] "Body origin velocities, world";
      input Real w_a[size(r_0, 1), 3] "Body angular velocities, frame_a";
      input Integer checked[size(r_0, 1), size(r_0, 1)] "Pairs to check";
      output Real force[size(r_0, 1), 3] "Forces at the frame_a origins, world";
      output Real torque[size(r_0, 1), 3] "Torques about the frame_a origins, world";
      external "C" cad2mo_collision_eval(shapes, r_0, R_T, v_0, w_a, checked, size(r_0, 1), force, torque)
        annotation ({include});
    end contactForces;
  end Internal;
  annotation (Documentation(info="<html>
<p>Collision handling as in Juh&aacute;sz and Schmucker's MultiBody collision extension: a collision manager (<code>World</code>) with the convex shapes that cad2mo made from the CAD meshes, and a <code>WorldForceAndTorque</code> per body applying its contact force. <code>Mechatronics</code> declares them when its parameter <code>collisions</code> is true.</p>
</html>"));
end Collision;
"#
    );
    vec![
        (format!("{pkg}/Components/Collision.mo"), text.into_bytes()),
        (format!("{pkg}/Resources/Include/cad2mo_collision.c"), C_SOURCE.as_bytes().to_vec()),
    ]
}

/// The Modelica name of a body's contact force component.
pub fn force_name(body: &str) -> String {
    format!("collisionForce_{body}")
}

/// What `Mechatronics` gets: `parameter Boolean collisions = false`, the conditional
/// `collisionWorld` (a `Components.Collision.World` holding the shapes of the bodies that have
/// some, in body order, fed by modifiers from each body's `frame_a`, `v_0` and `w_a`) and one
/// conditional `WorldForceAndTorque` per such body. `bodies[i]` is a `Parts.Body` (or anything
/// with `frame_a`, `v_0`, `w_a`) whose shape is `shapes[i]` (`None` or no parts: no shape);
/// `checked(i, j)` (i < j, indices into `bodies`) says whether the pair's contacts are computed.
///
/// The text is declarations, then an `equation` section with the `connect`s (conditional
/// components may only be named in `connect`), then `public`: it may be placed among
/// `Mechatronics`' declarations. Without any shape, only a comment.
pub fn declarations(pkg: &str, bodies: &[String], shapes: &[Option<Vec<ConvexPart>>], checked: &dyn Fn(usize, usize) -> bool) -> String {
    let shaped: Vec<usize> = (0..bodies.len())
        .filter(|&i| shapes.get(i).and_then(|s| s.as_ref()).is_some_and(|p| p.iter().any(|q| !q.vertices.is_empty())))
        .collect();
    let mut s = String::new();
    if shaped.is_empty() {
        let _ = writeln!(s, "\n  // Collisions: no body has a collision shape");
        return s;
    }
    let mut part_body = Vec::new();
    let mut part_vertices = Vec::new();
    let mut part_radius = Vec::new();
    let mut vertices = Vec::new();
    for (k, &i) in shaped.iter().enumerate() {
        for p in shapes[i].iter().flatten().filter(|p| !p.vertices.is_empty()) {
            part_body.push((k + 1).to_string());
            part_vertices.push(p.vertices.len().to_string());
            part_radius.push(num(p.radius.max(0.0)));
            for v in &p.vertices {
                vertices.push(format!("{{{}, {}, {}}}", num(v[0]), num(v[1]), num(v[2])));
            }
        }
    }
    let n = shaped.len();
    let rows: Vec<String> = (0..n)
        .map(|a| {
            let row: Vec<&str> = (0..n)
                .map(|b| {
                    let (i, j) = (shaped[a.min(b)], shaped[a.max(b)]);
                    if a != b && checked(i, j) {
                        "1"
                    } else {
                        "0"
                    }
                })
                .collect();
            format!("{{{}}}", row.join(", "))
        })
        .collect();
    let list = |f: &dyn Fn(&str) -> String| shaped.iter().map(|&i| f(&bodies[i])).collect::<Vec<_>>().join(", ");
    let _ = writeln!(s, "\n  // Collisions: contact forces between the bodies' collision shapes (see Components.Collision)");
    let _ = writeln!(
        s,
        "  parameter Boolean collisions = false \"Apply contact forces between the bodies' collision shapes\"\n    annotation (Dialog(group=\"Collisions\"), choices(checkBox=true));"
    );
    let _ = writeln!(
        s,
        "  {pkg}.Components.Collision.World collisionWorld(\n    nBodies={n},\n    nParts={},\n    partBody={{{}}},\n    partVertices={{{}}},\n    partRadius={{{}}},\n    vertices={{\n      {}}},\n    checked={{{}}},\n    r_0={{{}}},\n    R_T={{{}}},\n    v_0={{{}}},\n    w_a={{{}}}) if collisions \"Contact forces between the collision shapes\"\n    {PLACEHOLDER};",
        part_body.len(),
        part_body.join(", "),
        part_vertices.join(", "),
        part_radius.join(", "),
        vertices.join(",\n      "),
        rows.join(", "),
        list(&|b| format!("{b}.frame_a.r_0")),
        list(&|b| format!("{b}.frame_a.R.T")),
        list(&|b| format!("{b}.v_0")),
        list(&|b| format!("{b}.w_a")),
    );
    for &i in &shaped {
        let _ = writeln!(
            s,
            "  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque {} if collisions \"Contact force and torque on {} (resolved in world)\"\n    {PLACEHOLDER};",
            force_name(&bodies[i]),
            bodies[i]
        );
    }
    let _ = writeln!(s, "equation");
    for (k, &i) in shaped.iter().enumerate() {
        let f = force_name(&bodies[i]);
        let _ = writeln!(s, "  connect({f}.frame_b, {}.frame_a);", bodies[i]);
        let _ = writeln!(s, "  connect(collisionWorld.force[{}, :], {f}.force);", k + 1);
        let _ = writeln!(s, "  connect(collisionWorld.torque[{}, :], {f}.torque);", k + 1);
    }
    let _ = writeln!(s, "public");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(r: f64) -> ConvexPart {
        let mut v = Vec::new();
        for i in 0..8 {
            v.push([(i & 1) as f64 * 0.1, ((i >> 1) & 1) as f64 * 0.1, ((i >> 2) & 1) as f64 * 0.1]);
        }
        ConvexPart { vertices: v, faces: Vec::new(), radius: r }
    }

    #[test]
    fn collision_declarations_skip_bodies_without_shapes() {
        let bodies = vec!["B1".to_string(), "B2".to_string(), "B3".to_string()];
        let shapes = vec![Some(vec![cube(0.0)]), None, Some(vec![cube(0.0), cube(0.01)])];
        let d = declarations("P", &bodies, &shapes, &|_, _| true);
        assert!(d.contains("nBodies=2,"), "{d}");
        assert!(d.contains("nParts=3,"), "{d}");
        assert!(d.contains("partBody={1, 2, 2}"), "{d}");
        assert!(d.contains("checked={{0, 1}, {1, 0}}"), "{d}");
        assert!(d.contains("v_0={B1.v_0, B3.v_0}"), "{d}");
        assert!(!d.contains("B2"), "{d}");
        assert!(d.contains("connect(collisionWorld.force[2, :], collisionForce_B3.force);"), "{d}");
        let none = declarations("P", &bodies, &[None, None, None], &|_, _| true);
        assert!(!none.contains("collisionWorld"));
    }

    #[test]
    fn collision_files_ship_the_c_source() {
        let f = files("P");
        assert_eq!(f[0].0, "P/Components/Collision.mo");
        assert_eq!(f[1].1, C_SOURCE.as_bytes());
        let text = String::from_utf8_lossy(&f[0].1);
        assert!(text.contains("modelica://P/Resources/Include"));
    }
}

//! Contact forces in the Modelica model: `<Pkg>/Components/Collision.mo` (the `World` model with
//! the bodies' convex collision shapes in a C `ExternalObject`, GJK/EPA distances and the contact
//! law; `BodyForce`, which applies a body's share), the C source in
//! `<Pkg>/Resources/Include/cad2mo_collision.c`, the shape file the C code reads at
//! initialisation (`<Pkg>/Resources/Collision/contact.txt`: every convex part's vertices and the
//! pairs allowed to touch, so that `Mechatronics.mo` holds names and parameters, not vertices), and
//! the declarations `Mechatronics` gets: `parameter Boolean collisions = false`, the world fed with
//! every shaped body's pose and velocities by modifiers, and one conditional `BodyForce` per shaped
//! body beside it, on its `frame_a`.
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
    parameter Boolean enabled = true "Compute contact forces (false: none, the shape file is not read)";
    parameter Integer nBodies(min=1) "Number of bodies with collision shapes";
    parameter String bodyNames[nBodies] "The bodies, in the order of the inputs (checked against the shape file)";
    parameter String shapeFile = Modelica.Utilities.Files.loadResource("modelica://{pkg}/Resources/Collision/contact.txt") "The bodies' convex parts and the pairs allowed to touch, written by cad2mo"
      annotation (Dialog(loadSelector(filter="cad2mo collision shapes (*.txt)", caption="Collision shape file")));
    parameter Integer mayTouch[:, 2] = fill(0, 0, 2) "Further pairs of bodies (indices into bodyNames) allowed to touch";
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
    output Real force[nBodies, 3](each final unit="N") "Contact force on each body at its frame_a origin, resolved in world";
    output Real torque[nBodies, 3](each final unit="N.m") "Contact torque on each body about its frame_a origin, resolved in world";
  protected
    Internal.Shapes shapes = Internal.Shapes(if enabled then shapeFile else "", bodyNames, mayTouch, bodyStiffness, bodyRestitution, bodyFriction, exponent, vReg, vImpactMin) "The shapes and contact law in C";
  equation
    if enabled then
      (force, torque) = Internal.contactForces(shapes, r_0, R_T, v_0, w_a);
    else
      force = zeros(nBodies, 3);
      torque = zeros(nBodies, 3);
    end if;
    annotation (Icon(graphics={{Rectangle(extent={{{{-100,100}},{{100,-100}}}}, lineColor={{0,0,0}}, fillColor={{255,255,255}}, fillPattern=FillPattern.Solid), Polygon(points={{{{-70,-20}},{{-20,-60}},{{20,-20}},{{-30,20}},{{-70,-20}}}}, lineColor={{0,0,0}}, fillColor={{175,175,175}}, fillPattern=FillPattern.Solid), Ellipse(extent={{{{0,60}},{{60,0}}}}, lineColor={{0,0,0}}, fillColor={{215,215,215}}, fillPattern=FillPattern.Solid), Text(extent={{{{-150,150}},{{150,110}}}}, textString="%name", textColor={{0,0,255}})}}),
      Documentation(info="<html>
<p>The collision manager: one C object (<code>Resources/Include/cad2mo_collision.c</code>, plain C99, nothing to link) holds the convex parts of every body's collision shape (each the convex hull of its vertices in the body's <code>frame_a</code>, grown by a radius), and at every evaluation computes, for every pair of bodies not allowed to touch, the distance or penetration of their parts (GJK and EPA, converged to rounding on polytopes) and the contact force at the middle of the witness points.</p>
<p>The parts are read once, at initialisation, from <code>shapeFile</code> (by default <code>Resources/Collision/contact.txt</code> of this package, which cad2mo writes: the bodies in order, each part's radius and vertices, and the pairs allowed to touch, by default those joined by a joint or welded together and as edited in cad2mo's collision matrix); a file whose bodies differ from <code>bodyNames</code> is refused at initialisation with the first difference. <code>mayTouch</code> allows further pairs. With <code>enabled</code> = false the file is not read and the forces are zero.</p>
<p>Contact law (per touching pair of parts), penetration &delta; along the contact normal n:</p>
<ul>
<li>normal force F<sub>n</sub> = K &delta;<sup>exponent</sup> (1 + &chi; d&delta;/dt / v<sub>0</sub>), never pulling (Hunt&ndash;Crossley form as Flores et al. 2011), v<sub>0</sub> the approach speed at contact onset (at least <code>vImpactMin</code>, remembered per pair of parts by the C object), &chi; computed from the coefficient of restitution so that an impact rebounds with exactly <code>restitution</code> for any mass, stiffness and speed (Flores's closed form 8(1-e)/(5e) approximates it);</li>
<li>friction F<sub>t</sub> = -&mu; F<sub>n</sub> v<sub>t</sub> / sqrt(|v<sub>t</sub>|<sup>2</sup> + vReg<sup>2</sup>) against the slip velocity v<sub>t</sub> (regularised Coulomb).</li>
</ul>
<p>Materials per body: a pair uses the series stiffness (K<sub>1</sub><sup>-1/exponent</sup> + K<sub>2</sub><sup>-1/exponent</sup>)<sup>-exponent</sup>, the smaller restitution and the geometric mean of the friction coefficients. Stiff contacts make stiff equations: lower <code>stiffness</code> when the simulation crawls.</p>
<p>Outputs: the force and torque on every body at its <code>frame_a</code> origin, resolved in world; a <code>BodyForce</code> beside each body applies its row.</p>
</html>"));
  end World;

  model BodyForce "Applies one body's contact force and torque from the collision world"
    input Real force[3](each final unit="N") "Contact force at the body's frame_a origin, resolved in world";
    input Real torque[3](each final unit="N.m") "Contact torque about the body's frame_a origin, resolved in world";
    Modelica.Mechanics.MultiBody.Interfaces.Frame_b frame_b "Connect to the body's frame_a"
      annotation (Placement(transformation(extent={{{{84,-16}},{{116,16}}}})));
  protected
    Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque apply(force=force, torque=torque) "Force and torque resolved in world"
      annotation (Placement(transformation(extent={{{{-10,-10}},{{10,10}}}})));
  equation
    connect(apply.frame_b, frame_b);
    annotation (Icon(graphics={{Rectangle(extent={{{{-100,60}},{{100,-60}}}}, lineColor={{0,0,0}}, fillColor={{255,255,255}}, fillPattern=FillPattern.Solid), Polygon(points={{{{-80,-30}},{{-40,-50}},{{-20,-10}},{{-60,10}},{{-80,-30}}}}, lineColor={{0,0,0}}, fillColor={{175,175,175}}, fillPattern=FillPattern.Solid), Line(points={{{{-10,0}},{{80,0}}}}, color={{0,0,0}}, thickness=0.5), Polygon(points={{{{80,0}},{{60,10}},{{60,-10}},{{80,0}}}}, lineColor={{0,0,0}}, fillColor={{0,0,0}}, fillPattern=FillPattern.Solid), Text(extent={{{{-150,110}},{{150,70}}}}, textString="%name", textColor={{0,0,255}})}}),
      Documentation(info="<html>
<p>The contact force and torque the collision world computed for one body, applied at its <code>frame_a</code> (MSL <code>WorldForceAndTorque</code>). <code>Mechatronics</code> binds <code>force</code> and <code>torque</code> to the body's row of <code>collisionWorld</code> and places each <code>BodyForce</code> beside its body with one short frame connection, so the diagram has no wires from the world to the bodies.</p>
</html>"));
  end BodyForce;

  package Internal "The C collision code of World"
    extends Modelica.Icons.InternalPackage;

    class Shapes "The convex collision shapes of the bodies and the contact law"
      extends ExternalObject;

      function constructor "Reads the shapes from the shape file"
        extends Modelica.Icons.Function;
        input String shapeFile "The shape file (empty: no parts)";
        input String bodyNames[:] "The bodies, in order";
        input Integer mayTouch[:, 2] "Further pairs allowed to touch";
        input Real stiffness[size(bodyNames, 1)] "Stiffness per body";
        input Real restitution[size(bodyNames, 1)] "Restitution per body";
        input Real friction[size(bodyNames, 1)] "Friction coefficient per body";
        input Real exponent "Exponent of the penetration";
        input Real vReg "Friction regularisation speed";
        input Real vImpactMin "Least approach speed";
        output Shapes shapes "The shapes";
        external "C" shapes = cad2mo_collision_load(shapeFile, size(bodyNames, 1), bodyNames, size(mayTouch, 1), mayTouch, stiffness, restitution, friction, exponent, vReg, vImpactMin)
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
      output Real force[size(r_0, 1), 3] "Forces at the frame_a origins, world";
      output Real torque[size(r_0, 1), 3] "Torques about the frame_a origins, world";
      external "C" cad2mo_collision_forces(shapes, r_0, R_T, v_0, w_a, size(r_0, 1), force, torque)
        annotation ({include});
    end contactForces;
  end Internal;
  annotation (Documentation(info="<html>
<p>Collision handling as in Juh&aacute;sz and Schmucker's MultiBody collision extension: a collision manager (<code>World</code>) with the convex shapes that cad2mo made from the CAD meshes (read from <code>Resources/Collision/contact.txt</code> at initialisation), and a <code>BodyForce</code> per body applying its contact force. <code>Mechatronics</code> declares the forces when its parameter <code>collisions</code> is true.</p>
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

/// The file (in the package) the collision world reads its parts from.
pub const SHAPE_FILE: &str = "Resources/Collision/contact.txt";

/// What `Mechatronics` gets for contact forces: its declarations and the shape file.
#[derive(Clone, Debug)]
pub struct Contacts {
    /// Declarations, then an `equation` section with the `connect`s, then `public`: placed among
    /// `Mechatronics`' declarations.
    pub declarations: String,
    /// `<Pkg>/Resources/Collision/contact.txt` ([`SHAPE_FILE`]), read by the C code.
    pub shape_file: Vec<u8>,
}

/// What `Mechatronics` gets: `parameter Boolean collisions = false`, `collisionWorld` (a
/// `Components.Collision.World` for the bodies that have a shape, in body order, fed by modifiers
/// from each body's `frame_a`, `v_0` and `w_a`, enabled by `collisions`), and one conditional
/// `Components.Collision.BodyForce` per such body, bound to its row of the world's outputs and
/// connected to the body's `frame_a` (no signal wires). The parts and the pairs allowed to touch go
/// to the shape file, not into the text. `bodies[i]` is a `Parts.Body` (or anything with `frame_a`,
/// `v_0`, `w_a`) whose shape is `shapes[i]` (`None` or no parts: no shape); `allowed` are the
/// pairs (i < j, indices into `bodies`) allowed to touch, whose contacts are not computed (every
/// other pair is). `None` when no body has a shape.
pub fn declarations(pkg: &str, bodies: &[String], shapes: &[Option<Vec<ConvexPart>>], allowed: &[(usize, usize)]) -> Option<Contacts> {
    declarations_with_scene(pkg, bodies, shapes, allowed, &[])
}

/// [`declarations`] with the scene's objects after the bodies (`crate::scene::package`): their
/// poses and velocities from their members' expressions, a `BodyForce` only for those a force
/// acts on (free objects, objects attached to a body), the pairs of two prescribed objects and
/// of an attached object and its body allowed to touch; `collisions` defaults to true when the
/// scene has a free object (it would fall through everything).
pub fn declarations_with_scene(
    pkg: &str,
    bodies: &[String],
    shapes: &[Option<Vec<ConvexPart>>],
    allowed: &[(usize, usize)],
    scene: &[crate::scene::package::Member],
) -> Option<Contacts> {
    let shaped: Vec<usize> = (0..bodies.len())
        .filter(|&i| shapes.get(i).and_then(|s| s.as_ref()).is_some_and(|p| p.iter().any(|q| !q.vertices.is_empty())))
        .collect();
    let scene: Vec<&crate::scene::package::Member> = scene.iter().filter(|m| m.parts.iter().any(|q| !q.vertices.is_empty())).collect();
    if shaped.is_empty() && scene.is_empty() {
        return None;
    }
    let nb = shaped.len();
    let n = nb + scene.len();
    // Every member's name, in the world's order.
    let names: Vec<&str> = shaped.iter().map(|&i| bodies[i].as_str()).chain(scene.iter().map(|m| m.name.as_str())).collect();
    // The shape file: bodies, parts (radius, vertices), allowed pairs.
    let mut f = String::new();
    let _ = writeln!(f, "cad2mo-collision 1");
    let _ = writeln!(f, "# The convex parts of the bodies' collision shapes for {pkg}.Components.Collision.World (written by cad2mo):");
    let _ = writeln!(
        f,
        "# bodies in the order of the world's inputs; \"part <body> <radius m> <vertices>\" then the vertices in the body's frame_a (m);"
    );
    let _ = writeln!(f, "# \"allow <body> <body>\": a pair allowed to touch (no contact force); every other pair is checked.");
    let _ = writeln!(f, "bodies {n}");
    for (k, name) in names.iter().enumerate() {
        let _ = writeln!(f, "body {} {name}", k + 1);
    }
    let mut parts = 0usize;
    let member_parts = |k: usize| -> Vec<&ConvexPart> {
        match shaped.get(k) {
            Some(&i) => shapes[i].iter().flatten().collect(),
            None => scene[k - nb].parts.iter().collect(),
        }
    };
    for k in 0..n {
        for p in member_parts(k).into_iter().filter(|p| !p.vertices.is_empty()) {
            parts += 1;
            let _ = writeln!(f, "part {} {} {}", k + 1, num(p.radius.max(0.0)), p.vertices.len());
            // The vertices as `num` writes them, straight into the text (a string per number
            // was most of this file's cost for thousands of bodies).
            for v in &p.vertices {
                for (i, &x) in v.iter().enumerate() {
                    if i > 0 {
                        f.push(' ');
                    }
                    crate::numtext::push_dbg(&mut f, if x == 0.0 { 0.0 } else { x });
                }
                f.push('\n');
            }
        }
    }
    // A body's place among the shaped ones (1-based), by body index.
    let mut place = vec![0usize; bodies.len()];
    for (k, &i) in shaped.iter().enumerate() {
        place[i] = k + 1;
    }
    let mut pairs: Vec<(usize, usize)> = allowed
        .iter()
        .filter_map(|&(i, j)| {
            let (a, b) = (*place.get(i)?, *place.get(j)?);
            (a > 0 && b > 0 && a != b).then_some((a.min(b), a.max(b)))
        })
        .collect();
    for (a, m) in scene.iter().enumerate() {
        let a = nb + a + 1;
        if let Some(b) = m.attached_to.as_ref().and_then(|b| shaped.iter().position(|&i| bodies[i] == *b)) {
            pairs.push((b + 1, a));
        }
        for (c, other) in scene.iter().enumerate().take(a - nb - 1) {
            if m.prescribed && other.prescribed {
                pairs.push((nb + c + 1, a));
            }
        }
    }
    pairs.sort_unstable();
    pairs.dedup();
    for (a, b) in &pairs {
        let _ = writeln!(f, "allow {a} {b}");
    }
    let allowed = pairs.len();
    let _ = writeln!(f, "end");
    // A member's expression: a body's from its name, a scene object's from its member.
    let list = |f: &dyn Fn(&str) -> String, g: &dyn Fn(&crate::scene::package::Member) -> String| {
        shaped.iter().map(|&i| f(&bodies[i])).chain(scene.iter().map(|m| g(m))).collect::<Vec<_>>().join(", ")
    };
    let free = scene.iter().any(|m| m.force_frame.is_some() && m.attached_to.is_none());
    let mut s = String::new();
    let _ = writeln!(
        s,
        "\n  // Collisions: contact forces between the bodies' collision shapes ({n} bodies, {parts} convex parts, {} of {} pairs checked; see Components.Collision and {SHAPE_FILE})",
        n * (n - 1) / 2 - allowed,
        n * (n - 1) / 2
    );
    let _ = writeln!(
        s,
        "  parameter Boolean collisions = {free} \"Apply contact forces between the bodies' collision shapes\"\n    annotation (Dialog(group=\"Collisions\"), choices(checkBox=true));"
    );
    let _ = writeln!(
        s,
        "  {pkg}.Components.Collision.World collisionWorld(\n    enabled=collisions,\n    nBodies={n},\n    bodyNames={{{}}},\n    r_0={{{}}},\n    R_T={{{}}},\n    v_0={{{}}},\n    w_a={{{}}}) \"Contact forces between the collision shapes (read from {SHAPE_FILE} when collisions is true)\"\n    {PLACEHOLDER};",
        list(&|b| format!("\"{b}\""), &|m| format!("\"{}\"", m.name)),
        list(&|b| format!("{b}.frame_a.r_0"), &|m| m.r_0.clone()),
        list(&|b| format!("{b}.frame_a.R.T"), &|m| m.r_t.clone()),
        list(&|b| format!("{b}.v_0"), &|m| m.v_0.clone()),
        list(&|b| format!("{b}.w_a"), &|m| m.w_a.clone()),
    );
    // (member name, the frame its force acts on), 1-based place
    let forced: Vec<(usize, &str, String)> = shaped
        .iter()
        .enumerate()
        .map(|(k, &i)| (k + 1, bodies[i].as_str(), format!("{}.frame_a", bodies[i])))
        .chain(scene.iter().enumerate().filter_map(|(k, m)| Some((nb + k + 1, m.name.as_str(), m.force_frame.clone()?))))
        .collect();
    for (k1, name, _) in &forced {
        let _ = writeln!(
            s,
            "  {pkg}.Components.Collision.BodyForce {}(force=collisionWorld.force[{k1}, :], torque=collisionWorld.torque[{k1}, :]) if collisions \"Contact force and torque on {name} (from collisionWorld)\"\n    {PLACEHOLDER};",
            force_name(name),
        );
    }
    let _ = writeln!(s, "equation");
    for (_, name, frame) in &forced {
        let _ = writeln!(s, "  connect({}.frame_b, {frame});", force_name(name));
    }
    let _ = writeln!(s, "public");
    Some(Contacts { declarations: s, shape_file: f.into_bytes() })
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
        let c = declarations("P", &bodies, &shapes, &[]).expect("contacts");
        let d = &c.declarations;
        assert!(d.contains("nBodies=2,"), "{d}");
        assert!(d.contains("bodyNames={\"B1\", \"B3\"}"), "{d}");
        assert!(d.contains("v_0={B1.v_0, B3.v_0}"), "{d}");
        assert!(!d.contains("B2"), "{d}");
        assert!(d.contains("collisionForce_B3(force=collisionWorld.force[2, :], torque=collisionWorld.torque[2, :]) if collisions"), "{d}");
        assert!(d.contains("connect(collisionForce_B3.frame_b, B3.frame_a);"), "{d}");
        assert!(!d.contains("0.1, 0.1"), "no vertices in the text: {d}");
        let f = String::from_utf8(c.shape_file).expect("utf-8");
        assert!(f.starts_with("cad2mo-collision 1\n"), "{f}");
        assert!(f.contains("\nbodies 2\nbody 1 B1\nbody 2 B3\n"), "{f}");
        assert_eq!(f.matches("\npart ").count(), 3, "{f}");
        assert!(f.contains("\npart 2 0.01 8\n"), "{f}");
        assert!(!f.contains("\nallow "), "every pair checked: {f}");
        assert!(f.ends_with("\nend\n"), "{f}");
        let allowed = declarations("P", &bodies, &shapes, &[(0, 2)]).expect("contacts");
        assert!(String::from_utf8_lossy(&allowed.shape_file).contains("\nallow 1 2\n"));
        assert!(declarations("P", &bodies, &[None, None, None], &[]).is_none());
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

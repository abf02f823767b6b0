within broken;
model Mechanics "Mechanical model of broken (2 bodies, 2 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, 0.0, -1.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-160,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body a(
    m=1.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.01, I_22=0.01, I_33=0.01,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part a (nodeID a)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,0})));
  Modelica.Mechanics.MultiBody.Parts.Body b(
    m=1.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.01, I_22=0.01, I_33=0.01,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part b (nodeID b)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));

  // Frames: grounds, joint attachment frames and user-added CAD frames

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  broken.Components.Revolute j(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint j (nodeID j)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));

  // Shapes: CAD meshes in each body frame, metres
equation
  connect(world.frame_b, a.frame_a);
  connect(a.frame_a, j.frame_a);
  connect(j.frame_b, b.frame_a);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>robot.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
</html>"));
end Mechanics;

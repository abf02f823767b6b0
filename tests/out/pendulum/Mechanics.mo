within PENDULUM;
model Mechanics "Mechanical model of PENDULUM (2 bodies, 2 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-160,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.5, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID PENDULUM/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,0})));
  Modelica.Mechanics.MultiBody.Parts.Body LINK(
    m=0.2673,
    r_CM={0.15, 0.0, 0.0},
    I_11=2.2275e-5, I_22=0.00242798, I_33=0.0024458,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part LINK (nodeID 23)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootGround(r={0.0, 0.5, 0.0}, animation=false)
    "Ground RootGround (nodeID RootGround) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS2(r={0.0, 0.45, 0.0}, animation=false)
    "Frame CS2 of RootPart (nodeID 23:-:PENDULUM/RootPart::PENDULUM/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.5, 0.866025403784439, 0.0},
    n_y={-0.866025403784439, 0.5, 0.0},
    animation=false)
    "Frame CS2 of LINK (nodeID 23:-:PENDULUM/RootPart::23(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-50})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS3(r={0.0, 0.5, 0.0}, animation=false)
    "Frame CS3 of RootPart (nodeID PENDULUM/RootPart:-:RootGround::PENDULUM/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-75})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  PENDULUM.Components.Revolute RootPart_LINK(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--LINK (nodeID 23:-:PENDULUM/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape LINK_shape(
    shapeType="modelica://PENDULUM/Resources/Shapes/LINK.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of LINK" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,0})));
equation
  connect(world.frame_b, RootGround.frame_a);
  connect(RootPart.frame_a, RootPart_CS2.frame_a);
  connect(LINK.frame_a, LINK_CS2.frame_a);
  connect(RootPart.frame_a, RootPart_CS3.frame_a);
  connect(RootGround.frame_b, RootPart_CS3.frame_b);
  connect(RootPart_CS2.frame_b, RootPart_LINK.frame_a);
  connect(RootPart_LINK.frame_b, LINK_CS2.frame_b);
  connect(LINK.frame_a, LINK_shape.frame_a);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>PENDULUM.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 4.8 from Pro/E Wildfire Creo 7.0 - 2020454 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
</html>"));
end Mechanics;

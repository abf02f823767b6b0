within FOURBAR;
model Mechanics "Mechanical model of FOURBAR (4 bodies, 5 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-160,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID FOURBAR/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,0})));
  Modelica.Mechanics.MultiBody.Parts.Body CRANK(
    m=0.10048,
    r_CM={0.03, 0.0, 0.0},
    I_11=3.88523e-6, I_22=5.41252e-5, I_33=5.69387e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part CRANK (nodeID 40)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));
  Modelica.Mechanics.MultiBody.Parts.Body COUPLER(
    m=0.2512,
    r_CM={0.09, 0.0, 0.0},
    I_11=9.71307e-6, I_22=0.000838673, I_33=0.000845707,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part COUPLER (nodeID 41)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-50})));
  Modelica.Mechanics.MultiBody.Parts.Body ROCKER(
    m=0.21352,
    r_CM={0.075, 0.0, 0.0},
    I_11=8.25611e-6, I_22=0.000515366, I_33=0.000521345,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part ROCKER (nodeID 45)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-75})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS2(r={0.02, 0.01, 0.0}, animation=false)
    "Frame CS2 of RootPart (nodeID 40:-:FOURBAR/RootPart::FOURBAR/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.342020143325669, -0.939692620785908, 0.0},
    n_y={0.939692620785908, 0.342020143325669, 0.0},
    animation=false)
    "Frame CS2 of CRANK (nodeID 40:-:FOURBAR/RootPart::40(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS3(
    r={0.06, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.342020143325669, -0.939692620785908, 0.0},
    n_y={0.939692620785908, 0.342020143325669, 0.0},
    animation=false)
    "Frame CS3 of CRANK (nodeID 40:-:41::40(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-50})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation COUPLER_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.860834363403597, -0.508885251096477, 0.0},
    n_y={0.508885251096477, 0.860834363403597, 0.0},
    animation=false)
    "Frame CS2 of COUPLER (nodeID 40:-:41::41(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-75})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation COUPLER_CS3(
    r={0.18, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.860834363403597, -0.508885251096477, 0.0},
    n_y={0.508885251096477, 0.860834363403597, 0.0},
    animation=false)
    "Frame CS3 of COUPLER (nodeID 41:-:45::41(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROCKER_CS2(
    r={0.15, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.16352403991875, -0.986539349630136, 0.0},
    n_y={0.986539349630136, -0.16352403991875, 0.0},
    animation=false)
    "Frame CS2 of ROCKER (nodeID 41:-:45::45(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-125})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS3(r={0.22, 0.01, 0.0}, animation=false)
    "Frame CS3 of RootPart (nodeID 45:-:FOURBAR/RootPart::FOURBAR/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-150})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROCKER_CS3(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.16352403991875, -0.986539349630136, 0.0},
    n_y={0.986539349630136, -0.16352403991875, 0.0},
    animation=false)
    "Frame CS3 of ROCKER (nodeID 45:-:FOURBAR/RootPart::45(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-175})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  FOURBAR.Components.Revolute RootPart_CRANK(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--CRANK (nodeID 40:-:FOURBAR/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));
  FOURBAR.Components.Revolute CRANK_COUPLER(
    n={0.0, 0.0, 1.0},
    phi(start=0.0),
    w(start=0))
    "Joint CRANK--COUPLER (nodeID 40:-:41)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-25})));
  FOURBAR.Components.Revolute COUPLER_ROCKER(
    n={0.0, 0.0, 1.0},
    phi(start=0.0),
    w(start=0))
    "Joint COUPLER--ROCKER (nodeID 41:-:45)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-50})));
  Modelica.Mechanics.MultiBody.Joints.RevolutePlanarLoopConstraint RootPart_ROCKER(n={0.0, 0.0, -1.0}, animation=false)
    "Joint RootPart--ROCKER (nodeID 45:-:FOURBAR/RootPart): closes a planar loop" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-75})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape CRANK_shape(
    shapeType="modelica://FOURBAR/Resources/Shapes/CRANK.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of CRANK" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,0})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape COUPLER_shape(
    shapeType="modelica://FOURBAR/Resources/Shapes/COUPLER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of COUPLER" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-25})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape ROCKER_shape(
    shapeType="modelica://FOURBAR/Resources/Shapes/ROCKER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of ROCKER" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-50})));
equation
  connect(RootPart.frame_a, RootPart_CS2.frame_a);
  connect(CRANK.frame_a, CRANK_CS2.frame_a);
  connect(CRANK.frame_a, CRANK_CS3.frame_a);
  connect(COUPLER.frame_a, COUPLER_CS2.frame_a);
  connect(COUPLER.frame_a, COUPLER_CS3.frame_a);
  connect(ROCKER.frame_a, ROCKER_CS2.frame_a);
  connect(RootPart.frame_a, RootPart_CS3.frame_a);
  connect(ROCKER.frame_a, ROCKER_CS3.frame_a);
  connect(world.frame_b, RootPart.frame_a);
  connect(RootPart_CS2.frame_b, RootPart_CRANK.frame_a);
  connect(RootPart_CRANK.frame_b, CRANK_CS2.frame_b);
  connect(CRANK_CS3.frame_b, CRANK_COUPLER.frame_a);
  connect(CRANK_COUPLER.frame_b, COUPLER_CS2.frame_b);
  connect(COUPLER_CS3.frame_b, COUPLER_ROCKER.frame_a);
  connect(COUPLER_ROCKER.frame_b, ROCKER_CS2.frame_b);
  connect(RootPart_CS3.frame_b, RootPart_ROCKER.frame_a);
  connect(RootPart_ROCKER.frame_b, ROCKER_CS3.frame_b);
  connect(CRANK.frame_a, CRANK_shape.frame_a);
  connect(COUPLER.frame_a, COUPLER_shape.frame_a);
  connect(ROCKER.frame_a, ROCKER_shape.frame_a);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>FOURBAR.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Joint RootPart--ROCKER closes a loop: a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations.</li></ul>
</html>"));
end Mechanics;

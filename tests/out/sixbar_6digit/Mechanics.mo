within SIXBAR;
model Mechanics "Mechanical model of SIXBAR (6 bodies, 8 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-160,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID SIXBAR/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,0})));
  Modelica.Mechanics.MultiBody.Parts.Body CRANK(
    m=0.0279072,
    r_CM={0.03, -0.000499999999999994, 0.0},
    I_11=8.20936999999999e-7, I_22=1.35815e-5, I_33=1.41048e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part CRANK (nodeID 50)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));
  Modelica.Mechanics.MultiBody.Parts.Body COUPLER(
    m=0.0976752,
    r_CM={0.125, -0.000500000000000007, 0.0},
    I_11=2.87328e-6, I_22=0.000576446, I_33=0.000578278,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part COUPLER (nodeID 51)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-50})));
  Modelica.Mechanics.MultiBody.Parts.Body ROCKER(
    m=0.0539136,
    r_CM={0.07, 0.0, 0.0},
    I_11=1.4377e-6, I_22=0.000109624, I_33=0.000110487,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part ROCKER (nodeID 52)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-75})));
  Modelica.Mechanics.MultiBody.Parts.Body LINK5(
    m=0.0573696,
    r_CM={0.075, 0.0, 0.0},
    I_11=1.52986e-6, I_22=0.000132046, I_33=0.000132964,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part LINK5 (nodeID 53)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-100})));
  Modelica.Mechanics.MultiBody.Parts.Body LINK6(
    m=0.0470016,
    r_CM={0.06, 0.0, 0.0},
    I_11=1.25338e-6, I_22=7.26958e-5, I_33=7.34478e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part LINK6 (nodeID 54)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-125})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.258819045102521, -0.965925826289068, 0.0},
    n_y={0.965925826289068, 0.258819045102521, 0.0},
    animation=false)
    "Frame CS2 of CRANK (nodeID 50:-:SIXBAR/RootPart::50(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS3(
    r={0.06, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.258819045102521, -0.965925826289068, 0.0},
    n_y={0.965925826289068, 0.258819045102521, 0.0},
    animation=false)
    "Frame CS3 of CRANK (nodeID 50:-:51::50(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation COUPLER_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.903438254549634, -0.428718229395848, 0.0},
    n_y={0.428718229395848, 0.903438254549634, 0.0},
    animation=false)
    "Frame CS2 of COUPLER (nodeID 50:-:51::51(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-50})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation COUPLER_CS3(
    r={0.19, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.903438254549634, -0.428718229395848, 0.0},
    n_y={0.428718229395848, 0.903438254549634, 0.0},
    animation=false)
    "Frame CS3 of COUPLER (nodeID 51:-:52::51(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-75})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROCKER_CS2(
    r={0.14, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.0915542066387019, -0.995800094018251, 0.0},
    n_y={0.995800094018251, -0.0915542066387019, 0.0},
    animation=false)
    "Frame CS2 of ROCKER (nodeID 51:-:52::52(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROCKER_CS3(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.0915542066387019, -0.995800094018251, 0.0},
    n_y={0.995800094018251, -0.0915542066387019, 0.0},
    animation=false)
    "Frame CS3 of ROCKER (nodeID 52:-:SIXBAR/RootPart::52(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-125})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS3(r={0.2, 0.0, 0.0}, animation=false)
    "Frame CS3 of RootPart (nodeID 52:-:SIXBAR/RootPart::SIXBAR/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-150})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation COUPLER_CS4(
    r={0.25, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.903438254549634, -0.428718229395848, 0.0},
    n_y={0.428718229395848, 0.903438254549634, 0.0},
    animation=false)
    "Frame CS4 of COUPLER (nodeID 51:-:53::51(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-175})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK5_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.999286182401189, 0.0377773167662379, 0.0},
    n_y={-0.0377773167662379, 0.999286182401189, 0.0},
    animation=false)
    "Frame CS2 of LINK5 (nodeID 51:-:53::53(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK5_CS3(
    r={0.15, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.999286182401189, 0.0377773167662379, 0.0},
    n_y={-0.0377773167662379, 0.999286182401189, 0.0},
    animation=false)
    "Frame CS3 of LINK5 (nodeID 53:-:54::53(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-225})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK6_CS2(
    r={0.12, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0940136141978183, -0.995570911761419, 0.0},
    n_y={0.995570911761419, 0.0940136141978183, 0.0},
    animation=false)
    "Frame CS2 of LINK6 (nodeID 53:-:54::54(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-250})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK6_CS3(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0940136141978183, -0.995570911761419, 0.0},
    n_y={0.995570911761419, 0.0940136141978183, 0.0},
    animation=false)
    "Frame CS3 of LINK6 (nodeID 54:-:SIXBAR/RootPart::54(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-275})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS4(r={0.38, 0.04, 0.0}, animation=false)
    "Frame CS4 of RootPart (nodeID 54:-:SIXBAR/RootPart::SIXBAR/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-300})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  SIXBAR.Components.Revolute RootPart_CRANK(
    n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--CRANK (nodeID 50:-:SIXBAR/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));
  SIXBAR.Components.Revolute CRANK_COUPLER(
    n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674},
    phi(start=0.0),
    w(start=0))
    "Joint CRANK--COUPLER (nodeID 50:-:51)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-25})));
  SIXBAR.Components.Revolute COUPLER_ROCKER(
    n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674},
    phi(start=0.0),
    w(start=0))
    "Joint COUPLER--ROCKER (nodeID 51:-:52)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-50})));
  SIXBAR.Components.Revolute COUPLER_LINK5(
    n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674},
    phi(start=0.0),
    w(start=0))
    "Joint COUPLER--LINK5 (nodeID 51:-:53)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-75})));
  SIXBAR.Components.Revolute LINK5_LINK6(
    n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674},
    phi(start=0.0),
    w(start=0))
    "Joint LINK5--LINK6 (nodeID 53:-:54)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-100})));
  Modelica.Mechanics.MultiBody.Joints.RevolutePlanarLoopConstraint ROCKER_RootPart(n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674}, animation=false)
    "Joint ROCKER--RootPart (nodeID 52:-:SIXBAR/RootPart): closes a planar loop" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-125})));
  Modelica.Mechanics.MultiBody.Joints.RevolutePlanarLoopConstraint LINK6_RootPart(n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674}, animation=false)
    "Joint LINK6--RootPart (nodeID 54:-:SIXBAR/RootPart): closes a planar loop" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-150})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape CRANK_shape(
    shapeType="modelica://SIXBAR/Resources/Shapes/CRANK.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of CRANK" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,0})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape COUPLER_shape(
    shapeType="modelica://SIXBAR/Resources/Shapes/COUPLER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of COUPLER" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-25})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape ROCKER_shape(
    shapeType="modelica://SIXBAR/Resources/Shapes/ROCKER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of ROCKER" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-50})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape LINK5_shape(
    shapeType="modelica://SIXBAR/Resources/Shapes/LINK5.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of LINK5" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-75})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape LINK6_shape(
    shapeType="modelica://SIXBAR/Resources/Shapes/LINK6.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of LINK6" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-100})));
equation
  connect(CRANK.frame_a, CRANK_CS2.frame_a);
  connect(CRANK.frame_a, CRANK_CS3.frame_a);
  connect(COUPLER.frame_a, COUPLER_CS2.frame_a);
  connect(COUPLER.frame_a, COUPLER_CS3.frame_a);
  connect(ROCKER.frame_a, ROCKER_CS2.frame_a);
  connect(ROCKER.frame_a, ROCKER_CS3.frame_a);
  connect(RootPart.frame_a, RootPart_CS3.frame_a);
  connect(COUPLER.frame_a, COUPLER_CS4.frame_a);
  connect(LINK5.frame_a, LINK5_CS2.frame_a);
  connect(LINK5.frame_a, LINK5_CS3.frame_a);
  connect(LINK6.frame_a, LINK6_CS2.frame_a);
  connect(LINK6.frame_a, LINK6_CS3.frame_a);
  connect(RootPart.frame_a, RootPart_CS4.frame_a);
  connect(world.frame_b, RootPart.frame_a);
  connect(RootPart.frame_a, RootPart_CRANK.frame_a);
  connect(RootPart_CRANK.frame_b, CRANK_CS2.frame_b);
  connect(CRANK_CS3.frame_b, CRANK_COUPLER.frame_a);
  connect(CRANK_COUPLER.frame_b, COUPLER_CS2.frame_b);
  connect(COUPLER_CS3.frame_b, COUPLER_ROCKER.frame_a);
  connect(COUPLER_ROCKER.frame_b, ROCKER_CS2.frame_b);
  connect(COUPLER_CS4.frame_b, COUPLER_LINK5.frame_a);
  connect(COUPLER_LINK5.frame_b, LINK5_CS2.frame_b);
  connect(LINK5_CS3.frame_b, LINK5_LINK6.frame_a);
  connect(LINK5_LINK6.frame_b, LINK6_CS2.frame_b);
  connect(ROCKER_CS3.frame_b, ROCKER_RootPart.frame_a);
  connect(ROCKER_RootPart.frame_b, RootPart_CS3.frame_b);
  connect(LINK6_CS3.frame_b, LINK6_RootPart.frame_a);
  connect(LINK6_RootPart.frame_b, RootPart_CS4.frame_b);
  connect(CRANK.frame_a, CRANK_shape.frame_a);
  connect(COUPLER.frame_a, COUPLER_shape.frame_a);
  connect(ROCKER.frame_a, ROCKER_shape.frame_a);
  connect(LINK5.frame_a, LINK5_shape.frame_a);
  connect(LINK6.frame_a, LINK6_shape.frame_a);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>SIXBAR.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Joint ROCKER--RootPart closes a loop: a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations.</li><li>Joint LINK6--RootPart closes a loop: a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations.</li></ul>
</html>"));
end Mechanics;

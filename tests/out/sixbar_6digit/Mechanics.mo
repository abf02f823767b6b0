within SIXBAR;
model Mechanics "Mechanical model of SIXBAR (6 bodies, 8 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID SIXBAR/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body CRANK(
    m=0.0279072,
    r_CM={0.03, -0.000499999999999994, 0.0},
    I_11=8.20936999999999e-7, I_22=1.35815e-5, I_33=1.41048e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part CRANK (nodeID 50)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body COUPLER(
    m=0.0976752,
    r_CM={0.125, -0.000500000000000007, 0.0},
    I_11=2.87328e-6, I_22=0.000576446, I_33=0.000578278,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part COUPLER (nodeID 51)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));
  Modelica.Mechanics.MultiBody.Parts.Body ROCKER(
    m=0.0539136,
    r_CM={0.07, 0.0, 0.0},
    I_11=1.4377e-6, I_22=0.000109624, I_33=0.000110487,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part ROCKER (nodeID 52)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,0})));
  Modelica.Mechanics.MultiBody.Parts.Body LINK5(
    m=0.0573696,
    r_CM={0.075, 0.0, 0.0},
    I_11=1.52986e-6, I_22=0.000132046, I_33=0.000132964,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part LINK5 (nodeID 53)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,-200})));
  Modelica.Mechanics.MultiBody.Parts.Body LINK6(
    m=0.0470016,
    r_CM={0.06, 0.0, 0.0},
    I_11=1.25338e-6, I_22=7.26958e-5, I_33=7.34478e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part LINK6 (nodeID 54)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1700,-200})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.258819045102521, -0.965925826289068, 0.0},
    n_y={0.965925826289068, 0.258819045102521, 0.0},
    animation=false)
    "Frame CS2 of CRANK (nodeID 50:-:SIXBAR/RootPart::50(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={660,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS3(
    r={0.06, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.258819045102521, -0.965925826289068, 0.0},
    n_y={0.965925826289068, 0.258819045102521, 0.0},
    animation=false)
    "Frame CS3 of CRANK (nodeID 50:-:51::50(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation COUPLER_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.903438254549634, -0.428718229395848, 0.0},
    n_y={0.428718229395848, 0.903438254549634, 0.0},
    animation=false)
    "Frame CS2 of COUPLER (nodeID 50:-:51::51(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={980,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation COUPLER_CS3(
    r={0.19, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.903438254549634, -0.428718229395848, 0.0},
    n_y={0.428718229395848, 0.903438254549634, 0.0},
    animation=false)
    "Frame CS3 of COUPLER (nodeID 51:-:52::51(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROCKER_CS2(
    r={0.14, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.0915542066387019, -0.995800094018251, 0.0},
    n_y={0.995800094018251, -0.0915542066387019, 0.0},
    animation=false)
    "Frame CS2 of ROCKER (nodeID 51:-:52::52(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1300,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROCKER_CS3(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.0915542066387019, -0.995800094018251, 0.0},
    n_y={0.995800094018251, -0.0915542066387019, 0.0},
    animation=false)
    "Frame CS3 of ROCKER (nodeID 52:-:SIXBAR/RootPart::52(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1300,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS3(r={0.2, 0.0, 0.0}, animation=false)
    "Frame CS3 of RootPart (nodeID 52:-:SIXBAR/RootPart::SIXBAR/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation COUPLER_CS4(
    r={0.25, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.903438254549634, -0.428718229395848, 0.0},
    n_y={0.428718229395848, 0.903438254549634, 0.0},
    animation=false)
    "Frame CS4 of COUPLER (nodeID 51:-:53::51(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-300})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK5_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.999286182401189, 0.0377773167662379, 0.0},
    n_y={-0.0377773167662379, 0.999286182401189, 0.0},
    animation=false)
    "Frame CS2 of LINK5 (nodeID 51:-:53::53(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1300,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK5_CS3(
    r={0.15, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.999286182401189, 0.0377773167662379, 0.0},
    n_y={-0.0377773167662379, 0.999286182401189, 0.0},
    animation=false)
    "Frame CS3 of LINK5 (nodeID 53:-:54::53(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1380,-400})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK6_CS2(
    r={0.12, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0940136141978183, -0.995570911761419, 0.0},
    n_y={0.995570911761419, 0.0940136141978183, 0.0},
    animation=false)
    "Frame CS2 of LINK6 (nodeID 53:-:54::54(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1620,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK6_CS3(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0940136141978183, -0.995570911761419, 0.0},
    n_y={0.995570911761419, 0.0940136141978183, 0.0},
    animation=false)
    "Frame CS3 of LINK6 (nodeID 54:-:SIXBAR/RootPart::54(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1620,-300})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS4(r={0.38, 0.04, 0.0}, animation=false)
    "Frame CS4 of RootPart (nodeID 54:-:SIXBAR/RootPart::SIXBAR/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-200})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  SIXBAR.Components.Revolute RootPart_CRANK(
    n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--CRANK (nodeID 50:-:SIXBAR/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={500,0})));
  SIXBAR.Components.Revolute CRANK_COUPLER(
    n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674},
    phi(start=0.0),
    w(start=0))
    "Joint CRANK--COUPLER (nodeID 50:-:51)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={820,0})));
  SIXBAR.Components.Revolute COUPLER_ROCKER(
    n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674},
    phi(start=0.0),
    w(start=0))
    "Joint COUPLER--ROCKER (nodeID 51:-:52)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1140,0})));
  SIXBAR.Components.Revolute COUPLER_LINK5(
    n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674},
    phi(start=0.0),
    w(start=0))
    "Joint COUPLER--LINK5 (nodeID 51:-:53)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1140,-200})));
  SIXBAR.Components.Revolute LINK5_LINK6(
    n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674},
    phi(start=0.0),
    w(start=0))
    "Joint LINK5--LINK6 (nodeID 53:-:54)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1460,-200})));
  Modelica.Mechanics.MultiBody.Joints.RevolutePlanarLoopConstraint ROCKER_RootPart(n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674}, animation=false)
    "Joint ROCKER--RootPart (nodeID 52:-:SIXBAR/RootPart): closes a planar loop" annotation (Placement(transformation(extent={{15,-15},{-15,15}}, origin={1220,-100})));
  Modelica.Mechanics.MultiBody.Joints.RevolutePlanarLoopConstraint LINK6_RootPart(n={4.62499999999907e-7, 6.62499999997299e-7, 0.999999999999674}, animation=false)
    "Joint LINK6--RootPart (nodeID 54:-:SIXBAR/RootPart): closes a planar loop" annotation (Placement(transformation(extent={{15,-15},{-15,15}}, origin={1540,-300})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape CRANK_shape(
    shapeType="modelica://SIXBAR/Resources/Shapes/CRANK.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of CRANK" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape COUPLER_shape(
    shapeType="modelica://SIXBAR/Resources/Shapes/COUPLER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of COUPLER" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape ROCKER_shape(
    shapeType="modelica://SIXBAR/Resources/Shapes/ROCKER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of ROCKER" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1380,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape LINK5_shape(
    shapeType="modelica://SIXBAR/Resources/Shapes/LINK5.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of LINK5" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1380,-300})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape LINK6_shape(
    shapeType="modelica://SIXBAR/Resources/Shapes/LINK6.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of LINK6" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1700,-300})));
equation
  connect(CRANK.frame_a, CRANK_CS2.frame_a)
    annotation (Line(points={{725,0},{670,0}}, color={95,95,95}, thickness=0.5));
  connect(CRANK.frame_a, CRANK_CS3.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-200},{730,-200}}, color={95,95,95}, thickness=0.5));
  connect(COUPLER.frame_a, COUPLER_CS2.frame_a)
    annotation (Line(points={{1045,0},{990,0}}, color={95,95,95}, thickness=0.5));
  connect(COUPLER.frame_a, COUPLER_CS3.frame_a)
    annotation (Line(points={{1045,0},{1040,0},{1040,-200},{1050,-200}}, color={95,95,95}, thickness=0.5));
  connect(ROCKER.frame_a, ROCKER_CS2.frame_a)
    annotation (Line(points={{1365,0},{1310,0}}, color={95,95,95}, thickness=0.5));
  connect(ROCKER.frame_a, ROCKER_CS3.frame_a)
    annotation (Line(points={{1365,0},{1360,0},{1360,-100},{1310,-100}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CS3.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
  connect(COUPLER.frame_a, COUPLER_CS4.frame_a)
    annotation (Line(points={{1045,0},{1035,0},{1035,-300},{1050,-300}}, color={95,95,95}, thickness=0.5));
  connect(LINK5.frame_a, LINK5_CS2.frame_a)
    annotation (Line(points={{1365,-200},{1310,-200}}, color={95,95,95}, thickness=0.5));
  connect(LINK5.frame_a, LINK5_CS3.frame_a)
    annotation (Line(points={{1365,-200},{1360,-200},{1360,-400},{1370,-400}}, color={95,95,95}, thickness=0.5));
  connect(LINK6.frame_a, LINK6_CS2.frame_a)
    annotation (Line(points={{1685,-200},{1630,-200}}, color={95,95,95}, thickness=0.5));
  connect(LINK6.frame_a, LINK6_CS3.frame_a)
    annotation (Line(points={{1685,-200},{1680,-200},{1680,-300},{1630,-300}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CS4.frame_a)
    annotation (Line(points={{405,0},{395,0},{395,-200},{410,-200}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, RootPart.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CRANK.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,25},{480,25},{480,0},{485,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CRANK.frame_b, CRANK_CS2.frame_b)
    annotation (Line(points={{515,0},{650,0}}, color={95,95,95}, thickness=0.5));
  connect(CRANK_CS3.frame_b, CRANK_COUPLER.frame_a)
    annotation (Line(points={{750,-200},{800,-200},{800,0},{805,0}}, color={95,95,95}, thickness=0.5));
  connect(CRANK_COUPLER.frame_b, COUPLER_CS2.frame_b)
    annotation (Line(points={{835,0},{970,0}}, color={95,95,95}, thickness=0.5));
  connect(COUPLER_CS3.frame_b, COUPLER_ROCKER.frame_a)
    annotation (Line(points={{1070,-200},{1120,-200},{1120,0},{1125,0}}, color={95,95,95}, thickness=0.5));
  connect(COUPLER_ROCKER.frame_b, ROCKER_CS2.frame_b)
    annotation (Line(points={{1155,0},{1290,0}}, color={95,95,95}, thickness=0.5));
  connect(COUPLER_CS4.frame_b, COUPLER_LINK5.frame_a)
    annotation (Line(points={{1070,-300},{1120,-300},{1120,-200},{1125,-200}}, color={95,95,95}, thickness=0.5));
  connect(COUPLER_LINK5.frame_b, LINK5_CS2.frame_b)
    annotation (Line(points={{1155,-200},{1290,-200}}, color={95,95,95}, thickness=0.5));
  connect(LINK5_CS3.frame_b, LINK5_LINK6.frame_a)
    annotation (Line(points={{1390,-400},{1445,-400},{1445,-200},{1450,-200}}, color={95,95,95}, thickness=0.5));
  connect(LINK5_LINK6.frame_b, LINK6_CS2.frame_b)
    annotation (Line(points={{1470,-200},{1610,-200}}, color={95,95,95}, thickness=0.5));
  connect(ROCKER_CS3.frame_b, ROCKER_RootPart.frame_a)
    annotation (Line(points={{1290,-100},{1235,-100}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(ROCKER_RootPart.frame_b, RootPart_CS3.frame_b)
    annotation (Line(points={{1205,-100},{1080,-100},{1080,-120},{435,-120},{435,-100},{430,-100}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(LINK6_CS3.frame_b, LINK6_RootPart.frame_a)
    annotation (Line(points={{1610,-300},{1555,-300}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(LINK6_RootPart.frame_b, RootPart_CS4.frame_b)
    annotation (Line(points={{1525,-300},{1395,-300},{1395,-220},{435,-220},{435,-200},{430,-200}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(CRANK.frame_a, CRANK_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  connect(COUPLER.frame_a, COUPLER_shape.frame_a)
    annotation (Line(points={{1045,0},{1030,0},{1030,-100},{1045,-100}}, color={95,95,95}, thickness=0.5));
  connect(ROCKER.frame_a, ROCKER_shape.frame_a)
    annotation (Line(points={{1365,0},{1355,0},{1355,-100},{1370,-100}}, color={95,95,95}, thickness=0.5));
  connect(LINK5.frame_a, LINK5_shape.frame_a)
    annotation (Line(points={{1365,-200},{1355,-200},{1355,-300},{1370,-300}}, color={95,95,95}, thickness=0.5));
  connect(LINK6.frame_a, LINK6_shape.frame_a)
    annotation (Line(points={{1685,-200},{1675,-200},{1675,-300},{1690,-300}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-460},{1760,80}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>SIXBAR.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Joint ROCKER--RootPart closes a loop: a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations.</li><li>Joint LINK6--RootPart closes a loop: a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations.</li></ul>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.398 m, period 1.27 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

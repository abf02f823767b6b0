within FOURBAR;
model Mechanics "Mechanical model of FOURBAR (4 bodies, 5 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID FOURBAR/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body CRANK(
    m=0.10048,
    r_CM={0.03, 0.0, 0.0},
    I_11=3.88523e-6, I_22=5.41252e-5, I_33=5.69387e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part CRANK (nodeID 40)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body COUPLER(
    m=0.2512,
    r_CM={0.09, 0.0, 0.0},
    I_11=9.71307e-6, I_22=0.000838673, I_33=0.000845707,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part COUPLER (nodeID 41)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));
  Modelica.Mechanics.MultiBody.Parts.Body ROCKER(
    m=0.21352,
    r_CM={0.075, 0.0, 0.0},
    I_11=8.25611e-6, I_22=0.000515366, I_33=0.000521345,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part ROCKER (nodeID 45)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS2(r={0.02, 0.01, 0.0}, animation=false)
    "Frame CS2 of RootPart (nodeID 40:-:FOURBAR/RootPart::FOURBAR/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.342020143325669, -0.939692620785908, 0.0},
    n_y={0.939692620785908, 0.342020143325669, 0.0},
    animation=false)
    "Frame CS2 of CRANK (nodeID 40:-:FOURBAR/RootPart::40(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={660,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS3(
    r={0.06, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.342020143325669, -0.939692620785908, 0.0},
    n_y={0.939692620785908, 0.342020143325669, 0.0},
    animation=false)
    "Frame CS3 of CRANK (nodeID 40:-:41::40(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation COUPLER_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.860834363403597, -0.508885251096477, 0.0},
    n_y={0.508885251096477, 0.860834363403597, 0.0},
    animation=false)
    "Frame CS2 of COUPLER (nodeID 40:-:41::41(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={980,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation COUPLER_CS3(
    r={0.18, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.860834363403597, -0.508885251096477, 0.0},
    n_y={0.508885251096477, 0.860834363403597, 0.0},
    animation=false)
    "Frame CS3 of COUPLER (nodeID 41:-:45::41(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROCKER_CS2(
    r={0.15, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.16352403991875, -0.986539349630136, 0.0},
    n_y={0.986539349630136, -0.16352403991875, 0.0},
    animation=false)
    "Frame CS2 of ROCKER (nodeID 41:-:45::45(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1300,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS3(r={0.22, 0.01, 0.0}, animation=false)
    "Frame CS3 of RootPart (nodeID 45:-:FOURBAR/RootPart::FOURBAR/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROCKER_CS3(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.16352403991875, -0.986539349630136, 0.0},
    n_y={0.986539349630136, -0.16352403991875, 0.0},
    animation=false)
    "Frame CS3 of ROCKER (nodeID 45:-:FOURBAR/RootPart::45(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1300,-100})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  FOURBAR.Components.Revolute RootPart_CRANK(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--CRANK (nodeID 40:-:FOURBAR/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={500,0})));
  FOURBAR.Components.Revolute CRANK_COUPLER(
    n={0.0, 0.0, 1.0},
    phi(start=0.0),
    w(start=0))
    "Joint CRANK--COUPLER (nodeID 40:-:41)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={820,0})));
  FOURBAR.Components.Revolute COUPLER_ROCKER(
    n={0.0, 0.0, 1.0},
    phi(start=0.0),
    w(start=0))
    "Joint COUPLER--ROCKER (nodeID 41:-:45)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1140,0})));
  Modelica.Mechanics.MultiBody.Joints.RevolutePlanarLoopConstraint RootPart_ROCKER(n={0.0, 0.0, -1.0}, animation=false)
    "Joint RootPart--ROCKER (nodeID 45:-:FOURBAR/RootPart): closes a planar loop" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1140,-100})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape CRANK_shape(
    shapeType="modelica://FOURBAR/Resources/Shapes/CRANK.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of CRANK" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape COUPLER_shape(
    shapeType="modelica://FOURBAR/Resources/Shapes/COUPLER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of COUPLER" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape ROCKER_shape(
    shapeType="modelica://FOURBAR/Resources/Shapes/ROCKER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of ROCKER" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1380,-100})));
equation
  connect(RootPart.frame_a, RootPart_CS2.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
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
  connect(RootPart.frame_a, RootPart_CS3.frame_a)
    annotation (Line(points={{405,0},{395,0},{395,-200},{410,-200}}, color={95,95,95}, thickness=0.5));
  connect(ROCKER.frame_a, ROCKER_CS3.frame_a)
    annotation (Line(points={{1365,0},{1360,0},{1360,-100},{1310,-100}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, RootPart.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CS2.frame_b, RootPart_CRANK.frame_a)
    annotation (Line(points={{430,-100},{480,-100},{480,0},{485,0}}, color={95,95,95}, thickness=0.5));
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
  connect(RootPart_CS3.frame_b, RootPart_ROCKER.frame_a)
    annotation (Line(points={{430,-200},{715,-200},{715,-115},{1035,-115},{1035,-120},{1115,-120},{1115,-100},{1125,-100}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(RootPart_ROCKER.frame_b, ROCKER_CS3.frame_b)
    annotation (Line(points={{1155,-100},{1290,-100}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(CRANK.frame_a, CRANK_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  connect(COUPLER.frame_a, COUPLER_shape.frame_a)
    annotation (Line(points={{1045,0},{1035,0},{1035,-100},{1045,-100}}, color={95,95,95}, thickness=0.5));
  connect(ROCKER.frame_a, ROCKER_shape.frame_a)
    annotation (Line(points={{1365,0},{1355,0},{1355,-100},{1370,-100}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=3.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-260},{1440,60}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>FOURBAR.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Joint RootPart--ROCKER closes a loop: a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations.</li></ul>
<p>Experiment: 3.0 s, about three swings of a pendulum as long as the mechanism's reach (0.224 m, period 0.95 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

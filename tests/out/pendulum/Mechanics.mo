within PENDULUM;
model Mechanics "Mechanical model of PENDULUM (2 bodies, 2 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.5, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID PENDULUM/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body LINK(
    m=0.2673,
    r_CM={0.15, 0.0, 0.0},
    I_11=2.2275e-5, I_22=0.00242798, I_33=0.0024458,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part LINK (nodeID 23)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootGround(r={0.0, 0.5, 0.0}, animation=false)
    "Ground RootGround (nodeID RootGround) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={100,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS2(r={0.0, 0.45, 0.0}, animation=false)
    "Frame CS2 of RootPart (nodeID 23:-:PENDULUM/RootPart::PENDULUM/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.5, 0.866025403784439, 0.0},
    n_y={-0.866025403784439, 0.5, 0.0},
    animation=false)
    "Frame CS2 of LINK (nodeID 23:-:PENDULUM/RootPart::23(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={660,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS3(r={0.0, 0.5, 0.0}, animation=false)
    "Frame CS3 of RootPart (nodeID PENDULUM/RootPart:-:RootGround::PENDULUM/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={340,0})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  PENDULUM.Components.Revolute RootPart_LINK(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--LINK (nodeID 23:-:PENDULUM/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={500,0})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape LINK_shape(
    shapeType="modelica://PENDULUM/Resources/Shapes/LINK.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of LINK" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
equation
  connect(world.frame_b, RootGround.frame_a)
    annotation (Line(points={{30,0},{90,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CS2.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
  connect(LINK.frame_a, LINK_CS2.frame_a)
    annotation (Line(points={{725,0},{670,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CS3.frame_a)
    annotation (Line(points={{405,0},{350,0}}, color={95,95,95}, thickness=0.5));
  connect(RootGround.frame_b, RootPart_CS3.frame_b)
    annotation (Line(points={{110,0},{330,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CS2.frame_b, RootPart_LINK.frame_a)
    annotation (Line(points={{430,-100},{480,-100},{480,0},{485,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_LINK.frame_b, LINK_CS2.frame_b)
    annotation (Line(points={{515,0},{650,0}}, color={95,95,95}, thickness=0.5));
  connect(LINK.frame_a, LINK_shape.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-160},{800,60}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>PENDULUM.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 4.8 from Pro/E Wildfire Creo 7.0 - 2020454 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.329 m, period 1.15 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

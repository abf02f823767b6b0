within CHAIN_IN;
model Mechanics "Mechanical model of CHAIN_IN (3 bodies, 3 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.508, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body LINK1(
    m=0.28759298472058,
    r_CM={0.1524, 0.0, 0.0},
    I_11=1.93274444386622e-5, I_22=0.00261693595358369, I_33=0.00262853326304909,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part LINK1 (nodeID 39)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body LINK2(
    m=0.19910301003439,
    r_CM={0.1016, 0.0, 0.0},
    I_11=1.33805384575354e-5, I_22=0.000869736755577719, I_33=0.000877763861271282,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part LINK2 (nodeID 40)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootGround(r={0.0, 0.508, 0.0}, animation=false)
    "Ground RootGround (nodeID RootGround) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={100,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS2(r={0.0508, 0.4572, 0.0}, animation=false)
    "Frame CS2 of RootPart (nodeID 39:-:RootPart::RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK1_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.342020143325669, 0.939692620785908, 0.0},
    n_y={-0.939692620785908, 0.342020143325669, 0.0},
    animation=false)
    "Frame CS2 of LINK1 (nodeID 39:-:RootPart::39(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={660,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK1_CS3(
    r={0.3048, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.342020143325669, 0.939692620785908, 0.0},
    n_y={-0.939692620785908, 0.342020143325669, 0.0},
    animation=false)
    "Frame CS3 of LINK1 (nodeID 39:-:40::39(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK2_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.5, 0.866025403784439, 0.0},
    n_y={-0.866025403784439, -0.5, 0.0},
    animation=false)
    "Frame CS2 of LINK2 (nodeID 39:-:40::40(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={980,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS3(r={0.0, 0.508, 0.0}, animation=false)
    "Frame CS3 of RootPart (nodeID RootGround:-:RootPart::RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={340,0})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  CHAIN_IN.Components.Revolute RootPart_LINK1(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--LINK1 (nodeID 39:-:RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={500,0})));
  CHAIN_IN.Components.Revolute LINK1_LINK2(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint LINK1--LINK2 (nodeID 39:-:40)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={820,0})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape LINK1_shape(
    shapeType="modelica://CHAIN_IN/Resources/Shapes/LINK1.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of LINK1" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape LINK2_shape(
    shapeType="modelica://CHAIN_IN/Resources/Shapes/LINK2.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of LINK2" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-100})));
equation
  connect(world.frame_b, RootGround.frame_a)
    annotation (Line(points={{30,0},{90,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CS2.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
  connect(LINK1.frame_a, LINK1_CS2.frame_a)
    annotation (Line(points={{725,0},{670,0}}, color={95,95,95}, thickness=0.5));
  connect(LINK1.frame_a, LINK1_CS3.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-200},{730,-200}}, color={95,95,95}, thickness=0.5));
  connect(LINK2.frame_a, LINK2_CS2.frame_a)
    annotation (Line(points={{1045,0},{990,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CS3.frame_a)
    annotation (Line(points={{405,0},{350,0}}, color={95,95,95}, thickness=0.5));
  connect(RootGround.frame_b, RootPart_CS3.frame_b)
    annotation (Line(points={{110,0},{330,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CS2.frame_b, RootPart_LINK1.frame_a)
    annotation (Line(points={{430,-100},{480,-100},{480,0},{485,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_LINK1.frame_b, LINK1_CS2.frame_b)
    annotation (Line(points={{515,0},{650,0}}, color={95,95,95}, thickness=0.5));
  connect(LINK1_CS3.frame_b, LINK1_LINK2.frame_a)
    annotation (Line(points={{750,-200},{805,-200},{805,0},{810,0}}, color={95,95,95}, thickness=0.5));
  connect(LINK1_LINK2.frame_b, LINK2_CS2.frame_b)
    annotation (Line(points={{830,0},{970,0}}, color={95,95,95}, thickness=0.5));
  connect(LINK1.frame_a, LINK1_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  connect(LINK2.frame_a, LINK2_shape.frame_a)
    annotation (Line(points={{1045,0},{1040,0},{1040,-100},{1050,-100}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-260},{1120,60}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>CHAIN_IN.xml</code> (SimMechanics), exported by SimMechanics Link Version 3.1 from Pro/E Wildfire Wildfire 4.0 - 2008230 on 11/10/09||14:08:16 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.33 m, period 1.15 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

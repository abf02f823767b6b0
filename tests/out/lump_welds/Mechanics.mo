within LumpedArm;
model Mechanics "Mechanical model of LUMP (3 bodies, 3 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, 0.0, -1.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID LUMP/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body UPPER_A(
    m=0.818251,
    r_CM={0.164824974243844, -0.000135288560600577, 0.0},
    I_11=7.16734735563415e-5, I_22=0.00429287340868633, I_33=0.00429248478224267,
    I_21=-1.04971246487923e-5, I_31=0.0, I_32=0.0,
    animation=false)
    "Part UPPER_A (nodeID 302)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body FORE(
    m=0.19008,
    r_CM={0.1, 0.0, 0.0},
    I_11=1.0391e-5, I_22=0.000770711, I_33=0.000772992000000001,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part FORE (nodeID 304)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS2(r={0.0, 0.0, 0.3}, animation=false)
    "Frame CS2 of RootPart (nodeID 302:-:LUMP/RootPart::LUMP/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation UPPER_A_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0, 0.0, 1.0},
    n_y={0.928476690885259, 0.371390676354104, 0.0},
    animation=false)
    "Frame CS2 of UPPER_A (nodeID 302:-:LUMP/RootPart::302(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={660,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation UPPER_A_CS3(
    r={0.26, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0, 0.0, 1.0},
    n_y={0.928476690885259, 0.371390676354104, 0.0},
    animation=false)
    "Frame CS3 of UPPER_A (nodeID 303:-:304::303(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation FORE_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0, 0.0, 1.0},
    n_y={0.287347885566345, 0.957826285221152, 0.0},
    animation=false)
    "Frame CS2 of FORE (nodeID 303:-:304::304(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={980,0})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  LumpedArm.Components.Revolute RootPart_UPPER_A(
    n={1.0, 0.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--UPPER_A (nodeID 302:-:LUMP/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={500,0})));
  LumpedArm.Components.Revolute UPPER_B_FORE(
    n={1.0, 0.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint UPPER_B--FORE (nodeID 303:-:304)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={820,0})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape UPPER_A_shape(
    shapeType="modelica://LumpedArm/Resources/Shapes/UPPER_A.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of UPPER_A" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape FORE_shape(
    shapeType="modelica://LumpedArm/Resources/Shapes/FORE.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of FORE" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-100})));
equation
  connect(RootPart.frame_a, RootPart_CS2.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
  connect(UPPER_A.frame_a, UPPER_A_CS2.frame_a)
    annotation (Line(points={{725,0},{670,0}}, color={95,95,95}, thickness=0.5));
  connect(UPPER_A.frame_a, UPPER_A_CS3.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-200},{730,-200}}, color={95,95,95}, thickness=0.5));
  connect(FORE.frame_a, FORE_CS2.frame_a)
    annotation (Line(points={{1045,0},{990,0}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, RootPart.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CS2.frame_b, RootPart_UPPER_A.frame_a)
    annotation (Line(points={{430,-100},{480,-100},{480,0},{485,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_UPPER_A.frame_b, UPPER_A_CS2.frame_b)
    annotation (Line(points={{515,0},{650,0}}, color={95,95,95}, thickness=0.5));
  connect(UPPER_A_CS3.frame_b, UPPER_B_FORE.frame_a)
    annotation (Line(points={{750,-200},{805,-200},{805,0},{810,0}}, color={95,95,95}, thickness=0.5));
  connect(UPPER_B_FORE.frame_b, FORE_CS2.frame_b)
    annotation (Line(points={{830,0},{970,0}}, color={95,95,95}, thickness=0.5));
  connect(UPPER_A.frame_a, UPPER_A_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{725,-100}}, color={95,95,95}, thickness=0.5));
  connect(FORE.frame_a, FORE_shape.frame_a)
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
<p>Converted by cad2mo 0.1.0 from <code>LUMP.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 3.0 - 2014140 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.291 m, period 1.08 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

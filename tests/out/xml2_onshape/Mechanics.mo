within slide_arm;
model Mechanics "Mechanical model of slide arm (5 bodies, 5 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, 0.0, -1.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body Base_1(
    m=2.0,
    r_CM={0.0, 0.0, 0.025},
    I_11=0.00708333333333333, I_22=0.00708333333333333, I_33=0.0133333333333333,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part Base <1> (nodeID MBase1)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body Link_1(
    m=0.5,
    r_CM={0.15, 0.0, 0.0},
    I_11=8.33333333333333e-5, I_22=0.00376666666666667, I_33=0.00381666666666667,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part Link Ä <1> (nodeID MLink1)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body Rail_1(
    m=0.3,
    r_CM={0.1, 0.0, 0.01},
    I_11=3.25e-5, I_22=0.00101, I_33=0.0010225,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part Rail <1> (nodeID MSub1|MRail1)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));
  Modelica.Mechanics.MultiBody.Parts.Body Carriage_1(
    m=0.2,
    r_CM={0.0, 0.0, 0.03},
    I_11=3.33333333333333e-5, I_22=3.33333333333333e-5, I_33=5.33333333333333e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part Carriage <1> (nodeID MSub1|MCar1)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,0})));
  Modelica.Mechanics.MultiBody.Parts.Body Tool_gr_n_1(
    m=0.1,
    r_CM={0.01, 0.00200000000000001, 0.03},
    I_11=0.0001, I_22=0.00012, I_33=5e-5,
    I_21=-3e-6, I_31=2e-6, I_32=-1e-6)
    "Part Tool (grün) <1> (nodeID MTool1)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1700,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation Base_1_shoulder_base(r={0.0, 0.0, 0.05}, animation=false)
    "Frame CS3 of Base <1> (nodeID joint:shoulder::base)" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation Link_1_shoulder_follower(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.866025403784439, -0.5, 0.0},
    n_y={0.5, 0.866025403784439, 0.0},
    animation=false)
    "Frame CS2 of Link Ä <1> (nodeID joint:shoulder::follower)" annotation (Placement(transformation(extent={{20,-20},{-20,20}}, origin={660,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation Link_1_Fastened_1_base(r={0.3, 0.0, 0.0}, animation=false)
    "Frame CS3 of Link Ä <1> (nodeID joint:Fastened 1::base)" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation Carriage_1_Fastened_2_base(r={0.0, 0.0, 0.05}, animation=false)
    "Frame CS2 of Carriage <1> (nodeID joint:Fastened 2::base)" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={1380,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation Tool_gr_n_1_Fastened_2_follower(
    r={5.55111512312578e-17, 1.11022302462516e-16, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0, -1.0, 0.0},
    n_y={1.0, 0.0, 0.0},
    animation=false)
    "Frame CS2 of Tool (grün) <1> (nodeID joint:Fastened 2::follower)" annotation (Placement(transformation(extent={{20,-20},{-20,20}}, origin={1620,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation Rail_1_slide_base(
    r={0.0, 0.0, 0.02},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0, 0.0, -1.0},
    n_y={0.0, 1.0, 0.0},
    animation=false)
    "Frame CS3 of Rail <1> (nodeID joint:MSub1|slide::base)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation Carriage_1_slide_follower(
    r={-0.0999999999999999, 0.0, 0.02},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0, 0.0, -1.0},
    n_y={0.0, 1.0, 0.0},
    animation=false)
    "Frame CS3 of Carriage <1> (nodeID joint:MSub1|slide::follower)" annotation (Placement(transformation(extent={{20,-20},{-20,20}}, origin={1300,0})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  slide_arm.Components.Revolute shoulder(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint shoulder (nodeID joint:shoulder)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={500,0})));
  slide_arm.Components.Prismatic slide(
    n={0.0, 0.0, 1.0},
    s(start=0.0, fixed=true),
    v(start=0, fixed=true))
    "Joint slide (nodeID joint:MSub1|slide)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,0})));

  // Shapes: CAD meshes in each body frame, metres
equation
  connect(Base_1.frame_a, Base_1_shoulder_base.frame_a)
    annotation (Line(points={{405,0},{395,0},{395,-100},{400,-100}}, color={95,95,95}, thickness=0.5));
  connect(Link_1.frame_a, Link_1_shoulder_follower.frame_a)
    annotation (Line(points={{725,0},{680,0}}, color={95,95,95}, thickness=0.5));
  connect(Link_1.frame_a, Link_1_Fastened_1_base.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-70},{715,-70},{715,-100},{720,-100}}, color={95,95,95}, thickness=0.5));
  connect(Carriage_1.frame_a, Carriage_1_Fastened_2_base.frame_a)
    annotation (Line(points={{1365,0},{1355,0},{1355,-100},{1360,-100}}, color={95,95,95}, thickness=0.5));
  connect(Tool_gr_n_1.frame_a, Tool_gr_n_1_Fastened_2_follower.frame_a)
    annotation (Line(points={{1685,0},{1640,0}}, color={95,95,95}, thickness=0.5));
  connect(Rail_1.frame_a, Rail_1_slide_base.frame_a)
    annotation (Line(points={{1045,0},{1040,0},{1040,-100},{1045,-100}}, color={95,95,95}, thickness=0.5));
  connect(Carriage_1.frame_a, Carriage_1_slide_follower.frame_a)
    annotation (Line(points={{1365,0},{1320,0}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, Base_1.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(Base_1_shoulder_base.frame_b, shoulder.frame_a)
    annotation (Line(points={{440,-100},{485,-100},{485,0},{490,0}}, color={95,95,95}, thickness=0.5));
  connect(shoulder.frame_b, Link_1_shoulder_follower.frame_b)
    annotation (Line(points={{510,0},{640,0}}, color={95,95,95}, thickness=0.5));
  connect(Link_1_Fastened_1_base.frame_b, Rail_1.frame_a)
    annotation (Line(points={{760,-100},{765,-100},{765,0},{1045,0}}, color={95,95,95}, thickness=0.5));
  connect(Rail_1_slide_base.frame_b, slide.frame_a)
    annotation (Line(points={{1075,-100},{1125,-100},{1125,0},{1130,0}}, color={95,95,95}, thickness=0.5));
  connect(slide.frame_b, Carriage_1_slide_follower.frame_b)
    annotation (Line(points={{1150,0},{1280,0}}, color={95,95,95}, thickness=0.5));
  connect(Carriage_1_Fastened_2_base.frame_b, Tool_gr_n_1_Fastened_2_follower.frame_b)
    annotation (Line(points={{1400,-100},{1595,-100},{1595,0},{1600,0}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-160},{1760,60}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>slide_arm.xml</code> (SimscapeMultibodyImportXML), exported by Simscape Multibody Exporter from Onshape on 11/25/26||00:00:00 by cad2mo tests.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.419 m, period 1.3 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

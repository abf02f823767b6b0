within RELFRAMES;
model Mechanics "Mechanical model of RELFRAMES (4 bodies, 4 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID RELFRAMES/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body CRANK(
    m=0.369117,
    r_CM={0.09, -0.000500000000000021, 0.000500000000000009},
    I_11=4.31252282620984e-5, I_22=0.0013700727717379, I_33=0.00138607,
    I_21=9.39664956752678e-10, I_31=0.0, I_32=0.0,
    animation=false)
    "Part CRANK (nodeID 601)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body ROD(
    m=0.721219,
    r_CM={0.0755, 0.000500000000000028, 0.000500000000000021},
    I_11=6.40681967884917e-5, I_22=0.00186711307666552, I_33=0.00187817272654599,
    I_21=-2.98702527203867e-10, I_31=3.54721060318486e-10, I_32=-2.69857955268902e-9,
    animation=false)
    "Part ROD (nodeID 602)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));
  Modelica.Mechanics.MultiBody.Parts.Body SLIDER(
    m=0.317642,
    r_CM={-0.0055, 0.0245, -0.0175},
    I_11=0.000206097, I_22=0.00010551, I_33=0.000151462,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part SLIDER (nodeID 603)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootPart_CS2(
    r={0.04, -0.02, 0.12},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.965925826289068, 0.258819045102521, 0.0},
    n_y={-0.258819045102521, 0.965925826289068, 0.0},
    animation=false)
    "Frame CS2 of RootPart (nodeID 601:-:RELFRAMES/RootPart::RELFRAMES/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS2(
    r={0.005, -0.003, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.940589061684025, -0.339508872688113, -0.00509336886666348},
    n_y={0.300872337053394, 0.840313947408536, -0.450941577797737},
    animation=false)
    "Frame CS2 of CRANK (nodeID 601:-:RELFRAMES/RootPart::601(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={660,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS3(
    r={0.185, -0.00299999999999998, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.610205666909344, -0.586850406629498, -0.532217666289381},
    n_y={-0.210756974637257, 0.527333210623552, -0.82310460004498},
    animation=false)
    "Frame CS3 of CRANK (nodeID 601:-:602::601(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROD_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.580508250938423, -0.787846791246589, 0.205688123417146},
    n_y={0.282452879041691, -0.042085012893013, -0.958357565218147},
    animation=false)
    "Frame CS2 of ROD (nodeID 601:-:602::602(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={980,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROD_CS3(
    r={0.15, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.384083844066061, -0.923187616275199, -0.0142907621753999},
    n_y={-0.0594302619649119, 0.040165350014049, -0.997424076619886},
    animation=false)
    "Frame CS3 of ROD (nodeID 602:-:603::602(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation SLIDER_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.596635861525891, -0.380064476743202, -0.706807358662298},
    n_y={-0.784083261873079, -0.463737588420331, -0.412505621218146},
    animation=false)
    "Frame CS2 of SLIDER (nodeID 602:-:603::603(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1300,0})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  RELFRAMES.Components.Revolute RootPart_CRANK(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--CRANK (nodeID 601:-:RELFRAMES/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={500,0})));
  RELFRAMES.Components.Revolute CRANK_ROD(
    n={0.0, 0.0, 1.0},
    phi(start=0.436332312998582, fixed=true),
    w(start=0, fixed=true))
    "Joint CRANK--ROD (nodeID 601:-:602)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={820,0})));
  RELFRAMES.Components.Prismatic ROD_SLIDER(
    n={0.0, 0.0, 1.0},
    s(start=0.015, fixed=true),
    v(start=0, fixed=true))
    "Joint ROD--SLIDER (nodeID 602:-:603)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,0})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape CRANK_shape(
    shapeType="modelica://RELFRAMES/Resources/Shapes/CRANK.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of CRANK" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape ROD_shape(
    shapeType="modelica://RELFRAMES/Resources/Shapes/ROD.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of ROD" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape SLIDER_shape(
    shapeType="modelica://RELFRAMES/Resources/Shapes/SLIDER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of SLIDER" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1380,-100})));
equation
  connect(RootPart.frame_a, RootPart_CS2.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
  connect(CRANK.frame_a, CRANK_CS2.frame_a)
    annotation (Line(points={{725,0},{670,0}}, color={95,95,95}, thickness=0.5));
  connect(CRANK.frame_a, CRANK_CS3.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-200},{730,-200}}, color={95,95,95}, thickness=0.5));
  connect(ROD.frame_a, ROD_CS2.frame_a)
    annotation (Line(points={{1045,0},{990,0}}, color={95,95,95}, thickness=0.5));
  connect(ROD.frame_a, ROD_CS3.frame_a)
    annotation (Line(points={{1045,0},{1040,0},{1040,-200},{1050,-200}}, color={95,95,95}, thickness=0.5));
  connect(SLIDER.frame_a, SLIDER_CS2.frame_a)
    annotation (Line(points={{1365,0},{1310,0}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, RootPart.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CS2.frame_b, RootPart_CRANK.frame_a)
    annotation (Line(points={{430,-100},{480,-100},{480,0},{485,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CRANK.frame_b, CRANK_CS2.frame_b)
    annotation (Line(points={{515,0},{650,0}}, color={95,95,95}, thickness=0.5));
  connect(CRANK_CS3.frame_b, CRANK_ROD.frame_a)
    annotation (Line(points={{750,-200},{805,-200},{805,0},{810,0}}, color={95,95,95}, thickness=0.5));
  connect(CRANK_ROD.frame_b, ROD_CS2.frame_b)
    annotation (Line(points={{830,0},{970,0}}, color={95,95,95}, thickness=0.5));
  connect(ROD_CS3.frame_b, ROD_SLIDER.frame_a)
    annotation (Line(points={{1070,-200},{1125,-200},{1125,0},{1130,0}}, color={95,95,95}, thickness=0.5));
  connect(ROD_SLIDER.frame_b, SLIDER_CS2.frame_b)
    annotation (Line(points={{1150,0},{1290,0}}, color={95,95,95}, thickness=0.5));
  connect(CRANK.frame_a, CRANK_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  connect(ROD.frame_a, ROD_shape.frame_a)
    annotation (Line(points={{1045,0},{1035,0},{1035,-100},{1050,-100}}, color={95,95,95}, thickness=0.5));
  connect(SLIDER.frame_a, SLIDER_shape.frame_a)
    annotation (Line(points={{1365,0},{1360,0},{1360,-100},{1370,-100}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
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
<p>Converted by cad2mo 0.1.0 from <code>RELFRAMES.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 5.0 from Pro/E Wildfire Creo 9.0 - 2022073 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.371 m, period 1.22 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

within ARM;
model Mechanics "Mechanical model of ARM (6 bodies, 6 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart_ARM(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID ARM/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body BASE(
    m=3.4992,
    r_CM={0.0, 0.045, 0.0},
    I_11=0.006561, I_22=0.00839808, I_33=0.006561,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part BASE (nodeID 7)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body LINK_UPPER(
    m=0.564473,
    r_CM={0.1255, -0.000500000000000028, 0.0},
    I_11=7.22996e-5, I_22=0.00374137, I_33=0.00375948,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part LINK (nodeID 12/13)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));
  Modelica.Mechanics.MultiBody.Parts.Body RootPart_UPPER(
    m=0.0,
    r_CM={-0.0682074999015086, 0.168207499901509, 0.0802868227941012},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID 12/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,0})));
  Modelica.Mechanics.MultiBody.Parts.Body LINK_FORE(
    m=0.31752,
    r_CM={0.1, 0.000500000000000028, 0.000499999999999976},
    I_11=2.82064e-5, I_22=0.00133933, I_33=0.00134419,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part LINK (nodeID 12/20/21)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,-100})));
  Modelica.Mechanics.MultiBody.Parts.Body RootPart_FORE(
    m=0.0,
    r_CM={-0.205636683943754, 0.164215327706444, 0.160577329265766},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID 12/20/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1700,-100})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation BASE_CS3(
    r={0.0, 0.1, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0, 0.0, -1.0},
    n_y={-0.707106781186547, 0.707106781186547, 0.0},
    animation=false)
    "Frame CS3 of BASE (nodeID 12:12/13:-:7::7(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK_UPPER_CS4(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.642787609686539, -0.766044443118978, 0.0},
    n_y={0.766044443118978, -0.642787609686539, 0.0},
    animation=false)
    "Frame CS4 of LINK (nodeID 12:12/13:-:7::12/13(AUTOGEN))" annotation (Placement(transformation(extent={{15,-15},{-15,15}}, origin={980,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_UPPER_CS2(r={-0.0682074999015086, 0.168207499901509, 0.0802868227941012}, animation=false)
    "Frame CS2 of RootPart (nodeID 12/13:-:12/RootPart::12/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{15,-15},{-15,15}}, origin={1300,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK_UPPER_CS2(
    r={0.1255, -0.000500000000000028, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.541675220419702, 0.454519477672044, 0.707106781186548},
    n_y={0.541675220419702, -0.454519477672044, 0.707106781186548},
    animation=false)
    "Frame CS2 of LINK (nodeID 12/13:-:12/RootPart::12/13(AUTOGEN))" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK_UPPER_CS3(
    r={0.25, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.837541699231533, 0.220281415576432, 0.5},
    n_y={0.483554925508862, 0.127179534580525, -0.866025403784439},
    animation=false)
    "Frame CS3 of LINK (nodeID 12/13:-:12/20:12/20/21::12/13(AUTOGEN))" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,-300})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK_FORE_CS3(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.766044443118978, -0.64278760968654, 0.0},
    n_y={0.64278760968654, -0.766044443118978, 0.0},
    animation=false)
    "Frame CS3 of LINK (nodeID 12/13:-:12/20:12/20/21::12/20/21(AUTOGEN))" annotation (Placement(transformation(extent={{15,-15},{-15,15}}, origin={1300,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_FORE_CS2(r={-0.205636683943754, 0.164215327706444, 0.160577329265766}, animation=false)
    "Frame CS2 of RootPart (nodeID 12/20/21:-:12/20/RootPart::12/20/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{15,-15},{-15,15}}, origin={1620,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation LINK_FORE_CS2(
    r={0.1, 0.000499999999999945, 0.0005},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.707106781186548, 0.408248290463863, 0.577350269189626},
    n_y={-0.707106781186548, -0.408248290463863, -0.577350269189626},
    animation=false)
    "Frame CS2 of LINK (nodeID 12/20/21:-:12/20/RootPart::12/20/21(AUTOGEN))" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,-300})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  ARM.Components.Revolute BASE_LINK(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint BASE--LINK (nodeID 12:12/13:-:7)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={820,0})));
  ARM.Components.Revolute LINK_LINK(
    n={0.0, 0.0, 1.0},
    phi(start=-0.349065850398866, fixed=true),
    w(start=0, fixed=true))
    "Joint LINK--LINK (nodeID 12/13:-:12/20:12/20/21)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,-100})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape BASE_shape(
    shapeType="modelica://ARM/Resources/Shapes/BASE.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of BASE" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape LINK_UPPER_shape(
    shapeType="modelica://ARM/Resources/Shapes/LINK_UPPER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of LINK" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape LINK_FORE_shape(
    shapeType="modelica://ARM/Resources/Shapes/LINK_FORE.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of LINK" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,-200})));
equation
  connect(BASE.frame_a, BASE_CS3.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-200},{730,-200}}, color={95,95,95}, thickness=0.5));
  connect(LINK_UPPER.frame_a, LINK_UPPER_CS4.frame_a)
    annotation (Line(points={{1045,0},{995,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_UPPER.frame_a, RootPart_UPPER_CS2.frame_a)
    annotation (Line(points={{1365,0},{1315,0}}, color={95,95,95}, thickness=0.5));
  connect(LINK_UPPER.frame_a, LINK_UPPER_CS2.frame_a)
    annotation (Line(points={{1045,0},{1040,0},{1040,-200},{1045,-200}}, color={95,95,95}, thickness=0.5));
  connect(LINK_UPPER.frame_a, LINK_UPPER_CS3.frame_a)
    annotation (Line(points={{1045,0},{1035,0},{1035,-300},{1045,-300}}, color={95,95,95}, thickness=0.5));
  connect(LINK_FORE.frame_a, LINK_FORE_CS3.frame_a)
    annotation (Line(points={{1365,-100},{1315,-100}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_FORE.frame_a, RootPart_FORE_CS2.frame_a)
    annotation (Line(points={{1685,-100},{1635,-100}}, color={95,95,95}, thickness=0.5));
  connect(LINK_FORE.frame_a, LINK_FORE_CS2.frame_a)
    annotation (Line(points={{1365,-100},{1360,-100},{1360,-300},{1365,-300}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, RootPart_ARM.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_ARM.frame_a, BASE.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,25},{720,25},{720,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(BASE_CS3.frame_b, BASE_LINK.frame_a)
    annotation (Line(points={{750,-200},{805,-200},{805,0},{810,0}}, color={95,95,95}, thickness=0.5));
  connect(BASE_LINK.frame_b, LINK_UPPER_CS4.frame_b)
    annotation (Line(points={{830,0},{965,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_UPPER_CS2.frame_b, LINK_UPPER_CS2.frame_b)
    annotation (Line(points={{1285,0},{1080,0},{1080,-200},{1075,-200}}, color={95,95,95}, thickness=0.5));
  connect(LINK_UPPER_CS3.frame_b, LINK_LINK.frame_a)
    annotation (Line(points={{1075,-300},{1125,-300},{1125,-100},{1130,-100}}, color={95,95,95}, thickness=0.5));
  connect(LINK_LINK.frame_b, LINK_FORE_CS3.frame_b)
    annotation (Line(points={{1150,-100},{1285,-100}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_FORE_CS2.frame_b, LINK_FORE_CS2.frame_b)
    annotation (Line(points={{1605,-100},{1400,-100},{1400,-300},{1395,-300}}, color={95,95,95}, thickness=0.5));
  connect(BASE.frame_a, BASE_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  connect(LINK_UPPER.frame_a, LINK_UPPER_shape.frame_a)
    annotation (Line(points={{1045,0},{1030,0},{1030,-100},{1045,-100}}, color={95,95,95}, thickness=0.5));
  connect(LINK_FORE.frame_a, LINK_FORE_shape.frame_a)
    annotation (Line(points={{1365,-100},{1355,-100},{1355,-200},{1365,-200}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-360},{1760,80}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>ARM_SIM_MODEL.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.308 m, period 1.11 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

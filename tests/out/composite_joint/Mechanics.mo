within UJ;
model Mechanics "Mechanical model of UJ (4 bodies, 4 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID UJ/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body BASE(
    m=4.86,
    r_CM={0.0, 0.09, 0.0},
    I_11=0.017172, I_22=0.0081, I_33=0.017172,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part BASE (nodeID 201)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body CROSS(
    m=0.864,
    r_CM={0.0, 0.03, 0.02},
    I_11=0.0011808, I_22=0.000576, I_33=0.0008352,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part CROSS (nodeID 202)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1140,0})));
  Modelica.Mechanics.MultiBody.Parts.Body FLOAT(
    m=0.0972,
    r_CM={0.0, 0.0, 0.0},
    I_11=1.053e-5, I_22=3.24e-5, I_33=3.645e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part FLOAT (nodeID 203)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1700,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation BASE_CS3(r={0.0, 0.2, 0.0}, animation=false)
    "Frame CS3 of BASE (nodeID 201:-:202::201(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation CROSS_CS3(r={0.0, 0.06, 0.04}, animation=false)
    "Frame CS3 of CROSS (nodeID 202:-:203::202(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation FLOAT_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.90630778703665, -0.422618261740699, 0.0},
    n_y={0.422618261740699, 0.90630778703665, 0.0},
    animation=false)
    "Frame CS2 of FLOAT (nodeID 202:-:203::203(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1620,0})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  UJ.Components.Revolute BASE_CROSS_1(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint BASE--CROSS (nodeID 201:-:202), primitive 1 of 2" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={820,0})));
  UJ.Components.Revolute BASE_CROSS_2(
    n={0.0, 1.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint BASE--CROSS (nodeID 201:-:202), primitive 2 of 2" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={900,0})));
  UJ.Components.Prismatic CROSS_FLOAT_1(
    n={1.0, 0.0, 0.0},
    s(start=0.01, fixed=true),
    v(start=0, fixed=true))
    "Joint CROSS--FLOAT (nodeID 202:-:203), primitive 1 of 4" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1220,0})));
  UJ.Components.Prismatic CROSS_FLOAT_2(
    n={0.0, 1.0, 0.0},
    s(start=-0.02, fixed=true),
    v(start=0, fixed=true))
    "Joint CROSS--FLOAT (nodeID 202:-:203), primitive 2 of 4" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1300,0})));
  UJ.Components.Prismatic CROSS_FLOAT_3(
    n={0.0, 0.0, 1.0},
    s(start=0.03, fixed=true),
    v(start=0, fixed=true))
    "Joint CROSS--FLOAT (nodeID 202:-:203), primitive 3 of 4" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,0})));
  Modelica.Mechanics.MultiBody.Joints.Spherical CROSS_FLOAT_4(
    enforceStates=true,
    useQuaternions=true,
    angles_fixed=true,
    w_rel_a_fixed=true)
    "Joint CROSS--FLOAT (nodeID 202:-:203), primitive 4 of 4" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1460,0})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape BASE_shape(
    shapeType="modelica://UJ/Resources/Shapes/BASE.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of BASE" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape CROSS_shape(
    shapeType="modelica://UJ/Resources/Shapes/CROSS.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of CROSS" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape FLOAT_shape(
    shapeType="modelica://UJ/Resources/Shapes/FLOAT.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of FLOAT" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1700,-100})));
equation
  connect(BASE.frame_a, BASE_CS3.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-200},{730,-200}}, color={95,95,95}, thickness=0.5));
  connect(CROSS.frame_a, CROSS_CS3.frame_a)
    annotation (Line(points={{1125,0},{1120,0},{1120,-200},{1130,-200}}, color={95,95,95}, thickness=0.5));
  connect(FLOAT.frame_a, FLOAT_CS2.frame_a)
    annotation (Line(points={{1685,0},{1630,0}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, RootPart.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, BASE.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,25},{720,25},{720,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(BASE_CS3.frame_b, BASE_CROSS_1.frame_a)
    annotation (Line(points={{750,-200},{805,-200},{805,0},{810,0}}, color={95,95,95}, thickness=0.5));
  connect(BASE_CROSS_1.frame_b, BASE_CROSS_2.frame_a)
    annotation (Line(points={{830,0},{890,0}}, color={95,95,95}, thickness=0.5));
  connect(BASE_CROSS_2.frame_b, CROSS.frame_a)
    annotation (Line(points={{910,0},{1125,0}}, color={95,95,95}, thickness=0.5));
  connect(CROSS_CS3.frame_b, CROSS_FLOAT_1.frame_a)
    annotation (Line(points={{1150,-200},{1200,-200},{1200,0},{1205,0}}, color={95,95,95}, thickness=0.5));
  connect(CROSS_FLOAT_1.frame_b, CROSS_FLOAT_2.frame_a)
    annotation (Line(points={{1235,0},{1285,0}}, color={95,95,95}, thickness=0.5));
  connect(CROSS_FLOAT_2.frame_b, CROSS_FLOAT_3.frame_a)
    annotation (Line(points={{1315,0},{1365,0}}, color={95,95,95}, thickness=0.5));
  connect(CROSS_FLOAT_3.frame_b, CROSS_FLOAT_4.frame_a)
    annotation (Line(points={{1395,0},{1445,0}}, color={95,95,95}, thickness=0.5));
  connect(CROSS_FLOAT_4.frame_b, FLOAT_CS2.frame_b)
    annotation (Line(points={{1475,0},{1610,0}}, color={95,95,95}, thickness=0.5));
  connect(BASE.frame_a, BASE_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  connect(CROSS.frame_a, CROSS_shape.frame_a)
    annotation (Line(points={{1125,0},{1115,0},{1115,-100},{1130,-100}}, color={95,95,95}, thickness=0.5));
  connect(FLOAT.frame_a, FLOAT_shape.frame_a)
    annotation (Line(points={{1685,0},{1680,0},{1680,-100},{1690,-100}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-260},{1760,80}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>UJ.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 5.0 from Pro/E Wildfire Creo 9.0 - 2022073 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.25 m, period 1.0 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

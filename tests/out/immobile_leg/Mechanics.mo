within LEG;
model Mechanics "Mechanical model of LEG (4 bodies, 5 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, -0.25},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID LEG/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body HIP(
    m=0.0400896,
    r_CM={0.05, 0.0, 0.0},
    I_11=1.06906e-6, I_22=4.51676e-5, I_33=4.5809e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part HIP (nodeID 80)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body THIGH(
    m=0.0847584,
    r_CM={0.101, 0.0, 0.000499999999999987},
    I_11=2.3803e-6, I_22=0.000336244, I_33=0.00033748,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part THIGH (nodeID 81)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));
  Modelica.Mechanics.MultiBody.Parts.Body SHANK(
    m=0.0804168,
    r_CM={0.1015, 0.000500000000000002, 0.0},
    I_11=2.36559e-6, I_22=0.000321835, I_33=0.000323343,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part SHANK (nodeID 82)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation HIP_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0, 0.0, 1.0},
    n_y={0.0, 1.0, 0.0},
    animation=false)
    "Frame CS2 of HIP (nodeID 80:-:LEG/RootPart::80(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={660,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation HIP_CS3(
    r={0.1, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0, 0.0, 1.0},
    n_y={0.0, 1.0, 0.0},
    animation=false)
    "Frame CS3 of HIP (nodeID 80:-:81::80(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation THIGH_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0993807989999907, 0.0, 0.995049474543916},
    n_y={0.0496903994999953, 0.998752338877845, -0.00496284027203949},
    animation=false)
    "Frame CS2 of THIGH (nodeID 80:-:81::81(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={980,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation THIGH_CS3(
    r={0.201246117974981, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0993807989999907, 0.0, 0.995049474543916},
    n_y={0.0496903994999953, 0.998752338877845, -0.00496284027203949},
    animation=false)
    "Frame CS3 of THIGH (nodeID 81:-:82::81(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation SHANK_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0493864798324796, 0.0, 0.998779743291661},
    n_y={0.148159439497438, 0.988936352868298, -0.00732601278698039},
    animation=false)
    "Frame CS2 of SHANK (nodeID 81:-:82::82(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1300,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation SHANK_CS3(
    r={0.202484567313166, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0493864798324796, 0.0, 0.998779743291661},
    n_y={0.148159439497438, 0.988936352868298, -0.00732601278698039},
    animation=false)
    "Frame CS3 of SHANK (nodeID 82:-:LEG/RootPart::82(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1300,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation RootPart_CS3(r={0.03, 0.04, -0.5}, animation=false)
    "Frame CS3 of RootPart (nodeID 82:-:LEG/RootPart::LEG/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  LEG.Components.Revolute RootPart_HIP(
    n={0.0, 0.0, 1.0},
    phi(start=0.0),
    w(start=0))
    "Joint RootPart--HIP (nodeID 80:-:LEG/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={500,0})));
  LEG.Components.Revolute HIP_THIGH(
    n={1.0, 0.0, 0.0},
    phi(start=0.0),
    w(start=0))
    "Joint HIP--THIGH (nodeID 80:-:81)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={820,0})));
  LEG.Components.Revolute THIGH_SHANK(
    n={0.0, 0.98058067569092, 0.196116135138184},
    phi(start=0.0),
    w(start=0))
    "Joint THIGH--SHANK (nodeID 81:-:82)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,0})));
  Modelica.Mechanics.MultiBody.Joints.Constraints.Spherical SHANK_RootPart(x_locked=true, y_locked=true, z_locked=true, animation=false)
    "Joint SHANK--RootPart (nodeID 82:-:LEG/RootPart): closes a loop, imposing only its independent equations" annotation (Placement(transformation(extent={{15,-15},{-15,15}}, origin={1220,-100})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape HIP_shape(
    shapeType="modelica://LEG/Resources/Shapes/HIP.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of HIP" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape THIGH_shape(
    shapeType="modelica://LEG/Resources/Shapes/THIGH.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of THIGH" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape SHANK_shape(
    shapeType="modelica://LEG/Resources/Shapes/SHANK.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of SHANK" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1380,-100})));
equation
  connect(HIP.frame_a, HIP_CS2.frame_a)
    annotation (Line(points={{725,0},{670,0}}, color={95,95,95}, thickness=0.5));
  connect(HIP.frame_a, HIP_CS3.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-200},{730,-200}}, color={95,95,95}, thickness=0.5));
  connect(THIGH.frame_a, THIGH_CS2.frame_a)
    annotation (Line(points={{1045,0},{990,0}}, color={95,95,95}, thickness=0.5));
  connect(THIGH.frame_a, THIGH_CS3.frame_a)
    annotation (Line(points={{1045,0},{1040,0},{1040,-200},{1050,-200}}, color={95,95,95}, thickness=0.5));
  connect(SHANK.frame_a, SHANK_CS2.frame_a)
    annotation (Line(points={{1365,0},{1310,0}}, color={95,95,95}, thickness=0.5));
  connect(SHANK.frame_a, SHANK_CS3.frame_a)
    annotation (Line(points={{1365,0},{1360,0},{1360,-100},{1310,-100}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CS3.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, RootPart.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_HIP.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,25},{485,25},{485,0},{490,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_HIP.frame_b, HIP_CS2.frame_b)
    annotation (Line(points={{510,0},{650,0}}, color={95,95,95}, thickness=0.5));
  connect(HIP_CS3.frame_b, HIP_THIGH.frame_a)
    annotation (Line(points={{750,-200},{805,-200},{805,0},{810,0}}, color={95,95,95}, thickness=0.5));
  connect(HIP_THIGH.frame_b, THIGH_CS2.frame_b)
    annotation (Line(points={{830,0},{970,0}}, color={95,95,95}, thickness=0.5));
  connect(THIGH_CS3.frame_b, THIGH_SHANK.frame_a)
    annotation (Line(points={{1070,-200},{1125,-200},{1125,0},{1130,0}}, color={95,95,95}, thickness=0.5));
  connect(THIGH_SHANK.frame_b, SHANK_CS2.frame_b)
    annotation (Line(points={{1150,0},{1290,0}}, color={95,95,95}, thickness=0.5));
  connect(SHANK_CS3.frame_b, SHANK_RootPart.frame_a)
    annotation (Line(points={{1290,-100},{1235,-100}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(SHANK_RootPart.frame_b, RootPart_CS3.frame_b)
    annotation (Line(points={{1205,-100},{1075,-100},{1075,-115},{435,-115},{435,-100},{430,-100}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(HIP.frame_a, HIP_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  connect(THIGH.frame_a, THIGH_shape.frame_a)
    annotation (Line(points={{1045,0},{1035,0},{1035,-100},{1050,-100}}, color={95,95,95}, thickness=0.5));
  connect(SHANK.frame_a, SHANK_shape.frame_a)
    annotation (Line(points={{1365,0},{1355,0},{1355,-100},{1370,-100}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-260},{1440,80}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>LEG.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Joint SHANK--RootPart closes a loop: a plain revolute would repeat 2 of its 5 equations (3 independent); Joints.Constraints.Spherical imposes exactly those (translations locked: x, y, z).</li></ul>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.402 m, period 1.27 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

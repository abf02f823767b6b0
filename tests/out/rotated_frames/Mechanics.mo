within ROT;
model Mechanics "Mechanical model of ROT (4 bodies, 4 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.1, -0.05, 0.03},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID ROT/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body BRACKET(
    m=1.22148,
    r_CM={0.038, 0.0725, -0.0065},
    I_11=0.00229495467249297, I_22=0.00080627646903542, I_33=0.00279158885847162,
    I_21=2.42400847658142e-11, I_31=7.89738003833564e-10, I_32=4.34508208059514e-10,
    animation=false)
    "Part BRACKET (nodeID 101)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body SLIDER(
    m=3.0555,
    r_CM={0.051, 0.0175, 0.0245},
    I_11=0.00182769939820824, I_22=0.00527201302116988, I_33=0.00438591758062188,
    I_21=3.21858662074778e-9, I_31=2.89009390226115e-9, I_32=-3.07667965388468e-9,
    animation=false)
    "Part SLIDER (nodeID 102)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));
  Modelica.Mechanics.MultiBody.Parts.Body TOOL(
    m=0.543629,
    r_CM={-0.012, 0.042, 0.012},
    I_11=0.000577696852956156, I_22=0.00017541091452303, I_33=0.000577696232520814,
    I_21=1.83526085130383e-10, I_31=-3.15835915634752e-11, I_32=1.67771374700795e-10,
    animation=false)
    "Part TOOL (nodeID 103)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootGround(
    r={0.1, -0.05, 0.03},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={1.0, 0.0, 0.0},
    n_y={0.0, 0.0, -1.0},
    animation=false)
    "Ground RootGround (nodeID RootGround) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={100,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootPart_CS2(
    r={0.15, 0.02, -0.04},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.750471895489031, 0.56552113633408, 0.342020143325669},
    n_y={-0.501895475867953, 0.150970026744966, 0.851650739639147},
    animation=false)
    "Frame CS2 of RootPart (nodeID 101:-:ROT/RootPart::ROT/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation BRACKET_CS2(
    r={0.0134707703411041, 0.0155379034269251, -0.0101050434691187},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.159307744071341, 0.961457668513858, 0.224098626356333},
    n_y={-0.953586474805032, 0.0911076433392703, 0.287005631293319},
    animation=false)
    "Frame CS2 of BRACKET (nodeID 101:-:ROT/RootPart::101(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={660,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation BRACKET_CS3(
    r={0.0623011513662211, 0.129372164121891, -0.00253173633336725},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.0586938877883621, -0.0961102165134004, -0.993638693800737},
    n_y={-0.960007294181105, -0.267518262751253, 0.0825831351646641},
    animation=false)
    "Frame CS3 of BRACKET (nodeID 101:-:102::101(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation SLIDER_CS2(
    r={0.00153337851665661, 0.00851307140481951, 0.000419959023121086},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.144136507488167, 0.959763355390207, -0.240995785978189},
    n_y={-0.24693614184172, 0.270719408906242, 0.930448033741692},
    animation=false)
    "Frame CS2 of SLIDER (nodeID 101:-:102::102(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={980,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation SLIDER_CS3(
    r={0.100303881587864, 0.0265099442478837, 0.0488503244040602},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.918650459461403, -0.127546251230951, -0.373916149862886},
    n_y={0.377469135251024, -0.562728220045927, -0.735427768238858},
    animation=false)
    "Frame CS3 of SLIDER (nodeID 102:-:103::102(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation TOOL_CS3(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.385143934444574, -0.922852131125589, 0.00284496704948478},
    n_y={0.217229581405892, 0.0936540882462335, 0.971617322157745},
    animation=false)
    "Frame CS3 of TOOL (nodeID 102:-:103::103(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1300,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootPart_CS3(
    r={0.1, -0.05, 0.03},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={1.0, 0.0, 0.0},
    n_y={0.0, 0.0, -1.0},
    animation=false)
    "Frame CS3 of RootPart (nodeID ROT/RootPart:-:RootGround::ROT/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={340,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation TOOL_TOOL_TIP(
    r={-0.0235429031977969, 0.0835738646072377, 0.0236884120115778},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.0104915277600898, 0.473001306448205, 0.880999257629398},
    n_y={0.0872307473634907, -0.877256010499684, 0.472030389653659},
    animation=false)
    "Frame CS2 of TOOL (nodeID 126(USERADDED))" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,-200})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  ROT.Components.Revolute RootPart_BRACKET(
    n={0.0, 0.0, 1.0},
    phi(start=0.523598775598299, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--BRACKET (nodeID 101:-:ROT/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={500,0})));
  ROT.Components.Prismatic BRACKET_SLIDER(
    n={-0.919993139851766, -0.334998588111097, 0.203441806395001},
    s(start=0.025, fixed=true),
    v(start=0, fixed=true))
    "Joint BRACKET--SLIDER (nodeID 101:-:102)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={820,0})));
  ROT.Components.Revolute SLIDER_TOOL(
    n={0.0448383605547922, 0.315968192029263, 0.947709672340911},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint SLIDER--TOOL (nodeID 102:-:103)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,0})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape BRACKET_shape(
    shapeType="modelica://ROT/Resources/Shapes/BRACKET.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of BRACKET" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape SLIDER_shape(
    shapeType="modelica://ROT/Resources/Shapes/SLIDER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of SLIDER" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape TOOL_shape(
    shapeType="modelica://ROT/Resources/Shapes/TOOL.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of TOOL" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1380,-100})));
equation
  connect(world.frame_b, RootGround.frame_a)
    annotation (Line(points={{30,0},{90,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CS2.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
  connect(BRACKET.frame_a, BRACKET_CS2.frame_a)
    annotation (Line(points={{725,0},{670,0}}, color={95,95,95}, thickness=0.5));
  connect(BRACKET.frame_a, BRACKET_CS3.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-200},{730,-200}}, color={95,95,95}, thickness=0.5));
  connect(SLIDER.frame_a, SLIDER_CS2.frame_a)
    annotation (Line(points={{1045,0},{990,0}}, color={95,95,95}, thickness=0.5));
  connect(SLIDER.frame_a, SLIDER_CS3.frame_a)
    annotation (Line(points={{1045,0},{1040,0},{1040,-200},{1050,-200}}, color={95,95,95}, thickness=0.5));
  connect(TOOL.frame_a, TOOL_CS3.frame_a)
    annotation (Line(points={{1365,0},{1310,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CS3.frame_a)
    annotation (Line(points={{405,0},{350,0}}, color={95,95,95}, thickness=0.5));
  connect(TOOL.frame_a, TOOL_TOOL_TIP.frame_a)
    annotation (Line(points={{1365,0},{1360,0},{1360,-200},{1365,-200}}, color={95,95,95}, thickness=0.5));
  connect(RootGround.frame_b, RootPart_CS3.frame_b)
    annotation (Line(points={{110,0},{330,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CS2.frame_b, RootPart_BRACKET.frame_a)
    annotation (Line(points={{430,-100},{480,-100},{480,0},{485,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_BRACKET.frame_b, BRACKET_CS2.frame_b)
    annotation (Line(points={{515,0},{650,0}}, color={95,95,95}, thickness=0.5));
  connect(BRACKET_CS3.frame_b, BRACKET_SLIDER.frame_a)
    annotation (Line(points={{750,-200},{800,-200},{800,0},{805,0}}, color={95,95,95}, thickness=0.5));
  connect(BRACKET_SLIDER.frame_b, SLIDER_CS2.frame_b)
    annotation (Line(points={{835,0},{970,0}}, color={95,95,95}, thickness=0.5));
  connect(SLIDER_CS3.frame_b, SLIDER_TOOL.frame_a)
    annotation (Line(points={{1070,-200},{1125,-200},{1125,0},{1130,0}}, color={95,95,95}, thickness=0.5));
  connect(SLIDER_TOOL.frame_b, TOOL_CS3.frame_b)
    annotation (Line(points={{1150,0},{1290,0}}, color={95,95,95}, thickness=0.5));
  connect(BRACKET.frame_a, BRACKET_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{725,-100}}, color={95,95,95}, thickness=0.5));
  connect(SLIDER.frame_a, SLIDER_shape.frame_a)
    annotation (Line(points={{1045,0},{1035,0},{1035,-100},{1050,-100}}, color={95,95,95}, thickness=0.5));
  connect(TOOL.frame_a, TOOL_shape.frame_a)
    annotation (Line(points={{1365,0},{1355,0},{1355,-100},{1370,-100}}, color={95,95,95}, thickness=0.5));
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
<p>Converted by cad2mo 0.1.0 from <code>ROT.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 5.0 from Pro/E Wildfire Creo 9.0 - 2022073 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.318 m, period 1.13 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

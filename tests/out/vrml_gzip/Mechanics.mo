within VASM;
model Mechanics "Mechanical model of VASM (4 bodies, 4 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID VASM/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body BRACKET(
    m=0.1296,
    r_CM={0.06, 0.0, 0.0},
    I_11=1.08e-5, I_22=0.00027756, I_33=0.0002862,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part BRACKET (nodeID 101)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body SLIDER(
    m=0.0756,
    r_CM={0.025, 0.0, 0.0},
    I_11=5.04e-6, I_22=3.339e-5, I_33=3.339e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part SLIDER (nodeID 102)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));
  Modelica.Mechanics.MultiBody.Parts.Body TOOL(
    m=0.0677376,
    r_CM={0.041, 0.0, 0.0},
    I_11=2.89014e-6, I_22=5.56577e-5, I_33=5.56577e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part TOOL (nodeID 103)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootPart_CS2(
    r={0.15, 0.02, -0.04},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.945735270592286, 0.0278276880979378, -0.323744370967065},
    n_y={0.198266891274146, 0.739942111693848, 0.642787609686539},
    animation=false)
    "Frame CS2 of RootPart (nodeID 101:-:VASM/RootPart::VASM/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation BRACKET_CS3(
    r={0.138650487852323, 0.0551126562177748, -0.00797730173268193},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.0337243951244223, 0.97092882126416, -0.236980778148948},
    n_y={-0.29580256991936, -0.236188935551116, -0.925589340016583},
    animation=false)
    "Frame CS3 of BRACKET (nodeID 101:-:102::101(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation SLIDER_CS3(
    r={0.105506783802931, 0.0166989745665653, 0.0501444196295728},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.167222804024504, 0.561192668344382, -0.810616631220144},
    n_y={0.92669570745574, 0.370135178799074, 0.0650769943872891},
    animation=false)
    "Frame CS3 of SLIDER (nodeID 102:-:103::102(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-200})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  VASM.Components.Revolute RootPart_BRACKET(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--BRACKET (nodeID 101:-:VASM/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={500,0})));
  VASM.Components.Revolute BRACKET_SLIDER(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint BRACKET--SLIDER (nodeID 101:-:102)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={820,0})));
  VASM.Components.Revolute SLIDER_TOOL(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint SLIDER--TOOL (nodeID 102:-:103)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,0})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape BRACKET_shape(
    shapeType="modelica://VASM/Resources/Shapes/BRACKET.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={204, 51, 51})
    "Shape of BRACKET" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape SLIDER_shape(
    shapeType="modelica://VASM/Resources/Shapes/SLIDER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 153, 229})
    "Shape of SLIDER" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape TOOL_shape(
    shapeType="modelica://VASM/Resources/Shapes/TOOL.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={77, 204, 77})
    "Shape of TOOL" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1380,-100})));
equation
  connect(RootPart.frame_a, RootPart_CS2.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
  connect(BRACKET.frame_a, BRACKET_CS3.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-200},{730,-200}}, color={95,95,95}, thickness=0.5));
  connect(SLIDER.frame_a, SLIDER_CS3.frame_a)
    annotation (Line(points={{1045,0},{1040,0},{1040,-200},{1050,-200}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, RootPart.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CS2.frame_b, RootPart_BRACKET.frame_a)
    annotation (Line(points={{430,-100},{480,-100},{480,0},{485,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_BRACKET.frame_b, BRACKET.frame_a)
    annotation (Line(points={{515,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(BRACKET_CS3.frame_b, BRACKET_SLIDER.frame_a)
    annotation (Line(points={{750,-200},{800,-200},{800,0},{805,0}}, color={95,95,95}, thickness=0.5));
  connect(BRACKET_SLIDER.frame_b, SLIDER.frame_a)
    annotation (Line(points={{835,0},{1045,0}}, color={95,95,95}, thickness=0.5));
  connect(SLIDER_CS3.frame_b, SLIDER_TOOL.frame_a)
    annotation (Line(points={{1070,-200},{1125,-200},{1125,0},{1130,0}}, color={95,95,95}, thickness=0.5));
  connect(SLIDER_TOOL.frame_b, TOOL.frame_a)
    annotation (Line(points={{1150,0},{1365,0}}, color={95,95,95}, thickness=0.5));
  connect(BRACKET.frame_a, BRACKET_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{725,-100}}, color={95,95,95}, thickness=0.5));
  connect(SLIDER.frame_a, SLIDER_shape.frame_a)
    annotation (Line(points={{1045,0},{1035,0},{1035,-100},{1050,-100}}, color={95,95,95}, thickness=0.5));
  connect(TOOL.frame_a, TOOL_shape.frame_a)
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
<p>Converted by cad2mo 0.1.0 from <code>VASM.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.315 m, period 1.13 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

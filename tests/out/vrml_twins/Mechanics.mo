within VASM;
model Mechanics "Mechanical model of VASM (3 bodies, 3 joints)"
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
  Modelica.Mechanics.MultiBody.Parts.Body BOLT(
    m=0.0162,
    r_CM={0.0, 0.0, 0.03},
    I_11=4.995e-6, I_22=4.995e-6, I_33=2.7e-7,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part BOLT (nodeID 201)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body NUT(
    m=0.015552,
    r_CM={0.0, 0.0, 0.005},
    I_11=8.76096e-7, I_22=8.76096e-7, I_33=1.49299e-6,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part NUT (nodeID 202)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,-200})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootPart_CS2(
    r={0.12, 0.04, -0.03},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.90630778703665, 0.422618261740699, 0.0},
    n_y={-0.323744370967065, 0.694272044014884, 0.642787609686539},
    animation=false)
    "Frame CS2 of RootPart (nodeID 201:-:VASM/RootPart::VASM/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootPart_CS3(
    r={0.12, 0.04, -0.03},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.90630778703665, 0.422618261740699, 0.0},
    n_y={-0.323744370967065, 0.694272044014884, 0.642787609686539},
    animation=false)
    "Frame CS3 of RootPart (nodeID 202:-:VASM/RootPart::VASM/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-200})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  VASM.Components.Revolute RootPart_BOLT(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--BOLT (nodeID 201:-:VASM/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={500,0})));
  VASM.Components.Revolute RootPart_NUT(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--NUT (nodeID 202:-:VASM/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={500,-200})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape BOLT_shape(
    shapeType="modelica://VASM/Resources/Shapes/BOLT.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={204, 51, 51})
    "Shape of BOLT" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape NUT_shape(
    shapeType="modelica://VASM/Resources/Shapes/NUT.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 153, 229})
    "Shape of NUT" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-300})));
equation
  connect(RootPart.frame_a, RootPart_CS2.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CS3.frame_a)
    annotation (Line(points={{405,0},{395,0},{395,-200},{410,-200}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, RootPart.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CS2.frame_b, RootPart_BOLT.frame_a)
    annotation (Line(points={{430,-100},{480,-100},{480,0},{485,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_BOLT.frame_b, BOLT.frame_a)
    annotation (Line(points={{515,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CS3.frame_b, RootPart_NUT.frame_a)
    annotation (Line(points={{430,-200},{490,-200}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_NUT.frame_b, NUT.frame_a)
    annotation (Line(points={{510,-200},{725,-200}}, color={95,95,95}, thickness=0.5));
  connect(BOLT.frame_a, BOLT_shape.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  connect(NUT.frame_a, NUT_shape.frame_a)
    annotation (Line(points={{725,-200},{720,-200},{720,-300},{730,-300}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=3.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-360},{800,60}})),
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
<p>Experiment: 3.0 s, about three swings of a pendulum as long as the mechanism's reach (0.13 m, period 0.72 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

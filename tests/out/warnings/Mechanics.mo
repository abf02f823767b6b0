within WARN;
model Mechanics "Mechanical model of WARN (6 bodies, 6 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID WARN/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body ASYM(
    m=0.0648,
    r_CM={0.05, 0.0, 0.0},
    I_11=2.7e-6, I_22=7.83e-5, I_33=7.992e-5,
    I_21=1e-6, I_31=0.0, I_32=0.0,
    animation=false)
    "Part ASYM (nodeID 501)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body TRI(
    m=0.0648,
    r_CM={0.05, 0.0, 0.0},
    I_11=5.4e-7, I_22=7.83e-5, I_33=7.992e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part TRI (nodeID 502)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1140,0})));
  Modelica.Mechanics.MultiBody.Parts.Body GHOST(
    m=0.0648,
    r_CM={0.05, 0.0, 0.0},
    I_11=2.7e-6, I_22=7.83e-5, I_33=7.992e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part GHOST (nodeID 503)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1460,0})));
  Modelica.Mechanics.MultiBody.Parts.Body BARE(
    m=0.0648,
    r_CM={0.05, 0.0, 0.0},
    I_11=2.7e-6, I_22=7.83e-5, I_33=7.992e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part BARE (nodeID 504)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1780,0})));
  Modelica.Mechanics.MultiBody.Parts.Body NOMAT(
    m=12.5,
    r_CM={0.002, 0.0, 0.0},
    I_11=2.63021e-5, I_22=2.63021e-5, I_33=5.20833e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part NOMAT (nodeID 505)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={2100,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation ASYM_CS3(r={0.1, 0.0, 0.0}, animation=false)
    "Frame CS3 of ASYM (nodeID 501:-:502::501(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation TRI_CS3(r={0.1, 0.0, 0.0}, animation=false)
    "Frame CS3 of TRI (nodeID 502:-:503::502(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation GHOST_CS3(r={0.1, 0.0, 0.0}, animation=false)
    "Frame CS3 of GHOST (nodeID 503:-:504::503(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1460,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation BARE_CS3(r={0.1, 0.0, 0.0}, animation=false)
    "Frame CS3 of BARE (nodeID 504:-:505::504(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1780,-100})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  WARN.Components.Revolute RootPart_ASYM(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--ASYM (nodeID 501:-:WARN/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={500,0})));
  WARN.Components.Revolute ASYM_TRI(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint ASYM--TRI (nodeID 501:-:502)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={820,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation ASYM_TRI_offset(r={0.0, 0.002, 0.0}, animation=false)
    "CAD offset of joint ASYM--TRI (nodeID 501:-:502) at its start values" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={900,0})));
  WARN.Components.Revolute GHOST_BARE(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint GHOST--BARE (nodeID 503:-:504)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1540,0})));
  WARN.Components.Revolute BARE_NOMAT(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint BARE--NOMAT (nodeID 504:-:505)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1860,0})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape ASYM_shape(
    shapeType="modelica://WARN/Resources/Shapes/ASYM.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of ASYM" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape TRI_shape(
    shapeType="modelica://WARN/Resources/Shapes/TRI.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of TRI" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape NOMAT_shape(
    shapeType="modelica://WARN/Resources/Shapes/NOMAT.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of NOMAT" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={2100,-100})));
equation
  connect(ASYM.frame_a, ASYM_CS3.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-200},{730,-200}}, color={95,95,95}, thickness=0.5));
  connect(TRI.frame_a, TRI_CS3.frame_a)
    annotation (Line(points={{1125,0},{1120,0},{1120,-200},{1130,-200}}, color={95,95,95}, thickness=0.5));
  connect(GHOST.frame_a, GHOST_CS3.frame_a)
    annotation (Line(points={{1445,0},{1440,0},{1440,-100},{1450,-100}}, color={95,95,95}, thickness=0.5));
  connect(BARE.frame_a, BARE_CS3.frame_a)
    annotation (Line(points={{1765,0},{1760,0},{1760,-100},{1770,-100}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, RootPart.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_ASYM.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-20},{480,-20},{480,0},{485,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_ASYM.frame_b, ASYM.frame_a)
    annotation (Line(points={{515,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(ASYM_CS3.frame_b, ASYM_TRI.frame_a)
    annotation (Line(points={{750,-200},{805,-200},{805,0},{810,0}}, color={95,95,95}, thickness=0.5));
  connect(ASYM_TRI.frame_b, ASYM_TRI_offset.frame_a)
    annotation (Line(points={{830,0},{885,0}}, color={95,95,95}, thickness=0.5));
  connect(ASYM_TRI_offset.frame_b, TRI.frame_a)
    annotation (Line(points={{915,0},{1125,0}}, color={95,95,95}, thickness=0.5));
  connect(TRI_CS3.frame_b, GHOST.frame_a)
    annotation (Line(points={{1150,-200},{1435,-200},{1435,0},{1445,0}}, color={95,95,95}, thickness=0.5));
  connect(GHOST_CS3.frame_b, GHOST_BARE.frame_a)
    annotation (Line(points={{1470,-100},{1525,-100},{1525,0},{1530,0}}, color={95,95,95}, thickness=0.5));
  connect(GHOST_BARE.frame_b, BARE.frame_a)
    annotation (Line(points={{1550,0},{1765,0}}, color={95,95,95}, thickness=0.5));
  connect(BARE_CS3.frame_b, BARE_NOMAT.frame_a)
    annotation (Line(points={{1790,-100},{1845,-100},{1845,0},{1850,0}}, color={95,95,95}, thickness=0.5));
  connect(BARE_NOMAT.frame_b, NOMAT.frame_a)
    annotation (Line(points={{1870,0},{2085,0}}, color={95,95,95}, thickness=0.5));
  connect(ASYM.frame_a, ASYM_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  connect(TRI.frame_a, TRI_shape.frame_a)
    annotation (Line(points={{1125,0},{1115,0},{1115,-100},{1130,-100}}, color={95,95,95}, thickness=0.5));
  connect(NOMAT.frame_a, NOMAT_shape.frame_a)
    annotation (Line(points={{2085,0},{2080,0},{2080,-100},{2090,-100}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-260},{2160,60}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>WARN.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.402 m, period 1.27 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

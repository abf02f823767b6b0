within SLIDERCRANK;
model Mechanics "Mechanical model of SLIDERCRANK (4 bodies, 5 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID SLIDERCRANK/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body CRANK(
    m=0.0193536,
    r_CM={0.02, 0.0, 0.0},
    I_11=5.16096e-7, I_22=5.16096e-6, I_33=5.47062e-6,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part CRANK (nodeID 40)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body ROD(
    m=0.0470016,
    r_CM={0.06, 0.0, 0.0},
    I_11=1.25338e-6, I_22=7.26958e-5, I_33=7.34478e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part ROD (nodeID 41)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));
  Modelica.Mechanics.MultiBody.Parts.Body PISTON(
    m=0.0942,
    r_CM={0.0, 0.0, 0.0},
    I_11=6.28e-6, I_22=1.0205e-5, I_33=1.0205e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part PISTON (nodeID 42)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,-300})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.642787609686539, -0.766044443118978, 0.0},
    n_y={0.766044443118978, 0.642787609686539, 0.0},
    animation=false)
    "Frame CS2 of CRANK (nodeID 40:-:SLIDERCRANK/RootPart::40(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={660,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS3(
    r={0.04, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.642787609686539, -0.766044443118978, 0.0},
    n_y={0.766044443118978, 0.642787609686539, 0.0},
    animation=false)
    "Frame CS3 of CRANK (nodeID 40:-:41::40(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROD_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.966849173068348, 0.255348147706326, 0.0},
    n_y={-0.255348147706326, 0.966849173068348, 0.0},
    animation=false)
    "Frame CS2 of ROD (nodeID 40:-:41::41(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={980,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROD_CS3(
    r={0.12, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.966849173068348, 0.255348147706326, 0.0},
    n_y={-0.255348147706326, 0.966849173068348, 0.0},
    animation=false)
    "Frame CS3 of ROD (nodeID 41:-:42::41(AUTOGEN))" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={980,-100})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  SLIDERCRANK.Components.Revolute RootPart_CRANK(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--CRANK (nodeID 40:-:SLIDERCRANK/RootPart)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={500,0})));
  SLIDERCRANK.Components.Prismatic PISTON_RootPart(
    n={1.0, 0.0, 0.0},
    s(start=-0.141733405155663),
    v(start=0))
    "Joint PISTON--RootPart (nodeID 42:-:SLIDERCRANK/RootPart)" annotation (Placement(transformation(extent={{15,-15},{-15,15}}, origin={580,-300})));
  SLIDERCRANK.Components.Revolute CRANK_ROD(
    n={0.0, 0.0, 1.0},
    phi(start=0.0),
    w(start=0))
    "Joint CRANK--ROD (nodeID 40:-:41)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={820,0})));
  Modelica.Mechanics.MultiBody.Joints.RevolutePlanarLoopConstraint ROD_PISTON(n={0.0, 0.0, 1.0}, animation=false)
    "Joint ROD--PISTON (nodeID 41:-:42): closes a planar loop" annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={900,-100})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape CRANK_shape(
    shapeType="modelica://SLIDERCRANK/Resources/Shapes/CRANK.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of CRANK" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape ROD_shape(
    shapeType="modelica://SLIDERCRANK/Resources/Shapes/ROD.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of ROD" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1060,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape PISTON_shape(
    shapeType="modelica://SLIDERCRANK/Resources/Shapes/PISTON.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of PISTON" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-400})));
equation
  connect(CRANK.frame_a, CRANK_CS2.frame_a)
    annotation (Line(points={{725,0},{670,0}}, color={95,95,95}, thickness=0.5));
  connect(CRANK.frame_a, CRANK_CS3.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-200},{730,-200}}, color={95,95,95}, thickness=0.5));
  connect(ROD.frame_a, ROD_CS2.frame_a)
    annotation (Line(points={{1045,0},{990,0}}, color={95,95,95}, thickness=0.5));
  connect(ROD.frame_a, ROD_CS3.frame_a)
    annotation (Line(points={{1045,0},{1040,0},{1040,-100},{990,-100}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, RootPart.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart.frame_a, RootPart_CRANK.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-20},{480,-20},{480,0},{485,0}}, color={95,95,95}, thickness=0.5));
  connect(RootPart_CRANK.frame_b, CRANK_CS2.frame_b)
    annotation (Line(points={{515,0},{650,0}}, color={95,95,95}, thickness=0.5));
  connect(PISTON.frame_a, PISTON_RootPart.frame_a)
    annotation (Line(points={{725,-300},{595,-300}}, color={95,95,95}, thickness=0.5));
  connect(PISTON_RootPart.frame_b, RootPart.frame_a)
    annotation (Line(points={{565,-300},{400,-300},{400,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(CRANK_CS3.frame_b, CRANK_ROD.frame_a)
    annotation (Line(points={{750,-200},{805,-200},{805,0},{810,0}}, color={95,95,95}, thickness=0.5));
  connect(CRANK_ROD.frame_b, ROD_CS2.frame_b)
    annotation (Line(points={{830,0},{970,0}}, color={95,95,95}, thickness=0.5));
  connect(ROD_CS3.frame_b, ROD_PISTON.frame_a)
    annotation (Line(points={{970,-100},{910,-100}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(ROD_PISTON.frame_b, PISTON.frame_a)
    annotation (Line(points={{890,-100},{885,-100},{885,-275},{720,-275},{720,-300},{725,-300}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(CRANK.frame_a, CRANK_shape.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  connect(ROD.frame_a, ROD_shape.frame_a)
    annotation (Line(points={{1045,0},{1035,0},{1035,-100},{1050,-100}}, color={95,95,95}, thickness=0.5));
  connect(PISTON.frame_a, PISTON_shape.frame_a)
    annotation (Line(points={{725,-300},{720,-300},{720,-400},{730,-400}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=3.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-460},{1120,60}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>SLIDERCRANK.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Joint ROD--PISTON closes a loop: a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations.</li></ul>
<p>Experiment: 3.0 s, about three swings of a pendulum as long as the mechanism's reach (0.142 m, period 0.76 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

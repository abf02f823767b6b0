within mate_rig;
model Mechanics "Mechanical model of mate rig (6 bodies, 5 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, 0.0, -1.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body plate_1(
    m=3.0,
    r_CM={0.0, 0.0, 0.005},
    I_11=0.040025, I_22=0.062525, I_33=0.1025,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part plate-1 (nodeID plate-1)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,0})));
  Modelica.Mechanics.MultiBody.Parts.Body crank_1(
    m=0.4,
    r_CM={0.04, 0.0, 0.004},
    I_11=1.54666666666667e-5, I_22=0.000335466666666667, I_33=0.000346666666666667,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part crank-1 (nodeID crank-1)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,-100})));
  Modelica.Mechanics.MultiBody.Parts.Body puck_1(
    m=0.2,
    r_CM={0.0, 0.0, 0.005},
    I_11=4.33333333333334e-5, I_22=4.33333333333334e-5, I_33=8.33333333333334e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part puck-1 (nodeID puck-1)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,-300})));
  Modelica.Mechanics.MultiBody.Parts.Body slider_1(
    m=0.1,
    r_CM={0.0, 0.0, 0.005},
    I_11=4.16666666666667e-6, I_22=4.16666666666667e-6, I_33=6.66666666666667e-6,
    I_21=0.0, I_31=0.0, I_32=0.0,
    r_0(start={0.0, -0.1, 0.01}, each fixed=true),
    v_0(start={0, 0, 0}, each fixed=true),
    angles_fixed=true,
    angles_start={0.0, 0.0, 0.0},
    w_0_fixed=true)
    "Part slider-1 (nodeID slider-1)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,-400})));
  Modelica.Mechanics.MultiBody.Parts.Body grip_1(
    m=0.05,
    r_CM={0.0, 0.0, 0.015},
    I_11=5.41666666666667e-6, I_22=5.41666666666667e-6, I_33=3.33333333333333e-6,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part grip-1 (nodeID handle-1|grip-1)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={900,-100})));
  Modelica.Mechanics.MultiBody.Parts.Body knob_1(
    m=0.02,
    r_CM={0.0, 0.0, 0.005},
    I_11=8.33333333333334e-7, I_22=8.33333333333334e-7, I_33=1.33333333333333e-6,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part knob-1 (nodeID handle-1|knob-1)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1220,-100})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation World_2(r={0.1, 0.05, 0.0085}, animation=false)
    "Ground World (nodeID ground:mates:ground~crank-1) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={100,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation World_3(r={0.05, 0.14, 0.01}, animation=false)
    "Ground World (nodeID ground:mates:ground~puck-1) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={100,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation grip_1_knob_1_rigid_base(
    r={0.0, 0.0, 0.03},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-1.0, 0.0, 0.0},
    n_y={0.0, 1.0, 0.0},
    animation=false)
    "Frame CS2 of grip-1 (nodeID weld:handle-1|knob-1::base)" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={900,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation crank_1_revolute_World_crank_1_follower(
    r={0.0, 0.0, -0.0015},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.766044443118978, -0.642787609686539, 0.0},
    n_y={0.642787609686539, 0.766044443118978, 0.0},
    animation=false)
    "Frame CS2 of crank-1 (nodeID mates:ground~crank-1::follower)" annotation (Placement(transformation(extent={{20,-20},{-20,20}}, origin={500,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation puck_1_planar_World_puck_1_follower(
    r={0.110589072351056, 0.117771206483304, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.90630778703665, 0.422618261740699, 0.0},
    n_y={-0.422618261740699, 0.90630778703665, 0.0},
    animation=false)
    "Frame CS2 of puck-1 (nodeID mates:ground~puck-1::follower)" annotation (Placement(transformation(extent={{20,-20},{-20,20}}, origin={500,-300})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation crank_1_weld_crank_1_grip_1_base(
    r={0.08, 0.0, 0.01},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.766044443118978, -0.642787609686539, 0.0},
    n_y={0.642787609686539, 0.766044443118978, 0.0},
    animation=false)
    "Frame CS3 of crank-1 (nodeID mates:crank-1~handle-1|grip-1::base)" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={580,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation grip_1_weld_crank_1_grip_1_follower(
    r={2.77555756156289e-17, 2.77555756156289e-17, -6.93889390390723e-18},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.766044443118978, -0.642787609686539, 0.0},
    n_y={0.642787609686539, 0.766044443118978, 0.0},
    animation=false)
    "Frame CS3 of grip-1 (nodeID mates:crank-1~handle-1|grip-1::follower)" annotation (Placement(transformation(extent={{20,-20},{-20,20}}, origin={820,-100})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  mate_rig.Components.Revolute revolute_World_crank_1(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint revolute World--crank-1 (nodeID mates:ground~crank-1)" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={180,-100})));
  mate_rig.Components.Prismatic planar_World_puck_1_1(
    n={-1.0, 0.0, 0.0},
    s(start=0.0, fixed=true),
    v(start=0, fixed=true))
    "Joint planar World--puck-1 (nodeID mates:ground~puck-1), primitive 1 of 3" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={180,-300})));
  mate_rig.Components.Prismatic planar_World_puck_1_2(
    n={0.0, -1.0, 0.0},
    s(start=0.0, fixed=true),
    v(start=0, fixed=true))
    "Joint planar World--puck-1 (nodeID mates:ground~puck-1), primitive 2 of 3" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={260,-300})));
  mate_rig.Components.Revolute planar_World_puck_1_3(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint planar World--puck-1 (nodeID mates:ground~puck-1), primitive 3 of 3" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={340,-300})));

  // Shapes: CAD meshes in each body frame, metres
equation
  connect(world.frame_b, World_2.frame_a)
    annotation (Line(points={{30,0},{90,0}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, World_3.frame_a)
    annotation (Line(points={{30,0},{35,0},{35,-100},{90,-100}}, color={95,95,95}, thickness=0.5));
  connect(grip_1.frame_a, grip_1_knob_1_rigid_base.frame_a)
    annotation (Line(points={{885,-100},{875,-100},{875,-200},{880,-200}}, color={95,95,95}, thickness=0.5));
  connect(crank_1.frame_a, crank_1_revolute_World_crank_1_follower.frame_a)
    annotation (Line(points={{565,-100},{520,-100}}, color={95,95,95}, thickness=0.5));
  connect(puck_1.frame_a, puck_1_planar_World_puck_1_follower.frame_a)
    annotation (Line(points={{565,-300},{520,-300}}, color={95,95,95}, thickness=0.5));
  connect(crank_1.frame_a, crank_1_weld_crank_1_grip_1_base.frame_a)
    annotation (Line(points={{565,-100},{560,-100},{560,-170},{555,-170},{555,-200},{560,-200}}, color={95,95,95}, thickness=0.5));
  connect(grip_1.frame_a, grip_1_weld_crank_1_grip_1_follower.frame_a)
    annotation (Line(points={{885,-100},{840,-100}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, plate_1.frame_a)
    annotation (Line(points={{30,0},{35,0},{35,20},{560,20},{560,0},{565,0}}, color={95,95,95}, thickness=0.5));
  connect(World_2.frame_b, revolute_World_crank_1.frame_a)
    annotation (Line(points={{110,0},{155,0},{155,-100},{160,-100}}, color={95,95,95}, thickness=0.5));
  connect(revolute_World_crank_1.frame_b, crank_1_revolute_World_crank_1_follower.frame_b)
    annotation (Line(points={{200,-100},{480,-100}}, color={95,95,95}, thickness=0.5));
  connect(World_3.frame_b, planar_World_puck_1_1.frame_a)
    annotation (Line(points={{110,-100},{115,-100},{115,-300},{160,-300}}, color={95,95,95}, thickness=0.5));
  connect(planar_World_puck_1_1.frame_b, planar_World_puck_1_2.frame_a)
    annotation (Line(points={{200,-300},{240,-300}}, color={95,95,95}, thickness=0.5));
  connect(planar_World_puck_1_2.frame_b, planar_World_puck_1_3.frame_a)
    annotation (Line(points={{280,-300},{320,-300}}, color={95,95,95}, thickness=0.5));
  connect(planar_World_puck_1_3.frame_b, puck_1_planar_World_puck_1_follower.frame_b)
    annotation (Line(points={{360,-300},{480,-300}}, color={95,95,95}, thickness=0.5));
  connect(crank_1_weld_crank_1_grip_1_base.frame_b, grip_1_weld_crank_1_grip_1_follower.frame_b)
    annotation (Line(points={{600,-200},{795,-200},{795,-100},{800,-100}}, color={95,95,95}, thickness=0.5));
  connect(grip_1_knob_1_rigid_base.frame_b, knob_1.frame_a)
    annotation (Line(points={{920,-200},{1200,-200},{1200,-100},{1205,-100}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=3.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-460},{1280,60}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>mate rig.xml</code> (SimscapeMultibodyImportXML), exported by Simscape Multibody Link Version 7.4 from SolidWorks 28.0.0 on 11/25/26||00:00:00 by .</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Body slider-1 has no path to the ground (free body).</li></ul>
<p>Experiment: 3.0 s, about three swings of a pendulum as long as the mechanism's reach (0.196 m, period 0.89 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

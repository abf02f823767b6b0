within urdf_mimic;
model Mechanics "Mechanical model of urdf_mimic (11 bodies, 10 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, 0.0, -1.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body palm(
    m=1.0,
    r_CM={0.0, 0.0, 0.05},
    I_11=0.002, I_22=0.002, I_33=0.002,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part palm (nodeID palm)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,0})));
  Modelica.Mechanics.MultiBody.Parts.Body finger_a(
    m=0.1,
    r_CM={0.0, 0.0, 0.03},
    I_11=0.0001, I_22=0.0001, I_33=1e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part finger_a (nodeID finger_a)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={900,-300})));
  Modelica.Mechanics.MultiBody.Parts.Body finger_b(
    m=0.1,
    r_CM={0.0, 0.0, 0.03},
    I_11=0.0001, I_22=0.0001, I_33=1e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part finger_b (nodeID finger_b)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={900,-400})));
  Modelica.Mechanics.MultiBody.Parts.Body jaw_a(
    m=0.1,
    r_CM={0.01, 0.0, 0.0},
    I_11=1e-5, I_22=0.0001, I_33=0.0001,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part jaw_a (nodeID jaw_a)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={900,0})));
  Modelica.Mechanics.MultiBody.Parts.Body jaw_b(
    m=0.1,
    r_CM={-0.01, 0.0, 0.0},
    I_11=1e-5, I_22=0.0001, I_33=0.0001,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part jaw_b (nodeID jaw_b)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={900,-100})));
  Modelica.Mechanics.MultiBody.Parts.Body thumb(
    m=0.05,
    r_CM={0.0, 0.0, 0.02},
    I_11=1e-5, I_22=1e-5, I_33=1e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part thumb (nodeID thumb)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={900,-600})));
  Modelica.Mechanics.MultiBody.Parts.Body nail(
    m=0.01,
    r_CM={0.0, 0.0, 0.01},
    I_11=1e-6, I_22=1e-6, I_33=9.99999999999999e-7,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part nail (nodeID nail)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1300,-600})));
  Modelica.Mechanics.MultiBody.Parts.Body puck(
    m=0.3,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.001, I_22=0.001, I_33=0.002,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part puck (nodeID puck)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,-800})));
  Modelica.Mechanics.MultiBody.Parts.Body ball_link(
    m=0.2,
    r_CM={0.0, 0.0, 0.05},
    I_11=0.0002, I_22=0.0002, I_33=0.0002,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part ball_link (nodeID ball_link)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={900,-800})));
  Modelica.Mechanics.MultiBody.Parts.Body cardan(
    m=0.2,
    r_CM={0.0, 0.0, 0.05},
    I_11=0.0002, I_22=0.0002, I_33=0.0002,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part cardan (nodeID cardan)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1300,-800})));
  Modelica.Mechanics.MultiBody.Parts.Body drone(
    m=0.8,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.01, I_22=0.01, I_33=0.02,
    I_21=0.0, I_31=0.0, I_32=0.0,
    r_0(start={-1.0, 0.0, 2.0}, each fixed=true),
    v_0(start={0, 0, 0}, each fixed=true),
    angles_fixed=true,
    angles_start={0.0, 0.0, 0.0},
    w_0_fixed=true)
    "Part drone (nodeID drone)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,-1000})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation world_2(
    r={0.0, 0.0, 1.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.877582561890373, 0.479425538604203, 0.0},
    n_y={-0.479425538604203, 0.877582561890373, 0.0},
    animation=false)
    "Ground world (nodeID world::wrist) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={100,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation world_3(r={1.0, 0.0, 0.5}, animation=false)
    "Ground world (nodeID world::table) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={100,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation palm_knuckle_a(r={0.03, 0.0, 0.1}, animation=false)
    "Frame knuckle_a of palm (nodeID palm::knuckle_a)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation palm_knuckle_b(r={-0.03, 0.0, 0.1}, animation=false)
    "Frame knuckle_b of palm (nodeID palm::knuckle_b)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation palm_jaw_a_slide(r={0.0, 0.03, 0.1}, animation=false)
    "Frame jaw_a_slide of palm (nodeID palm::jaw_a_slide)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,-300})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation palm_jaw_b_slide(r={0.0, -0.03, 0.1}, animation=false)
    "Frame jaw_b_slide of palm (nodeID palm::jaw_b_slide)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,-400})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation palm_thumb_slide(r={0.03, 0.03, 0.05}, animation=false)
    "Frame thumb_slide of palm (nodeID palm::thumb_slide)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,-500})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation thumb_nail_hinge(r={0.0, 0.0, 0.04}, animation=false)
    "Frame nail_hinge of thumb (nodeID thumb::nail_hinge)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={900,-700})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation puck_shoulder_ball(r={0.0, 0.0, 0.05}, animation=false)
    "Frame shoulder_ball of puck (nodeID puck::shoulder_ball)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={580,-900})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ball_link_cardan_joint(
    r={0.0, 0.0, 0.1},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.955336489125606, 0.29552020666134, 0.0},
    n_y={-0.29552020666134, 0.955336489125606, 0.0},
    animation=false)
    "Frame cardan_joint of ball_link (nodeID ball_link::cardan_joint)" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={900,-900})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  urdf_mimic.Components.Prismatic table_1(
    n={1.0, 0.0, 0.0},
    s(start=0.0, fixed=true),
    v(start=0, fixed=true))
    "Joint table (nodeID table), primitive 1 of 3" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={180,-800})));
  urdf_mimic.Components.Prismatic table_2(
    n={0.0, 1.0, 0.0},
    s(start=0.0, fixed=true),
    v(start=0, fixed=true))
    "Joint table (nodeID table), primitive 2 of 3" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={260,-800})));
  urdf_mimic.Components.Revolute table_3(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint table (nodeID table), primitive 3 of 3" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={340,-800})));
  urdf_mimic.Components.Prismatic jaw_a_slide(
    n={0.0, 1.0, 0.0},
    s(start=0.0, fixed=true),
    v(start=0, fixed=true))
    "Joint jaw_a_slide (nodeID jaw_a_slide)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={660,0})));
  urdf_mimic.Components.Prismatic jaw_b_slide(
    n={0.0, -1.0, 0.0},
    s(start=0.0),
    v(start=0))
    "Joint jaw_b_slide (nodeID jaw_b_slide)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={660,-100})));
  urdf_mimic.Components.Revolute knuckle_a(
    n={0.0, 1.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint knuckle_a (nodeID knuckle_a)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={660,-300})));
  urdf_mimic.Components.Revolute knuckle_b(
    n={0.0, 1.0, 0.0},
    phi(start=0.0),
    w(start=0))
    "Joint knuckle_b (nodeID knuckle_b)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={660,-400})));
  urdf_mimic.Components.Prismatic thumb_slide(
    n={1.0, 0.0, 0.0},
    s(start=0.0),
    v(start=0))
    "Joint thumb_slide (nodeID thumb_slide)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={660,-600})));
  Modelica.Mechanics.MultiBody.Joints.Spherical shoulder_ball(
    enforceStates=true,
    useQuaternions=true,
    angles_fixed=true,
    w_rel_a_fixed=true)
    "Joint shoulder_ball (nodeID shoulder_ball)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={660,-800})));
  urdf_mimic.Components.Revolute nail_hinge(
    n={1.0, 0.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint nail_hinge (nodeID nail_hinge)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={980,-600})));
  urdf_mimic.Components.Revolute cardan_joint_1(
    n={1.0, 0.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint cardan_joint (nodeID cardan_joint), primitive 1 of 2" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={980,-800})));
  urdf_mimic.Components.Revolute cardan_joint_2(
    n={0.0, 1.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint cardan_joint (nodeID cardan_joint), primitive 2 of 2" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,-800})));

  // Couplings: joints whose coordinate follows another joint's (URDF mimic)
  Modelica.Mechanics.Rotational.Components.IdealGear knuckle_b_mimic(ratio=1/(-1.0))
    "knuckle_b = -1.0 * knuckle_a (URDF mimic)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={660,-500})));
  Modelica.Mechanics.Rotational.Components.IdealGearR2T jaw_b_slide_mimic(ratio=1)
    "jaw_b_slide = 1.0 * jaw_a_slide (URDF mimic): leader side" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={660,-200})));
  Modelica.Mechanics.Rotational.Components.IdealGearR2T jaw_b_slide_mimic_b(ratio=1/(1.0))
    "jaw_b_slide = 1.0 * jaw_a_slide (URDF mimic): follower side" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={740,-200})));
  Modelica.Mechanics.Rotational.Components.IdealGearR2T thumb_slide_mimic(ratio=1/(0.02))
    "thumb_slide = 0.02 * knuckle_a (URDF mimic)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={660,-700})));

  // Shapes: CAD meshes in each body frame, metres
equation
  connect(world.frame_b, world_2.frame_a)
    annotation (Line(points={{30,0},{90,0}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, world_3.frame_a)
    annotation (Line(points={{30,0},{35,0},{35,-100},{90,-100}}, color={95,95,95}, thickness=0.5));
  connect(palm.frame_a, palm_knuckle_a.frame_a)
    annotation (Line(points={{565,0},{560,0},{560,-100},{565,-100}}, color={95,95,95}, thickness=0.5));
  connect(palm.frame_a, palm_knuckle_b.frame_a)
    annotation (Line(points={{565,0},{555,0},{555,-200},{565,-200}}, color={95,95,95}, thickness=0.5));
  connect(palm.frame_a, palm_jaw_a_slide.frame_a)
    annotation (Line(points={{565,0},{550,0},{550,-300},{565,-300}}, color={95,95,95}, thickness=0.5));
  connect(palm.frame_a, palm_jaw_b_slide.frame_a)
    annotation (Line(points={{565,0},{545,0},{545,-400},{565,-400}}, color={95,95,95}, thickness=0.5));
  connect(palm.frame_a, palm_thumb_slide.frame_a)
    annotation (Line(points={{565,0},{540,0},{540,-500},{565,-500}}, color={95,95,95}, thickness=0.5));
  connect(thumb.frame_a, thumb_nail_hinge.frame_a)
    annotation (Line(points={{885,-600},{880,-600},{880,-700},{885,-700}}, color={95,95,95}, thickness=0.5));
  connect(puck.frame_a, puck_shoulder_ball.frame_a)
    annotation (Line(points={{565,-800},{560,-800},{560,-900},{565,-900}}, color={95,95,95}, thickness=0.5));
  connect(ball_link.frame_a, ball_link_cardan_joint.frame_a)
    annotation (Line(points={{885,-800},{875,-800},{875,-900},{880,-900}}, color={95,95,95}, thickness=0.5));
  connect(world_2.frame_b, palm.frame_a)
    annotation (Line(points={{110,0},{565,0}}, color={95,95,95}, thickness=0.5));
  connect(world_3.frame_b, table_1.frame_a)
    annotation (Line(points={{110,-100},{165,-100},{165,-800},{170,-800}}, color={95,95,95}, thickness=0.5));
  connect(table_1.frame_b, table_2.frame_a)
    annotation (Line(points={{190,-800},{250,-800}}, color={95,95,95}, thickness=0.5));
  connect(table_2.frame_b, table_3.frame_a)
    annotation (Line(points={{270,-800},{330,-800}}, color={95,95,95}, thickness=0.5));
  connect(table_3.frame_b, puck.frame_a)
    annotation (Line(points={{350,-800},{565,-800}}, color={95,95,95}, thickness=0.5));
  connect(palm_jaw_a_slide.frame_b, jaw_a_slide.frame_a)
    annotation (Line(points={{595,-300},{600,-300},{600,0},{650,0}}, color={95,95,95}, thickness=0.5));
  connect(jaw_a_slide.frame_b, jaw_a.frame_a)
    annotation (Line(points={{670,0},{885,0}}, color={95,95,95}, thickness=0.5));
  connect(palm_jaw_b_slide.frame_b, jaw_b_slide.frame_a)
    annotation (Line(points={{595,-400},{640,-400},{640,-100},{650,-100}}, color={95,95,95}, thickness=0.5));
  connect(jaw_b_slide.frame_b, jaw_b.frame_a)
    annotation (Line(points={{670,-100},{885,-100}}, color={95,95,95}, thickness=0.5));
  connect(palm_knuckle_a.frame_b, knuckle_a.frame_a)
    annotation (Line(points={{595,-100},{635,-100},{635,-300},{650,-300}}, color={95,95,95}, thickness=0.5));
  connect(knuckle_a.frame_b, finger_a.frame_a)
    annotation (Line(points={{670,-300},{885,-300}}, color={95,95,95}, thickness=0.5));
  connect(palm_knuckle_b.frame_b, knuckle_b.frame_a)
    annotation (Line(points={{595,-200},{630,-200},{630,-395},{645,-395},{645,-400},{650,-400}}, color={95,95,95}, thickness=0.5));
  connect(knuckle_b.frame_b, finger_b.frame_a)
    annotation (Line(points={{670,-400},{885,-400}}, color={95,95,95}, thickness=0.5));
  connect(palm_thumb_slide.frame_b, thumb_slide.frame_a)
    annotation (Line(points={{595,-500},{600,-500},{600,-600},{650,-600}}, color={95,95,95}, thickness=0.5));
  connect(thumb_slide.frame_b, thumb.frame_a)
    annotation (Line(points={{670,-600},{885,-600}}, color={95,95,95}, thickness=0.5));
  connect(puck_shoulder_ball.frame_b, shoulder_ball.frame_a)
    annotation (Line(points={{595,-900},{640,-900},{640,-800},{645,-800}}, color={95,95,95}, thickness=0.5));
  connect(shoulder_ball.frame_b, ball_link.frame_a)
    annotation (Line(points={{675,-800},{885,-800}}, color={95,95,95}, thickness=0.5));
  connect(thumb_nail_hinge.frame_b, nail_hinge.frame_a)
    annotation (Line(points={{915,-700},{965,-700},{965,-600},{970,-600}}, color={95,95,95}, thickness=0.5));
  connect(nail_hinge.frame_b, nail.frame_a)
    annotation (Line(points={{990,-600},{1285,-600}}, color={95,95,95}, thickness=0.5));
  connect(ball_link_cardan_joint.frame_b, cardan_joint_1.frame_a)
    annotation (Line(points={{920,-900},{960,-900},{960,-800},{965,-800}}, color={95,95,95}, thickness=0.5));
  connect(cardan_joint_1.frame_b, cardan_joint_2.frame_a)
    annotation (Line(points={{995,-800},{1045,-800}}, color={95,95,95}, thickness=0.5));
  connect(cardan_joint_2.frame_b, cardan.frame_a)
    annotation (Line(points={{1075,-800},{1285,-800}}, color={95,95,95}, thickness=0.5));
  connect(knuckle_a.drive, knuckle_b_mimic.flange_a)
    annotation (Line(points={{654,-290},{654,-280},{645,-280},{645,-475},{640,-475},{640,-500},{645,-500}}, color={0,0,0}));
  connect(knuckle_b_mimic.flange_b, knuckle_b.drive)
    annotation (Line(points={{675,-500},{680,-500},{680,-380},{654,-380},{654,-390}}, color={0,0,0}));
  connect(jaw_b_slide_mimic.flangeT, jaw_a_slide.drive)
    annotation (Line(points={{675,-200},{680,-200},{680,20},{654,20},{654,10}}, color={0,0,0}));
  connect(jaw_b_slide_mimic_b.flangeT, jaw_b_slide.drive)
    annotation (Line(points={{760,-200},{765,-200},{765,-80},{654,-80},{654,-90}}, color={0,0,0}));
  connect(jaw_b_slide_mimic.flangeR, jaw_b_slide_mimic_b.flangeR)
    annotation (Line(points={{645,-200},{640,-200},{640,-220},{715,-220},{715,-200},{720,-200}}, color={0,0,0}));
  connect(knuckle_a.drive, thumb_slide_mimic.flangeR)
    annotation (Line(points={{654,-290},{654,-280},{675,-280},{675,-470},{635,-470},{635,-700},{645,-700}}, color={0,0,0}));
  connect(thumb_slide_mimic.flangeT, thumb_slide.drive)
    annotation (Line(points={{675,-700},{680,-700},{680,-580},{654,-580},{654,-590}}, color={0,0,0}));
  annotation (
    experiment(StopTime=9.0, Interval=0.02, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-1060},{1360,60}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>mimic.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Body drone has no path to the ground (free body).</li></ul>
<p>Experiment: 9.0 s, about three swings of a pendulum as long as the mechanism's reach (2.236 m, period 3.0 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

within urdf_mimic;
model Mechanics "Mechanical model of urdf_mimic (11 bodies, 10 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, 0.0, -1.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-160,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body palm(
    m=1.0,
    r_CM={0.0, 0.0, 0.05},
    I_11=0.002, I_22=0.002, I_33=0.002,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part palm (nodeID palm)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,0})));
  Modelica.Mechanics.MultiBody.Parts.Body finger_a(
    m=0.1,
    r_CM={0.0, 0.0, 0.03},
    I_11=0.0001, I_22=0.0001, I_33=1e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part finger_a (nodeID finger_a)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));
  Modelica.Mechanics.MultiBody.Parts.Body finger_b(
    m=0.1,
    r_CM={0.0, 0.0, 0.03},
    I_11=0.0001, I_22=0.0001, I_33=1e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part finger_b (nodeID finger_b)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-50})));
  Modelica.Mechanics.MultiBody.Parts.Body jaw_a(
    m=0.1,
    r_CM={0.01, 0.0, 0.0},
    I_11=1e-5, I_22=0.0001, I_33=0.0001,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part jaw_a (nodeID jaw_a)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-75})));
  Modelica.Mechanics.MultiBody.Parts.Body jaw_b(
    m=0.1,
    r_CM={-0.01, 0.0, 0.0},
    I_11=1e-5, I_22=0.0001, I_33=0.0001,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part jaw_b (nodeID jaw_b)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-100})));
  Modelica.Mechanics.MultiBody.Parts.Body thumb(
    m=0.05,
    r_CM={0.0, 0.0, 0.02},
    I_11=1e-5, I_22=1e-5, I_33=1e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part thumb (nodeID thumb)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-125})));
  Modelica.Mechanics.MultiBody.Parts.Body nail(
    m=0.01,
    r_CM={0.0, 0.0, 0.01},
    I_11=1e-6, I_22=1e-6, I_33=9.99999999999999e-7,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part nail (nodeID nail)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-150})));
  Modelica.Mechanics.MultiBody.Parts.Body puck(
    m=0.3,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.001, I_22=0.001, I_33=0.002,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part puck (nodeID puck)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-175})));
  Modelica.Mechanics.MultiBody.Parts.Body ball_link(
    m=0.2,
    r_CM={0.0, 0.0, 0.05},
    I_11=0.0002, I_22=0.0002, I_33=0.0002,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part ball_link (nodeID ball_link)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-200})));
  Modelica.Mechanics.MultiBody.Parts.Body cardan(
    m=0.2,
    r_CM={0.0, 0.0, 0.05},
    I_11=0.0002, I_22=0.0002, I_33=0.0002,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part cardan (nodeID cardan)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-225})));
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
    "Part drone (nodeID drone)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-250})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation world_2(
    r={0.0, 0.0, 1.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.877582561890373, 0.479425538604203, 0.0},
    n_y={-0.479425538604203, 0.877582561890373, 0.0},
    animation=false)
    "Ground world (nodeID world::wrist) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation world_3(r={1.0, 0.0, 0.5}, animation=false)
    "Ground world (nodeID world::table) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation palm_knuckle_a(r={0.03, 0.0, 0.1}, animation=false)
    "Frame knuckle_a of palm (nodeID palm::knuckle_a)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-50})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation palm_knuckle_b(r={-0.03, 0.0, 0.1}, animation=false)
    "Frame knuckle_b of palm (nodeID palm::knuckle_b)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-75})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation palm_jaw_a_slide(r={0.0, 0.03, 0.1}, animation=false)
    "Frame jaw_a_slide of palm (nodeID palm::jaw_a_slide)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation palm_jaw_b_slide(r={0.0, -0.03, 0.1}, animation=false)
    "Frame jaw_b_slide of palm (nodeID palm::jaw_b_slide)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-125})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation palm_thumb_slide(r={0.03, 0.03, 0.05}, animation=false)
    "Frame thumb_slide of palm (nodeID palm::thumb_slide)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-150})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation thumb_nail_hinge(r={0.0, 0.0, 0.04}, animation=false)
    "Frame nail_hinge of thumb (nodeID thumb::nail_hinge)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-175})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation puck_shoulder_ball(r={0.0, 0.0, 0.05}, animation=false)
    "Frame shoulder_ball of puck (nodeID puck::shoulder_ball)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ball_link_cardan_joint(
    r={0.0, 0.0, 0.1},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.955336489125606, 0.29552020666134, 0.0},
    n_y={-0.29552020666134, 0.955336489125606, 0.0},
    animation=false)
    "Frame cardan_joint of ball_link (nodeID ball_link::cardan_joint)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-225})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  urdf_mimic.Components.Prismatic table_1(
    n={1.0, 0.0, 0.0},
    s(start=0.0, fixed=true),
    v(start=0, fixed=true))
    "Joint table (nodeID table), primitive 1 of 3" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));
  urdf_mimic.Components.Prismatic table_2(
    n={0.0, 1.0, 0.0},
    s(start=0.0, fixed=true),
    v(start=0, fixed=true))
    "Joint table (nodeID table), primitive 2 of 3" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-25})));
  urdf_mimic.Components.Revolute table_3(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint table (nodeID table), primitive 3 of 3" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-50})));
  urdf_mimic.Components.Prismatic jaw_a_slide(
    n={0.0, 1.0, 0.0},
    s(start=0.0, fixed=true),
    v(start=0, fixed=true))
    "Joint jaw_a_slide (nodeID jaw_a_slide)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-75})));
  urdf_mimic.Components.Prismatic jaw_b_slide(
    n={0.0, -1.0, 0.0},
    s(start=0.0),
    v(start=0))
    "Joint jaw_b_slide (nodeID jaw_b_slide)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-100})));
  urdf_mimic.Components.Revolute knuckle_a(
    n={0.0, 1.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint knuckle_a (nodeID knuckle_a)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-125})));
  urdf_mimic.Components.Revolute knuckle_b(
    n={0.0, 1.0, 0.0},
    phi(start=0.0),
    w(start=0))
    "Joint knuckle_b (nodeID knuckle_b)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-150})));
  urdf_mimic.Components.Prismatic thumb_slide(
    n={1.0, 0.0, 0.0},
    s(start=0.0),
    v(start=0))
    "Joint thumb_slide (nodeID thumb_slide)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-175})));
  Modelica.Mechanics.MultiBody.Joints.Spherical shoulder_ball(
    enforceStates=true,
    useQuaternions=true,
    angles_fixed=true,
    w_rel_a_fixed=true)
    "Joint shoulder_ball (nodeID shoulder_ball)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-200})));
  urdf_mimic.Components.Revolute nail_hinge(
    n={1.0, 0.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint nail_hinge (nodeID nail_hinge)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-225})));
  urdf_mimic.Components.Revolute cardan_joint_1(
    n={1.0, 0.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint cardan_joint (nodeID cardan_joint), primitive 1 of 2" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-250})));
  urdf_mimic.Components.Revolute cardan_joint_2(
    n={0.0, 1.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint cardan_joint (nodeID cardan_joint), primitive 2 of 2" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-275})));

  // Couplings: joints whose coordinate follows another joint's (URDF mimic)
  Modelica.Mechanics.Rotational.Components.IdealGear knuckle_b_mimic(ratio=1/(-1.0))
    "knuckle_b = -1.0 * knuckle_a (URDF mimic)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-300})));
  Modelica.Mechanics.Rotational.Components.IdealGearR2T jaw_b_slide_mimic(ratio=1)
    "jaw_b_slide = 1.0 * jaw_a_slide (URDF mimic): leader side" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-325})));
  Modelica.Mechanics.Rotational.Components.IdealGearR2T jaw_b_slide_mimic_b(ratio=1/(1.0))
    "jaw_b_slide = 1.0 * jaw_a_slide (URDF mimic): follower side" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-350})));
  Modelica.Mechanics.Rotational.Components.IdealGearR2T thumb_slide_mimic(ratio=1/(0.02))
    "thumb_slide = 0.02 * knuckle_a (URDF mimic)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-375})));

  // Shapes: CAD meshes in each body frame, metres
equation
  connect(world.frame_b, world_2.frame_a);
  connect(world.frame_b, world_3.frame_a);
  connect(palm.frame_a, palm_knuckle_a.frame_a);
  connect(palm.frame_a, palm_knuckle_b.frame_a);
  connect(palm.frame_a, palm_jaw_a_slide.frame_a);
  connect(palm.frame_a, palm_jaw_b_slide.frame_a);
  connect(palm.frame_a, palm_thumb_slide.frame_a);
  connect(thumb.frame_a, thumb_nail_hinge.frame_a);
  connect(puck.frame_a, puck_shoulder_ball.frame_a);
  connect(ball_link.frame_a, ball_link_cardan_joint.frame_a);
  connect(world_2.frame_b, palm.frame_a);
  connect(world_3.frame_b, table_1.frame_a);
  connect(table_1.frame_b, table_2.frame_a);
  connect(table_2.frame_b, table_3.frame_a);
  connect(table_3.frame_b, puck.frame_a);
  connect(palm_jaw_a_slide.frame_b, jaw_a_slide.frame_a);
  connect(jaw_a_slide.frame_b, jaw_a.frame_a);
  connect(palm_jaw_b_slide.frame_b, jaw_b_slide.frame_a);
  connect(jaw_b_slide.frame_b, jaw_b.frame_a);
  connect(palm_knuckle_a.frame_b, knuckle_a.frame_a);
  connect(knuckle_a.frame_b, finger_a.frame_a);
  connect(palm_knuckle_b.frame_b, knuckle_b.frame_a);
  connect(knuckle_b.frame_b, finger_b.frame_a);
  connect(palm_thumb_slide.frame_b, thumb_slide.frame_a);
  connect(thumb_slide.frame_b, thumb.frame_a);
  connect(puck_shoulder_ball.frame_b, shoulder_ball.frame_a);
  connect(shoulder_ball.frame_b, ball_link.frame_a);
  connect(thumb_nail_hinge.frame_b, nail_hinge.frame_a);
  connect(nail_hinge.frame_b, nail.frame_a);
  connect(ball_link_cardan_joint.frame_b, cardan_joint_1.frame_a);
  connect(cardan_joint_1.frame_b, cardan_joint_2.frame_a);
  connect(cardan_joint_2.frame_b, cardan.frame_a);
  connect(knuckle_a.drive, knuckle_b_mimic.flange_a);
  connect(knuckle_b_mimic.flange_b, knuckle_b.drive);
  connect(jaw_b_slide_mimic.flangeT, jaw_a_slide.drive);
  connect(jaw_b_slide_mimic_b.flangeT, jaw_b_slide.drive);
  connect(jaw_b_slide_mimic.flangeR, jaw_b_slide_mimic_b.flangeR);
  connect(knuckle_a.drive, thumb_slide_mimic.flangeR);
  connect(thumb_slide_mimic.flangeT, thumb_slide.drive);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>mimic.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Body drone has no path to the ground (free body).</li></ul>
</html>"));
end Mechanics;

within urdf_arm;
model Mechanics "Mechanical model of urdf_arm (6 bodies, 6 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, 0.0, -1.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-160,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body base(
    m=4.0,
    r_CM={0.0, 0.0, 0.05},
    I_11=0.02, I_22=0.02, I_33=0.03,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part base (nodeID base)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,0})));
  Modelica.Mechanics.MultiBody.Parts.Body shoulder(
    m=2.5,
    r_CM={0.01, 0.02, 0.15},
    I_11=0.0466703324113328, I_22=0.0394697789806108, I_33=0.0238598886080563,
    I_21=0.00542548612894775, I_31=-0.000731006587573745, I_32=0.00902169038250619,
    animation=false)
    "Part shoulder (nodeID shoulder)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));
  Modelica.Mechanics.MultiBody.Parts.Body upper_arm(
    m=1.8,
    r_CM={0.0, 0.0, 0.2},
    I_11=0.03, I_22=0.03, I_33=0.002,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part upper_arm (nodeID upper_arm)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-50})));
  Modelica.Mechanics.MultiBody.Parts.Body forearm(
    m=1.1,
    r_CM={0.12, 0.0, 0.0},
    I_11=0.001, I_22=0.01, I_33=0.01,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part forearm (nodeID forearm)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-75})));
  Modelica.Mechanics.MultiBody.Parts.Body slide(
    m=0.4,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0001, I_22=0.0001, I_33=0.0001,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part slide (nodeID slide)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-100})));
  Modelica.Mechanics.MultiBody.Parts.Body tool(
    m=0.2,
    r_CM={0.0, 0.0, 0.02},
    I_11=2e-5, I_22=2e-5, I_33=1e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part tool (nodeID tool)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-125})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation world_2(
    r={0.5, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0, 1.0, 0.0},
    n_y={-1.0, 0.0, 0.0},
    animation=false)
    "Ground world (nodeID world::mount) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation base_shoulder_yaw(r={0.0, 0.0, 0.1}, animation=false)
    "Frame shoulder_yaw of base (nodeID base::shoulder_yaw)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation shoulder_shoulder_pitch(
    r={0.0, 0.0, 0.3},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.936293363584199, -0.289629477625516, -0.198669330795061},
    n_y={0.312991825785468, 0.944702485994894, 0.0978433950072557},
    animation=false)
    "Frame shoulder_pitch of shoulder (nodeID shoulder::shoulder_pitch)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-50})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation upper_arm_elbow(
    r={0.0, 0.0, 0.4},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={1.0, 0.0, 0.0},
    n_y={0.0, 0.0, 1.0},
    animation=false)
    "Frame elbow of upper_arm (nodeID upper_arm::elbow)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-75})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation forearm_extend(r={0.25, 0.0, 0.0}, animation=false)
    "Frame extend of forearm (nodeID forearm::extend)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation slide_tool_mount(
    r={0.05, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.764842187284488, 0.0, -0.644217687237691},
    n_y={0.0, 1.0, 0.0},
    animation=false)
    "Frame tool_mount of slide (nodeID slide::tool_mount)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-125})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  urdf_arm.Components.Revolute shoulder_yaw(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint shoulder_yaw (nodeID shoulder_yaw)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));
  urdf_arm.Components.Revolute shoulder_pitch(
    n={0.0, 1.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint shoulder_pitch (nodeID shoulder_pitch)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-25})));
  urdf_arm.Components.Revolute elbow(
    n={0.6, 0.0, 0.8},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint elbow (nodeID elbow)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-50})));
  urdf_arm.Components.Prismatic extend(
    n={1.0, 0.0, 0.0},
    s(start=0.0, fixed=true),
    v(start=0, fixed=true))
    "Joint extend (nodeID extend)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-75})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape base_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/base.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={26, 51, 204})
    "Shape of base" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,0})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape shoulder_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/shoulder.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={255, 128, 0})
    "Shape of shoulder" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-25})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape upper_arm_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/upper_arm.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of upper_arm" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-50})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape forearm_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/forearm.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of forearm" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-75})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape slide_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/slide.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of slide" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape tool_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/tool.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of tool" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-125})));
equation
  connect(world.frame_b, world_2.frame_a);
  connect(base.frame_a, base_shoulder_yaw.frame_a);
  connect(shoulder.frame_a, shoulder_shoulder_pitch.frame_a);
  connect(upper_arm.frame_a, upper_arm_elbow.frame_a);
  connect(forearm.frame_a, forearm_extend.frame_a);
  connect(slide.frame_a, slide_tool_mount.frame_a);
  connect(world_2.frame_b, base.frame_a);
  connect(base_shoulder_yaw.frame_b, shoulder_yaw.frame_a);
  connect(shoulder_yaw.frame_b, shoulder.frame_a);
  connect(shoulder_shoulder_pitch.frame_b, shoulder_pitch.frame_a);
  connect(shoulder_pitch.frame_b, upper_arm.frame_a);
  connect(upper_arm_elbow.frame_b, elbow.frame_a);
  connect(elbow.frame_b, forearm.frame_a);
  connect(forearm_extend.frame_b, extend.frame_a);
  connect(extend.frame_b, slide.frame_a);
  connect(slide_tool_mount.frame_b, tool.frame_a);
  connect(base.frame_a, base_shape.frame_a);
  connect(shoulder.frame_a, shoulder_shape.frame_a);
  connect(upper_arm.frame_a, upper_arm_shape.frame_a);
  connect(forearm.frame_a, forearm_shape.frame_a);
  connect(slide.frame_a, slide_shape.frame_a);
  connect(tool.frame_a, tool_shape.frame_a);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>arm.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
</html>"));
end Mechanics;

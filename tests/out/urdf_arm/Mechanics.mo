within urdf_arm;
model Mechanics "Mechanical model of urdf_arm (6 bodies, 6 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, 0.0, -1.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body base(
    m=4.0,
    r_CM={0.0, 0.0, 0.05},
    I_11=0.02, I_22=0.02, I_33=0.03,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part base (nodeID base)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body shoulder(
    m=2.5,
    r_CM={0.01, 0.02, 0.15},
    I_11=0.0466703324113328, I_22=0.0394697789806108, I_33=0.0238598886080563,
    I_21=0.00542548612894775, I_31=-0.000731006587573745, I_32=0.00902169038250619,
    animation=false)
    "Part shoulder (nodeID shoulder)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body upper_arm(
    m=1.8,
    r_CM={0.0, 0.0, 0.2},
    I_11=0.03, I_22=0.03, I_33=0.002,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part upper_arm (nodeID upper_arm)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));
  Modelica.Mechanics.MultiBody.Parts.Body forearm(
    m=1.1,
    r_CM={0.12, 0.0, 0.0},
    I_11=0.001, I_22=0.01, I_33=0.01,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part forearm (nodeID forearm)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,0})));
  Modelica.Mechanics.MultiBody.Parts.Body slide(
    m=0.4,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0001, I_22=0.0001, I_33=0.0001,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part slide (nodeID slide)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1700,0})));
  Modelica.Mechanics.MultiBody.Parts.Body tool(
    m=0.2,
    r_CM={0.0, 0.0, 0.02},
    I_11=2e-5, I_22=2e-5, I_33=1e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part tool (nodeID tool)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={2020,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation world_2(
    r={0.5, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.0, 1.0, 0.0},
    n_y={-1.0, 0.0, 0.0},
    animation=false)
    "Ground world (nodeID world::mount) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={100,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation base_shoulder_yaw(r={0.0, 0.0, 0.1}, animation=false)
    "Frame shoulder_yaw of base (nodeID base::shoulder_yaw)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation shoulder_shoulder_pitch(
    r={0.0, 0.0, 0.3},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.936293363584199, -0.289629477625516, -0.198669330795061},
    n_y={0.312991825785468, 0.944702485994894, 0.0978433950072557},
    animation=false)
    "Frame shoulder_pitch of shoulder (nodeID shoulder::shoulder_pitch)" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation upper_arm_elbow(
    r={0.0, 0.0, 0.4},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={1.0, 0.0, 0.0},
    n_y={0.0, 0.0, 1.0},
    animation=false)
    "Frame elbow of upper_arm (nodeID upper_arm::elbow)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation forearm_extend(r={0.25, 0.0, 0.0}, animation=false)
    "Frame extend of forearm (nodeID forearm::extend)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation slide_tool_mount(
    r={0.05, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.764842187284488, 0.0, -0.644217687237691},
    n_y={0.0, 1.0, 0.0},
    animation=false)
    "Frame tool_mount of slide (nodeID slide::tool_mount)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1700,-200})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  urdf_arm.Components.Revolute shoulder_yaw(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint shoulder_yaw (nodeID shoulder_yaw)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={500,0})));
  urdf_arm.Components.Revolute shoulder_pitch(
    n={0.0, 1.0, 0.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint shoulder_pitch (nodeID shoulder_pitch)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={820,0})));
  urdf_arm.Components.Revolute elbow(
    n={0.6, 0.0, 0.8},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint elbow (nodeID elbow)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,0})));
  urdf_arm.Components.Prismatic extend(
    n={1.0, 0.0, 0.0},
    s(start=0.0, fixed=true),
    v(start=0, fixed=true))
    "Joint extend (nodeID extend)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1460,0})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape base_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/base.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={26, 51, 204})
    "Shape of base" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape shoulder_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/shoulder.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={255, 128, 0})
    "Shape of shoulder" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape upper_arm_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/upper_arm.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of upper_arm" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape forearm_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/forearm.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of forearm" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape slide_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/slide.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of slide" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1700,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape tool_shape(
    shapeType="modelica://urdf_arm/Resources/Shapes/tool.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of tool" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={2020,-100})));
equation
  connect(world.frame_b, world_2.frame_a)
    annotation (Line(points={{30,0},{90,0}}, color={95,95,95}, thickness=0.5));
  connect(base.frame_a, base_shoulder_yaw.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-200},{405,-200}}, color={95,95,95}, thickness=0.5));
  connect(shoulder.frame_a, shoulder_shoulder_pitch.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-200},{720,-200}}, color={95,95,95}, thickness=0.5));
  connect(upper_arm.frame_a, upper_arm_elbow.frame_a)
    annotation (Line(points={{1045,0},{1040,0},{1040,-200},{1045,-200}}, color={95,95,95}, thickness=0.5));
  connect(forearm.frame_a, forearm_extend.frame_a)
    annotation (Line(points={{1365,0},{1360,0},{1360,-200},{1365,-200}}, color={95,95,95}, thickness=0.5));
  connect(slide.frame_a, slide_tool_mount.frame_a)
    annotation (Line(points={{1685,0},{1680,0},{1680,-200},{1685,-200}}, color={95,95,95}, thickness=0.5));
  connect(world_2.frame_b, base.frame_a)
    annotation (Line(points={{110,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(base_shoulder_yaw.frame_b, shoulder_yaw.frame_a)
    annotation (Line(points={{435,-200},{485,-200},{485,0},{490,0}}, color={95,95,95}, thickness=0.5));
  connect(shoulder_yaw.frame_b, shoulder.frame_a)
    annotation (Line(points={{510,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(shoulder_shoulder_pitch.frame_b, shoulder_pitch.frame_a)
    annotation (Line(points={{760,-200},{800,-200},{800,0},{805,0}}, color={95,95,95}, thickness=0.5));
  connect(shoulder_pitch.frame_b, upper_arm.frame_a)
    annotation (Line(points={{835,0},{1045,0}}, color={95,95,95}, thickness=0.5));
  connect(upper_arm_elbow.frame_b, elbow.frame_a)
    annotation (Line(points={{1075,-200},{1125,-200},{1125,0},{1130,0}}, color={95,95,95}, thickness=0.5));
  connect(elbow.frame_b, forearm.frame_a)
    annotation (Line(points={{1150,0},{1365,0}}, color={95,95,95}, thickness=0.5));
  connect(forearm_extend.frame_b, extend.frame_a)
    annotation (Line(points={{1395,-200},{1445,-200},{1445,0},{1450,0}}, color={95,95,95}, thickness=0.5));
  connect(extend.frame_b, slide.frame_a)
    annotation (Line(points={{1470,0},{1685,0}}, color={95,95,95}, thickness=0.5));
  connect(slide_tool_mount.frame_b, tool.frame_a)
    annotation (Line(points={{1715,-200},{2000,-200},{2000,0},{2005,0}}, color={95,95,95}, thickness=0.5));
  connect(base.frame_a, base_shape.frame_a)
    annotation (Line(points={{405,0},{395,0},{395,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
  connect(shoulder.frame_a, shoulder_shape.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-100},{725,-100}}, color={95,95,95}, thickness=0.5));
  connect(upper_arm.frame_a, upper_arm_shape.frame_a)
    annotation (Line(points={{1045,0},{1035,0},{1035,-100},{1045,-100}}, color={95,95,95}, thickness=0.5));
  connect(forearm.frame_a, forearm_shape.frame_a)
    annotation (Line(points={{1365,0},{1355,0},{1355,-100},{1365,-100}}, color={95,95,95}, thickness=0.5));
  connect(slide.frame_a, slide_shape.frame_a)
    annotation (Line(points={{1685,0},{1675,0},{1675,-100},{1690,-100}}, color={95,95,95}, thickness=0.5));
  connect(tool.frame_a, tool_shape.frame_a)
    annotation (Line(points={{2005,0},{1995,0},{1995,-100},{2010,-100}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=7.0, Interval=0.02, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-260},{2080,60}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>arm.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 7.0 s, about three swings of a pendulum as long as the mechanism's reach (1.047 m, period 2.05 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

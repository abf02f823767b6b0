within urdf_fourbar;
model Mechanics "Mechanical model of urdf_fourbar (4 bodies, 5 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, 0.0, -1.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-160,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body ground(
    m=5.0,
    r_CM={1.0, 0.0, 0.0},
    I_11=0.1, I_22=0.1, I_33=0.1,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part ground (nodeID ground)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,0})));
  Modelica.Mechanics.MultiBody.Parts.Body crank(
    m=0.5,
    r_CM={0.0, 0.5, 0.0},
    I_11=0.04, I_22=0.001, I_33=0.04,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part crank (nodeID crank)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));
  Modelica.Mechanics.MultiBody.Parts.Body coupler(
    m=1.0,
    r_CM={1.0, 0.0, 0.0},
    I_11=0.001, I_22=0.33, I_33=0.33,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part coupler (nodeID coupler)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-50})));
  Modelica.Mechanics.MultiBody.Parts.Body rocker(
    m=0.5,
    r_CM={0.0, 0.5, 0.0},
    I_11=0.04, I_22=0.001, I_33=0.04,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part rocker (nodeID rocker)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-75})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation crank_crank_coupler(r={0.0, 1.0, 0.0}, animation=false)
    "Frame crank_coupler of crank (nodeID crank::crank_coupler)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation ground_rocker_pivot(r={2.0, 0.0, 0.0}, animation=false)
    "Frame rocker_pivot of ground (nodeID ground::rocker_pivot)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation coupler_coupler_rocker(r={2.0, 0.0, 0.0}, animation=false)
    "Frame coupler_rocker of coupler (nodeID coupler::coupler_rocker)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-50})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation rocker_coupler_rocker(r={0.0, 1.0, 0.0}, animation=false)
    "Frame coupler_rocker of rocker (nodeID rocker::coupler_rocker)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-75})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  urdf_fourbar.Components.Revolute crank_pivot(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint crank_pivot (nodeID crank_pivot)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));
  urdf_fourbar.Components.Revolute crank_coupler(
    n={0.0, 0.0, 1.0},
    phi(start=0.0),
    w(start=0))
    "Joint crank_coupler (nodeID crank_coupler)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-25})));
  urdf_fourbar.Components.Revolute coupler_rocker(
    n={0.0, 0.0, 1.0},
    phi(start=0.0),
    w(start=0))
    "Joint coupler_rocker (nodeID coupler_rocker)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-50})));
  Modelica.Mechanics.MultiBody.Joints.RevolutePlanarLoopConstraint rocker_pivot(n={0.0, 0.0, 1.0}, animation=false)
    "Joint rocker_pivot (nodeID rocker_pivot): closes a planar loop" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-75})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape ground_shape(
    shapeType="modelica://urdf_fourbar/Resources/Shapes/ground.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of ground" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,0})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape crank_shape(
    shapeType="modelica://urdf_fourbar/Resources/Shapes/crank.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of crank" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-25})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape coupler_shape(
    shapeType="modelica://urdf_fourbar/Resources/Shapes/coupler.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of coupler" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-50})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape rocker_shape(
    shapeType="modelica://urdf_fourbar/Resources/Shapes/rocker.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of rocker" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-75})));
equation
  connect(crank.frame_a, crank_crank_coupler.frame_a);
  connect(ground.frame_a, ground_rocker_pivot.frame_a);
  connect(coupler.frame_a, coupler_coupler_rocker.frame_a);
  connect(rocker.frame_a, rocker_coupler_rocker.frame_a);
  connect(world.frame_b, ground.frame_a);
  connect(ground.frame_a, crank_pivot.frame_a);
  connect(crank_pivot.frame_b, crank.frame_a);
  connect(crank_crank_coupler.frame_b, crank_coupler.frame_a);
  connect(crank_coupler.frame_b, coupler.frame_a);
  connect(coupler_coupler_rocker.frame_b, coupler_rocker.frame_a);
  connect(coupler_rocker.frame_b, rocker_coupler_rocker.frame_b);
  connect(ground_rocker_pivot.frame_b, rocker_pivot.frame_a);
  connect(rocker_pivot.frame_b, rocker.frame_a);
  connect(ground.frame_a, ground_shape.frame_a);
  connect(crank.frame_a, crank_shape.frame_a);
  connect(coupler.frame_a, coupler_shape.frame_a);
  connect(rocker.frame_a, rocker_shape.frame_a);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>fourbar.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Joint rocker_pivot closes a loop: a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations.</li></ul>
</html>"));
end Mechanics;

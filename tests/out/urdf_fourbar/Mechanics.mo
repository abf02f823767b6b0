within urdf_fourbar;
model Mechanics "Mechanical model of urdf_fourbar (4 bodies, 5 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, 0.0, -1.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body ground(
    m=5.0,
    r_CM={1.0, 0.0, 0.0},
    I_11=0.1, I_22=0.1, I_33=0.1,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part ground (nodeID ground)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body crank(
    m=0.5,
    r_CM={0.0, 0.5, 0.0},
    I_11=0.04, I_22=0.001, I_33=0.04,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part crank (nodeID crank)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));
  Modelica.Mechanics.MultiBody.Parts.Body coupler(
    m=1.0,
    r_CM={1.0, 0.0, 0.0},
    I_11=0.001, I_22=0.33, I_33=0.33,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part coupler (nodeID coupler)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,0})));
  Modelica.Mechanics.MultiBody.Parts.Body rocker(
    m=0.5,
    r_CM={0.0, 0.5, 0.0},
    I_11=0.04, I_22=0.001, I_33=0.04,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part rocker (nodeID rocker)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1380,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation crank_crank_coupler(r={0.0, 1.0, 0.0}, animation=false)
    "Frame crank_coupler of crank (nodeID crank::crank_coupler)" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={740,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation ground_rocker_pivot(r={2.0, 0.0, 0.0}, animation=false)
    "Frame rocker_pivot of ground (nodeID ground::rocker_pivot)" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={420,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation coupler_coupler_rocker(r={2.0, 0.0, 0.0}, animation=false)
    "Frame coupler_rocker of coupler (nodeID coupler::coupler_rocker)" annotation (Placement(transformation(extent={{-20,-20},{20,20}}, origin={1060,-200})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation rocker_coupler_rocker(r={0.0, 1.0, 0.0}, animation=false)
    "Frame coupler_rocker of rocker (nodeID rocker::coupler_rocker)" annotation (Placement(transformation(extent={{20,-20},{-20,20}}, origin={1300,0})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  urdf_fourbar.Components.Revolute crank_pivot(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint crank_pivot (nodeID crank_pivot)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={500,0})));
  urdf_fourbar.Components.Revolute crank_coupler(
    n={0.0, 0.0, 1.0},
    phi(start=0.0),
    w(start=0))
    "Joint crank_coupler (nodeID crank_coupler)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={820,0})));
  urdf_fourbar.Components.Revolute coupler_rocker(
    n={0.0, 0.0, 1.0},
    phi(start=0.0),
    w(start=0))
    "Joint coupler_rocker (nodeID coupler_rocker)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1140,0})));
  Modelica.Mechanics.MultiBody.Joints.RevolutePlanarLoopConstraint rocker_pivot(n={0.0, 0.0, 1.0}, animation=false)
    "Joint rocker_pivot (nodeID rocker_pivot): closes a planar loop" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1140,-100})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape ground_shape(
    shapeType="modelica://urdf_fourbar/Resources/Shapes/ground.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of ground" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={420,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape crank_shape(
    shapeType="modelica://urdf_fourbar/Resources/Shapes/crank.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of crank" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={740,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape coupler_shape(
    shapeType="modelica://urdf_fourbar/Resources/Shapes/coupler.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of coupler" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={1060,-100})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape rocker_shape(
    shapeType="modelica://urdf_fourbar/Resources/Shapes/rocker.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of rocker" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={1380,-100})));
equation
  connect(crank.frame_a, crank_crank_coupler.frame_a)
    annotation (Line(points={{725,0},{715,0},{715,-200},{720,-200}}, color={95,95,95}, thickness=0.5));
  connect(ground.frame_a, ground_rocker_pivot.frame_a)
    annotation (Line(points={{405,0},{395,0},{395,-200},{400,-200}}, color={95,95,95}, thickness=0.5));
  connect(coupler.frame_a, coupler_coupler_rocker.frame_a)
    annotation (Line(points={{1045,0},{1035,0},{1035,-200},{1040,-200}}, color={95,95,95}, thickness=0.5));
  connect(rocker.frame_a, rocker_coupler_rocker.frame_a)
    annotation (Line(points={{1365,0},{1320,0}}, color={95,95,95}, thickness=0.5));
  connect(world.frame_b, ground.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(ground.frame_a, crank_pivot.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-20},{485,-20},{485,0},{490,0}}, color={95,95,95}, thickness=0.5));
  connect(crank_pivot.frame_b, crank.frame_a)
    annotation (Line(points={{510,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(crank_crank_coupler.frame_b, crank_coupler.frame_a)
    annotation (Line(points={{760,-200},{800,-200},{800,0},{805,0}}, color={95,95,95}, thickness=0.5));
  connect(crank_coupler.frame_b, coupler.frame_a)
    annotation (Line(points={{835,0},{1045,0}}, color={95,95,95}, thickness=0.5));
  connect(coupler_coupler_rocker.frame_b, coupler_rocker.frame_a)
    annotation (Line(points={{1080,-200},{1120,-200},{1120,0},{1125,0}}, color={95,95,95}, thickness=0.5));
  connect(coupler_rocker.frame_b, rocker_coupler_rocker.frame_b)
    annotation (Line(points={{1155,0},{1280,0}}, color={95,95,95}, thickness=0.5));
  connect(ground_rocker_pivot.frame_b, rocker_pivot.frame_a)
    annotation (Line(points={{440,-200},{445,-200},{445,-225},{1125,-225},{1125,-100},{1130,-100}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(rocker_pivot.frame_b, rocker.frame_a)
    annotation (Line(points={{1150,-100},{1360,-100},{1360,0},{1365,0}}, color={238,46,47}, pattern=LinePattern.Dash, thickness=0.5));
  connect(ground.frame_a, ground_shape.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-100},{410,-100}}, color={95,95,95}, thickness=0.5));
  connect(crank.frame_a, crank_shape.frame_a)
    annotation (Line(points={{725,0},{720,0},{720,-100},{730,-100}}, color={95,95,95}, thickness=0.5));
  connect(coupler.frame_a, coupler_shape.frame_a)
    annotation (Line(points={{1045,0},{1040,0},{1040,-100},{1045,-100}}, color={95,95,95}, thickness=0.5));
  connect(rocker.frame_a, rocker_shape.frame_a)
    annotation (Line(points={{1365,0},{1355,0},{1355,-100},{1370,-100}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=9.0, Interval=0.02, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-280},{1440,60}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>fourbar.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Joint rocker_pivot closes a loop: a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations.</li></ul>
<p>Experiment: 9.0 s, about three swings of a pendulum as long as the mechanism's reach (2.062 m, period 2.88 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

within urdf_arm;
model Mechatronics "Mechatronic model of urdf_arm: Mechanics with no joint drive"
  extends urdf_arm.Mechanics;

  // Collisions: contact forces between the bodies' collision shapes (see Components.Collision)
  parameter Boolean collisions = false "Apply contact forces between the bodies' collision shapes"
    annotation (Dialog(group="Collisions"), choices(checkBox=true));
  urdf_arm.Components.Collision.World collisionWorld(
    nBodies=6,
    nParts=6,
    partBody={1, 2, 3, 4, 5, 6},
    partVertices={48, 8, 8, 8, 1, 8},
    partRadius={0.0, 0.0, 0.0, 0.0, 0.030000001, 0.0},
    vertices={
      {0.1008629, -2.3716923e-18, -7.4505807e-10},
      {0.09742608, 0.02610524, -7.4505807e-10},
      {0.08734983, 0.05043145, -7.4505807e-10},
      {0.07132084, 0.07132084, -7.4505807e-10},
      {0.05043145, 0.08734983, -7.4505807e-10},
      {0.02610524, 0.09742608, -7.4505807e-10},
      {7.531324e-18, 0.1008629, -7.4505807e-10},
      {-0.02610524, 0.09742608, -7.4505807e-10},
      {-0.05043145, 0.08734983, -7.4505807e-10},
      {-0.07132084, 0.07132084, -7.4505807e-10},
      {-0.08734983, 0.05043145, -7.4505807e-10},
      {-0.09742608, 0.02610524, -7.4505807e-10},
      {-0.1008629, 9.98045e-18, -7.4505807e-10},
      {-0.09742608, -0.02610524, -7.4505807e-10},
      {-0.08734983, -0.05043145, -7.4505807e-10},
      {-0.07132084, -0.07132084, -7.4505807e-10},
      {-0.05043145, -0.08734983, -7.4505807e-10},
      {-0.02610524, -0.09742608, -7.4505807e-10},
      {-1.7172961e-17, -0.1008629, -7.4505807e-10},
      {0.02610524, -0.09742608, -7.4505807e-10},
      {0.05043145, -0.08734983, -7.4505807e-10},
      {0.07132084, -0.07132084, -7.4505807e-10},
      {0.08734983, -0.05043145, -7.4505807e-10},
      {0.09742608, -0.02610524, -7.4505807e-10},
      {0.1008629, -2.3716923e-18, 0.1},
      {0.09742608, 0.02610524, 0.1},
      {0.08734983, 0.05043145, 0.1},
      {0.07132084, 0.07132084, 0.1},
      {0.05043145, 0.08734983, 0.1},
      {0.02610524, 0.09742608, 0.1},
      {7.531324e-18, 0.1008629, 0.1},
      {-0.02610524, 0.09742608, 0.1},
      {-0.05043145, 0.08734983, 0.1},
      {-0.07132084, 0.07132084, 0.1},
      {-0.08734983, 0.05043145, 0.1},
      {-0.09742608, 0.02610524, 0.1},
      {-0.1008629, 9.98045e-18, 0.1},
      {-0.09742608, -0.02610524, 0.1},
      {-0.08734983, -0.05043145, 0.1},
      {-0.07132084, -0.07132084, 0.1},
      {-0.05043145, -0.08734983, 0.1},
      {-0.02610524, -0.09742608, 0.1},
      {-1.7172961e-17, -0.1008629, 0.1},
      {0.02610524, -0.09742608, 0.1},
      {0.05043145, -0.08734983, 0.1},
      {0.07132084, -0.07132084, 0.1},
      {0.08734983, -0.05043145, 0.1},
      {0.09742608, -0.02610524, 0.1},
      {-0.04, -0.04, -5.9604646e-9},
      {-0.04, -0.04, 0.3},
      {0.04, -0.04, -5.9604646e-9},
      {0.04, -0.04, 0.3},
      {-0.04, 0.04, -5.9604646e-9},
      {-0.04, 0.04, 0.3},
      {0.04, 0.04, -5.9604646e-9},
      {0.04, 0.04, 0.3},
      {-0.03, -0.03, -2.9802323e-9},
      {0.03, -0.03, -2.9802323e-9},
      {-0.03, 0.03, -2.9802323e-9},
      {0.03, 0.03, -2.9802323e-9},
      {-0.03, -0.03, 0.4},
      {0.03, -0.03, 0.4},
      {-0.03, 0.03, 0.4},
      {0.03, 0.03, 0.4},
      {0.0, -0.03, -0.03},
      {0.25, -0.03, -0.03},
      {0.0, 0.03, -0.03},
      {0.25, 0.03, -0.03},
      {0.0, -0.03, 0.03},
      {0.25, -0.03, 0.03},
      {0.0, 0.03, 0.03},
      {0.25, 0.03, 0.03},
      {-2.8453788e-11, -1.7107598e-11, 1.2572653e-11},
      {-0.01, -0.01, 0.0},
      {0.01, -0.01, 0.0},
      {-0.01, 0.01, 0.0},
      {0.01, 0.01, 0.0},
      {-0.01, -0.01, 0.04},
      {0.01, -0.01, 0.04},
      {-0.01, 0.01, 0.04},
      {0.01, 0.01, 0.04}},
    checked={{0, 0, 1, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, {1, 0, 0, 0, 1, 1}, {1, 1, 0, 0, 0, 0}, {1, 1, 1, 0, 0, 0}, {1, 1, 1, 0, 0, 0}},
    r_0={base.frame_a.r_0, shoulder.frame_a.r_0, upper_arm.frame_a.r_0, forearm.frame_a.r_0, slide.frame_a.r_0, tool.frame_a.r_0},
    R_T={base.frame_a.R.T, shoulder.frame_a.R.T, upper_arm.frame_a.R.T, forearm.frame_a.R.T, slide.frame_a.R.T, tool.frame_a.R.T},
    v_0={base.v_0, shoulder.v_0, upper_arm.v_0, forearm.v_0, slide.v_0, tool.v_0},
    w_a={base.w_a, shoulder.w_a, upper_arm.w_a, forearm.w_a, slide.w_a, tool.w_a}) if collisions "Contact forces between the collision shapes"
    annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={-80,0})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_base if collisions "Contact force and torque on base (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={360,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_shoulder if collisions "Contact force and torque on shoulder (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={680,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_upper_arm if collisions "Contact force and torque on upper_arm (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1000,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_forearm if collisions "Contact force and torque on forearm (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1320,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_slide if collisions "Contact force and torque on slide (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1640,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_tool if collisions "Contact force and torque on tool (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1960,50})));
equation
  connect(collisionForce_base.frame_b, base.frame_a)
    annotation (Line(points={{350,50},{345,50},{345,5},{400,5},{400,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[1, :], collisionForce_base.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,5},{5,5},{5,55},{345,55},{345,70},{375,70},{375,56},{372,56}}, color={0,0,127}));
  connect(collisionWorld.torque[1, :], collisionForce_base.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-5},{0,-5},{0,45},{340,45},{340,35},{375,35},{375,44},{372,44}}, color={0,0,127}));
  connect(collisionForce_shoulder.frame_b, shoulder.frame_a)
    annotation (Line(points={{670,50},{665,50},{665,5},{720,5},{720,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[2, :], collisionForce_shoulder.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,55},{0,55},{0,60},{340,60},{340,75},{695,75},{695,56},{692,56}}, color={0,0,127}));
  connect(collisionWorld.torque[2, :], collisionForce_shoulder.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,0},{-5,0},{-5,50},{335,50},{335,30},{695,30},{695,44},{692,44}}, color={0,0,127}));
  connect(collisionForce_upper_arm.frame_b, upper_arm.frame_a)
    annotation (Line(points={{990,50},{985,50},{985,5},{1040,5},{1040,0},{1045,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[3, :], collisionForce_upper_arm.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,10},{-10,10},{-10,65},{335,65},{335,80},{1015,80},{1015,56},{1012,56}}, color={0,0,127}));
  connect(collisionWorld.torque[3, :], collisionForce_upper_arm.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-10},{5,-10},{5,-15},{390,-15},{390,45},{660,45},{660,35},{1015,35},{1015,44},{1012,44}}, color={0,0,127}));
  connect(collisionForce_forearm.frame_b, forearm.frame_a)
    annotation (Line(points={{1310,50},{1305,50},{1305,5},{1360,5},{1360,0},{1365,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[4, :], collisionForce_forearm.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,5},{-55,5},{-55,40},{330,40},{330,25},{1335,25},{1335,56},{1332,56}}, color={0,0,127}));
  connect(collisionWorld.torque[4, :], collisionForce_forearm.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-15},{0,-15},{0,-20},{1340,-20},{1340,45},{1335,45},{1335,44},{1332,44}}, color={0,0,127}));
  connect(collisionForce_slide.frame_b, slide.frame_a)
    annotation (Line(points={{1630,50},{1625,50},{1625,5},{1680,5},{1680,0},{1685,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[5, :], collisionForce_slide.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,5},{-50,5},{-50,35},{325,35},{325,20},{385,20},{385,55},{665,55},{665,70},{1655,70},{1655,56},{1652,56}}, color={0,0,127}));
  connect(collisionWorld.torque[5, :], collisionForce_slide.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-20},{-5,-20},{-5,-25},{1655,-25},{1655,44},{1652,44}}, color={0,0,127}));
  connect(collisionForce_tool.frame_b, tool.frame_a)
    annotation (Line(points={{1950,50},{1945,50},{1945,0},{2005,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[6, :], collisionForce_tool.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,5},{-45,5},{-45,30},{320,30},{320,15},{400,15},{400,40},{655,40},{655,20},{720,20},{720,55},{985,55},{985,75},{1975,75},{1975,56},{1972,56}}, color={0,0,127}));
  connect(collisionWorld.torque[6, :], collisionForce_tool.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,20},{315,20},{315,10},{395,10},{395,35},{700,35},{700,45},{980,45},{980,30},{1975,30},{1975,44},{1972,44}}, color={0,0,127}));
public
equation
  annotation (
    experiment(StopTime=7.0, Interval=0.02, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-140,-260},{2080,120}})),
    Icon(graphics={
      Rectangle(extent={{10,-70},{60,-30}}, lineColor={0,0,0}, fillColor={0,128,255}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{60,-54},{80,-46}}, lineColor={0,0,0}, fillColor={160,160,164}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{20,-80},{50,-70}}, lineColor={0,0,0}, fillColor={64,64,64}, fillPattern=FillPattern.Solid)}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>arm.urdf</code> (robot), exported by URDF from  on  by .</p>
<p><code>Mechatronics</code> extends <code>Mechanics</code> and refers to joints by name only: a <code>Mechanics</code> regenerated after a CAD change slots under it unchanged. Generated by cad2mo 0.1.0.</p>
<p>No drive is assigned: every joint is free, as in <code>Mechanics</code>. Assign motors, gears and controllers to joints in the motor library and regenerate this model.</p>
<p>Experiment: 7.0 s, about three swings of a pendulum as long as the mechanism's reach (1.047 m, period 2.05 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the Mechanics diagram, with each drive above the joint it moves, each contact force beside its body, and the reference tables and the collision and live-view blocks in a column left of the world.</p>
</html>"));
end Mechatronics;

within urdf_fourbar;
model Mechatronics "Mechatronic model of urdf_fourbar: Mechanics with no joint drive"
  extends urdf_fourbar.Mechanics;

  // Collisions: contact forces between the bodies' collision shapes (see Components.Collision)
  parameter Boolean collisions = false "Apply contact forces between the bodies' collision shapes"
    annotation (Dialog(group="Collisions"), choices(checkBox=true));
  urdf_fourbar.Components.Collision.World collisionWorld(
    nBodies=4,
    nParts=4,
    partBody={1, 2, 3, 4},
    partVertices={8, 8, 8, 8},
    partRadius={0.0, 0.0, 0.0, 0.0},
    vertices={
      {-0.100000024, -0.05, -0.03},
      {2.1, -0.05, -0.03},
      {-0.100000024, 0.05, -0.03},
      {2.1, 0.05, -0.03},
      {-0.100000024, -0.05, -0.01},
      {2.1, -0.05, -0.01},
      {-0.100000024, 0.05, -0.01},
      {2.1, 0.05, -0.01},
      {-0.02, 0.0, -0.01},
      {0.02, 0.0, -0.01},
      {-0.02, 1.0, -0.01},
      {0.02, 1.0, -0.01},
      {-0.02, 0.0, 0.01},
      {0.02, 0.0, 0.01},
      {-0.02, 1.0, 0.01},
      {0.02, 1.0, 0.01},
      {0.0, -0.02, -0.01},
      {2.0, -0.02, -0.01},
      {0.0, 0.02, -0.01},
      {2.0, 0.02, -0.01},
      {0.0, -0.02, 0.01},
      {2.0, -0.02, 0.01},
      {0.0, 0.02, 0.01},
      {2.0, 0.02, 0.01},
      {-0.02, 0.0, -0.01},
      {0.02, 0.0, -0.01},
      {-0.02, 1.0, -0.01},
      {0.02, 1.0, -0.01},
      {-0.02, 0.0, 0.01},
      {0.02, 0.0, 0.01},
      {-0.02, 1.0, 0.01},
      {0.02, 1.0, 0.01}},
    checked={{0, 0, 1, 0}, {0, 0, 0, 1}, {1, 0, 0, 0}, {0, 1, 0, 0}},
    r_0={ground.frame_a.r_0, crank.frame_a.r_0, coupler.frame_a.r_0, rocker.frame_a.r_0},
    R_T={ground.frame_a.R.T, crank.frame_a.R.T, coupler.frame_a.R.T, rocker.frame_a.R.T},
    v_0={ground.v_0, crank.v_0, coupler.v_0, rocker.v_0},
    w_a={ground.w_a, crank.w_a, coupler.w_a, rocker.w_a}) if collisions "Contact forces between the collision shapes"
    annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={-80,20})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_ground if collisions "Contact force and torque on ground (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={360,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_crank if collisions "Contact force and torque on crank (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={680,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_coupler if collisions "Contact force and torque on coupler (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1000,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_rocker if collisions "Contact force and torque on rocker (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1320,50})));
equation
  connect(collisionForce_ground.frame_b, ground.frame_a)
    annotation (Line(points={{350,50},{345,50},{345,5},{400,5},{400,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[1, :], collisionForce_ground.force)
    annotation (Line(points={{-63.5,26},{-60,26},{-60,25},{375,25},{375,56},{372,56}}, color={0,0,127}));
  connect(collisionWorld.torque[1, :], collisionForce_ground.torque)
    annotation (Line(points={{-63.5,14},{-60,14},{-60,15},{5,15},{5,45},{340,45},{340,35},{375,35},{375,44},{372,44}}, color={0,0,127}));
  connect(collisionForce_crank.frame_b, crank.frame_a)
    annotation (Line(points={{670,50},{665,50},{665,5},{720,5},{720,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[2, :], collisionForce_crank.force)
    annotation (Line(points={{-63.5,26},{-60,26},{-60,55},{345,55},{345,70},{695,70},{695,56},{692,56}}, color={0,0,127}));
  connect(collisionWorld.torque[2, :], collisionForce_crank.torque)
    annotation (Line(points={{-63.5,14},{-60,14},{-60,20},{395,20},{395,45},{660,45},{660,35},{695,35},{695,44},{692,44}}, color={0,0,127}));
  connect(collisionForce_coupler.frame_b, coupler.frame_a)
    annotation (Line(points={{990,50},{985,50},{985,5},{1040,5},{1040,0},{1045,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[3, :], collisionForce_coupler.force)
    annotation (Line(points={{-63.5,26},{-60,26},{-60,30},{1015,30},{1015,56},{1012,56}}, color={0,0,127}));
  connect(collisionWorld.torque[3, :], collisionForce_coupler.torque)
    annotation (Line(points={{-63.5,14},{-60,14},{-60,10},{0,10},{0,50},{340,50},{340,75},{1020,75},{1020,45},{1015,45},{1015,44},{1012,44}}, color={0,0,127}));
  connect(collisionForce_rocker.frame_b, rocker.frame_a)
    annotation (Line(points={{1310,50},{1305,50},{1305,30},{1360,30},{1360,0},{1365,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[4, :], collisionForce_rocker.force)
    annotation (Line(points={{-63.5,26},{-60,26},{-60,35},{1335,35},{1335,56},{1332,56}}, color={0,0,127}));
  connect(collisionWorld.torque[4, :], collisionForce_rocker.torque)
    annotation (Line(points={{-63.5,14},{-60,14},{-60,40},{335,40},{335,80},{1340,80},{1340,45},{1335,45},{1335,44},{1332,44}}, color={0,0,127}));
public
equation
  annotation (
    experiment(StopTime=9.0, Interval=0.02, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-140,-260},{1440,120}})),
    Icon(graphics={
      Rectangle(extent={{10,-70},{60,-30}}, lineColor={0,0,0}, fillColor={0,128,255}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{60,-54},{80,-46}}, lineColor={0,0,0}, fillColor={160,160,164}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{20,-80},{50,-70}}, lineColor={0,0,0}, fillColor={64,64,64}, fillPattern=FillPattern.Solid)}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>fourbar.urdf</code> (robot), exported by URDF from  on  by .</p>
<p><code>Mechatronics</code> extends <code>Mechanics</code> and refers to joints by name only: a <code>Mechanics</code> regenerated after a CAD change slots under it unchanged. Generated by cad2mo 0.1.0.</p>
<p>No drive is assigned: every joint is free, as in <code>Mechanics</code>. Assign motors, gears and controllers to joints in the motor library and regenerate this model.</p>
<p>Experiment: 9.0 s, about three swings of a pendulum as long as the mechanism's reach (2.062 m, period 2.88 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the Mechanics diagram, with each drive above the joint it moves, each contact force beside its body, and the reference tables and the collision and live-view blocks in a column left of the world.</p>
</html>"));
end Mechatronics;

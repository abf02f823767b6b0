within CRANKROCKER;
model Mechatronics "Mechatronic model of CRANKROCKER: Mechanics with no joint drive"
  extends CRANKROCKER.Mechanics;

  // Collisions: contact forces between the bodies' collision shapes (see Components.Collision)
  parameter Boolean collisions = false "Apply contact forces between the bodies' collision shapes"
    annotation (Dialog(group="Collisions"), choices(checkBox=true));
  CRANKROCKER.Components.Collision.World collisionWorld(
    nBodies=3,
    nParts=3,
    partBody={1, 2, 3},
    partVertices={8, 8, 8},
    partRadius={0.0, 0.0, 0.0},
    vertices={
      {-0.008, -0.008, -0.004},
      {0.058, -0.008, -0.004},
      {-0.008, 0.008, -0.004},
      {0.058, 0.008, -0.004},
      {-0.008, -0.008, 0.004},
      {0.058, -0.008, 0.004},
      {-0.008, 0.008, 0.004},
      {0.058, 0.008, 0.004},
      {-0.008, -0.009, -0.004},
      {0.229, -0.009, -0.004},
      {-0.008, 0.008, -0.004},
      {0.229, 0.008, -0.004},
      {-0.008, -0.009, 0.004},
      {0.229, -0.009, 0.004},
      {-0.008, 0.008, 0.004},
      {0.229, 0.008, 0.004},
      {-0.008, -0.008, -0.004},
      {0.169, -0.008, -0.004},
      {-0.008, 0.009, -0.004},
      {0.169, 0.009, -0.004},
      {-0.008, -0.008, 0.004},
      {0.169, -0.008, 0.004},
      {-0.008, 0.009, 0.004},
      {0.169, 0.009, 0.004}},
    checked={{0, 0, 1}, {0, 0, 0}, {1, 0, 0}},
    r_0={CRANK.frame_a.r_0, COUPLER.frame_a.r_0, ROCKER.frame_a.r_0},
    R_T={CRANK.frame_a.R.T, COUPLER.frame_a.R.T, ROCKER.frame_a.R.T},
    v_0={CRANK.v_0, COUPLER.v_0, ROCKER.v_0},
    w_a={CRANK.w_a, COUPLER.w_a, ROCKER.w_a}) if collisions "Contact forces between the collision shapes"
    annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={-80,0})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_CRANK if collisions "Contact force and torque on CRANK (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={680,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_COUPLER if collisions "Contact force and torque on COUPLER (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1000,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_ROCKER if collisions "Contact force and torque on ROCKER (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1320,50})));
equation
  connect(collisionForce_CRANK.frame_b, CRANK.frame_a)
    annotation (Line(points={{670,50},{665,50},{665,20},{720,20},{720,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[1, :], collisionForce_CRANK.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,5},{5,5},{5,55},{665,55},{665,70},{695,70},{695,56},{692,56}}, color={0,0,127}));
  connect(collisionWorld.torque[1, :], collisionForce_CRANK.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-5},{0,-5},{0,45},{660,45},{660,35},{695,35},{695,44},{692,44}}, color={0,0,127}));
  connect(collisionForce_COUPLER.frame_b, COUPLER.frame_a)
    annotation (Line(points={{990,50},{985,50},{985,20},{1040,20},{1040,0},{1045,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[2, :], collisionForce_COUPLER.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,55},{0,55},{0,60},{660,60},{660,75},{1015,75},{1015,56},{1012,56}}, color={0,0,127}));
  connect(collisionWorld.torque[2, :], collisionForce_COUPLER.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,0},{-5,0},{-5,50},{655,50},{655,30},{1015,30},{1015,44},{1012,44}}, color={0,0,127}));
  connect(collisionForce_ROCKER.frame_b, ROCKER.frame_a)
    annotation (Line(points={{1310,50},{1305,50},{1305,20},{1360,20},{1360,0},{1365,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[3, :], collisionForce_ROCKER.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,10},{-10,10},{-10,65},{655,65},{655,80},{1335,80},{1335,56},{1332,56}}, color={0,0,127}));
  connect(collisionWorld.torque[3, :], collisionForce_ROCKER.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-10},{5,-10},{5,-15},{390,-15},{390,40},{650,40},{650,25},{1335,25},{1335,44},{1332,44}}, color={0,0,127}));
public
equation
  annotation (
    experiment(StopTime=3.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-140,-260},{1440,120}})),
    Icon(graphics={
      Rectangle(extent={{10,-70},{60,-30}}, lineColor={0,0,0}, fillColor={0,128,255}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{60,-54},{80,-46}}, lineColor={0,0,0}, fillColor={160,160,164}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{20,-80},{50,-70}}, lineColor={0,0,0}, fillColor={64,64,64}, fillPattern=FillPattern.Solid)}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>CRANKROCKER.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 5.0 from Pro/E Wildfire Creo 7.0 - 2020454 on 03/14/24||10:20:30 by cad2mo.</p>
<p><code>Mechatronics</code> extends <code>Mechanics</code> and refers to joints by name only: a <code>Mechanics</code> regenerated after a CAD change slots under it unchanged. Generated by cad2mo 0.1.0.</p>
<p>No drive is assigned: every joint is free, as in <code>Mechanics</code>. Assign motors, gears and controllers to joints in the motor library and regenerate this model.</p>
<p>Experiment: 3.0 s, about three swings of a pendulum as long as the mechanism's reach (0.23 m, period 0.96 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the Mechanics diagram, with each drive above the joint it moves, each contact force beside its body, and the reference tables and the collision and live-view blocks in a column left of the world.</p>
</html>"));
end Mechatronics;

within UJ;
model Mechatronics "Mechatronic model of UJ: Mechanics with no joint drive"
  extends UJ.Mechanics;

  // Collisions: contact forces between the bodies' collision shapes (see Components.Collision)
  parameter Boolean collisions = false "Apply contact forces between the bodies' collision shapes"
    annotation (Dialog(group="Collisions"), choices(checkBox=true));
  UJ.Components.Collision.World collisionWorld(
    nBodies=3,
    nParts=3,
    partBody={1, 2, 3},
    partVertices={8, 8, 8},
    partRadius={0.0, 0.0, 0.0},
    vertices={
      {-0.05, 0.0, -0.05},
      {0.05, 0.0, -0.05},
      {-0.05, 0.18, -0.05},
      {0.05, 0.18, -0.05},
      {-0.05, 0.0, 0.05},
      {0.05, 0.0, 0.05},
      {-0.05, 0.18, 0.05},
      {0.05, 0.18, 0.05},
      {-0.02, -0.02, -0.02},
      {0.02, -0.02, -0.02},
      {-0.02, 0.08, -0.02},
      {0.02, 0.08, -0.02},
      {-0.02, -0.02, 0.06},
      {0.02, -0.02, 0.06},
      {-0.02, 0.08, 0.06},
      {0.02, 0.08, 0.06},
      {-0.03, -0.015, -0.01},
      {0.03, -0.015, -0.01},
      {-0.03, 0.015, -0.01},
      {0.03, 0.015, -0.01},
      {-0.03, -0.015, 0.01},
      {0.03, -0.015, 0.01},
      {-0.03, 0.015, 0.01},
      {0.03, 0.015, 0.01}},
    checked={{0, 0, 1}, {0, 0, 0}, {1, 0, 0}},
    r_0={BASE.frame_a.r_0, CROSS.frame_a.r_0, FLOAT.frame_a.r_0},
    R_T={BASE.frame_a.R.T, CROSS.frame_a.R.T, FLOAT.frame_a.R.T},
    v_0={BASE.v_0, CROSS.v_0, FLOAT.v_0},
    w_a={BASE.w_a, CROSS.w_a, FLOAT.w_a}) if collisions "Contact forces between the collision shapes"
    annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={-80,0})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_BASE if collisions "Contact force and torque on BASE (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={680,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_CROSS if collisions "Contact force and torque on CROSS (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1080,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_FLOAT if collisions "Contact force and torque on FLOAT (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1640,50})));
equation
  connect(collisionForce_BASE.frame_b, BASE.frame_a)
    annotation (Line(points={{670,50},{665,50},{665,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[1, :], collisionForce_BASE.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,5},{5,5},{5,55},{665,55},{665,70},{695,70},{695,56},{692,56}}, color={0,0,127}));
  connect(collisionWorld.torque[1, :], collisionForce_BASE.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-5},{0,-5},{0,45},{660,45},{660,35},{695,35},{695,44},{692,44}}, color={0,0,127}));
  connect(collisionForce_CROSS.frame_b, CROSS.frame_a)
    annotation (Line(points={{1070,50},{1065,50},{1065,5},{1120,5},{1120,0},{1125,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[2, :], collisionForce_CROSS.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,55},{0,55},{0,60},{660,60},{660,75},{1095,75},{1095,56},{1092,56}}, color={0,0,127}));
  connect(collisionWorld.torque[2, :], collisionForce_CROSS.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,0},{-5,0},{-5,50},{655,50},{655,30},{1095,30},{1095,44},{1092,44}}, color={0,0,127}));
  connect(collisionForce_FLOAT.frame_b, FLOAT.frame_a)
    annotation (Line(points={{1630,50},{1625,50},{1625,20},{1680,20},{1680,0},{1685,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[3, :], collisionForce_FLOAT.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,10},{-10,10},{-10,65},{655,65},{655,80},{1655,80},{1655,56},{1652,56}}, color={0,0,127}));
  connect(collisionWorld.torque[3, :], collisionForce_FLOAT.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-10},{5,-10},{5,-15},{395,-15},{395,40},{650,40},{650,25},{1655,25},{1655,44},{1652,44}}, color={0,0,127}));
public
equation
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-140,-260},{1760,120}})),
    Icon(graphics={
      Rectangle(extent={{10,-70},{60,-30}}, lineColor={0,0,0}, fillColor={0,128,255}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{60,-54},{80,-46}}, lineColor={0,0,0}, fillColor={160,160,164}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{20,-80},{50,-70}}, lineColor={0,0,0}, fillColor={64,64,64}, fillPattern=FillPattern.Solid)}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>UJ.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 5.0 from Pro/E Wildfire Creo 9.0 - 2022073 on 03/14/24||10:20:30 by cad2mo.</p>
<p><code>Mechatronics</code> extends <code>Mechanics</code> and refers to joints by name only: a <code>Mechanics</code> regenerated after a CAD change slots under it unchanged. Generated by cad2mo 0.1.0.</p>
<p>No drive is assigned: every joint is free, as in <code>Mechanics</code>. Assign motors, gears and controllers to joints in the motor library and regenerate this model.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.25 m, period 1.0 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the Mechanics diagram, with each drive above the joint it moves, each contact force beside its body, and the reference tables and the collision and live-view blocks in a column left of the world.</p>
</html>"));
end Mechatronics;

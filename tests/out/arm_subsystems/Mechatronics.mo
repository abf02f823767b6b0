within ARM;
model Mechatronics "Mechatronic model of ARM: Mechanics with no joint drive"
  extends ARM.Mechanics;

  // Collisions: contact forces between the bodies' collision shapes (see Components.Collision)
  parameter Boolean collisions = false "Apply contact forces between the bodies' collision shapes"
    annotation (Dialog(group="Collisions"), choices(checkBox=true));
  ARM.Components.Collision.World collisionWorld(
    nBodies=3,
    nParts=3,
    partBody={1, 2, 3},
    partVertices={8, 8, 8},
    partRadius={0.0, 0.0, 0.0},
    vertices={
      {-0.06, 0.0, -0.06},
      {0.06, 0.0, -0.06},
      {-0.06, 0.09, -0.06},
      {0.06, 0.09, -0.06},
      {-0.06, 0.0, 0.06},
      {0.06, 0.0, 0.06},
      {-0.06, 0.09, 0.06},
      {0.06, 0.09, 0.06},
      {-0.015, -0.016, -0.012},
      {0.266, -0.016, -0.012},
      {-0.015, 0.015, -0.012},
      {0.266, 0.015, -0.012},
      {-0.015, -0.016, 0.012},
      {0.266, -0.016, 0.012},
      {-0.015, 0.015, 0.012},
      {0.266, 0.015, 0.012},
      {-0.012, -0.012, -0.01},
      {0.212, -0.012, -0.01},
      {-0.012, 0.013, -0.01},
      {0.212, 0.013, -0.01},
      {-0.012, -0.012, 0.011},
      {0.212, -0.012, 0.011},
      {-0.012, 0.013, 0.011},
      {0.212, 0.013, 0.011}},
    checked={{0, 0, 1}, {0, 0, 0}, {1, 0, 0}},
    r_0={BASE.frame_a.r_0, LINK_UPPER.frame_a.r_0, LINK_FORE.frame_a.r_0},
    R_T={BASE.frame_a.R.T, LINK_UPPER.frame_a.R.T, LINK_FORE.frame_a.R.T},
    v_0={BASE.v_0, LINK_UPPER.v_0, LINK_FORE.v_0},
    w_a={BASE.w_a, LINK_UPPER.w_a, LINK_FORE.w_a}) if collisions "Contact forces between the collision shapes"
    annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={-80,0})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_BASE if collisions "Contact force and torque on BASE (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={680,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_LINK_UPPER if collisions "Contact force and torque on LINK_UPPER (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1000,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_LINK_FORE if collisions "Contact force and torque on LINK_FORE (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1320,-50})));
equation
  connect(collisionForce_BASE.frame_b, BASE.frame_a)
    annotation (Line(points={{670,50},{665,50},{665,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[1, :], collisionForce_BASE.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,5},{5,5},{5,55},{665,55},{665,70},{695,70},{695,56},{692,56}}, color={0,0,127}));
  connect(collisionWorld.torque[1, :], collisionForce_BASE.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-5},{0,-5},{0,45},{660,45},{660,35},{695,35},{695,44},{692,44}}, color={0,0,127}));
  connect(collisionForce_LINK_UPPER.frame_b, LINK_UPPER.frame_a)
    annotation (Line(points={{990,50},{985,50},{985,25},{1040,25},{1040,0},{1045,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[2, :], collisionForce_LINK_UPPER.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,55},{0,55},{0,60},{660,60},{660,75},{1015,75},{1015,56},{1012,56}}, color={0,0,127}));
  connect(collisionWorld.torque[2, :], collisionForce_LINK_UPPER.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,0},{-5,0},{-5,50},{655,50},{655,30},{1015,30},{1015,44},{1012,44}}, color={0,0,127}));
  connect(collisionForce_LINK_FORE.frame_b, LINK_FORE.frame_a)
    annotation (Line(points={{1310,-50},{1305,-50},{1305,-75},{1360,-75},{1360,-100},{1365,-100}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[3, :], collisionForce_LINK_FORE.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,-45},{1305,-45},{1305,-30},{1335,-30},{1335,-44},{1332,-44}}, color={0,0,127}));
  connect(collisionWorld.torque[3, :], collisionForce_LINK_FORE.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-10},{5,-10},{5,-40},{1300,-40},{1300,-65},{1335,-65},{1335,-56},{1332,-56}}, color={0,0,127}));
public
equation
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-140,-360},{1760,120}})),
    Icon(graphics={
      Rectangle(extent={{10,-70},{60,-30}}, lineColor={0,0,0}, fillColor={0,128,255}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{60,-54},{80,-46}}, lineColor={0,0,0}, fillColor={160,160,164}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{20,-80},{50,-70}}, lineColor={0,0,0}, fillColor={64,64,64}, fillPattern=FillPattern.Solid)}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>ARM_SIM_MODEL.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p><code>Mechatronics</code> extends <code>Mechanics</code> and refers to joints by name only: a <code>Mechanics</code> regenerated after a CAD change slots under it unchanged. Generated by cad2mo 0.1.0.</p>
<p>No drive is assigned: every joint is free, as in <code>Mechanics</code>. Assign motors, gears and controllers to joints in the motor library and regenerate this model.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.308 m, period 1.11 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the Mechanics diagram, with each drive above the joint it moves, each contact force beside its body, and the reference tables and the collision and live-view blocks in a column left of the world.</p>
</html>"));
end Mechatronics;

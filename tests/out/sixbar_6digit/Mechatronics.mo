within SIXBAR;
model Mechatronics "Mechatronic model of SIXBAR: Mechanics with no joint drive"
  extends SIXBAR.Mechanics;

  // Collisions: contact forces between the bodies' collision shapes (see Components.Collision)
  parameter Boolean collisions = false "Apply contact forces between the bodies' collision shapes"
    annotation (Dialog(group="Collisions"), choices(checkBox=true));
  SIXBAR.Components.Collision.World collisionWorld(
    nBodies=5,
    nParts=5,
    partBody={1, 2, 3, 4, 5},
    partVertices={8, 8, 8, 8, 8},
    partRadius={0.0, 0.0, 0.0, 0.0, 0.0},
    vertices={
      {-0.008, -0.009, -0.004},
      {0.068, -0.009, -0.004},
      {-0.008, 0.008, -0.004},
      {0.068, 0.008, -0.004},
      {-0.008, -0.009, 0.004},
      {0.068, -0.009, 0.004},
      {-0.008, 0.008, 0.004},
      {0.068, 0.008, 0.004},
      {-0.008, -0.009, -0.004},
      {0.258, -0.009, -0.004},
      {-0.008, 0.008, -0.004},
      {0.258, 0.008, -0.004},
      {-0.008, -0.009, 0.004},
      {0.258, -0.009, 0.004},
      {-0.008, 0.008, 0.004},
      {0.258, 0.008, 0.004},
      {-0.008, -0.008, -0.004},
      {0.148, -0.008, -0.004},
      {-0.008, 0.008, -0.004},
      {0.148, 0.008, -0.004},
      {-0.008, -0.008, 0.004},
      {0.148, -0.008, 0.004},
      {-0.008, 0.008, 0.004},
      {0.148, 0.008, 0.004},
      {-0.008, -0.008, -0.004},
      {0.158, -0.008, -0.004},
      {-0.008, 0.008, -0.004},
      {0.158, 0.008, -0.004},
      {-0.008, -0.008, 0.004},
      {0.158, -0.008, 0.004},
      {-0.008, 0.008, 0.004},
      {0.158, 0.008, 0.004},
      {-0.008, -0.008, -0.004},
      {0.128, -0.008, -0.004},
      {-0.008, 0.008, -0.004},
      {0.128, 0.008, -0.004},
      {-0.008, -0.008, 0.004},
      {0.128, -0.008, 0.004},
      {-0.008, 0.008, 0.004},
      {0.128, 0.008, 0.004}},
    checked={{0, 0, 1, 1, 1}, {0, 0, 0, 0, 1}, {1, 0, 0, 1, 1}, {1, 0, 1, 0, 0}, {1, 1, 1, 0, 0}},
    r_0={CRANK.frame_a.r_0, COUPLER.frame_a.r_0, ROCKER.frame_a.r_0, LINK5.frame_a.r_0, LINK6.frame_a.r_0},
    R_T={CRANK.frame_a.R.T, COUPLER.frame_a.R.T, ROCKER.frame_a.R.T, LINK5.frame_a.R.T, LINK6.frame_a.R.T},
    v_0={CRANK.v_0, COUPLER.v_0, ROCKER.v_0, LINK5.v_0, LINK6.v_0},
    w_a={CRANK.w_a, COUPLER.w_a, ROCKER.w_a, LINK5.w_a, LINK6.w_a}) if collisions "Contact forces between the collision shapes"
    annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={-80,20})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_CRANK if collisions "Contact force and torque on CRANK (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={680,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_COUPLER if collisions "Contact force and torque on COUPLER (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1000,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_ROCKER if collisions "Contact force and torque on ROCKER (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1320,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_LINK5 if collisions "Contact force and torque on LINK5 (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1320,-150})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_LINK6 if collisions "Contact force and torque on LINK6 (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1640,-150})));
equation
  connect(collisionForce_CRANK.frame_b, CRANK.frame_a)
    annotation (Line(points={{670,50},{665,50},{665,20},{720,20},{720,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[1, :], collisionForce_CRANK.force)
    annotation (Line(points={{-63.5,26},{-60,26},{-60,25},{395,25},{395,55},{665,55},{665,70},{695,70},{695,56},{692,56}}, color={0,0,127}));
  connect(collisionWorld.torque[1, :], collisionForce_CRANK.torque)
    annotation (Line(points={{-63.5,14},{-60,14},{-60,15},{5,15},{5,45},{660,45},{660,35},{695,35},{695,44},{692,44}}, color={0,0,127}));
  connect(collisionForce_COUPLER.frame_b, COUPLER.frame_a)
    annotation (Line(points={{990,50},{985,50},{985,20},{1040,20},{1040,0},{1045,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[2, :], collisionForce_COUPLER.force)
    annotation (Line(points={{-63.5,26},{-60,26},{-60,55},{390,55},{390,60},{660,60},{660,75},{1015,75},{1015,56},{1012,56}}, color={0,0,127}));
  connect(collisionWorld.torque[2, :], collisionForce_COUPLER.torque)
    annotation (Line(points={{-63.5,14},{-60,14},{-60,20},{400,20},{400,40},{655,40},{655,30},{1015,30},{1015,44},{1012,44}}, color={0,0,127}));
  connect(collisionForce_ROCKER.frame_b, ROCKER.frame_a)
    annotation (Line(points={{1310,50},{1305,50},{1305,20},{1360,20},{1360,0},{1365,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[3, :], collisionForce_ROCKER.force)
    annotation (Line(points={{-63.5,26},{-60,26},{-60,30},{650,30},{650,25},{1335,25},{1335,56},{1332,56}}, color={0,0,127}));
  connect(collisionWorld.torque[3, :], collisionForce_ROCKER.torque)
    annotation (Line(points={{-63.5,14},{-60,14},{-60,10},{0,10},{0,50},{655,50},{655,80},{1340,80},{1340,45},{1335,45},{1335,44},{1332,44}}, color={0,0,127}));
  connect(collisionForce_LINK5.frame_b, LINK5.frame_a)
    annotation (Line(points={{1310,-150},{1305,-150},{1305,-180},{1360,-180},{1360,-200},{1365,-200}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[4, :], collisionForce_LINK5.force)
    annotation (Line(points={{-63.5,26},{-60,26},{-60,-145},{1305,-145},{1305,-130},{1335,-130},{1335,-144},{1332,-144}}, color={0,0,127}));
  connect(collisionWorld.torque[4, :], collisionForce_LINK5.torque)
    annotation (Line(points={{-63.5,14},{-60,14},{-60,5},{5,5},{5,-140},{1300,-140},{1300,-165},{1335,-165},{1335,-156},{1332,-156}}, color={0,0,127}));
  connect(collisionForce_LINK6.frame_b, LINK6.frame_a)
    annotation (Line(points={{1630,-150},{1625,-150},{1625,-180},{1680,-180},{1680,-200},{1685,-200}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[5, :], collisionForce_LINK6.force)
    annotation (Line(points={{-63.5,26},{-60,26},{-60,0},{0,0},{0,-135},{1300,-135},{1300,-125},{1655,-125},{1655,-144},{1652,-144}}, color={0,0,127}));
  connect(collisionWorld.torque[5, :], collisionForce_LINK6.torque)
    annotation (Line(points={{-63.5,14},{-60,14},{-60,-5},{-5,-5},{-5,-155},{1295,-155},{1295,-170},{1655,-170},{1655,-156},{1652,-156}}, color={0,0,127}));
public
equation
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-140,-460},{1760,120}})),
    Icon(graphics={
      Rectangle(extent={{10,-70},{60,-30}}, lineColor={0,0,0}, fillColor={0,128,255}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{60,-54},{80,-46}}, lineColor={0,0,0}, fillColor={160,160,164}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{20,-80},{50,-70}}, lineColor={0,0,0}, fillColor={64,64,64}, fillPattern=FillPattern.Solid)}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>SIXBAR.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p><code>Mechatronics</code> extends <code>Mechanics</code> and refers to joints by name only: a <code>Mechanics</code> regenerated after a CAD change slots under it unchanged. Generated by cad2mo 0.1.0.</p>
<p>No drive is assigned: every joint is free, as in <code>Mechanics</code>. Assign motors, gears and controllers to joints in the motor library and regenerate this model.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.398 m, period 1.27 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the Mechanics diagram, with each drive above the joint it moves, each contact force beside its body, and the reference tables and the collision and live-view blocks in a column left of the world.</p>
</html>"));
end Mechatronics;

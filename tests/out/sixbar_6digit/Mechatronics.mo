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
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-140,20})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_CRANK if collisions "Contact force and torque on CRANK (resolved in world)"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-110,20})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_COUPLER if collisions "Contact force and torque on COUPLER (resolved in world)"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-110,-10})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_ROCKER if collisions "Contact force and torque on ROCKER (resolved in world)"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-110,-40})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_LINK5 if collisions "Contact force and torque on LINK5 (resolved in world)"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-110,-70})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_LINK6 if collisions "Contact force and torque on LINK6 (resolved in world)"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-110,-100})));
equation
  connect(collisionForce_CRANK.frame_b, CRANK.frame_a);
  connect(collisionWorld.force[1, :], collisionForce_CRANK.force);
  connect(collisionWorld.torque[1, :], collisionForce_CRANK.torque);
  connect(collisionForce_COUPLER.frame_b, COUPLER.frame_a);
  connect(collisionWorld.force[2, :], collisionForce_COUPLER.force);
  connect(collisionWorld.torque[2, :], collisionForce_COUPLER.torque);
  connect(collisionForce_ROCKER.frame_b, ROCKER.frame_a);
  connect(collisionWorld.force[3, :], collisionForce_ROCKER.force);
  connect(collisionWorld.torque[3, :], collisionForce_ROCKER.torque);
  connect(collisionForce_LINK5.frame_b, LINK5.frame_a);
  connect(collisionWorld.force[4, :], collisionForce_LINK5.force);
  connect(collisionWorld.torque[4, :], collisionForce_LINK5.torque);
  connect(collisionForce_LINK6.frame_b, LINK6.frame_a);
  connect(collisionWorld.force[5, :], collisionForce_LINK6.force);
  connect(collisionWorld.torque[5, :], collisionForce_LINK6.torque);
public
equation
  annotation (
    experiment(StopTime=1.0),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>SIXBAR.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p><code>Mechatronics</code> extends <code>Mechanics</code> and refers to joints by name only: a <code>Mechanics</code> regenerated after a CAD change slots under it unchanged. Generated by cad2mo 0.1.0.</p>
<p>No drive is assigned: every joint is free, as in <code>Mechanics</code>. Assign motors, gears and controllers to joints in the motor library and regenerate this model.</p>
</html>"));
end Mechatronics;

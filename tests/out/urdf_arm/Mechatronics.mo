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
      {4.4116298e-20, -3.676358e-21, 1.5991183e-18},
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
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-140,20})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_base if collisions "Contact force and torque on base (resolved in world)"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-110,20})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_shoulder if collisions "Contact force and torque on shoulder (resolved in world)"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-110,-10})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_upper_arm if collisions "Contact force and torque on upper_arm (resolved in world)"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-110,-40})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_forearm if collisions "Contact force and torque on forearm (resolved in world)"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-110,-70})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_slide if collisions "Contact force and torque on slide (resolved in world)"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-110,-100})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_tool if collisions "Contact force and torque on tool (resolved in world)"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-110,-130})));
equation
  connect(collisionForce_base.frame_b, base.frame_a);
  connect(collisionWorld.force[1, :], collisionForce_base.force);
  connect(collisionWorld.torque[1, :], collisionForce_base.torque);
  connect(collisionForce_shoulder.frame_b, shoulder.frame_a);
  connect(collisionWorld.force[2, :], collisionForce_shoulder.force);
  connect(collisionWorld.torque[2, :], collisionForce_shoulder.torque);
  connect(collisionForce_upper_arm.frame_b, upper_arm.frame_a);
  connect(collisionWorld.force[3, :], collisionForce_upper_arm.force);
  connect(collisionWorld.torque[3, :], collisionForce_upper_arm.torque);
  connect(collisionForce_forearm.frame_b, forearm.frame_a);
  connect(collisionWorld.force[4, :], collisionForce_forearm.force);
  connect(collisionWorld.torque[4, :], collisionForce_forearm.torque);
  connect(collisionForce_slide.frame_b, slide.frame_a);
  connect(collisionWorld.force[5, :], collisionForce_slide.force);
  connect(collisionWorld.torque[5, :], collisionForce_slide.torque);
  connect(collisionForce_tool.frame_b, tool.frame_a);
  connect(collisionWorld.force[6, :], collisionForce_tool.force);
  connect(collisionWorld.torque[6, :], collisionForce_tool.torque);
public
equation
  annotation (
    experiment(StopTime=1.0),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>arm.urdf</code> (robot), exported by URDF from  on  by .</p>
<p><code>Mechatronics</code> extends <code>Mechanics</code> and refers to joints by name only: a <code>Mechanics</code> regenerated after a CAD change slots under it unchanged. Generated by cad2mo 0.1.0.</p>
<p>No drive is assigned: every joint is free, as in <code>Mechanics</code>. Assign motors, gears and controllers to joints in the motor library and regenerate this model.</p>
</html>"));
end Mechatronics;

within VASM;
model Mechatronics "Mechatronic model of VASM: Mechanics with no joint drive"
  extends VASM.Mechanics;

  // Collisions: contact forces between the bodies' collision shapes (see Components.Collision)
  parameter Boolean collisions = false "Apply contact forces between the bodies' collision shapes"
    annotation (Dialog(group="Collisions"), choices(checkBox=true));
  VASM.Components.Collision.World collisionWorld(
    nBodies=3,
    nParts=3,
    partBody={1, 2, 3},
    partVertices={8, 8, 8},
    partRadius={0.0, 0.0, 0.0},
    vertices={
      {-0.02, -0.015, -0.005},
      {0.14, -0.015, -0.005},
      {-0.02, 0.015, -0.005},
      {0.14, 0.015, -0.005},
      {0.14, 0.015, 0.005},
      {-0.02, 0.015, 0.005},
      {0.14, -0.015, 0.005},
      {-0.02, -0.015, 0.005},
      {-0.01, -0.01, -0.01},
      {0.06, -0.01, -0.01},
      {-0.01, 0.01, -0.01},
      {0.06, 0.01, -0.01},
      {0.06, 0.01, 0.01},
      {-0.01, 0.01, 0.01},
      {0.06, -0.01, 0.01},
      {-0.01, -0.01, 0.01},
      {-0.008, -0.008, -0.008},
      {0.09, -0.008, -0.008},
      {-0.008, 0.008, -0.008},
      {0.09, 0.008, -0.008},
      {0.09, 0.008, 0.008},
      {-0.008, 0.008, 0.008},
      {0.09, -0.008, 0.008},
      {-0.008, -0.008, 0.008}},
    checked={{0, 0, 1}, {0, 0, 0}, {1, 0, 0}},
    r_0={BRACKET.frame_a.r_0, SLIDER.frame_a.r_0, TOOL.frame_a.r_0},
    R_T={BRACKET.frame_a.R.T, SLIDER.frame_a.R.T, TOOL.frame_a.R.T},
    v_0={BRACKET.v_0, SLIDER.v_0, TOOL.v_0},
    w_a={BRACKET.w_a, SLIDER.w_a, TOOL.w_a}) if collisions "Contact forces between the collision shapes"
    annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={-80,0})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_BRACKET if collisions "Contact force and torque on BRACKET (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={680,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_SLIDER if collisions "Contact force and torque on SLIDER (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1000,50})));
  Modelica.Mechanics.MultiBody.Forces.WorldForceAndTorque collisionForce_TOOL if collisions "Contact force and torque on TOOL (resolved in world)"
    annotation (Placement(transformation(extent={{10,-10},{-10,10}}, origin={1320,50})));
equation
  connect(collisionForce_BRACKET.frame_b, BRACKET.frame_a)
    annotation (Line(points={{670,50},{665,50},{665,5},{720,5},{720,0},{725,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[1, :], collisionForce_BRACKET.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,5},{5,5},{5,55},{665,55},{665,70},{695,70},{695,56},{692,56}}, color={0,0,127}));
  connect(collisionWorld.torque[1, :], collisionForce_BRACKET.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-5},{0,-5},{0,45},{660,45},{660,35},{695,35},{695,44},{692,44}}, color={0,0,127}));
  connect(collisionForce_SLIDER.frame_b, SLIDER.frame_a)
    annotation (Line(points={{990,50},{985,50},{985,5},{1040,5},{1040,0},{1045,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[2, :], collisionForce_SLIDER.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,55},{0,55},{0,60},{660,60},{660,75},{1015,75},{1015,56},{1012,56}}, color={0,0,127}));
  connect(collisionWorld.torque[2, :], collisionForce_SLIDER.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,0},{-5,0},{-5,50},{655,50},{655,30},{1015,30},{1015,44},{1012,44}}, color={0,0,127}));
  connect(collisionForce_TOOL.frame_b, TOOL.frame_a)
    annotation (Line(points={{1310,50},{1305,50},{1305,5},{1360,5},{1360,0},{1365,0}}, color={95,95,95}, thickness=0.5));
  connect(collisionWorld.force[3, :], collisionForce_TOOL.force)
    annotation (Line(points={{-63.5,6},{-60,6},{-60,10},{-10,10},{-10,65},{655,65},{655,80},{1335,80},{1335,56},{1332,56}}, color={0,0,127}));
  connect(collisionWorld.torque[3, :], collisionForce_TOOL.torque)
    annotation (Line(points={{-63.5,-6},{-60,-6},{-60,-10},{5,-10},{5,-15},{395,-15},{395,40},{650,40},{650,25},{1335,25},{1335,44},{1332,44}}, color={0,0,127}));
public
equation
  annotation (
    experiment(StopTime=4.0, Interval=0.01, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-140,-260},{1440,120}})),
    Icon(graphics={
      Rectangle(extent={{10,-70},{60,-30}}, lineColor={0,0,0}, fillColor={0,128,255}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{60,-54},{80,-46}}, lineColor={0,0,0}, fillColor={160,160,164}, fillPattern=FillPattern.HorizontalCylinder),
      Rectangle(extent={{20,-80},{50,-70}}, lineColor={0,0,0}, fillColor={64,64,64}, fillPattern=FillPattern.Solid)}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>VASM.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p><code>Mechatronics</code> extends <code>Mechanics</code> and refers to joints by name only: a <code>Mechanics</code> regenerated after a CAD change slots under it unchanged. Generated by cad2mo 0.1.0.</p>
<p>No drive is assigned: every joint is free, as in <code>Mechanics</code>. Assign motors, gears and controllers to joints in the motor library and regenerate this model.</p>
<p>Experiment: 4.0 s, about three swings of a pendulum as long as the mechanism's reach (0.315 m, period 1.13 s), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the Mechanics diagram, with each drive above the joint it moves, each contact force beside its body, and the reference tables and the collision and live-view blocks in a column left of the world.</p>
</html>"));
end Mechatronics;

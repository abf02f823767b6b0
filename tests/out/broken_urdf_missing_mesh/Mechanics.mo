within broken;
model Mechanics "Mechanical model of broken (2 bodies, 2 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, 0.0, -1.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={20,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body a(
    m=1.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.01, I_22=0.01, I_33=0.01,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part a (nodeID a)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={420,0})));
  Modelica.Mechanics.MultiBody.Parts.Body b(
    m=1.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.01, I_22=0.01, I_33=0.01,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part b (nodeID b)" annotation (Placement(transformation(extent={{-15,-15},{15,15}}, origin={740,0})));

  // Frames: grounds, joint attachment frames and user-added CAD frames

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  broken.Components.Revolute j(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint j (nodeID j)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={500,0})));

  // Shapes: CAD meshes in each body frame, metres
equation
  connect(world.frame_b, a.frame_a)
    annotation (Line(points={{30,0},{405,0}}, color={95,95,95}, thickness=0.5));
  connect(a.frame_a, j.frame_a)
    annotation (Line(points={{405,0},{400,0},{400,-20},{485,-20},{485,0},{490,0}}, color={95,95,95}, thickness=0.5));
  connect(j.frame_b, b.frame_a)
    annotation (Line(points={{510,0},{725,0}}, color={95,95,95}, thickness=0.5));
  annotation (
    experiment(StopTime=1.0, Interval=0.002, Tolerance=1e-06),
    Diagram(coordinateSystem(preserveAspectRatio=false, extent={{-40,-60},{800,60}})),
    Icon(coordinateSystem(preserveAspectRatio=false, extent={{-100,-100},{100,100}}), graphics={
      Rectangle(extent={{-100,-100},{100,100}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid, radius=8),
      Rectangle(extent={{-80,-80},{0,-66}}, lineColor={95,95,95}, fillColor={175,175,175}, fillPattern=FillPattern.Solid),
      Line(points={{-40,-66},{-40,10},{50,50}}, color={95,95,95}, thickness=1),
      Ellipse(extent={{-50,-76},{-30,-56}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Ellipse(extent={{-50,0},{-30,20}}, lineColor={95,95,95}, fillColor={255,255,255}, fillPattern=FillPattern.Solid),
      Polygon(points={{50,50},{70,40},{66,62}}, lineColor={95,95,95}, fillColor={95,95,95}, fillPattern=FillPattern.Solid),
      Text(extent={{-150,110},{150,150}}, textString="%name", textColor={0,0,255})}),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>robot.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<p>Experiment: 1 s (no gravity or no mass to set a time scale), 500 output intervals, tolerance 1e-6.</p>
<p>Diagram: the kinematic tree from the world (left) to the deepest bodies (right), one column per depth; each body stands with the frames fixed on it; the joints stand between the bodies they connect; dashed red lines close kinematic loops.</p>
</html>"));
end Mechanics;

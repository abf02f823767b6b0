within SLIDERCRANK;
model Mechanics "Mechanical model of SLIDERCRANK (4 bodies, 5 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-160,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID SLIDERCRANK/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,0})));
  Modelica.Mechanics.MultiBody.Parts.Body CRANK(
    m=0.0193536,
    r_CM={0.02, 0.0, 0.0},
    I_11=5.16096e-7, I_22=5.16096e-6, I_33=5.47062e-6,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part CRANK (nodeID 40)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));
  Modelica.Mechanics.MultiBody.Parts.Body ROD(
    m=0.0470016,
    r_CM={0.06, 0.0, 0.0},
    I_11=1.25338e-6, I_22=7.26958e-5, I_33=7.34478e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part ROD (nodeID 41)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-50})));
  Modelica.Mechanics.MultiBody.Parts.Body PISTON(
    m=0.0942,
    r_CM={0.0, 0.0, 0.0},
    I_11=6.28e-6, I_22=1.0205e-5, I_33=1.0205e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part PISTON (nodeID 42)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-75})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.642787609686539, -0.766044443118978, 0.0},
    n_y={0.766044443118978, 0.642787609686539, 0.0},
    animation=false)
    "Frame CS2 of CRANK (nodeID 40:-:SLIDERCRANK/RootPart::40(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation CRANK_CS3(
    r={0.04, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.642787609686539, -0.766044443118978, 0.0},
    n_y={0.766044443118978, 0.642787609686539, 0.0},
    animation=false)
    "Frame CS3 of CRANK (nodeID 40:-:41::40(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROD_CS2(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.966849173068348, 0.255348147706326, 0.0},
    n_y={-0.255348147706326, 0.966849173068348, 0.0},
    animation=false)
    "Frame CS2 of ROD (nodeID 40:-:41::41(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-50})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation ROD_CS3(
    r={0.12, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.966849173068348, 0.255348147706326, 0.0},
    n_y={-0.255348147706326, 0.966849173068348, 0.0},
    animation=false)
    "Frame CS3 of ROD (nodeID 41:-:42::41(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-75})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  SLIDERCRANK.Components.Revolute RootPart_CRANK(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--CRANK (nodeID 40:-:SLIDERCRANK/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));
  SLIDERCRANK.Components.Prismatic PISTON_RootPart(
    n={1.0, 0.0, 0.0},
    s(start=-0.141733405155663),
    v(start=0))
    "Joint PISTON--RootPart (nodeID 42:-:SLIDERCRANK/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-25})));
  SLIDERCRANK.Components.Revolute CRANK_ROD(
    n={0.0, 0.0, 1.0},
    phi(start=0.0),
    w(start=0))
    "Joint CRANK--ROD (nodeID 40:-:41)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-50})));
  Modelica.Mechanics.MultiBody.Joints.RevolutePlanarLoopConstraint ROD_PISTON(n={0.0, 0.0, 1.0}, animation=false)
    "Joint ROD--PISTON (nodeID 41:-:42): closes a planar loop" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-75})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape CRANK_shape(
    shapeType="modelica://SLIDERCRANK/Resources/Shapes/CRANK.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of CRANK" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,0})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape ROD_shape(
    shapeType="modelica://SLIDERCRANK/Resources/Shapes/ROD.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of ROD" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-25})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape PISTON_shape(
    shapeType="modelica://SLIDERCRANK/Resources/Shapes/PISTON.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of PISTON" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-50})));
equation
  connect(CRANK.frame_a, CRANK_CS2.frame_a);
  connect(CRANK.frame_a, CRANK_CS3.frame_a);
  connect(ROD.frame_a, ROD_CS2.frame_a);
  connect(ROD.frame_a, ROD_CS3.frame_a);
  connect(world.frame_b, RootPart.frame_a);
  connect(RootPart.frame_a, RootPart_CRANK.frame_a);
  connect(RootPart_CRANK.frame_b, CRANK_CS2.frame_b);
  connect(PISTON.frame_a, PISTON_RootPart.frame_a);
  connect(PISTON_RootPart.frame_b, RootPart.frame_a);
  connect(CRANK_CS3.frame_b, CRANK_ROD.frame_a);
  connect(CRANK_ROD.frame_b, ROD_CS2.frame_b);
  connect(ROD_CS3.frame_b, ROD_PISTON.frame_a);
  connect(ROD_PISTON.frame_b, PISTON.frame_a);
  connect(CRANK.frame_a, CRANK_shape.frame_a);
  connect(ROD.frame_a, ROD_shape.frame_a);
  connect(PISTON.frame_a, PISTON_shape.frame_a);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>SLIDERCRANK.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
<ul><li>Joint ROD--PISTON closes a loop: a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations.</li></ul>
</html>"));
end Mechanics;

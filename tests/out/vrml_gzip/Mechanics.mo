within VASM;
model Mechanics "Mechanical model of VASM (4 bodies, 4 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-160,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID VASM/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,0})));
  Modelica.Mechanics.MultiBody.Parts.Body BRACKET(
    m=0.1296,
    r_CM={0.06, -8.673617379884035e-19, 0.0},
    I_11=1.0799999999999998e-5, I_22=0.0002775600000000001, I_33=0.0002862000000000001,
    I_21=-2.0328790734103208e-20, I_31=-5.421010862427522e-20, I_32=0.0,
    animation=false)
    "Part BRACKET (nodeID 101)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));
  Modelica.Mechanics.MultiBody.Parts.Body SLIDER(
    m=0.0756,
    r_CM={0.02499999999999999, -2.0816681711721685e-17, -2.2551405187698492e-17},
    I_11=5.040000000000002e-6, I_22=3.338999999999999e-5, I_33=3.339e-5,
    I_21=1.6940658945086007e-21, I_31=-1.6940658945086007e-21, I_32=1.6940658945086007e-21,
    animation=false)
    "Part SLIDER (nodeID 102)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-50})));
  Modelica.Mechanics.MultiBody.Parts.Body TOOL(
    m=0.0677376,
    r_CM={0.040999999999999995, -2.0816681711721685e-17, 0.0},
    I_11=2.89014e-6, I_22=5.5657699999999994e-5, I_33=5.565770000000001e-5,
    I_21=1.6940658945086007e-21, I_31=-6.776263578034403e-21, I_32=0.0,
    animation=false)
    "Part TOOL (nodeID 103)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-75})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootPart_CS2(
    r={0.15, 0.02, -0.04},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.9457352705922856, 0.027827688097937786, -0.32374437096706465},
    n_y={0.19826689127414615, 0.7399421116938482, 0.6427876096865394},
    animation=false)
    "Frame CS2 of RootPart (nodeID 101:-:VASM/RootPart::VASM/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation BRACKET_CS3(
    r={0.13865048785232284, 0.05511265621777477, -0.007977301732681928},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.033724395124422324, 0.97092882126416, -0.23698077814894836},
    n_y={-0.29580256991935966, -0.23618893555111567, -0.9255893400165829},
    animation=false)
    "Frame CS3 of BRACKET (nodeID 101:-:102::101(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation SLIDER_CS3(
    r={0.10550678380293146, 0.016698974566565272, 0.050144419629572834},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.16722280402450435, 0.5611926683443818, -0.8106166312201439},
    n_y={0.9266957074557398, 0.3701351787990739, 0.06507699438728914},
    animation=false)
    "Frame CS3 of SLIDER (nodeID 102:-:103::102(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-50})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  VASM.Components.Revolute RootPart_BRACKET(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--BRACKET (nodeID 101:-:VASM/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));
  VASM.Components.Revolute BRACKET_SLIDER(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint BRACKET--SLIDER (nodeID 101:-:102)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-25})));
  VASM.Components.Revolute SLIDER_TOOL(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint SLIDER--TOOL (nodeID 102:-:103)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-50})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape BRACKET_shape(
    shapeType="modelica://VASM/Resources/Shapes/BRACKET.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={204, 51, 51})
    "Shape of BRACKET" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,0})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape SLIDER_shape(
    shapeType="modelica://VASM/Resources/Shapes/SLIDER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 153, 229})
    "Shape of SLIDER" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-25})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape TOOL_shape(
    shapeType="modelica://VASM/Resources/Shapes/TOOL.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={77, 204, 77})
    "Shape of TOOL" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-50})));
equation
  connect(RootPart.frame_a, RootPart_CS2.frame_a);
  connect(BRACKET.frame_a, BRACKET_CS3.frame_a);
  connect(SLIDER.frame_a, SLIDER_CS3.frame_a);
  connect(world.frame_b, RootPart.frame_a);
  connect(RootPart_CS2.frame_b, RootPart_BRACKET.frame_a);
  connect(RootPart_BRACKET.frame_b, BRACKET.frame_a);
  connect(BRACKET_CS3.frame_b, BRACKET_SLIDER.frame_a);
  connect(BRACKET_SLIDER.frame_b, SLIDER.frame_a);
  connect(SLIDER_CS3.frame_b, SLIDER_TOOL.frame_a);
  connect(SLIDER_TOOL.frame_b, TOOL.frame_a);
  connect(BRACKET.frame_a, BRACKET_shape.frame_a);
  connect(SLIDER.frame_a, SLIDER_shape.frame_a);
  connect(TOOL.frame_a, TOOL_shape.frame_a);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>VASM.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
</html>"));
end Mechanics;

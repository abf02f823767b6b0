within ROT;
model Mechanics "Mechanical model of ROT (4 bodies, 4 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-160,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.1, -0.05, 0.03},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID ROT/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,0})));
  Modelica.Mechanics.MultiBody.Parts.Body BRACKET(
    m=1.22148,
    r_CM={0.038000000000000006, 0.07250000000000001, -0.006500000000000002},
    I_11=0.0022949546724929655, I_22=0.0008062764690354197, I_33=0.002791588858471616,
    I_21=2.4240084765814185e-11, I_31=7.897380038335636e-10, I_32=4.345082080595142e-10,
    animation=false)
    "Part BRACKET (nodeID 101)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));
  Modelica.Mechanics.MultiBody.Parts.Body SLIDER(
    m=3.0555,
    r_CM={0.051000000000000004, 0.017500000000000022, 0.024500000000000015},
    I_11=0.0018276993982082363, I_22=0.005272013021169884, I_33=0.004385917580621877,
    I_21=3.218586620747782e-9, I_31=2.890093902261151e-9, I_32=-3.0766796538846813e-9,
    animation=false)
    "Part SLIDER (nodeID 102)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-50})));
  Modelica.Mechanics.MultiBody.Parts.Body TOOL(
    m=0.543629,
    r_CM={-0.011999999999999988, 0.04199999999999999, 0.01199999999999999},
    I_11=0.0005776968529561558, I_22=0.00017541091452303033, I_33=0.0005776962325208137,
    I_21=1.835260851303826e-10, I_31=-3.1583591563475247e-11, I_32=1.6777137470079528e-10,
    animation=false)
    "Part TOOL (nodeID 103)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-75})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootGround(
    r={0.1, -0.05, 0.03},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={1.0, 0.0, 0.0},
    n_y={0.0, 2.220446049250313e-16, -1.0},
    animation=false)
    "Ground RootGround (nodeID RootGround) in the world frame" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootPart_CS2(
    r={0.15, 0.02, -0.04},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.7504718954890314, 0.5655211363340804, 0.34202014332566877},
    n_y={-0.501895475867953, 0.15097002674496557, 0.8516507396391466},
    animation=false)
    "Frame CS2 of RootPart (nodeID 101:-:ROT/RootPart::ROT/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation BRACKET_CS2(
    r={0.013470770341104138, 0.015537903426925093, -0.010105043469118717},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.15930774407134057, 0.9614576685138584, 0.22409862635633318},
    n_y={-0.9535864748050319, 0.0911076433392703, 0.28700563129331863},
    animation=false)
    "Frame CS2 of BRACKET (nodeID 101:-:ROT/RootPart::101(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-50})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation BRACKET_CS3(
    r={0.062301151366221136, 0.12937216412189106, -0.00253173633336725},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.0586938877883621, -0.0961102165134004, -0.9936386938007369},
    n_y={-0.9600072941811049, -0.26751826275125284, 0.08258313516466415},
    animation=false)
    "Frame CS3 of BRACKET (nodeID 101:-:102::101(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-75})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation SLIDER_CS2(
    r={0.0015333785166566083, 0.008513071404819508, 0.0004199590231210859},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.14413650748816745, 0.9597633553902065, -0.24099578597818916},
    n_y={-0.24693614184172036, 0.2707194089062418, 0.9304480337416918},
    animation=false)
    "Frame CS2 of SLIDER (nodeID 101:-:102::102(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-100})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation SLIDER_CS3(
    r={0.10030388158786362, 0.02650994424788375, 0.04885032440406023},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.9186504594614032, -0.12754625123095076, -0.3739161498628856},
    n_y={0.377469135251024, -0.562728220045927, -0.7354277682388576},
    animation=false)
    "Frame CS3 of SLIDER (nodeID 102:-:103::102(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-125})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation TOOL_CS3(
    r={0.0, 0.0, 0.0},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.38514393444457373, -0.9228521311255888, 0.002844967049484781},
    n_y={0.2172295814058922, 0.09365408824623347, 0.9716173221577451},
    animation=false)
    "Frame CS3 of TOOL (nodeID 102:-:103::103(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-150})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootPart_CS3(
    r={0.1, -0.05, 0.03},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={1.0, 0.0, 0.0},
    n_y={0.0, 2.220446049250313e-16, -1.0},
    animation=false)
    "Frame CS3 of RootPart (nodeID ROT/RootPart:-:RootGround::ROT/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-175})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation TOOL_TOOL_TIP(
    r={-0.02354290319779692, 0.0835738646072377, 0.023688412011577842},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={-0.01049152776008977, 0.47300130644820526, 0.8809992576293978},
    n_y={0.08723074736349065, -0.8772560104996842, 0.4720303896536585},
    animation=false)
    "Frame CS2 of TOOL (nodeID 126(USERADDED))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-200})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  ROT.Components.Revolute RootPart_BRACKET(
    n={0.0, 0.0, 1.0},
    phi(start=0.5235987755982988, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--BRACKET (nodeID 101:-:ROT/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));
  ROT.Components.Prismatic BRACKET_SLIDER(
    n={-0.9199931398517658, -0.3349985881110967, 0.20344180639500115},
    s(start=0.024999999999999994, fixed=true),
    v(start=0, fixed=true))
    "Joint BRACKET--SLIDER (nodeID 101:-:102)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-25})));
  ROT.Components.Revolute SLIDER_TOOL(
    n={0.04483836055479218, 0.31596819202926274, 0.9477096723409113},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint SLIDER--TOOL (nodeID 102:-:103)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-50})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape BRACKET_shape(
    shapeType="modelica://ROT/Resources/Shapes/BRACKET.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={170, 170, 170})
    "Shape of BRACKET" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,0})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape SLIDER_shape(
    shapeType="modelica://ROT/Resources/Shapes/SLIDER.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 89, 204})
    "Shape of SLIDER" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-25})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape TOOL_shape(
    shapeType="modelica://ROT/Resources/Shapes/TOOL.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={242, 140, 26})
    "Shape of TOOL" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-50})));
equation
  connect(world.frame_b, RootGround.frame_a);
  connect(RootPart.frame_a, RootPart_CS2.frame_a);
  connect(BRACKET.frame_a, BRACKET_CS2.frame_a);
  connect(BRACKET.frame_a, BRACKET_CS3.frame_a);
  connect(SLIDER.frame_a, SLIDER_CS2.frame_a);
  connect(SLIDER.frame_a, SLIDER_CS3.frame_a);
  connect(TOOL.frame_a, TOOL_CS3.frame_a);
  connect(RootPart.frame_a, RootPart_CS3.frame_a);
  connect(TOOL.frame_a, TOOL_TOOL_TIP.frame_a);
  connect(RootGround.frame_b, RootPart_CS3.frame_b);
  connect(RootPart_CS2.frame_b, RootPart_BRACKET.frame_a);
  connect(RootPart_BRACKET.frame_b, BRACKET_CS2.frame_b);
  connect(BRACKET_CS3.frame_b, BRACKET_SLIDER.frame_a);
  connect(BRACKET_SLIDER.frame_b, SLIDER_CS2.frame_b);
  connect(SLIDER_CS3.frame_b, SLIDER_TOOL.frame_a);
  connect(SLIDER_TOOL.frame_b, TOOL_CS3.frame_b);
  connect(BRACKET.frame_a, BRACKET_shape.frame_a);
  connect(SLIDER.frame_a, SLIDER_shape.frame_a);
  connect(TOOL.frame_a, TOOL_shape.frame_a);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>ROT.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 5.0 from Pro/E Wildfire Creo 9.0 - 2022073 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
</html>"));
end Mechanics;

within VASM;
model Mechanics "Mechanical model of VASM (3 bodies, 3 joints)"
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
  Modelica.Mechanics.MultiBody.Parts.Body BOLT(
    m=0.0162,
    r_CM={0.0, 0.0, 0.03},
    I_11=4.995e-6, I_22=4.995e-6, I_33=2.7e-7,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part BOLT (nodeID 201)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));
  Modelica.Mechanics.MultiBody.Parts.Body NUT(
    m=0.015552,
    r_CM={0.0, 0.0, 0.005},
    I_11=8.76096e-7, I_22=8.76096e-7, I_33=1.49299e-6,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part NUT (nodeID 202)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-50})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootPart_CS2(
    r={0.12, 0.04, -0.03},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.90630778703665, 0.422618261740699, 0.0},
    n_y={-0.323744370967065, 0.694272044014884, 0.642787609686539},
    animation=false)
    "Frame CS2 of RootPart (nodeID 201:-:VASM/RootPart::VASM/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedRotation RootPart_CS3(
    r={0.12, 0.04, -0.03},
    rotationType=Modelica.Mechanics.MultiBody.Types.RotationTypes.TwoAxesVectors,
    n_x={0.90630778703665, 0.422618261740699, 0.0},
    n_y={-0.323744370967065, 0.694272044014884, 0.642787609686539},
    animation=false)
    "Frame CS3 of RootPart (nodeID 202:-:VASM/RootPart::VASM/RootPart(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  VASM.Components.Revolute RootPart_BOLT(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--BOLT (nodeID 201:-:VASM/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));
  VASM.Components.Revolute RootPart_NUT(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--NUT (nodeID 202:-:VASM/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-25})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape BOLT_shape(
    shapeType="modelica://VASM/Resources/Shapes/BOLT.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={204, 51, 51})
    "Shape of BOLT" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,0})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape NUT_shape(
    shapeType="modelica://VASM/Resources/Shapes/NUT.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={51, 153, 229})
    "Shape of NUT" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-25})));
equation
  connect(RootPart.frame_a, RootPart_CS2.frame_a);
  connect(RootPart.frame_a, RootPart_CS3.frame_a);
  connect(world.frame_b, RootPart.frame_a);
  connect(RootPart_CS2.frame_b, RootPart_BOLT.frame_a);
  connect(RootPart_BOLT.frame_b, BOLT.frame_a);
  connect(RootPart_CS3.frame_b, RootPart_NUT.frame_a);
  connect(RootPart_NUT.frame_b, NUT.frame_a);
  connect(BOLT.frame_a, BOLT_shape.frame_a);
  connect(NUT.frame_a, NUT_shape.frame_a);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>VASM.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
</html>"));
end Mechanics;

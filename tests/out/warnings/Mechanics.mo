within WARN;
model Mechanics "Mechanical model of WARN (6 bodies, 6 joints)"
  inner Modelica.Mechanics.MultiBody.World world(n={0.0, -1.0, 0.0}, g=9.81) "World frame: the CAD assembly's frame"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-160,0})));

  // Bodies: frame_a is each part's CS1 frame
  Modelica.Mechanics.MultiBody.Parts.Body RootPart(
    m=0.0,
    r_CM={0.0, 0.0, 0.0},
    I_11=0.0, I_22=0.0, I_33=0.0,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Assembly root RootPart (nodeID WARN/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,0})));
  Modelica.Mechanics.MultiBody.Parts.Body ASYM(
    m=0.0648,
    r_CM={0.05, 0.0, 0.0},
    I_11=2.7e-6, I_22=7.83e-5, I_33=7.992e-5,
    I_21=1e-6, I_31=0.0, I_32=0.0,
    animation=false)
    "Part ASYM (nodeID 501)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-25})));
  Modelica.Mechanics.MultiBody.Parts.Body TRI(
    m=0.0648,
    r_CM={0.05, 0.0, 0.0},
    I_11=5.4e-7, I_22=7.83e-5, I_33=7.992e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part TRI (nodeID 502)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-50})));
  Modelica.Mechanics.MultiBody.Parts.Body GHOST(
    m=0.0648,
    r_CM={0.05, 0.0, 0.0},
    I_11=2.7e-6, I_22=7.83e-5, I_33=7.992e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part GHOST (nodeID 503)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-75})));
  Modelica.Mechanics.MultiBody.Parts.Body BARE(
    m=0.0648,
    r_CM={0.05, 0.0, 0.0},
    I_11=2.7e-6, I_22=7.83e-5, I_33=7.992e-5,
    I_21=0.0, I_31=0.0, I_32=0.0)
    "Part BARE (nodeID 504)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-100})));
  Modelica.Mechanics.MultiBody.Parts.Body NOMAT(
    m=12.5,
    r_CM={0.002, 0.0, 0.0},
    I_11=2.63021e-5, I_22=2.63021e-5, I_33=5.20833e-5,
    I_21=0.0, I_31=0.0, I_32=0.0,
    animation=false)
    "Part NOMAT (nodeID 505)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={280,-125})));

  // Frames: grounds, joint attachment frames and user-added CAD frames
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation ASYM_CS3(r={0.1, 0.0, 0.0}, animation=false)
    "Frame CS3 of ASYM (nodeID 501:-:502::501(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,0})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation TRI_CS3(r={0.1, 0.0, 0.0}, animation=false)
    "Frame CS3 of TRI (nodeID 502:-:503::502(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-25})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation GHOST_CS3(r={0.1, 0.0, 0.0}, animation=false)
    "Frame CS3 of GHOST (nodeID 503:-:504::503(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-50})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation BARE_CS3(r={0.1, 0.0, 0.0}, animation=false)
    "Frame CS3 of BARE (nodeID 504:-:505::504(AUTOGEN))" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-75})));

  // Joints: base frame -> follower frame; start values reproduce the CAD pose
  WARN.Components.Revolute RootPart_ASYM(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint RootPart--ASYM (nodeID 501:-:WARN/RootPart)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,0})));
  WARN.Components.Revolute ASYM_TRI(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint ASYM--TRI (nodeID 501:-:502)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-25})));
  Modelica.Mechanics.MultiBody.Parts.FixedTranslation ASYM_TRI_offset(r={0.0, 0.002, 0.0}, animation=false)
    "CAD offset of joint ASYM--TRI (nodeID 501:-:502) at its start values" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={160,-100})));
  WARN.Components.Revolute GHOST_BARE(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint GHOST--BARE (nodeID 503:-:504)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-50})));
  WARN.Components.Revolute BARE_NOMAT(
    n={0.0, 0.0, 1.0},
    phi(start=0.0, fixed=true),
    w(start=0, fixed=true))
    "Joint BARE--NOMAT (nodeID 504:-:505)" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={-40,-75})));

  // Shapes: CAD meshes in each body frame, metres
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape ASYM_shape(
    shapeType="modelica://WARN/Resources/Shapes/ASYM.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of ASYM" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,0})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape TRI_shape(
    shapeType="modelica://WARN/Resources/Shapes/TRI.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of TRI" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-25})));
  Modelica.Mechanics.MultiBody.Visualizers.FixedShape NOMAT_shape(
    shapeType="modelica://WARN/Resources/Shapes/NOMAT.dxf",
    length=1, width=1, height=1,
    extra=0,
    color={179, 179, 179})
    "Shape of NOMAT" annotation (Placement(transformation(extent={{-10,-10},{10,10}}, origin={400,-50})));
equation
  connect(ASYM.frame_a, ASYM_CS3.frame_a);
  connect(TRI.frame_a, TRI_CS3.frame_a);
  connect(GHOST.frame_a, GHOST_CS3.frame_a);
  connect(BARE.frame_a, BARE_CS3.frame_a);
  connect(world.frame_b, RootPart.frame_a);
  connect(RootPart.frame_a, RootPart_ASYM.frame_a);
  connect(RootPart_ASYM.frame_b, ASYM.frame_a);
  connect(ASYM_CS3.frame_b, ASYM_TRI.frame_a);
  connect(ASYM_TRI.frame_b, ASYM_TRI_offset.frame_a);
  connect(ASYM_TRI_offset.frame_b, TRI.frame_a);
  connect(TRI_CS3.frame_b, GHOST.frame_a);
  connect(GHOST_CS3.frame_b, GHOST_BARE.frame_a);
  connect(GHOST_BARE.frame_b, BARE.frame_a);
  connect(BARE_CS3.frame_b, BARE_NOMAT.frame_a);
  connect(BARE_NOMAT.frame_b, NOMAT.frame_a);
  connect(ASYM.frame_a, ASYM_shape.frame_a);
  connect(TRI.frame_a, TRI_shape.frame_a);
  connect(NOMAT.frame_a, NOMAT_shape.frame_a);
  annotation (
    experiment(StopTime=1),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>WARN.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>All quantities in SI units. Each body's frame_a is its CAD part frame CS1; joint start values reproduce the CAD pose.</p>
</html>"));
end Mechanics;

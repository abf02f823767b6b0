//! The Modelica text of the drive library `<Pkg>/Components/Drives/`.
//!
//! Templates use `$P` for the package name, `$V` for the converter version and `$PARAMS` for the
//! parameter declarations generated from the class table (`super::SPECS`), so the Rust validation
//! and the Modelica classes cannot drift apart.

use super::{spec, Param, Ty, RATIO};

/// Small icon: a framed box with the instance name above it.
const ICON: &str = r#"Icon(graphics={Rectangle(extent={{-100,100},{100,-100}}, lineColor={0,0,127}, fillColor={255,255,255}, fillPattern=FillPattern.Solid), Text(extent={{-150,150},{150,110}}, textString="%name", textColor={0,0,255})})"#;

fn param_decl(p: &Param) -> String {
    // A plain Real gets no `unit` attribute (the MSL blocks it feeds are unitless, like the gains
    // of RobotR3's controller): its unit goes into the description instead.
    let range = p.range.attributes();
    let attrs = if range.is_empty() || matches!(p.ty, Ty::Boolean | Ty::String) { String::new() } else { format!("({range})") };
    let doc = if p.mtype == "Real" && !p.unit.is_empty() && p.unit != "1" { format!("{}, {}", p.doc, p.unit) } else { p.doc.to_string() };
    format!("  parameter {} {}{attrs} = {} \"{}\";", p.mtype, p.name, p.default, super::mstr(&doc))
}

/// Declarations of the parameters a class declares itself (not those of its interface).
fn params_of(path: &str) -> String {
    spec(path).map(|s| s.params.iter().filter(|p| !p.inherited).map(param_decl).collect::<Vec<_>>().join("\n")).unwrap_or_default()
}

/// HTML table of a class's library parameters.
fn params_html(path: &str) -> String {
    let Some(s) = spec(path) else { return String::new() };
    let rows: Vec<String> = s
        .params
        .iter()
        .map(|p| {
            format!(
                "<tr><td><code>{}</code></td><td>{}</td><td>{}</td><td>{}</td></tr>",
                p.name,
                super::html(p.unit),
                super::html(p.default),
                super::html(p.doc)
            )
        })
        .collect();
    format!(
        "<p>Parameters set by the motor library (library class <code>{}</code>):</p>\n<table border='1' cellspacing='0' cellpadding='2'>\n<tr><th>Name</th><th>Unit</th><th>Default</th><th>Meaning</th></tr>\n{}\n</table>",
        super::html(s.path),
        rows.join("\n")
    )
}

/// HTML table of the library classes: what the motor library may refer to.
fn library_html() -> String {
    let rows: Vec<String> = super::SPECS
        .iter()
        .map(|s| {
            let joints = s.fits.map_or("any", |k| k.name());
            format!(
                "<tr><td><code>{}</code></td><td>{}</td><td><code>{}</code></td><td>{}</td><td>{}</td></tr>",
                super::html(s.path),
                s.domain.name(),
                super::html(s.class),
                joints,
                super::html(s.doc)
            )
        })
        .collect();
    format!(
        "<p>Library classes (a path starting with <code>cad2mo.</code> is our own class; an MSL path is the MSL model the class wraps):</p>\n<table border='1' cellspacing='0' cellpadding='2'>\n<tr><th>Library class</th><th>Slot</th><th>Class</th><th>Joints</th><th>Description</th></tr>\n{}\n</table>",
        rows.join("\n")
    )
}

fn fill(template: &str, pkg: &str, params: &str, params_html: &str) -> Vec<u8> {
    template
        .replace("$CLASSES", &library_html())
        .replace("$PARAMS_HTML", params_html)
        .replace("$PARAMS", params)
        .replace("$ICON", ICON)
        .replace("$V", &super::html(crate::pipeline::VERSION))
        .replace("$P", pkg)
        .into_bytes()
}

/// Every file of the drive library.
pub(super) fn files(pkg: &str) -> Vec<(String, Vec<u8>)> {
    let dir = format!("{pkg}/Components/Drives");
    let plain = |rel: &str, t: &str| (format!("{dir}/{rel}"), fill(t, pkg, "", ""));
    let class = |rel: &str, t: &str, path: &str| (format!("{dir}/{rel}"), fill(t, pkg, &params_of(path), &params_html(path)));
    let ratio = param_decl(&RATIO);
    vec![
        plain("package.mo", DRIVES),
        plain("package.order", "Interfaces\nMotors\nGears\nControllers\nJointDrive\nLinearJointDrive\n"),
        plain("JointDrive.mo", JOINT_DRIVE),
        plain("LinearJointDrive.mo", LINEAR_JOINT_DRIVE),
        plain("Interfaces/package.mo", INTERFACES),
        plain("Interfaces/package.order", "Motor\nGear\nLinearGear\nController\nPartialJointDrive\n"),
        plain("Interfaces/Motor.mo", MOTOR),
        (format!("{dir}/Interfaces/Gear.mo"), fill(GEAR, pkg, &ratio, "")),
        plain("Interfaces/LinearGear.mo", LINEAR_GEAR),
        plain("Interfaces/Controller.mo", CONTROLLER),
        plain("Interfaces/PartialJointDrive.mo", PARTIAL_JOINT_DRIVE),
        plain("Motors/package.mo", MOTORS),
        plain("Motors/package.order", "DCPermanentMagnet\nMSL_DC_PermanentMagnet\nServoMotor\n"),
        class("Motors/DCPermanentMagnet.mo", DC_PERMANENT_MAGNET, "cad2mo.Drives.Motors.DCPermanentMagnet"),
        class(
            "Motors/MSL_DC_PermanentMagnet.mo",
            MSL_DC_PERMANENT_MAGNET,
            "Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet",
        ),
        class("Motors/ServoMotor.mo", SERVO_MOTOR, "cad2mo.Drives.Motors.ServoMotor"),
        plain("Gears/package.mo", GEARS),
        plain("Gears/package.order", "Ideal\nEfficiency\nLeadScrew\n"),
        class("Gears/Ideal.mo", IDEAL, "Modelica.Mechanics.Rotational.Components.IdealGear"),
        class("Gears/Efficiency.mo", EFFICIENCY, "cad2mo.Drives.Gears.Efficiency"),
        class("Gears/LeadScrew.mo", LEAD_SCREW, "cad2mo.Drives.Gears.LeadScrew"),
        plain("Controllers/package.mo", CONTROLLERS),
        plain("Controllers/package.order", "CascadePPI\n"),
        class("Controllers/CascadePPI.mo", CASCADE_PPI, "cad2mo.Drives.Controllers.CascadePPI"),
    ]
}

const DRIVES: &str = r#"within $P.Components;
package Drives "Joint drives: reference, controller, motor and gear"
  annotation (Documentation(info="<html>
<p>Drives for the joints of <code>Mechanics</code>, used by <code>Mechatronics</code>. A drive
(<code>JointDrive</code> for a revolute joint, <code>LinearJointDrive</code> for a prismatic one)
connects to the joint's <code>drive</code> flange and holds four parts:</p>
<pre>
reference --q_ref--&gt; controller --i_ref--&gt; motor --flange--&gt; gear --flange--&gt; joint.drive
                        ^     ^                       |
              phi_motor |     | w_motor &lt;-------------+   (sensors on the motor shaft)
</pre>
<ul>
<li><b>Motor</b> (<code>Interfaces.Motor</code>): the command is the armature current
<code>i_ref</code> in A; every motor has an inner current loop with current and voltage limits.
The stator is fixed to the ground, as is the joint's support.</li>
<li><b>Gear</b> (<code>Interfaces.Gear</code>, revolute joints): <code>ratio</code> = motor speed /
joint speed, as in <code>Modelica.Mechanics.Rotational.Components.IdealGear</code>
(flange_a.phi = ratio*flange_b.phi). <b>Linear gear</b> (<code>Interfaces.LinearGear</code>,
prismatic joints): <code>transmission</code> = motor angle / joint displacement in rad/m.</li>
<li><b>Controller</b> (<code>Interfaces.Controller</code>): reference joint coordinate (rad or m),
measured motor angle (rad) and speed (rad/s) in, current command (A) out. Its <code>ratio</code>
is set by the drive to the gear's transmission, so it compares <code>ratio*q_ref</code> with the
motor angle: it works in motor radians and drives the joint coordinate to the reference.</li>
<li><b>Reference</b>: a constant (<code>q_constant</code>) or a table over time
(<code>table</code>, linear interpolation, last value held).</li>
</ul>
<p>The motor angle is exactly <code>ratio</code> times the joint coordinate (the gears are rigid and
both supports are fixed), so measuring on the motor side loses nothing.</p>
$CLASSES
<p>Generated by cad2mo $V.</p>
</html>"));
end Drives;
"#;

const INTERFACES: &str = r#"within $P.Components.Drives;
package Interfaces "Partial models of the drive slots: motor, gear, controller"
  annotation (Documentation(info="<html><p>The constraining classes of the replaceable motor, gear
and controller of <code>JointDrive</code> and <code>LinearJointDrive</code>. Generated by cad2mo $V.</p></html>"));
end Interfaces;
"#;

const MOTORS: &str = r#"within $P.Components.Drives;
package Motors "Motors with a current command input"
  annotation (Documentation(info="<html><p>Motors extending <code>Interfaces.Motor</code>.
Generated by cad2mo $V.</p></html>"));
end Motors;
"#;

const GEARS: &str = r#"within $P.Components.Drives;
package Gears "Gears (revolute joints) and screws (prismatic joints)"
  annotation (Documentation(info="<html><p>Gears extending <code>Interfaces.Gear</code> and
<code>Interfaces.LinearGear</code>. Generated by cad2mo $V.</p></html>"));
end Gears;
"#;

const CONTROLLERS: &str = r#"within $P.Components.Drives;
package Controllers "Joint controllers"
  annotation (Documentation(info="<html><p>Controllers extending <code>Interfaces.Controller</code>.
Generated by cad2mo $V.</p></html>"));
end Controllers;
"#;

const MOTOR: &str = r#"within $P.Components.Drives.Interfaces;
partial model Motor "Motor: armature current command in, torque on the motor shaft out"
  Modelica.Blocks.Interfaces.RealInput i_ref "Armature current command, A"
    annotation (Placement(transformation(extent={{-140,-20},{-100,20}})));
  Modelica.Mechanics.Rotational.Interfaces.Flange_b flange "Motor shaft (the stator is fixed to the ground)"
    annotation (Placement(transformation(extent={{90,-10},{110,10}})));
  annotation ($ICON, Documentation(info="<html>
<p>Interface of a motor: the input <code>i_ref</code> is the armature current command in A, the
output is the shaft <code>flange</code> (motor side of the gear). A motor contains its own current
loop and limits; its stator is fixed to the ground.</p>
</html>"));
end Motor;
"#;

const GEAR: &str = r#"within $P.Components.Drives.Interfaces;
partial model Gear "Rotational gear: flange_a to the motor, flange_b to the joint"
$PARAMS
  Modelica.Mechanics.Rotational.Interfaces.Flange_a flange_a "Motor side"
    annotation (Placement(transformation(extent={{-110,-10},{-90,10}})));
  Modelica.Mechanics.Rotational.Interfaces.Flange_b flange_b "Joint side"
    annotation (Placement(transformation(extent={{90,-10},{110,10}})));
  annotation ($ICON, Documentation(info="<html>
<p>Interface of a gear between the motor (<code>flange_a</code>) and a revolute joint
(<code>flange_b</code>). <code>ratio</code> = motor speed / joint speed =
flange_a.phi / flange_b.phi, as in <code>Modelica.Mechanics.Rotational.Components.IdealGear</code>;
the drive's controller uses it to scale the reference to motor radians.</p>
</html>"));
end Gear;
"#;

const LINEAR_GEAR: &str = r#"within $P.Components.Drives.Interfaces;
partial model LinearGear "Rotational-to-translational transmission: flange_a to the motor, flange_b to the joint"
  parameter Real transmission(unit="rad/m") = 1 "Motor angle / joint displacement (flange_a.phi / flange_b.s)";
  Modelica.Mechanics.Rotational.Interfaces.Flange_a flange_a "Motor side"
    annotation (Placement(transformation(extent={{-110,-10},{-90,10}})));
  Modelica.Mechanics.Translational.Interfaces.Flange_b flange_b "Joint side"
    annotation (Placement(transformation(extent={{90,-10},{110,10}})));
  annotation ($ICON, Documentation(info="<html>
<p>Interface of a transmission between the motor (rotational <code>flange_a</code>) and a
prismatic joint (translational <code>flange_b</code>). <code>transmission</code> = motor angle /
joint displacement in rad/m, as the <code>ratio</code> of
<code>Modelica.Mechanics.Rotational.Components.IdealGearR2T</code>; the drive's controller uses it
to scale the reference to motor radians.</p>
</html>"));
end LinearGear;
"#;

const CONTROLLER: &str = r#"within $P.Components.Drives.Interfaces;
partial block Controller "Joint controller: reference and measured motor angle and speed in, current command out"
  parameter Real ratio = 1 "Motor angle per unit of the joint coordinate: gear ratio (rad/rad) or transmission (rad/m), set by the drive";
  Modelica.Blocks.Interfaces.RealInput q_ref "Reference joint coordinate: angle in rad or position in m"
    annotation (Placement(transformation(extent={{-140,-20},{-100,20}})));
  Modelica.Blocks.Interfaces.RealInput qd_ref "Reference joint speed (feed-forward): rad/s or m/s"
    annotation (Placement(transformation(extent={{-140,40},{-100,80}})));
  Modelica.Blocks.Interfaces.RealInput phi_motor "Measured motor angle, rad"
    annotation (Placement(transformation(extent={{-20,-20},{20,20}}, rotation=90, origin={-60,-120})));
  Modelica.Blocks.Interfaces.RealInput w_motor "Measured motor speed, rad/s"
    annotation (Placement(transformation(extent={{-20,-20},{20,20}}, rotation=90, origin={60,-120})));
  Modelica.Blocks.Interfaces.RealOutput i_ref "Armature current command, A"
    annotation (Placement(transformation(extent={{100,-10},{120,10}})));
  annotation ($ICON, Documentation(info="<html>
<p>Interface of a joint controller. Inputs: the reference joint coordinate <code>q_ref</code>
(rad for a revolute joint, m for a prismatic one), its speed <code>qd_ref</code> for feed-forward
(0 for a constant or table reference), the measured motor angle
<code>phi_motor</code> (rad) and speed <code>w_motor</code> (rad/s). Output: the armature current
command <code>i_ref</code> (A). <code>ratio</code> (motor angle per unit of the joint coordinate)
is set by the drive from its gear, so <code>ratio*q_ref</code> is the motor angle at which the
joint is at the reference.</p>
</html>"));
end Controller;
"#;

const DC_PERMANENT_MAGNET: &str = r#"within $P.Components.Drives.Motors;
model DCPermanentMagnet "DC permanent-magnet motor with an inner current loop and voltage and current limits"
  import SI = Modelica.Units.SI;
  extends $P.Components.Drives.Interfaces.Motor;
$PARAMS
  SI.Angle phi "Rotor angle";
  SI.AngularVelocity w "Rotor speed";
  SI.Current i(start=0, fixed=true) "Armature current";
  SI.Current i_cmd "Current command after the current limit";
  SI.Voltage v_cmd "Voltage demanded by the current loop";
  SI.Voltage v "Armature voltage: v_cmd limited to the supply voltage";
  SI.Torque tau "Electromagnetic torque";
equation
  // Current limit, then the current loop: proportional gain L/Tc with resistive and back-EMF
  // feed-forward, limited by the supply voltage.
  i_cmd = smooth(0, noEvent(if i_ref > I_max then I_max else if i_ref < -I_max then -I_max else i_ref));
  v_cmd = R*i_cmd + k*w + L/Tc*(i_cmd - i);
  v = smooth(0, noEvent(if v_cmd > V_max then V_max else if v_cmd < -V_max then -V_max else v_cmd));
  // Armature circuit and rotor.
  L*der(i) = v - R*i - k*w;
  tau = k*i;
  phi = flange.phi;
  w = der(phi);
  J*der(w) = tau - d*w + flange.tau;
  annotation (Documentation(info="<html>
<p>A brushed DC motor with permanent-magnet excitation and its power stage, written out as
equations (no MSL machine inside):</p>
<pre>
i_cmd    = limit(i_ref, -I_max, I_max)
v_cmd    = R*i_cmd + k*w + L/Tc*(i_cmd - i)
v        = limit(v_cmd, -V_max, V_max)
L*der(i) = v - R*i - k*w
tau      = k*i
J*der(w) = tau - d*w + flange.tau,   w = der(phi),   phi = flange.phi
</pre>
<p>While the voltage is not limited, the current follows the command with the time constant
L/(R + L/Tc) &lt;= Tc and no steady-state error (feed-forward of R*i_cmd and the back-EMF k*w).
The voltage limit caps the speed at about V_max/k; the current limit caps the torque at k*I_max.
The stator is fixed to the ground. The rotor angle and speed are not fixed at the start: the joint
they drive through the gear fixes them.</p>
$PARAMS_HTML
</html>"));
end DCPermanentMagnet;
"#;

const SERVO_MOTOR: &str = r#"within $P.Components.Drives.Motors;
model ServoMotor "Permanent-magnet AC servo motor with field-oriented current control and a current limit"
  import SI = Modelica.Units.SI;
  extends $P.Components.Drives.Interfaces.Motor;
$PARAMS
  SI.Angle phi "Rotor angle";
  SI.AngularVelocity w "Rotor speed";
  SI.Current i(start=0, fixed=true) "Torque-forming current (A rms)";
  SI.Current i_cmd "Current command after the current limit";
  SI.Torque tau "Electromagnetic torque";
equation
  // Current limit, then the servo amplifier's current loop as a first-order lag.
  i_cmd = smooth(0, noEvent(if i_ref > I_max then I_max else if i_ref < -I_max then -I_max else i_ref));
  Tc*der(i) = i_cmd - i;
  tau = k*i;
  phi = flange.phi;
  w = der(phi);
  J*der(w) = tau + flange.tau;
  annotation (Documentation(info="<html>
<p>A permanent-magnet synchronous (AC servo) motor and its servo amplifier as servo makers rate
them: under field-oriented control the torque is the torque constant times the torque-forming
current (A rms), and the amplifier's current loop makes that current follow the command:</p>
<pre>
i_cmd     = limit(i_ref, -I_max, I_max)
Tc*der(i) = i_cmd - i
tau       = k*i
J*der(w)  = tau + flange.tau,   w = der(phi),   phi = flange.phi
</pre>
<p>Servo datasheets give no winding resistance or inductance for this use, so the motor voltage
and the speed limit it sets are not modelled; the current limit caps the torque at k*I_max (the
maker's instantaneous maximum torque). The stator is fixed to the ground.</p>
$PARAMS_HTML
</html>"));
end ServoMotor;
"#;

const MSL_DC_PERMANENT_MAGNET: &str = r#"within $P.Components.Drives.Motors;
model MSL_DC_PermanentMagnet "MSL DC permanent-magnet machine fed by a voltage source with a current loop"
  import SI = Modelica.Units.SI;
  extends $P.Components.Drives.Interfaces.Motor;
$PARAMS
  parameter SI.Voltage V_max = VaNominal "Supply voltage: limit of the armature voltage";
  parameter SI.Current I_max = IaNominal "Current limit of the drive";
  parameter SI.Time Tc(min=0) = 0.001 "Time constant of the current loop (proportional gain La/Tc)";
  final parameter SI.Resistance Ra_operational = Modelica.Electrical.Machines.Thermal.convertResistance(
    RRef=Ra, TRef=TaRef, alpha20=alpha20a, T=TaOperational) "Armature resistance at the operational temperature";
  final parameter SI.ElectricalTorqueConstant psi = (VaNominal - Modelica.Electrical.Machines.Thermal.convertResistance(
    RRef=Ra, TRef=TaRef, alpha20=alpha20a, T=TaNominal)*IaNominal)/wNominal "Back-EMF constant of the machine (no brush losses)";
  Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet dcpm(
    VaNominal=VaNominal,
    IaNominal=IaNominal,
    wNominal=wNominal,
    TaNominal=TaNominal,
    Ra=Ra,
    TaRef=TaRef,
    alpha20a=alpha20a,
    La=La,
    Jr=Jr,
    Js=Js,
    TaOperational=TaOperational,
    useSupport=false,
    useThermalPort=false,
    ia(start=0, fixed=true)) "The MSL machine"
    annotation (Placement(transformation(extent={{20,-10},{40,10}})));
  Modelica.Electrical.Analog.Sources.SignalVoltage supply "Power stage: controlled armature voltage"
    annotation (Placement(transformation(extent={{-10,10},{10,30}})));
  Modelica.Electrical.Analog.Basic.Ground ground "Electrical ground"
    annotation (Placement(transformation(extent={{-30,-40},{-10,-20}})));
  SI.Current i_cmd "Current command after the current limit";
  SI.Voltage v_cmd "Voltage demanded by the current loop";
equation
  i_cmd = smooth(0, noEvent(if i_ref > I_max then I_max else if i_ref < -I_max then -I_max else i_ref));
  v_cmd = Ra_operational*i_cmd + psi*dcpm.wMechanical + La/Tc*(i_cmd - dcpm.ia);
  supply.v = smooth(0, noEvent(if v_cmd > V_max then V_max else if v_cmd < -V_max then -V_max else v_cmd));
  connect(supply.p, dcpm.pin_ap);
  connect(supply.n, dcpm.pin_an);
  connect(supply.n, ground.p);
  connect(dcpm.flange, flange);
  annotation (Documentation(info="<html>
<p>Wraps <code>Modelica.Electrical.Machines.BasicMachines.DCMachines.DC_PermanentMagnet</code>
(the library class path) so that it fits <code>Interfaces.Motor</code>: the machine's parameters
are forwarded 1:1; a signal voltage source (the power stage) feeds the armature; a current loop
sets its voltage:</p>
<pre>
i_cmd = limit(i_ref, -I_max, I_max)
v     = limit(Ra_operational*i_cmd + psi*w + La/Tc*(i_cmd - ia), -V_max, V_max)
psi   = (VaNominal - Ra(TaNominal)*IaNominal)/wNominal
</pre>
<p>With the default (zero) brush, core, stray-load and friction losses of the MSL machine the
feed-forward is exact and the current follows the command with a time constant below Tc. The
voltage limit defaults to VaNominal, the current limit to IaNominal. The stator is fixed
(<code>useSupport=false</code>); the armature current starts at 0; the rotor angle and speed are
fixed by the joint the motor drives.</p>
$PARAMS_HTML
</html>"));
end MSL_DC_PermanentMagnet;
"#;

const IDEAL: &str = r#"within $P.Components.Drives.Gears;
model Ideal "Ideal gear (MSL IdealGear)"
  extends $P.Components.Drives.Interfaces.Gear;
  Modelica.Mechanics.Rotational.Components.IdealGear idealGear(final ratio=ratio, useSupport=false) "The MSL gear"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}})));
equation
  connect(flange_a, idealGear.flange_a);
  connect(idealGear.flange_b, flange_b);
  annotation (Documentation(info="<html>
<p><code>Modelica.Mechanics.Rotational.Components.IdealGear</code> (the library class path) with
its support fixed: flange_a.phi = ratio*flange_b.phi, flange_b.tau = -ratio*flange_a.tau. No
inertia, no losses.</p>
$PARAMS_HTML
</html>"));
end Ideal;
"#;

const EFFICIENCY: &str = r#"within $P.Components.Drives.Gears;
model Efficiency "Gear with a constant efficiency (MSL LossyGear)"
  extends $P.Components.Drives.Interfaces.Gear;
$PARAMS
  Modelica.Mechanics.Rotational.Components.LossyGear lossyGear(
    final ratio=ratio,
    final lossTable=[0, eta, eta, 0, 0],
    useSupport=false) "The MSL gear with losses"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}})));
equation
  connect(flange_a, lossyGear.flange_a);
  connect(lossyGear.flange_b, flange_b);
  annotation (Documentation(info="<html>
<p><code>Modelica.Mechanics.Rotational.Components.LossyGear</code> with its support fixed and
<code>lossTable=[0, eta, eta, 0, 0]</code>: the same efficiency <code>eta</code> whichever side
drives, at every speed, and no bearing friction. flange_a.phi = ratio*flange_b.phi; the
transmitted power is reduced by the factor eta.</p>
$PARAMS_HTML
</html>"));
end Efficiency;
"#;

const LEAD_SCREW: &str = r#"within $P.Components.Drives.Gears;
model LeadScrew "Ideal gearbox and lead screw for a prismatic joint (MSL IdealGearR2T)"
  import SI = Modelica.Units.SI;
  extends $P.Components.Drives.Interfaces.LinearGear(final transmission=2*Modelica.Constants.pi*ratio/lead);
$PARAMS
  Modelica.Mechanics.Rotational.Components.IdealGearR2T screw(
    final ratio=transmission,
    useSupportR=false,
    useSupportT=false) "Gearbox and screw as one ideal transmission"
    annotation (Placement(transformation(extent={{-10,-10},{10,10}})));
equation
  connect(flange_a, screw.flangeR);
  connect(screw.flangeT, flange_b);
  annotation (Documentation(info="<html>
<p>A gearbox (<code>ratio</code> = motor speed / screw speed) and a lead screw (<code>lead</code> =
joint travel per screw revolution, in m) as one
<code>Modelica.Mechanics.Rotational.Components.IdealGearR2T</code> with its supports fixed:
transmission = 2*pi*ratio/lead rad/m, flange_a.phi = transmission*flange_b.s. No inertia, no
losses.</p>
$PARAMS_HTML
</html>"));
end LeadScrew;
"#;

const CASCADE_PPI: &str = r#"within $P.Components.Drives.Controllers;
block CascadePPI "Cascade joint controller: P position loop, PI speed loop (as MSL RobotR3)"
  import SI = Modelica.Units.SI;
  extends $P.Components.Drives.Interfaces.Controller;
$PARAMS
  Modelica.Blocks.Math.Gain toMotorAngle(k=ratio) "Reference joint coordinate to motor angle, rad"
    annotation (Placement(transformation(extent={{-90,-10},{-70,10}})));
  Modelica.Blocks.Math.Feedback positionError "Motor angle error, rad"
    annotation (Placement(transformation(extent={{-60,-10},{-40,10}})));
  Modelica.Blocks.Math.Gain positionController(k=kp) "Speed command of the position loop, rad/s"
    annotation (Placement(transformation(extent={{-30,-10},{-10,10}})));
  Modelica.Blocks.Math.Gain toMotorSpeed(k=ratio) "Reference joint speed to motor speed, rad/s"
    annotation (Placement(transformation(extent={{-60,50},{-40,70}})));
  Modelica.Blocks.Math.Add speedCommand "Speed command with feed-forward, rad/s"
    annotation (Placement(transformation(extent={{-10,30},{10,50}})));
  Modelica.Blocks.Math.Feedback speedError "Motor speed error, rad/s"
    annotation (Placement(transformation(extent={{0,-10},{20,10}})));
  Modelica.Blocks.Continuous.PI speedController(
    k=ks,
    T=Ts,
    initType=Modelica.Blocks.Types.Init.InitialState,
    x_start=0) "Current command, A"
    annotation (Placement(transformation(extent={{40,-10},{60,10}})));
equation
  connect(q_ref, toMotorAngle.u);
  connect(toMotorAngle.y, positionError.u1);
  connect(phi_motor, positionError.u2);
  connect(positionError.y, positionController.u);
  connect(qd_ref, toMotorSpeed.u);
  connect(positionController.y, speedCommand.u1);
  connect(toMotorSpeed.y, speedCommand.u2);
  connect(speedCommand.y, speedError.u1);
  connect(w_motor, speedError.u2);
  connect(speedError.y, speedController.u);
  connect(speedController.y, i_ref);
  annotation (Documentation(info="<html>
<p>The controller of <code>Modelica.Mechanics.MultiBody.Examples.Systems.RobotR3.Components.Controller</code>
with its speed feed-forward, in motor coordinates:</p>
<pre>
w_cmd = kp*(ratio*q_ref - phi_motor) + ratio*qd_ref         position loop (P) + feed-forward
i_ref = ks*(e + x/Ts),  der(x) = e,  e = w_cmd - w_motor    speed loop (PI), x(0) = 0
</pre>
<p><code>ratio</code> (set by the drive to the gear's transmission) turns the joint reference into
a motor angle, so at rest the joint coordinate equals <code>q_ref</code>; the integrator removes
the steady-state error caused by gravity or other loads. Units: kp in 1/s, ks in A.s/rad, Ts in s.
The motor's current limit saturates the output; there is no anti-windup.</p>
$PARAMS_HTML
</html>"));
end CascadePPI;
"#;

const PARTIAL_JOINT_DRIVE: &str = r#"within $P.Components.Drives.Interfaces;
partial model PartialJointDrive "Reference table, controller, motor and motor sensors of a joint drive"
  parameter Boolean useTable = false "= true: the reference follows table; = false: it is constant"
    annotation (Evaluate=true, choices(checkBox=true));
  parameter Real table[:, 2] = [0, 0; 1, 0] "Reference joint coordinate over time: [time in s, value; ...]"
    annotation (Dialog(enable=useTable));
  parameter Real motorPerJoint "Motor angle per unit of joint coordinate (the gear's ratio or transmission)";
  parameter Boolean useMotion = false
    "= true: reference position and speed come from the inputs q_motion and qd_motion (a motion of Mechatronics)"
    annotation (Evaluate=true, choices(checkBox=true));
  Modelica.Blocks.Interfaces.RealInput q_motion if useMotion "Reference joint coordinate of a motion"
    annotation (Placement(transformation(extent={{-140,40},{-100,80}})));
  Modelica.Blocks.Interfaces.RealInput qd_motion if useMotion "Reference joint speed of a motion (feed-forward)"
    annotation (Placement(transformation(extent={{-140,-80},{-100,-40}})));
  Modelica.Blocks.Sources.Constant noSpeed(k=0) if not useMotion "No speed feed-forward for a constant or table reference"
    annotation (Placement(transformation(extent={{-90,-60},{-70,-40}})));

  replaceable $P.Components.Drives.Controllers.CascadePPI controller
    constrainedby $P.Components.Drives.Interfaces.Controller(final ratio=motorPerJoint)
    "Joint controller: reference and motor angle and speed in, current command out"
    annotation (choicesAllMatching=true, Placement(transformation(extent={{-50,-10},{-30,10}})));
  replaceable $P.Components.Drives.Motors.DCPermanentMagnet motor
    constrainedby $P.Components.Drives.Interfaces.Motor
    "Motor: current command in, shaft torque out"
    annotation (choicesAllMatching=true, Placement(transformation(extent={{-10,-10},{10,10}})));
  Modelica.Blocks.Sources.CombiTimeTable tableReference(
    table=table,
    smoothness=Modelica.Blocks.Types.Smoothness.LinearSegments,
    extrapolation=Modelica.Blocks.Types.Extrapolation.HoldLastPoint) if useTable and not useMotion
    "Reference joint coordinate over time"
    annotation (Placement(transformation(extent={{-90,-30},{-70,-10}})));
  Modelica.Mechanics.Rotational.Sensors.AngleSensor motorAngle "Motor angle, rad"
    annotation (Placement(transformation(extent={{10,-40},{-10,-20}})));
  Modelica.Mechanics.Rotational.Sensors.SpeedSensor motorSpeed "Motor speed, rad/s"
    annotation (Placement(transformation(extent={{10,-70},{-10,-50}})));
equation
  connect(tableReference.y[1], controller.q_ref);
  connect(q_motion, controller.q_ref);
  connect(qd_motion, controller.qd_ref);
  connect(noSpeed.y, controller.qd_ref);
  connect(controller.i_ref, motor.i_ref);
  connect(motor.flange, motorAngle.flange);
  connect(motor.flange, motorSpeed.flange);
  connect(motorAngle.phi, controller.phi_motor);
  connect(motorSpeed.w, controller.w_motor);
  annotation (Documentation(info="<html>
<p>What the joint drives share: the reference (a constant, declared with its unit by the
extending drive, or with <code>useTable=true</code> the table <code>table</code> = [time in s,
value; ...], linear interpolation, last value held; or, with <code>useMotion=true</code>, the
position and speed of a motion from the inputs <code>q_motion</code> and <code>qd_motion</code>,
the speed fed forward as in RobotR3), the controller, the motor and the sensors on
the motor shaft. The extending drive adds the gear, the flange to the joint and the constant
reference, and sets <code>motorPerJoint</code> (motor angle per unit of joint coordinate) from its
gear, so the controller works in motor radians and drives the joint coordinate to the reference.
Replace <code>motor</code> and <code>controller</code> by any class extending
<code>Interfaces.Motor</code> and <code>Interfaces.Controller</code>.</p>
</html>"));
end PartialJointDrive;
"#;

const JOINT_DRIVE: &str = r#"within $P.Components.Drives;
model JointDrive "Drive of a revolute joint: reference, controller, motor and gear"
  import SI = Modelica.Units.SI;
  extends $P.Components.Drives.Interfaces.PartialJointDrive(final motorPerJoint=gear.ratio);
  parameter SI.Angle q_constant = 0 "Constant reference joint angle"
    annotation (Dialog(enable=not useTable));
  replaceable $P.Components.Drives.Gears.Ideal gear
    constrainedby $P.Components.Drives.Interfaces.Gear
    "Gear: ratio = motor speed / joint speed"
    annotation (choicesAllMatching=true, Placement(transformation(extent={{30,-10},{50,10}})));
  Modelica.Blocks.Sources.Constant constantReference(k=q_constant) if not useTable and not useMotion
    "Constant reference angle, rad"
    annotation (Placement(transformation(extent={{-90,10},{-70,30}})));
  Modelica.Mechanics.Rotational.Interfaces.Flange_b flange "Connect to the revolute joint's drive flange"
    annotation (Placement(transformation(extent={{90,-10},{110,10}})));
equation
  connect(constantReference.y, controller.q_ref);
  connect(motor.flange, gear.flange_a);
  connect(gear.flange_b, flange);
  annotation ($ICON, Documentation(info="<html>
<p>Drives a revolute joint: connect <code>flange</code> to the joint's <code>drive</code> flange.
The reference joint angle (rad, the joint's own <code>phi</code>, which includes the CAD offset)
is the constant <code>q_constant</code> or, with <code>useTable=true</code>, the table
<code>table</code> = [time in s, angle in rad; ...] (linear interpolation, last value held).</p>
<p>The controller gets the reference, the motor angle and the motor speed (sensors on the motor
shaft) and commands the motor current; the motor drives the joint through the gear.
<code>controller.ratio</code> is the gear's <code>ratio</code> (motor speed / joint speed), so the
controller drives the joint angle to the reference. Replace <code>motor</code>, <code>gear</code>
and <code>controller</code> by any class extending <code>Interfaces.Motor</code>,
<code>Interfaces.Gear</code> and <code>Interfaces.Controller</code>.</p>
</html>"));
end JointDrive;
"#;

const LINEAR_JOINT_DRIVE: &str = r#"within $P.Components.Drives;
model LinearJointDrive "Drive of a prismatic joint: reference, controller, motor and screw"
  import SI = Modelica.Units.SI;
  extends $P.Components.Drives.Interfaces.PartialJointDrive(final motorPerJoint=gear.transmission);
  parameter SI.Position q_constant = 0 "Constant reference joint position"
    annotation (Dialog(enable=not useTable));
  replaceable $P.Components.Drives.Gears.LeadScrew gear
    constrainedby $P.Components.Drives.Interfaces.LinearGear
    "Gearbox and screw: transmission = motor angle / joint displacement, rad/m"
    annotation (choicesAllMatching=true, Placement(transformation(extent={{30,-10},{50,10}})));
  Modelica.Blocks.Sources.Constant constantReference(k=q_constant) if not useTable and not useMotion
    "Constant reference position, m"
    annotation (Placement(transformation(extent={{-90,10},{-70,30}})));
  Modelica.Mechanics.Translational.Interfaces.Flange_b flange "Connect to the prismatic joint's drive flange"
    annotation (Placement(transformation(extent={{90,-10},{110,10}})));
equation
  connect(constantReference.y, controller.q_ref);
  connect(motor.flange, gear.flange_a);
  connect(gear.flange_b, flange);
  annotation ($ICON, Documentation(info="<html>
<p>Drives a prismatic joint: connect <code>flange</code> to the joint's <code>drive</code> flange.
The reference joint position (m, the joint's own <code>s</code>, which includes the CAD offset) is
the constant <code>q_constant</code> or, with <code>useTable=true</code>, the table
<code>table</code> = [time in s, position in m; ...] (linear interpolation, last value held).</p>
<p>The rotary motor drives the joint through a rotational-to-translational transmission
(<code>Interfaces.LinearGear</code>, by default <code>Gears.LeadScrew</code>: gearbox and lead
screw on <code>Modelica.Mechanics.Rotational.Components.IdealGearR2T</code>).
<code>controller.ratio</code> is the transmission in rad/m, so the controller works in motor
radians and drives the joint position to the reference.</p>
</html>"));
end LinearJointDrive;
"#;

//! The live view block: `<Pkg>/Components/Visualization.mo` (the `LiveView` model and its C
//! sender as an `ExternalObject`), the sender's C source in `<Pkg>/Resources/Include/`, and the
//! declarations `Mechatronics` gets when the package is written for a model the service knows
//! (its id and version go into every frame; see docs/live-protocol.md).

use crate::pipeline::back::modelica::diagram::extend::PLACEHOLDER;
use std::fmt::Write as _;

use sha2::{Digest, Sha256};

use super::{mstr, num};

/// The sender's C source, shipped in every package written with a live view.
pub const C_SOURCE: &str = include_str!("cad2mo_live.c");

/// Most bodies one frame carries (it must fit a UDP datagram).
pub const MAX_BODIES: usize = 1024;

/// Where a package's live view sends to and what it says it is.
#[derive(Clone, Debug)]
pub struct LiveTarget {
    /// The model's id (a UUID) and version in the service.
    pub model_id: String,
    pub version: u32,
    /// The service's live view address as the simulating machine should reach it.
    pub host: String,
    pub port: u16,
}

/// The layout id of a body list: the first 8 bytes of SHA-256 of the names, each followed by
/// `\n`. Sender and receiver compute it from the same list, so a frame of another body list is
/// told apart even when the count agrees.
pub fn layout_id(names: &[String]) -> [u8; 8] {
    let mut h = Sha256::new();
    for n in names {
        h.update(n.as_bytes());
        h.update(b"\n");
    }
    let d = h.finalize();
    let mut out = [0u8; 8];
    out.copy_from_slice(&d[..8]);
    out
}

/// [`layout_id`] as 16 lowercase hex digits.
pub fn layout_hex(names: &[String]) -> String {
    hex::encode(layout_id(names))
}

/// `<Pkg>/Components/Visualization.mo` and `<Pkg>/Resources/Include/cad2mo_live.c`.
pub fn files(pkg: &str) -> Vec<(String, Vec<u8>)> {
    let include = super::include_annotation(pkg, "cad2mo_live.c");
    let text = format!(
        r#"within {pkg}.Components;
package Visualization "Live view of a running simulation in cad2mo"
  extends Modelica.Icons.Package;

  model LiveView "Sends the poses of the bodies to the cad2mo live view while simulating"
    parameter Integer nBodies(min=1, max={MAX_BODIES}) "Number of bodies sent";
    parameter String host = "127.0.0.1" "Host name or address of the cad2mo service";
    parameter Integer port(min=1, max=65535) = 7878 "UDP port of the service's live view";
    parameter String token = "" "API token of the service (needed when it listens beyond loopback)";
    parameter String modelId = "" "The model's id in cad2mo";
    parameter Integer version(min=1) = 1 "The model version this package was written for";
    parameter String layout = "" "Hash of the body list (16 hex digits), checked by the service";
    parameter Modelica.Units.SI.Time samplePeriod = 0.02 "Simulated time between frames (0.02 s: 50 frames per simulated second)";
    parameter Boolean realTime = false "Pace the simulation so that it runs no faster than wall-clock time";
    input Real r_0[nBodies, 3](each final unit="m") "Origins of the bodies' frame_a, resolved in world";
    input Real R_T[nBodies, 3, 3] "Orientations of the bodies' frame_a (R.T: world to frame_a)";
    Integer sent(start=0, fixed=true) "Frames handed to the network so far";
  protected
    Internal.Sender sender = Internal.Sender(host, port, modelId, version, layout, token, nBodies, realTime) "The UDP sender";
  algorithm
    when sample(0, samplePeriod) then
      sent := Internal.send(sender, time, r_0, R_T, false);
    end when;
    when terminal() then
      sent := Internal.send(sender, time, r_0, R_T, true);
    end when;
    annotation (Documentation(info="<html>
<p>Every <code>samplePeriod</code> of simulated time, sends one UDP datagram with the simulated time and the pose (<code>r_0</code>, <code>R.T</code>) of every body to the cad2mo service, which shows the model moving in the browser (the version's Live tab). The last frame, at the end of the simulation, says so. Sending never blocks the simulation: a frame the network refuses is skipped, and a wrong host or port is reported once as a warning.</p>
<p>With <code>realTime=true</code> the simulation waits so that simulated time does not run ahead of wall-clock time (for watching a fast model at its real speed).</p>
<p>The C source is <code>Resources/Include/cad2mo_live.c</code> (plain C99, nothing to link). The frames carry the model's id, version and a hash of its body list, so that the service shows them only for this version; with a <code>token</code>, every frame is signed (HMAC-SHA256 keyed with the token's SHA-256) and the token itself never crosses the network.</p>
</html>"));
  end LiveView;

  package Internal "The C sender of LiveView"
    extends Modelica.Icons.InternalPackage;

    class Sender "A UDP sender of live view frames"
      extends ExternalObject;

      function constructor "Opens the sender"
        extends Modelica.Icons.Function;
        input String host "Host of the service";
        input Integer port "Its UDP port";
        input String modelId "Model id";
        input Integer version "Model version";
        input String layout "Body list hash";
        input String token "API token or empty";
        input Integer nBodies "Number of bodies";
        input Boolean realTime "Pace to wall-clock time";
        output Sender sender "The sender";
        external "C" sender = cad2mo_live_open(host, port, modelId, version, layout, token, nBodies, realTime)
          annotation ({include});
      end constructor;

      function destructor "Closes the sender"
        extends Modelica.Icons.Function;
        input Sender sender "The sender";
        external "C" cad2mo_live_close(sender)
          annotation ({include});
      end destructor;
    end Sender;

    function send "Sends one frame and returns how many were sent so far"
      extends Modelica.Icons.Function;
      input Sender sender "The sender";
      input Real t "Simulated time";
      input Real r_0[:, 3] "Body origins";
      input Real R_T[size(r_0, 1), 3, 3] "Body orientations";
      input Boolean last "The last frame of the run";
      output Integer sent "Frames sent so far";
      external "C" sent = cad2mo_live_send(sender, t, r_0, R_T, size(r_0, 1), last)
        annotation ({include});
    end send;
  end Internal;
  annotation (Documentation(info="<html>
<p>The live view of Juh&aacute;sz and Schmucker's online visualisation, over the network: <code>Mechatronics</code> declares a <code>LiveView</code> that is active when its parameter <code>liveView</code> is true.</p>
</html>"));
end Visualization;
"#
    );
    vec![
        (format!("{pkg}/Components/Visualization.mo"), text.into_bytes()),
        (format!("{pkg}/Resources/Include/cad2mo_live.c"), C_SOURCE.as_bytes().to_vec()),
    ]
}

/// The declarations `Mechatronics` gets: its live view parameters and the conditional block,
/// fed from every body's `frame_a` (bodies in package order, as the report lists them).
pub fn declarations(pkg: &str, target: &LiveTarget, bodies: &[String]) -> String {
    let r: Vec<String> = bodies.iter().map(|b| format!("{b}.frame_a.r_0")).collect();
    let t: Vec<String> = bodies.iter().map(|b| format!("{b}.frame_a.R.T")).collect();
    let mut s = String::new();
    let _ = writeln!(s, "\n  // Live view: the bodies' poses to the cad2mo service while simulating (see Components.Visualization)");
    let _ = writeln!(
        s,
        "  parameter Boolean liveView = false \"Send the bodies' poses to the cad2mo live view while simulating\"\n    annotation (Dialog(group=\"Live view\"), choices(checkBox=true));"
    );
    let _ = writeln!(
        s,
        "  parameter String liveHost = \"{}\" \"Host of the cad2mo service\"\n    annotation (Dialog(group=\"Live view\"));",
        mstr(&target.host)
    );
    let _ = writeln!(
        s,
        "  parameter Integer livePort = {} \"UDP port of its live view\"\n    annotation (Dialog(group=\"Live view\"));",
        target.port
    );
    let _ = writeln!(
        s,
        "  parameter String liveToken = \"\" \"API token (needed when the service listens beyond loopback)\"\n    annotation (Dialog(group=\"Live view\"));"
    );
    let _ = writeln!(
        s,
        "  parameter Modelica.Units.SI.Time livePeriod = {} \"Simulated time between frames\"\n    annotation (Dialog(group=\"Live view\"));",
        num(0.02)
    );
    let _ = writeln!(
        s,
        "  parameter Boolean liveRealTime = false \"Pace the simulation to wall-clock time\"\n    annotation (Dialog(group=\"Live view\"), choices(checkBox=true));"
    );
    let _ = writeln!(
        s,
        "  {pkg}.Components.Visualization.LiveView liveViewer(\n    nBodies={},\n    host=liveHost,\n    port=livePort,\n    token=liveToken,\n    modelId=\"{}\",\n    version={},\n    layout=\"{}\",\n    samplePeriod=livePeriod,\n    realTime=liveRealTime,\n    r_0={{{}}},\n    R_T={{{}}}) if liveView \"Sends the bodies' poses to cad2mo\"\n    {PLACEHOLDER};",
        bodies.len(),
        mstr(&target.model_id),
        target.version,
        layout_hex(bodies),
        r.join(", "),
        t.join(", ")
    );
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layout_ids_tell_lists_apart() {
        let a = vec!["A".to_string(), "B".to_string()];
        let b = vec!["B".to_string(), "A".to_string()];
        let c = vec!["AB".to_string()];
        assert_ne!(layout_id(&a), layout_id(&b));
        assert_ne!(layout_id(&a), layout_id(&c));
        // SHA-256("A\nB\n"), independently: printf 'A\nB\n' | sha256sum
        assert_eq!(layout_hex(&a), "daee1cd25194ae95");
    }
}

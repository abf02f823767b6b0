within ;
package WARN "Modelica model of CAD assembly WARN, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>WARN.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>Source: <code>WARN.xml</code>, written by SimMechanics Link Version 4.0 from the CAD system Pro/E Wildfire Creo 2.0 - 2012360, on 03/14/24||10:20:30.</p>
<p><code>Mechanics</code>: 6 bodies, 6 joints, 0 loops, 0 free bodies; gravity {0, -9.81, 0} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart</code></td><td>RootPart</td><td>WARN/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>ASYM</code></td><td>ASYM</td><td>501</td><td>0.0648</td><td>WARN/Resources/Shapes/ASYM.dxf</td></tr>
<tr><td><code>TRI</code></td><td>TRI</td><td>502</td><td>0.0648</td><td>WARN/Resources/Shapes/TRI.dxf</td></tr>
<tr><td><code>GHOST</code></td><td>GHOST</td><td>503</td><td>0.0648</td><td>none</td></tr>
<tr><td><code>BARE</code></td><td>BARE</td><td>504</td><td>0.0648</td><td>none</td></tr>
<tr><td><code>NOMAT</code></td><td>NOMAT</td><td>505</td><td>12.5</td><td>WARN/Resources/Shapes/NOMAT.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_ASYM</code></td><td>RootPart--ASYM</td><td>501:-:WARN/RootPart</td><td>revolute</td><td>RootPart</td><td>ASYM</td></tr>
<tr><td><code>ASYM_TRI</code></td><td>ASYM--TRI</td><td>501:-:502</td><td>revolute</td><td>ASYM</td><td>TRI</td></tr>
<tr><td><code>TRI_GHOST</code></td><td>TRI--GHOST</td><td>502:-:503</td><td>connect</td><td>TRI</td><td>GHOST</td></tr>
<tr><td><code>GHOST_BARE</code></td><td>GHOST--BARE</td><td>503:-:504</td><td>revolute</td><td>GHOST</td><td>BARE</td></tr>
<tr><td><code>BARE_NOMAT</code></td><td>BARE--NOMAT</td><td>504:-:505</td><td>revolute</td><td>BARE</td><td>NOMAT</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>RootGround:-:WARN/RootPart</td><td>connect</td><td>RootGround</td><td>RootPart</td></tr>
</table>
<h4>Warnings</h4>
<ul>
<li><code>geometry-missing</code> WARN.xml:226:7: body &quot;GHOST&quot; names geometry file &quot;GHOST_prt.stl&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>inertia-not-symmetric</code> WARN.xml:90:7 (body &quot;ASYM&quot;, nodeID &quot;501&quot;): inertia tensor [[2.7e-6, 0e0, 0e0], [2e-6, 7.83e-5, 0e0], [0e0, 0e0, 7.992e-5]] kg*m^2 is not symmetric (largest difference 2e-6); its symmetric part is used</li>
<li><code>inertia-triangle-inequality</code> WARN.xml:158:7 (body &quot;TRI&quot;, nodeID &quot;502&quot;): principal moments 5.4e-7 + 7.83e-5 &lt; 7.992e-5 kg*m^2 violate the triangle inequality: no real mass distribution has this inertia</li>
<li><code>no-material</code> WARN.xml:362:7 (body &quot;NOMAT&quot;, nodeID &quot;505&quot;): mass equals volume numerically (kg and mm^3; density 1.000000e9 kg/m^3): the part probably has no material assigned in CAD, so its mass and inertia are wrong</li>
<li><code>joint-frames-apart</code> WARN.xml:448:7 (joint &quot;ASYM--TRI&quot;, nodeID &quot;501:-:502&quot;): revolute joint: base and follower frames are 2.000000 mm apart; the CAD offset is kept as a fixed translation</li>
<li><code>zero-axis</code> WARN.xml:477:7 (joint &quot;TRI--GHOST&quot;, nodeID &quot;502:-:503&quot;): revolute primitive has axis (0, 0, 0), which has no direction; it is emitted as rigid</li>
<li><code>no-geometry</code> WARN.xml: 1 bodies have no geometry: &quot;BARE&quot; (504)</li>
<li><code>no-collision-shape</code> collision shapes: 2 bodies with mass but no mesh have no collision shape and cannot collide: GHOST, BARE</li>
</ul>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>WARN.xml</code> (exported 03/14/24||10:20:30).</li></ul>
</html>"));
end WARN;

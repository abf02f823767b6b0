within ;
package mate_rig "Modelica model of CAD assembly mate rig, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>mate rig.xml</code> (SimscapeMultibodyImportXML), exported by Simscape Multibody Link Version 7.4 from SolidWorks 28.0.0 on 11/25/26||00:00:00 by .</p>
<p>Source: <code>mate rig.xml</code>, written by Simscape Multibody Link Version 7.4 from the CAD system SolidWorks 28.0.0, on 11/25/26||00:00:00.</p>
<p><code>Mechanics</code>: 6 bodies, 5 joints, 0 loops, 1 free bodies; gravity {0, 0, -9.81} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>plate_1</code></td><td>plate-1</td><td>plate-1</td><td>3</td><td>none</td></tr>
<tr><td><code>crank_1</code></td><td>crank-1</td><td>crank-1</td><td>0.4</td><td>none</td></tr>
<tr><td><code>puck_1</code></td><td>puck-1</td><td>puck-1</td><td>0.2</td><td>none</td></tr>
<tr><td><code>slider_1</code></td><td>slider-1</td><td>slider-1</td><td>0.1</td><td>none</td></tr>
<tr><td><code>grip_1</code></td><td>grip-1</td><td>handle-1|grip-1</td><td>0.05</td><td>none</td></tr>
<tr><td><code>knob_1</code></td><td>knob-1</td><td>handle-1|knob-1</td><td>0.02</td><td>none</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>plate_1_grounded</code></td><td>plate-1 (grounded)</td><td>weld:plate-1</td><td>connect</td><td>World</td><td>plate_1</td></tr>
<tr><td><code>knob_1_rigid</code></td><td>knob-1 (rigid)</td><td>weld:handle-1|knob-1</td><td>connect</td><td>grip_1</td><td>knob_1</td></tr>
<tr><td><code>revolute_World_crank_1</code></td><td>revolute World--crank-1</td><td>mates:ground~crank-1</td><td>revolute</td><td>World</td><td>crank_1</td></tr>
<tr><td><code>planar_World_puck_1</code></td><td>planar World--puck-1</td><td>mates:ground~puck-1</td><td>chain</td><td>World</td><td>puck_1</td></tr>
<tr><td><code>weld_crank_1_grip_1</code></td><td>weld crank-1--grip-1</td><td>mates:crank-1~handle-1|grip-1</td><td>connect</td><td>crank_1</td><td>grip_1</td></tr>
</table>
<p>Free bodies (no path to the ground; they start at their CAD pose and fall): slider_1.</p>
<h4>Warnings</h4>
<ul>
<li><code>mate-unreducible</code> mate rig.xml:104:1: Coincident &quot;Coincident3&quot;: mates between the ground and group [&quot;slider-1&quot;] leave a rotation and a translation that are not along one axis free, which no single joint allows; no joint is made between them (mates: Coincident &quot;Coincident3&quot;, Coincident &quot;SlotPin&quot;)</li>
<li><code>geometry-missing</code> mate rig.xml:15:1: body &quot;plate-1&quot; names geometry file &quot;plate_Default_sldprt.STEP&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>geometry-missing</code> mate rig.xml:21:1: body &quot;crank-1&quot; names geometry file &quot;crank_Default_sldprt.STEP&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>geometry-missing</code> mate rig.xml:27:1: body &quot;puck-1&quot; names geometry file &quot;puck_Default_sldprt.STEP&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>geometry-missing</code> mate rig.xml:33:1: body &quot;slider-1&quot; names geometry file &quot;slider_Default_sldprt.STEP&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>geometry-missing</code> mate rig.xml:44:1: body &quot;grip-1&quot; names geometry file &quot;grip_Default_sldprt.STEP&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>geometry-missing</code> mate rig.xml:50:1: body &quot;knob-1&quot; names geometry file &quot;knob_Default_sldprt.STEP&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>free-bodies</code> mate rig.xml: 1 bodies have no path to a ground and float freely from their CAD pose (6 degrees of freedom per free group): &quot;slider-1&quot;</li>
<li><code>no-collision-shape</code> collision shapes: 6 bodies with mass but no mesh have no collision shape and cannot collide: plate_1, crank_1, puck_1, slider_1, grip_1, knob_1</li>
</ul>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>mate rig.xml</code> (exported 11/25/26||00:00:00).</li></ul>
</html>"));
end mate_rig;

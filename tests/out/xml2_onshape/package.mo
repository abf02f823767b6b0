within ;
package slide_arm "Modelica model of CAD assembly slide arm, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>slide_arm.xml</code> (SimscapeMultibodyImportXML), exported by Simscape Multibody Exporter from Onshape on 11/25/26||00:00:00 by cad2mo tests.</p>
<p>Source: <code>slide_arm.xml</code>, written by Simscape Multibody Exporter from the CAD system Onshape, on 11/25/26||00:00:00.</p>
<p><code>Mechanics</code>: 5 bodies, 5 joints, 0 loops, 0 free bodies; gravity {0, 0, -9.81} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>Base_1</code></td><td>Base &lt;1&gt;</td><td>MBase1</td><td>2</td><td>none</td></tr>
<tr><td><code>Link_1</code></td><td>Link Ä &lt;1&gt;</td><td>MLink1</td><td>0.5</td><td>none</td></tr>
<tr><td><code>Rail_1</code></td><td>Rail &lt;1&gt;</td><td>MSub1|MRail1</td><td>0.3</td><td>none</td></tr>
<tr><td><code>Carriage_1</code></td><td>Carriage &lt;1&gt;</td><td>MSub1|MCar1</td><td>0.2</td><td>none</td></tr>
<tr><td><code>Tool_gr_n_1</code></td><td>Tool (grün) &lt;1&gt;</td><td>MTool1</td><td>0.1</td><td>none</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>Base_1_grounded</code></td><td>Base &lt;1&gt; (grounded)</td><td>weld:MBase1</td><td>connect</td><td>World</td><td>Base_1</td></tr>
<tr><td><code>shoulder</code></td><td>shoulder</td><td>joint:shoulder</td><td>revolute</td><td>Base_1</td><td>Link_1</td></tr>
<tr><td><code>Fastened_1</code></td><td>Fastened 1</td><td>joint:Fastened 1</td><td>connect</td><td>Link_1</td><td>Rail_1</td></tr>
<tr><td><code>Fastened_2</code></td><td>Fastened 2</td><td>joint:Fastened 2</td><td>connect</td><td>Carriage_1</td><td>Tool_gr_n_1</td></tr>
<tr><td><code>slide</code></td><td>slide</td><td>joint:MSub1|slide</td><td>prismatic</td><td>Rail_1</td><td>Carriage_1</td></tr>
</table>
<h4>Warnings</h4>
<ul>
<li><code>geometry-missing</code> slide_arm.xml:18:10: body &quot;Base &lt;1&gt;&quot; names geometry file &quot;Base.step&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>geometry-missing</code> slide_arm.xml:24:10: body &quot;Link Ä &lt;1&gt;&quot; names geometry file &quot;Link.step&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>geometry-missing</code> slide_arm.xml:35:13: body &quot;Rail &lt;1&gt;&quot; names geometry file &quot;Rail.step&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>geometry-missing</code> slide_arm.xml:41:13: body &quot;Carriage &lt;1&gt;&quot; names geometry file &quot;Carriage.step&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>geometry-missing</code> slide_arm.xml:48:10: body &quot;Tool (grün) &lt;1&gt;&quot; names geometry file &quot;Tool (grün).step&quot;, which is not in the bundle (looked up case-insensitively and in sub-folders); the body converts without a shape</li>
<li><code>no-collision-shape</code> collision shapes: 5 bodies with mass but no mesh have no collision shape and cannot collide: Base_1, Link_1, Rail_1, Carriage_1, Tool_gr_n_1</li>
</ul>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>slide_arm.xml</code> (exported 11/25/26||00:00:00).</li></ul>
</html>"));
end slide_arm;

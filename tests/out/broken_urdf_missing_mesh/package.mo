within ;
package broken "Modelica model of CAD assembly broken, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>robot.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>Source: <code>robot.urdf</code>, written by URDF from the CAD system , on .</p>
<p><code>Mechanics</code>: 2 bodies, 2 joints, 0 loops, 0 free bodies; gravity {0, 0, -9.81} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>a</code></td><td>a</td><td>a</td><td>1</td><td>none</td></tr>
<tr><td><code>b</code></td><td>b</td><td>b</td><td>1</td><td>none</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>a_fixed_to_world</code></td><td>a_fixed_to_world</td><td>world::a</td><td>connect</td><td>world</td><td>a</td></tr>
<tr><td><code>j</code></td><td>j</td><td>j</td><td>revolute</td><td>a</td><td>b</td></tr>
</table>
<h4>Warnings</h4>
<ul>
<li><code>urdf-root-fixed</code> robot.urdf:3:3 (link &quot;a&quot;): root link &quot;a&quot; is fixed to the world at its origin (URDF cannot say whether a root floats; to make it a free body, add a `floating` joint from a `world` link)</li>
<li><code>geometry-missing</code> robot.urdf:5:5: link &quot;b&quot; names visual mesh &quot;package://broken/meshes/b.stl&quot;, which is not in the bundle (looked up case-insensitively, package:// by path suffix); the body converts without a shape</li>
<li><code>no-geometry</code> robot.urdf: 2 bodies have no geometry: &quot;a&quot; (a), &quot;b&quot; (b)</li>
<li><code>no-collision-shape</code> collision shapes: 2 bodies with mass but no mesh have no collision shape and cannot collide: a, b</li>
</ul>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>robot.urdf</code> (exported ).</li></ul>
</html>"));
end broken;

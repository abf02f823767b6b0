within ;
package urdf_arm "Modelica model of CAD assembly urdf_arm, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>arm.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>Source: <code>arm.urdf</code>, written by URDF from the CAD system , on .</p>
<p><code>Mechanics</code>: 6 bodies, 6 joints, 0 loops, 0 free bodies; gravity {0, 0, -9.81} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>base</code></td><td>base</td><td>base</td><td>4</td><td>urdf_arm/Resources/Shapes/base.dxf</td></tr>
<tr><td><code>shoulder</code></td><td>shoulder</td><td>shoulder</td><td>2.5</td><td>urdf_arm/Resources/Shapes/shoulder.dxf</td></tr>
<tr><td><code>upper_arm</code></td><td>upper_arm</td><td>upper_arm</td><td>1.8</td><td>urdf_arm/Resources/Shapes/upper_arm.dxf</td></tr>
<tr><td><code>forearm</code></td><td>forearm</td><td>forearm</td><td>1.1</td><td>urdf_arm/Resources/Shapes/forearm.dxf</td></tr>
<tr><td><code>slide</code></td><td>slide</td><td>slide</td><td>0.4</td><td>urdf_arm/Resources/Shapes/slide.dxf</td></tr>
<tr><td><code>tool</code></td><td>tool</td><td>tool</td><td>0.2</td><td>urdf_arm/Resources/Shapes/tool.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>mount</code></td><td>mount</td><td>mount</td><td>connect</td><td>world</td><td>base</td></tr>
<tr><td><code>shoulder_yaw</code></td><td>shoulder_yaw</td><td>shoulder_yaw</td><td>revolute</td><td>base</td><td>shoulder</td></tr>
<tr><td><code>shoulder_pitch</code></td><td>shoulder_pitch</td><td>shoulder_pitch</td><td>revolute</td><td>shoulder</td><td>upper_arm</td></tr>
<tr><td><code>elbow</code></td><td>elbow</td><td>elbow</td><td>revolute</td><td>upper_arm</td><td>forearm</td></tr>
<tr><td><code>extend</code></td><td>extend</td><td>extend</td><td>prismatic</td><td>forearm</td><td>slide</td></tr>
<tr><td><code>tool_mount</code></td><td>tool_mount</td><td>tool_mount</td><td>connect</td><td>slide</td><td>tool</td></tr>
</table>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>arm.urdf</code> (exported ).</li></ul>
</html>"));
end urdf_arm;

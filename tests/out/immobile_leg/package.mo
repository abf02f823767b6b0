within ;
package LEG "Modelica model of CAD assembly LEG, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>LEG.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>Source: <code>LEG.xml</code>, written by SimMechanics Link Version 4.0 from the CAD system Pro/E Wildfire Creo 2.0 - 2012360, on 03/14/24||10:20:30.</p>
<p><code>Mechanics</code>: 4 bodies, 5 joints, 1 loops, 0 free bodies; gravity {0, -9.81, 0} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart</code></td><td>RootPart</td><td>LEG/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>HIP</code></td><td>HIP</td><td>80</td><td>0.04009</td><td>LEG/Resources/Shapes/HIP.dxf</td></tr>
<tr><td><code>THIGH</code></td><td>THIGH</td><td>81</td><td>0.084758</td><td>LEG/Resources/Shapes/THIGH.dxf</td></tr>
<tr><td><code>SHANK</code></td><td>SHANK</td><td>82</td><td>0.080417</td><td>LEG/Resources/Shapes/SHANK.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_HIP</code></td><td>RootPart--HIP</td><td>80:-:LEG/RootPart</td><td>revolute</td><td>RootPart</td><td>HIP</td></tr>
<tr><td><code>HIP_THIGH</code></td><td>HIP--THIGH</td><td>80:-:81</td><td>revolute</td><td>HIP</td><td>THIGH</td></tr>
<tr><td><code>THIGH_SHANK</code></td><td>THIGH--SHANK</td><td>81:-:82</td><td>revolute</td><td>THIGH</td><td>SHANK</td></tr>
<tr><td><code>SHANK_RootPart</code></td><td>SHANK--RootPart</td><td>82:-:LEG/RootPart</td><td>constraint-spherical</td><td>SHANK</td><td>RootPart</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>LEG/RootPart:-:RootGround</td><td>connect</td><td>RootGround</td><td>RootPart</td></tr>
</table>
<h4>Loops and how they were closed</h4>
<ul>
<li>SHANK_RootPart (a spatial loop through SHANK_RootPart, THIGH_SHANK, HIP_THIGH, RootPart_HIP): a plain revolute would repeat 2 of its 5 equations (3 independent); Joints.Constraints.Spherical imposes exactly those (translations locked: x, y, z)</li>
</ul>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>LEG.xml</code> (exported 03/14/24||10:20:30).</li></ul>
</html>"));
end LEG;

within ;
package LumpedArm "Modelica model of CAD assembly LUMP, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>LUMP.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 3.0 - 2014140 on 03/14/24||10:20:30 by cad2mo.</p>
<p>Source: <code>LUMP.xml</code>, written by SimMechanics Link Version 4.0 from the CAD system Pro/E Wildfire Creo 3.0 - 2014140, on 03/14/24||10:20:30.</p>
<p><code>Mechanics</code>: 3 bodies, 4 joints, 0 loops, 0 free bodies; gravity {0, 0, -9.81} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart</code></td><td>RootPart</td><td>LUMP/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>UPPER_A</code></td><td>UPPER_A</td><td>302</td><td>0.818251</td><td>LumpedArm/Resources/Shapes/UPPER_A.dxf</td></tr>
<tr><td><code>FORE</code></td><td>FORE</td><td>304</td><td>0.19008</td><td>LumpedArm/Resources/Shapes/FORE.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_UPPER_A</code></td><td>RootPart--UPPER_A</td><td>302:-:LUMP/RootPart</td><td>revolute</td><td>RootPart</td><td>UPPER_A</td></tr>
<tr><td><code>UPPER_B_FORE</code></td><td>UPPER_B--FORE</td><td>303:-:304</td><td>revolute</td><td>UPPER_A</td><td>FORE</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>LUMP/RootPart:-:RootGround</td><td>connect</td><td>RootGround</td><td>RootPart</td></tr>
<tr><td><code></code></td><td>UPPER_A--UPPER_B</td><td>302:-:303</td><td>lumped</td><td>UPPER_A</td><td>UPPER_A</td></tr>
</table>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>LUMP.xml</code> (exported 03/14/24||10:20:30).</li></ul>
</html>"));
end LumpedArm;

within ;
package ARM "Modelica model of CAD assembly ARM, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>ARM_SIM_MODEL.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>Source: <code>ARM_SIM_MODEL.xml</code>, written by SimMechanics Link Version 4.0 from the CAD system Pro/E Wildfire Creo 2.0 - 2012360, on 03/14/24||10:20:30.</p>
<p><code>Mechanics</code>: 6 bodies, 6 joints, 0 loops, 0 free bodies; gravity {0, -9.81, 0} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart_ARM</code></td><td>RootPart</td><td>ARM/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>BASE</code></td><td>BASE</td><td>7</td><td>3.4992</td><td>ARM/Resources/Shapes/BASE.dxf</td></tr>
<tr><td><code>LINK_UPPER</code></td><td>LINK</td><td>12/13</td><td>0.564473</td><td>ARM/Resources/Shapes/LINK_UPPER.dxf</td></tr>
<tr><td><code>RootPart_UPPER</code></td><td>RootPart</td><td>12/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>LINK_FORE</code></td><td>LINK</td><td>12/20/21</td><td>0.31752</td><td>ARM/Resources/Shapes/LINK_FORE.dxf</td></tr>
<tr><td><code>RootPart_FORE</code></td><td>RootPart</td><td>12/20/RootPart</td><td>0</td><td>none</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_BASE</code></td><td>RootPart--BASE</td><td>7:-:ARM/RootPart</td><td>connect</td><td>RootPart_ARM</td><td>BASE</td></tr>
<tr><td><code>BASE_LINK</code></td><td>BASE--LINK</td><td>12:12/13:-:7</td><td>revolute</td><td>BASE</td><td>LINK_UPPER</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>ARM/RootPart:-:RootGround</td><td>connect</td><td>RootGround</td><td>RootPart_ARM</td></tr>
<tr><td><code>RootPart_LINK_UPPER</code></td><td>RootPart--LINK</td><td>12/13:-:12/RootPart</td><td>connect</td><td>RootPart_UPPER</td><td>LINK_UPPER</td></tr>
<tr><td><code>LINK_LINK</code></td><td>LINK--LINK</td><td>12/13:-:12/20:12/20/21</td><td>revolute</td><td>LINK_UPPER</td><td>LINK_FORE</td></tr>
<tr><td><code>RootPart_LINK_FORE</code></td><td>RootPart--LINK</td><td>12/20/21:-:12/20/RootPart</td><td>connect</td><td>RootPart_FORE</td><td>LINK_FORE</td></tr>
</table>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>ARM_SIM_MODEL.xml</code> (exported 03/14/24||10:20:30).</li></ul>
</html>"));
end ARM;

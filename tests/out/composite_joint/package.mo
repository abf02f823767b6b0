within ;
package UJ "Modelica model of CAD assembly UJ, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>UJ.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 5.0 from Pro/E Wildfire Creo 9.0 - 2022073 on 03/14/24||10:20:30 by cad2mo.</p>
<p>Source: <code>UJ.xml</code>, written by Simscape Multibody Link Version 5.0 from the CAD system Pro/E Wildfire Creo 9.0 - 2022073, on 03/14/24||10:20:30.</p>
<p><code>Mechanics</code>: 4 bodies, 4 joints, 0 loops, 0 free bodies; gravity {0, -9.81, 0} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart</code></td><td>RootPart</td><td>UJ/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>BASE</code></td><td>BASE</td><td>201</td><td>4.86</td><td>UJ/Resources/Shapes/BASE.dxf</td></tr>
<tr><td><code>CROSS</code></td><td>CROSS</td><td>202</td><td>0.864</td><td>UJ/Resources/Shapes/CROSS.dxf</td></tr>
<tr><td><code>FLOAT</code></td><td>FLOAT</td><td>203</td><td>0.0972</td><td>UJ/Resources/Shapes/FLOAT.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_BASE</code></td><td>RootPart--BASE</td><td>201:-:UJ/RootPart</td><td>connect</td><td>RootPart</td><td>BASE</td></tr>
<tr><td><code>BASE_CROSS</code></td><td>BASE--CROSS</td><td>201:-:202</td><td>chain</td><td>BASE</td><td>CROSS</td></tr>
<tr><td><code>CROSS_FLOAT</code></td><td>CROSS--FLOAT</td><td>202:-:203</td><td>chain</td><td>CROSS</td><td>FLOAT</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>RootGround:-:UJ/RootPart</td><td>connect</td><td>RootGround</td><td>RootPart</td></tr>
</table>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>UJ.xml</code> (exported 03/14/24||10:20:30).</li></ul>
</html>"));
end UJ;

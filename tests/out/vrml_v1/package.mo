within ;
package VASM "Modelica model of CAD assembly VASM, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>VASM.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>Source: <code>VASM.xml</code>, written by SimMechanics Link Version 4.0 from the CAD system Pro/E Wildfire Creo 2.0 - 2012360, on 03/14/24||10:20:30.</p>
<p><code>Mechanics</code>: 4 bodies, 4 joints, 0 loops, 0 free bodies; gravity {0, -9.81, 0} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart</code></td><td>RootPart</td><td>VASM/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>BRACKET</code></td><td>BRACKET</td><td>101</td><td>0.1296</td><td>VASM/Resources/Shapes/BRACKET.dxf</td></tr>
<tr><td><code>SLIDER</code></td><td>SLIDER</td><td>102</td><td>0.0756</td><td>VASM/Resources/Shapes/SLIDER.dxf</td></tr>
<tr><td><code>TOOL</code></td><td>TOOL</td><td>103</td><td>0.067738</td><td>VASM/Resources/Shapes/TOOL.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_BRACKET</code></td><td>RootPart--BRACKET</td><td>101:-:VASM/RootPart</td><td>revolute</td><td>RootPart</td><td>BRACKET</td></tr>
<tr><td><code>BRACKET_SLIDER</code></td><td>BRACKET--SLIDER</td><td>101:-:102</td><td>revolute</td><td>BRACKET</td><td>SLIDER</td></tr>
<tr><td><code>SLIDER_TOOL</code></td><td>SLIDER--TOOL</td><td>102:-:103</td><td>revolute</td><td>SLIDER</td><td>TOOL</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>RootGround:-:VASM/RootPart</td><td>connect</td><td>RootGround</td><td>RootPart</td></tr>
</table>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>VASM.xml</code> (exported 03/14/24||10:20:30).</li></ul>
</html>"));
end VASM;

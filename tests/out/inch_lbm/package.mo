within ;
package CHAIN_IN "Modelica model of CAD assembly CHAIN_IN, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>CHAIN_IN.xml</code> (SimMechanics), exported by SimMechanics Link Version 3.1 from Pro/E Wildfire Wildfire 4.0 - 2008230 on 11/10/09||14:08:16 by cad2mo.</p>
<p>Source: <code>CHAIN_IN.xml</code>, written by SimMechanics Link Version 3.1 from the CAD system Pro/E Wildfire Wildfire 4.0 - 2008230, on 11/10/09||14:08:16.</p>
<p><code>Mechanics</code>: 3 bodies, 3 joints, 0 loops, 0 free bodies; gravity {0, -9.81, 0} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart</code></td><td>RootPart</td><td>RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>LINK1</code></td><td>LINK1</td><td>39</td><td>0.287593</td><td>CHAIN_IN/Resources/Shapes/LINK1.dxf</td></tr>
<tr><td><code>LINK2</code></td><td>LINK2</td><td>40</td><td>0.199103</td><td>CHAIN_IN/Resources/Shapes/LINK2.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_LINK1</code></td><td>RootPart--LINK1</td><td>39:-:RootPart</td><td>revolute</td><td>RootPart</td><td>LINK1</td></tr>
<tr><td><code>LINK1_LINK2</code></td><td>LINK1--LINK2</td><td>39:-:40</td><td>revolute</td><td>LINK1</td><td>LINK2</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>RootGround:-:RootPart</td><td>connect</td><td>RootGround</td><td>RootPart</td></tr>
</table>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>CHAIN_IN.xml</code> (exported 11/10/09||14:08:16).</li></ul>
</html>"));
end CHAIN_IN;

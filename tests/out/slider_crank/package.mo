within ;
package SLIDERCRANK "Modelica model of CAD assembly SLIDERCRANK, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>SLIDERCRANK.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>Source: <code>SLIDERCRANK.xml</code>, written by SimMechanics Link Version 4.0 from the CAD system Pro/E Wildfire Creo 2.0 - 2012360, on 03/14/24||10:20:30.</p>
<p><code>Mechanics</code>: 4 bodies, 5 joints, 1 loops, 0 free bodies; gravity {0, -9.81, 0} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart</code></td><td>RootPart</td><td>SLIDERCRANK/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>CRANK</code></td><td>CRANK</td><td>40</td><td>0.019354</td><td>SLIDERCRANK/Resources/Shapes/CRANK.dxf</td></tr>
<tr><td><code>ROD</code></td><td>ROD</td><td>41</td><td>0.047002</td><td>SLIDERCRANK/Resources/Shapes/ROD.dxf</td></tr>
<tr><td><code>PISTON</code></td><td>PISTON</td><td>42</td><td>0.0942</td><td>SLIDERCRANK/Resources/Shapes/PISTON.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_CRANK</code></td><td>RootPart--CRANK</td><td>40:-:SLIDERCRANK/RootPart</td><td>revolute</td><td>RootPart</td><td>CRANK</td></tr>
<tr><td><code>CRANK_ROD</code></td><td>CRANK--ROD</td><td>40:-:41</td><td>revolute</td><td>CRANK</td><td>ROD</td></tr>
<tr><td><code>ROD_PISTON</code></td><td>ROD--PISTON</td><td>41:-:42</td><td>revolute-planar-loop-constraint</td><td>ROD</td><td>PISTON</td></tr>
<tr><td><code>PISTON_RootPart</code></td><td>PISTON--RootPart</td><td>42:-:SLIDERCRANK/RootPart</td><td>prismatic</td><td>PISTON</td><td>RootPart</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>RootGround:-:SLIDERCRANK/RootPart</td><td>connect</td><td>RootGround</td><td>RootPart</td></tr>
</table>
<h4>Loops and how they were closed</h4>
<ul>
<li>ROD_PISTON (a planar loop through ROD_PISTON, CRANK_ROD, RootPart_CRANK, PISTON_RootPart): a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations</li>
</ul>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>SLIDERCRANK.xml</code> (exported 03/14/24||10:20:30).</li></ul>
</html>"));
end SLIDERCRANK;

within ;
package FOURBAR "Modelica model of CAD assembly FOURBAR, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>FOURBAR.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>Source: <code>FOURBAR.xml</code>, written by SimMechanics Link Version 4.0 from the CAD system Pro/E Wildfire Creo 2.0 - 2012360, on 03/14/24||10:20:30.</p>
<p><code>Mechanics</code>: 4 bodies, 5 joints, 1 loops, 0 free bodies; gravity {0, -9.81, 0} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart</code></td><td>RootPart</td><td>FOURBAR/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>CRANK</code></td><td>CRANK</td><td>40</td><td>0.10048</td><td>FOURBAR/Resources/Shapes/CRANK.dxf</td></tr>
<tr><td><code>COUPLER</code></td><td>COUPLER</td><td>41</td><td>0.2512</td><td>FOURBAR/Resources/Shapes/COUPLER.dxf</td></tr>
<tr><td><code>ROCKER</code></td><td>ROCKER</td><td>45</td><td>0.21352</td><td>FOURBAR/Resources/Shapes/ROCKER.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_CRANK</code></td><td>RootPart--CRANK</td><td>40:-:FOURBAR/RootPart</td><td>revolute</td><td>RootPart</td><td>CRANK</td></tr>
<tr><td><code>CRANK_COUPLER</code></td><td>CRANK--COUPLER</td><td>40:-:41</td><td>revolute</td><td>CRANK</td><td>COUPLER</td></tr>
<tr><td><code>COUPLER_ROCKER</code></td><td>COUPLER--ROCKER</td><td>41:-:45</td><td>revolute</td><td>COUPLER</td><td>ROCKER</td></tr>
<tr><td><code>RootPart_ROCKER</code></td><td>RootPart--ROCKER</td><td>45:-:FOURBAR/RootPart</td><td>revolute-planar-loop-constraint</td><td>RootPart</td><td>ROCKER</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>FOURBAR/RootPart:-:RootGround</td><td>connect</td><td>RootGround</td><td>RootPart</td></tr>
</table>
<h4>Loops and how they were closed</h4>
<ul>
<li>RootPart_ROCKER (a planar loop through RootPart_ROCKER, RootPart_CRANK, CRANK_COUPLER, COUPLER_ROCKER): a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations</li>
</ul>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>FOURBAR.xml</code> (exported 03/14/24||10:20:30).</li></ul>
</html>"));
end FOURBAR;

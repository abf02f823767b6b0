within ;
package CRANKROCKER "Modelica model of CAD assembly CRANKROCKER, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>CRANKROCKER.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 5.0 from Pro/E Wildfire Creo 7.0 - 2020454 on 03/14/24||10:20:30 by cad2mo.</p>
<p>Source: <code>CRANKROCKER.xml</code>, written by Simscape Multibody Link Version 5.0 from the CAD system Pro/E Wildfire Creo 7.0 - 2020454, on 03/14/24||10:20:30.</p>
<p><code>Mechanics</code>: 4 bodies, 5 joints, 1 loops, 0 free bodies; gravity {0, -9.81, 0} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart</code></td><td>RootPart</td><td>CRANKROCKER/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>CRANK</code></td><td>CRANK</td><td>60</td><td>0.02281</td><td>CRANKROCKER/Resources/Shapes/CRANK.dxf</td></tr>
<tr><td><code>COUPLER</code></td><td>COUPLER</td><td>61</td><td>0.087026</td><td>CRANKROCKER/Resources/Shapes/COUPLER.dxf</td></tr>
<tr><td><code>ROCKER</code></td><td>ROCKER</td><td>62</td><td>0.064994</td><td>CRANKROCKER/Resources/Shapes/ROCKER.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_CRANK</code></td><td>RootPart--CRANK</td><td>60:-:CRANKROCKER/RootPart</td><td>revolute</td><td>RootPart</td><td>CRANK</td></tr>
<tr><td><code>CRANK_COUPLER</code></td><td>CRANK--COUPLER</td><td>60:-:61</td><td>revolute</td><td>CRANK</td><td>COUPLER</td></tr>
<tr><td><code>COUPLER_ROCKER</code></td><td>COUPLER--ROCKER</td><td>61:-:62</td><td>revolute</td><td>COUPLER</td><td>ROCKER</td></tr>
<tr><td><code>ROCKER_RootPart</code></td><td>ROCKER--RootPart</td><td>62:-:CRANKROCKER/RootPart</td><td>revolute-planar-loop-constraint</td><td>ROCKER</td><td>RootPart</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>CRANKROCKER/RootPart:-:RootGround</td><td>connect</td><td>RootGround</td><td>RootPart</td></tr>
</table>
<h4>Loops and how they were closed</h4>
<ul>
<li>ROCKER_RootPart (a planar loop through ROCKER_RootPart, COUPLER_ROCKER, CRANK_COUPLER, RootPart_CRANK): a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations</li>
</ul>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>CRANKROCKER.xml</code> (exported 03/14/24||10:20:30).</li></ul>
</html>"));
end CRANKROCKER;

within ;
package PENDULUM "Modelica model of CAD assembly PENDULUM, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>PENDULUM.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 4.8 from Pro/E Wildfire Creo 7.0 - 2020454 on 03/14/24||10:20:30 by cad2mo.</p>
<p>Source: <code>PENDULUM.xml</code>, written by Simscape Multibody Link Version 4.8 from the CAD system Pro/E Wildfire Creo 7.0 - 2020454, on 03/14/24||10:20:30.</p>
<p><code>Mechanics</code>: 2 bodies, 2 joints, 0 loops, 0 free bodies; gravity {0, -9.81, 0} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart</code></td><td>RootPart</td><td>PENDULUM/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>LINK</code></td><td>LINK</td><td>23</td><td>0.2673</td><td>PENDULUM/Resources/Shapes/LINK.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_LINK</code></td><td>RootPart--LINK</td><td>23:-:PENDULUM/RootPart</td><td>revolute</td><td>RootPart</td><td>LINK</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>PENDULUM/RootPart:-:RootGround</td><td>connect</td><td>RootGround</td><td>RootPart</td></tr>
</table>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>PENDULUM.xml</code> (exported 03/14/24||10:20:30).</li></ul>
</html>"));
end PENDULUM;

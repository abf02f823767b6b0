within ;
package SIXBAR "Modelica model of CAD assembly SIXBAR, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>SIXBAR.xml</code> (SimMechanics), exported by SimMechanics Link Version 4.0 from Pro/E Wildfire Creo 2.0 - 2012360 on 03/14/24||10:20:30 by cad2mo.</p>
<p>Source: <code>SIXBAR.xml</code>, written by SimMechanics Link Version 4.0 from the CAD system Pro/E Wildfire Creo 2.0 - 2012360, on 03/14/24||10:20:30.</p>
<p><code>Mechanics</code>: 6 bodies, 8 joints, 2 loops, 0 free bodies; gravity {0, -9.81, 0} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>RootPart</code></td><td>RootPart</td><td>SIXBAR/RootPart</td><td>0</td><td>none</td></tr>
<tr><td><code>CRANK</code></td><td>CRANK</td><td>50</td><td>0.027907</td><td>SIXBAR/Resources/Shapes/CRANK.dxf</td></tr>
<tr><td><code>COUPLER</code></td><td>COUPLER</td><td>51</td><td>0.097675</td><td>SIXBAR/Resources/Shapes/COUPLER.dxf</td></tr>
<tr><td><code>ROCKER</code></td><td>ROCKER</td><td>52</td><td>0.053914</td><td>SIXBAR/Resources/Shapes/ROCKER.dxf</td></tr>
<tr><td><code>LINK5</code></td><td>LINK5</td><td>53</td><td>0.05737</td><td>SIXBAR/Resources/Shapes/LINK5.dxf</td></tr>
<tr><td><code>LINK6</code></td><td>LINK6</td><td>54</td><td>0.047002</td><td>SIXBAR/Resources/Shapes/LINK6.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>RootPart_CRANK</code></td><td>RootPart--CRANK</td><td>50:-:SIXBAR/RootPart</td><td>revolute</td><td>RootPart</td><td>CRANK</td></tr>
<tr><td><code>CRANK_COUPLER</code></td><td>CRANK--COUPLER</td><td>50:-:51</td><td>revolute</td><td>CRANK</td><td>COUPLER</td></tr>
<tr><td><code>COUPLER_ROCKER</code></td><td>COUPLER--ROCKER</td><td>51:-:52</td><td>revolute</td><td>COUPLER</td><td>ROCKER</td></tr>
<tr><td><code>ROCKER_RootPart</code></td><td>ROCKER--RootPart</td><td>52:-:SIXBAR/RootPart</td><td>revolute-planar-loop-constraint</td><td>ROCKER</td><td>RootPart</td></tr>
<tr><td><code>COUPLER_LINK5</code></td><td>COUPLER--LINK5</td><td>51:-:53</td><td>revolute</td><td>COUPLER</td><td>LINK5</td></tr>
<tr><td><code>LINK5_LINK6</code></td><td>LINK5--LINK6</td><td>53:-:54</td><td>revolute</td><td>LINK5</td><td>LINK6</td></tr>
<tr><td><code>LINK6_RootPart</code></td><td>LINK6--RootPart</td><td>54:-:SIXBAR/RootPart</td><td>revolute-planar-loop-constraint</td><td>LINK6</td><td>RootPart</td></tr>
<tr><td><code>RootGround_RootPart</code></td><td>RootGround--RootPart</td><td>RootGround:-:SIXBAR/RootPart</td><td>connect</td><td>RootGround</td><td>RootPart</td></tr>
</table>
<h4>Loops and how they were closed</h4>
<ul>
<li>ROCKER_RootPart (a planar loop through ROCKER_RootPart, COUPLER_ROCKER, CRANK_COUPLER, RootPart_CRANK): a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations</li>
<li>LINK6_RootPart (a planar loop through LINK6_RootPart, LINK5_LINK6, COUPLER_LINK5, CRANK_COUPLER, RootPart_CRANK): a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations</li>
</ul>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>SIXBAR.xml</code> (exported 03/14/24||10:20:30).</li></ul>
</html>"));
end SIXBAR;

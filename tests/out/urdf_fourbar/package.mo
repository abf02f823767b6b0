within ;
package urdf_fourbar "Modelica model of CAD assembly urdf_fourbar, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>fourbar.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>Source: <code>fourbar.urdf</code>, written by URDF from the CAD system , on .</p>
<p><code>Mechanics</code>: 4 bodies, 5 joints, 1 loops, 0 free bodies; gravity {0, 0, -9.81} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>ground</code></td><td>ground</td><td>ground</td><td>5</td><td>urdf_fourbar/Resources/Shapes/ground.dxf</td></tr>
<tr><td><code>crank</code></td><td>crank</td><td>crank</td><td>0.5</td><td>urdf_fourbar/Resources/Shapes/crank.dxf</td></tr>
<tr><td><code>coupler</code></td><td>coupler</td><td>coupler</td><td>1</td><td>urdf_fourbar/Resources/Shapes/coupler.dxf</td></tr>
<tr><td><code>rocker</code></td><td>rocker</td><td>rocker</td><td>0.5</td><td>urdf_fourbar/Resources/Shapes/rocker.dxf</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>ground_fixed_to_world</code></td><td>ground_fixed_to_world</td><td>world::ground</td><td>connect</td><td>world</td><td>ground</td></tr>
<tr><td><code>crank_pivot</code></td><td>crank_pivot</td><td>crank_pivot</td><td>revolute</td><td>ground</td><td>crank</td></tr>
<tr><td><code>crank_coupler</code></td><td>crank_coupler</td><td>crank_coupler</td><td>revolute</td><td>crank</td><td>coupler</td></tr>
<tr><td><code>rocker_pivot</code></td><td>rocker_pivot</td><td>rocker_pivot</td><td>revolute-planar-loop-constraint</td><td>ground</td><td>rocker</td></tr>
<tr><td><code>coupler_rocker</code></td><td>coupler_rocker</td><td>coupler_rocker</td><td>revolute</td><td>coupler</td><td>rocker</td></tr>
</table>
<h4>Loops and how they were closed</h4>
<ul>
<li>rocker_pivot (a planar loop through rocker_pivot, crank_pivot, crank_coupler, coupler_rocker): a plain revolute would repeat 3 of its 5 equations (2 independent); the loop is planar (axes parallel within 1e-4 rad, emitted exactly parallel; a change beyond 1e-12 rad is in the joint's corrections), so RevolutePlanarLoopConstraint imposes the 2 in-plane position equations</li>
</ul>
<h4>Warnings</h4>
<ul>
<li><code>urdf-root-fixed</code> fourbar.urdf:5:3 (link &quot;ground&quot;): root link &quot;ground&quot; is fixed to the world at its origin (URDF cannot say whether a root floats; to make it a free body, add a `floating` joint from a `world` link)</li>
</ul>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>fourbar.urdf</code> (exported ).</li></ul>
</html>"));
end urdf_fourbar;

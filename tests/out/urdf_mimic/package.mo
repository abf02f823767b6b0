within ;
package urdf_mimic "Modelica model of CAD assembly urdf_mimic, converted by cad2mo"
  extends Modelica.Icons.Package;
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>mimic.urdf</code> (robot), exported by URDF from  on  by .</p>
<p>Source: <code>mimic.urdf</code>, written by URDF from the CAD system , on .</p>
<p><code>Mechanics</code>: 11 bodies, 10 joints, 0 loops, 1 free bodies; gravity {0, 0, -9.81} m/s2. <code>Mechatronics</code>: 0 drives.</p>
<h4>Bodies</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>mass, kg</th><th>shape</th></tr>
<tr><td><code>palm</code></td><td>palm</td><td>palm</td><td>1</td><td>none</td></tr>
<tr><td><code>finger_a</code></td><td>finger_a</td><td>finger_a</td><td>0.1</td><td>none</td></tr>
<tr><td><code>finger_b</code></td><td>finger_b</td><td>finger_b</td><td>0.1</td><td>none</td></tr>
<tr><td><code>jaw_a</code></td><td>jaw_a</td><td>jaw_a</td><td>0.1</td><td>none</td></tr>
<tr><td><code>jaw_b</code></td><td>jaw_b</td><td>jaw_b</td><td>0.1</td><td>none</td></tr>
<tr><td><code>thumb</code></td><td>thumb</td><td>thumb</td><td>0.05</td><td>none</td></tr>
<tr><td><code>nail</code></td><td>nail</td><td>nail</td><td>0.01</td><td>none</td></tr>
<tr><td><code>puck</code></td><td>puck</td><td>puck</td><td>0.3</td><td>none</td></tr>
<tr><td><code>ball_link</code></td><td>ball_link</td><td>ball_link</td><td>0.2</td><td>none</td></tr>
<tr><td><code>cardan</code></td><td>cardan</td><td>cardan</td><td>0.2</td><td>none</td></tr>
<tr><td><code>drone</code></td><td>drone</td><td>drone</td><td>0.8</td><td>none</td></tr>
</table>
<h4>Joints</h4>
<table border=\"1\" cellspacing=\"0\" cellpadding=\"2\">
<tr><th>Modelica</th><th>CAD name</th><th>node ID</th><th>emitted as</th><th>base body</th><th>follower body</th></tr>
<tr><td><code>wrist</code></td><td>wrist</td><td>wrist</td><td>connect</td><td>world</td><td>palm</td></tr>
<tr><td><code>knuckle_a</code></td><td>knuckle_a</td><td>knuckle_a</td><td>revolute</td><td>palm</td><td>finger_a</td></tr>
<tr><td><code>knuckle_b</code></td><td>knuckle_b</td><td>knuckle_b</td><td>revolute</td><td>palm</td><td>finger_b</td></tr>
<tr><td><code>jaw_a_slide</code></td><td>jaw_a_slide</td><td>jaw_a_slide</td><td>prismatic</td><td>palm</td><td>jaw_a</td></tr>
<tr><td><code>jaw_b_slide</code></td><td>jaw_b_slide</td><td>jaw_b_slide</td><td>prismatic</td><td>palm</td><td>jaw_b</td></tr>
<tr><td><code>thumb_slide</code></td><td>thumb_slide</td><td>thumb_slide</td><td>prismatic</td><td>palm</td><td>thumb</td></tr>
<tr><td><code>nail_hinge</code></td><td>nail_hinge</td><td>nail_hinge</td><td>revolute</td><td>thumb</td><td>nail</td></tr>
<tr><td><code>table</code></td><td>table</td><td>table</td><td>chain</td><td>world</td><td>puck</td></tr>
<tr><td><code>shoulder_ball</code></td><td>shoulder_ball</td><td>shoulder_ball</td><td>spherical</td><td>puck</td><td>ball_link</td></tr>
<tr><td><code>cardan_joint</code></td><td>cardan_joint</td><td>cardan_joint</td><td>chain</td><td>ball_link</td><td>cardan</td></tr>
</table>
<p>Free bodies (no path to the ground; they start at their CAD pose and fall): drone.</p>
<h4>Warnings</h4>
<ul>
<li><code>urdf-floating</code> mimic.urdf:150:3 (joint &quot;float&quot;): floating joint: link &quot;drone&quot; and what hangs on it form a free body (6 degrees of freedom)</li>
<li><code>mimic-not-expressible</code> mimic.urdf:132:5 (joint &quot;nail_hinge&quot; / mimic): joint &quot;nail_hinge&quot; is left uncoupled: the offset 0.1 is not zero, so the zero configuration (the pose the model starts in) does not satisfy it</li>
<li><code>free-bodies</code> mimic.urdf: 1 bodies have no path to a ground and float freely from their CAD pose (6 degrees of freedom per free group): &quot;drone&quot;</li>
<li><code>no-geometry</code> mimic.urdf: 11 bodies have no geometry: &quot;palm&quot; (palm), &quot;finger_a&quot; (finger_a), &quot;finger_b&quot; (finger_b), &quot;jaw_a&quot; (jaw_a), &quot;jaw_b&quot; (jaw_b), &quot;thumb&quot; (thumb), &quot;nail&quot; (nail), &quot;puck&quot; (puck), &quot;ball_link&quot; (ball_link), &quot;cardan&quot; (cardan), &quot;drone&quot; (drone)</li>
<li><code>no-collision-shape</code> collision shapes: 11 bodies with mass but no mesh have no collision shape and cannot collide: palm, finger_a, finger_b, jaw_a, jaw_b, thumb, nail, puck, ball_link, cardan and 1 more</li>
</ul>
<h4>Regenerating</h4>
<p>Do not edit <code>Mechanics</code>: it is rewritten whenever the CAD model changes. Upload the new CAD export as a new version of the model in cad2mo (the web UI, or <code>POST /api/models/MODEL_ID/versions</code>); body and joint names, diagram places and drives are kept for everything that did not change. Without the service: <code>cad2mo convert EXPORT.zip -o package.zip</code>. Put your own models in another package that uses this one.</p>
</html>", revisions="<html>
<ul><li>cad2mo 0.1.0: converted from <code>mimic.urdf</code> (exported ).</li></ul>
</html>"));
end urdf_mimic;

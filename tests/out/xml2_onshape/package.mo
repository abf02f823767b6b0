within ;
package slide_arm "Modelica model of CAD assembly slide arm, converted by cad2mo"
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>slide_arm.xml</code> (SimscapeMultibodyImportXML), exported by Simscape Multibody Exporter from Onshape on 11/25/26||00:00:00 by cad2mo tests.</p>
<p><code>Mechanics</code> is the pure mechanical model, regenerated at every CAD change. <code>Components</code> holds joints with a 1-D <code>drive</code> flange: left open the joint is free, a motor connected to it actuates the joint.</p>
</html>"));
end slide_arm;

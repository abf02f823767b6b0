within ;
package mate_rig "Modelica model of CAD assembly mate rig, converted by cad2mo"
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>mate rig.xml</code> (SimscapeMultibodyImportXML), exported by Simscape Multibody Link Version 7.4 from SolidWorks 28.0.0 on 11/25/26||00:00:00 by .</p>
<p><code>Mechanics</code> is the pure mechanical model, regenerated at every CAD change. <code>Components</code> holds joints with a 1-D <code>drive</code> flange: left open the joint is free, a motor connected to it actuates the joint.</p>
</html>"));
end mate_rig;

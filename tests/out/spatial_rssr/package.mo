within ;
package RSSR "Modelica model of CAD assembly RSSR, converted by cad2mo"
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>RSSR.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 5.0 from Pro/E Wildfire Creo 7.0 - 2020454 on 03/14/24||10:20:30 by cad2mo.</p>
<p><code>Mechanics</code> is the pure mechanical model, regenerated at every CAD change. <code>Components</code> holds joints with a 1-D <code>drive</code> flange: left open the joint is free, a motor connected to it actuates the joint.</p>
</html>"));
end RSSR;

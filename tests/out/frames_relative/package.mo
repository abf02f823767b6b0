within ;
package RELFRAMES "Modelica model of CAD assembly RELFRAMES, converted by cad2mo"
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>RELFRAMES.xml</code> (SimscapeMultibody), exported by Simscape Multibody Link Version 5.0 from Pro/E Wildfire Creo 9.0 - 2022073 on 03/14/24||10:20:30 by cad2mo.</p>
<p><code>Mechanics</code> is the pure mechanical model, regenerated at every CAD change. <code>Components</code> holds joints with a 1-D <code>drive</code> flange: left open the joint is free, a motor connected to it actuates the joint.</p>
</html>"));
end RELFRAMES;

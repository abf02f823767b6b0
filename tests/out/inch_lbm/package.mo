within ;
package CHAIN_IN "Modelica model of CAD assembly CHAIN_IN, converted by cad2mo"
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>CHAIN_IN.xml</code> (SimMechanics), exported by SimMechanics Link Version 3.1 from Pro/E Wildfire Wildfire 4.0 - 2008230 on 11/10/09||14:08:16 by cad2mo.</p>
<p><code>Mechanics</code> is the pure mechanical model, regenerated at every CAD change. <code>Components</code> holds joints with a 1-D <code>drive</code> flange: left open the joint is free, a motor connected to it actuates the joint.</p>
</html>"));
end CHAIN_IN;

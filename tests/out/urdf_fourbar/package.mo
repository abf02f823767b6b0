within ;
package urdf_fourbar "Modelica model of CAD assembly urdf_fourbar, converted by cad2mo"
  annotation (
    uses(Modelica(version="4.0.0")),
    Documentation(info="<html>
<p>Converted by cad2mo 0.1.0 from <code>fourbar.urdf</code> (robot), exported by URDF from  on  by .</p>
<p><code>Mechanics</code> is the pure mechanical model, regenerated at every CAD change. <code>Components</code> holds joints with a 1-D <code>drive</code> flange: left open the joint is free, a motor connected to it actuates the joint.</p>
</html>"));
end urdf_fourbar;

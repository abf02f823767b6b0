//! Modelica back end.

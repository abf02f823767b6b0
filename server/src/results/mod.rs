//! Simulation results brought back to a converted model (issue 13, started): the MATLAB v4
//! trajectory files of Dymola and OpenModelica ([`mat`]). No IO, no HTTP, no SQL.

pub mod mat;

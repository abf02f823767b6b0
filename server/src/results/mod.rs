//! Simulation results brought back to a converted model (issue 13, started): the MATLAB v4
//! trajectory files of Dymola and OpenModelica ([`mat`]) and the body poses in them ([`poses`]). No IO, no HTTP, no SQL.

pub mod mat;
pub mod poses;

#[cfg(test)]
pub(crate) mod testmat;

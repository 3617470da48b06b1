//! Scalar numerics shared by the layers above: root bracketing, one-dimensional maximisation and
//! the beta functions of the power-law impact.

pub mod beta;
pub mod roots;

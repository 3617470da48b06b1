//! Scalar numerics shared by the layers above: root bracketing and one-dimensional maximisation.

pub mod roots;

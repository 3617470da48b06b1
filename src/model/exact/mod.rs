//! Exact solutions of the impact ODE where mathematics allows (physics notes §3).

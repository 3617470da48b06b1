//! The presets compiled into the binary, so an installed binary works from any directory.

/// (name, TOML text) of every built-in material.
pub(super) const MATERIALS: &[(&str, &str)] = &[
    (
        "steel",
        include_str!("../../../presets/materials/steel.toml"),
    ),
    (
        "aluminium-alloy",
        include_str!("../../../presets/materials/aluminium-alloy.toml"),
    ),
];

/// (name, TOML text) of every built-in scene.
pub(super) const SCENES: &[(&str, &str)] = &[
    (
        "steel-sphere-r5-plate",
        include_str!("../../../presets/scenes/steel-sphere-r5-plate.toml"),
    ),
    (
        "steel-sphere-r10-plate",
        include_str!("../../../presets/scenes/steel-sphere-r10-plate.toml"),
    ),
    (
        "aluminium-sphere-r10-plate",
        include_str!("../../../presets/scenes/aluminium-sphere-r10-plate.toml"),
    ),
    (
        "steel-cylinders-r20-l100",
        include_str!("../../../presets/scenes/steel-cylinders-r20-l100.toml"),
    ),
    (
        "steel-cylinder-r20-l100-plate",
        include_str!("../../../presets/scenes/steel-cylinder-r20-l100-plate.toml"),
    ),
    (
        "fig4-steel-sphere-r10-plate",
        include_str!("../../../presets/scenes/fig4-steel-sphere-r10-plate.toml"),
    ),
    (
        "fig5-steel-sphere-r10-plate",
        include_str!("../../../presets/scenes/fig5-steel-sphere-r10-plate.toml"),
    ),
    (
        "bouncing-ball",
        include_str!("../../../presets/scenes/bouncing-ball.toml"),
    ),
    (
        "impact-oscillator",
        include_str!("../../../presets/scenes/impact-oscillator.toml"),
    ),
    (
        "impact-oscillator-clearance",
        include_str!("../../../presets/scenes/impact-oscillator-clearance.toml"),
    ),
];

/// How messages name a built-in preset's source: its path in the repository.
pub(super) fn origin(kind: &str, name: &str) -> String {
    format!("presets/{kind}/{name}.toml (built-in)")
}

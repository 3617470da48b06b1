//! Which explorer chart: F(x), F(t) or v(x).

/// The charts, in the order `c` cycles them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChartKind {
    ForceDisplacement,
    ForceTime,
    VelocityDisplacement,
}

impl ChartKind {
    pub const ALL: [ChartKind; 3] = [
        ChartKind::ForceDisplacement,
        ChartKind::VelocityDisplacement,
        ChartKind::ForceTime,
    ];

    pub fn next(self) -> ChartKind {
        let i = ChartKind::ALL.iter().position(|&c| c == self).unwrap_or(0);
        ChartKind::ALL[(i + 1) % ChartKind::ALL.len()]
    }
}

//! The table of contact-force laws: the one place a law is declared (docs/physics.md §6).
//!
//! Everything that lists laws — `--model`, scene files, sweeps, the explorer's panes and arrays —
//! iterates [`LAWS`] through [`super::ForceModel`]. The one `law_table!` invocation below (the
//! macro is in `any.rs`) is both [`LAWS`] and the generator of [`AnyLaw`]: each row names its
//! variant, the law type of its file and that type's builder (`Variant = file::Type::builder`),
//! then its table data, its style included (the glyph and hue it is drawn with everywhere). A
//! Hunt–Crossley-type law is one row with its χ(e); a law with its own equations is one file (a
//! `ForceLaw` type and its builder, declared by its `mod` line in `force/mod.rs`) plus one row.

use super::any::law_table;

/// Which kind of dissipation a law models; the Models pane groups laws by it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Family {
    /// No dissipation.
    Elastic,
    /// F = k·xⁿ plus a friction term switching with sign(ẋ).
    Friction,
    /// F = elastic part plus a damping coefficient times ẋ.
    Viscous,
    /// Elastic–plastic: a permanent dent, no rate dependence.
    Plastic,
    /// F = k·xⁿ·(1 + χ(e)·ẋ/v₀), the Hunt–Crossley family.
    HuntCrossley,
}

impl Family {
    /// The group heading in the Models pane.
    pub fn title(self) -> &'static str {
        match self {
            Family::Elastic => "elastic",
            Family::Friction => "friction",
            Family::Viscous => "viscous damping",
            Family::Plastic => "elastic–plastic",
            Family::HuntCrossley => "Hunt–Crossley family",
        }
    }
}

/// The damping parameter of a law: what calibration solves for and what `solve` reports.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct DampingParam {
    /// Its symbol, e.g. `χ`.
    pub symbol: &'static str,
    /// The key it is reported under in JSON, e.g. `chi`.
    pub key: &'static str,
    /// SI unit; `1` for a pure number.
    pub unit: &'static str,
}

/// How contact ends (besides the compressive-only cutoff that [`ContactRule::ApproachZero`] laws
/// apply where they would turn tensile, see [`super::law`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ContactRule {
    /// At x = 0; where the law would pull (F < 0) first, contact ends there.
    ApproachZero,
    /// Where F returns to 0 (F ≥ 0 enforced): a residual approach is left.
    ForceZero,
    /// At x = 0, the law's tensile force acting on the way out (a bilateral spring–damper).
    TensionAllowed,
}

impl ContactRule {
    pub fn describe(self) -> &'static str {
        match self {
            ContactRule::ApproachZero => "ends at x = 0 (or where F would turn tensile)",
            ContactRule::ForceZero => "ends where F returns to 0 (F ≥ 0)",
            ContactRule::TensionAllowed => "ends at x = 0, tension allowed",
        }
    }
}

/// A colour by name, for renderers to map to their palettes: the terminal shows it in the ANSI
/// colour of that name (not the bright variant, which fades on white), a figure in a print colour
/// of that hue.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Hue {
    /// The renderer's own foreground (black in figures).
    Foreground,
    Red,
    Green,
    Yellow,
    Blue,
    Magenta,
    Cyan,
}

/// The pattern a curve is drawn with, as print tells curves apart: where curves lie on one
/// another, the gaps of a dotted or dashed one show the curve under it, and the pattern names a
/// curve without colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Dash {
    #[default]
    Solid,
    /// Every other dot.
    Dotted,
    /// Dashes of four dots, two dots apart.
    Dashed,
}

impl Dash {
    /// The dots drawn and the dots left out in each period of the pattern, along the curve
    /// (`off` = 0: solid).
    pub fn on_off(self) -> (u8, u8) {
        match self {
            Dash::Solid => (1, 0),
            Dash::Dotted => (1, 1),
            Dash::Dashed => (4, 2),
        }
    }
}

/// How a law's curves and legend entries look in every chart, pane and figure: part of its row,
/// so that adding a law restyles no other. No two laws share a glyph (it tells curves apart
/// where colour cannot), nor a hue and a pattern at once while the 21 pairs last; the paper's
/// five take five different hues.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct LawStyle {
    /// Marks the law's curves at their peak and end; printable ASCII, which every font has.
    pub glyph: char,
    pub hue: Hue,
    /// The line's pattern: the paper's Hunt–Crossley and Lankarani–Nikravesh, which lie within
    /// a dot or two of each other, dotted and dashed.
    pub dash: Dash,
}

/// One law of the table.
#[derive(Debug, Clone, Copy)]
pub struct LawSpec {
    /// The id of `--model` and of scene files, kebab-case.
    pub id: &'static str,
    /// The name shown in every pane.
    pub label: &'static str,
    /// An abbreviation for narrow panes.
    pub short: &'static str,
    /// Its equation or published source.
    pub source: &'static str,
    pub family: Family,
    /// The damping parameter, `None` for a law without one.
    pub damping: Option<DampingParam>,
    pub contact: ContactRule,
    pub style: LawStyle,
    /// χ(e) of a Hunt–Crossley-family row, F = k·xⁿ·(1 + χ(e)·ẋ/v₀); `None` for other laws.
    pub chi: Option<fn(f64) -> f64>,
    /// With its damping from e, its impact in the solver's scaled variables (x/x_e, ẋ/v₀,
    /// t·v₀/x_e) depends on n, e and its contact rule alone, so one solve scaled serves every v₀,
    /// m and k (docs/physics.md §6.9). Tested against direct solves for every row.
    pub similar: bool,
}

const CHI: DampingParam = DampingParam {
    symbol: "χ",
    key: "chi",
    unit: "1",
};

const GAMMA: DampingParam = DampingParam {
    symbol: "γ",
    key: "gamma",
    unit: "N·s/m^((n+1)/2)",
};

const KK_A: DampingParam = DampingParam {
    symbol: "A",
    key: "a",
    unit: "s",
};

const KV_C: DampingParam = DampingParam {
    symbol: "c",
    key: "c",
    unit: "N·s/m",
};

// Every law, grouped by family; the paper's five keep their ids and their relative order.
law_table! {
    Elastic = elastic::Elastic::build,
    LawSpec {
        id: "quasistatic",
        label: "Hertz, elastic (eq 1)",
        short: "Hertz",
        source: "eq 1",
        family: Family::Elastic,
        damping: None,
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: 'o',
            hue: Hue::Blue,
            dash: Dash::Dashed,
        },
        chi: None,
        similar: true,
    };
    HertzLineExact = hertz_line_exact::HertzLineExact::build,
    LawSpec {
        id: "hertz-line-exact",
        label: "Hertz exact line (eq 13/14)",
        short: "Hz line",
        source: "eqs 13–14 inverted for F(x) (eq 1 on spheres); docs/physics.md §6.7",
        family: Family::Elastic,
        damping: None,
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: '%',
            hue: Hue::Yellow,
            dash: Dash::Dotted,
        },
        chi: None,
        similar: false,
    };
    DryFriction = dry_friction::DryFriction::build,
    LawSpec {
        id: "dry-friction",
        label: "dry friction (eq 15)",
        short: "dry fr.",
        source: "eqs 15–17",
        family: Family::Friction,
        damping: Some(DampingParam {
            symbol: "P",
            key: "p",
            unit: "N/m",
        }),
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: '+',
            hue: Hue::Green,
            dash: Dash::Solid,
        },
        chi: None,
        similar: true,
    };
    Proposed = proposed::Proposed::build,
    LawSpec {
        id: "proposed",
        label: "proposed viscous (eq 18)",
        short: "proposed",
        source: "eq 18",
        family: Family::Viscous,
        damping: Some(DampingParam {
            symbol: "b",
            key: "b",
            unit: "N·s/m^n",
        }),
        contact: ContactRule::ForceZero,
        style: LawStyle {
            glyph: '*',
            hue: Hue::Red,
            dash: Dash::Solid,
        },
        chi: None,
        similar: false,
    };
    HertzViscous = hertz_viscous::HertzViscous::build,
    LawSpec {
        id: "hertz-viscous",
        label: "Hertz–viscous F≥0",
        short: "H+visc",
        source: "Tsuji, Tanaka & Ishida, Powder Technol. 71 (1992); docs/physics.md §6.2",
        family: Family::Viscous,
        damping: Some(GAMMA),
        contact: ContactRule::ForceZero,
        style: LawStyle {
            glyph: '@',
            hue: Hue::Foreground,
            dash: Dash::Solid,
        },
        chi: None,
        similar: true,
    };
    HertzViscousTension = hertz_viscous::HertzViscous::build,
    LawSpec {
        id: "hertz-viscous-tension",
        label: "Hertz–visc. tension",
        short: "H+visc±",
        source: "Tsuji, Tanaka & Ishida, Powder Technol. 71 (1992); docs/physics.md §6.2",
        family: Family::Viscous,
        damping: Some(GAMMA),
        contact: ContactRule::TensionAllowed,
        style: LawStyle {
            glyph: '&',
            hue: Hue::Red,
            dash: Dash::Dashed,
        },
        chi: None,
        similar: true,
    };
    KelvinVoigt = kelvin_voigt::KelvinVoigt::build,
    LawSpec {
        id: "kelvin-voigt",
        label: "Kelvin–Voigt F≥0",
        short: "K–V",
        source: "linear spring–dashpot; docs/physics.md §6.3",
        family: Family::Viscous,
        damping: Some(KV_C),
        contact: ContactRule::ForceZero,
        style: LawStyle {
            glyph: '$',
            hue: Hue::Cyan,
            dash: Dash::Solid,
        },
        chi: None,
        similar: true,
    };
    KelvinVoigtTension = kelvin_voigt::KelvinVoigt::build,
    LawSpec {
        id: "kelvin-voigt-tension",
        label: "Kelvin–Voigt tension",
        short: "K–V±",
        source: "linear spring–dashpot; docs/physics.md §6.3",
        family: Family::Viscous,
        damping: Some(KV_C),
        contact: ContactRule::TensionAllowed,
        style: LawStyle {
            glyph: '~',
            hue: Hue::Magenta,
            dash: Dash::Dotted,
        },
        chi: None,
        similar: true,
    };
    KuwabaraKono = proposed::Proposed::build_kuwabara_kono,
    LawSpec {
        id: "kuwabara-kono",
        label: "Kuwabara–Kono",
        short: "K–K",
        source: "Kuwabara & Kono, Jpn. J. Appl. Phys. 26 (1987); Brilliantov et al., Phys. Rev. E 53 (1996); docs/physics.md §6.5",
        family: Family::Viscous,
        damping: Some(KK_A),
        contact: ContactRule::ForceZero,
        style: LawStyle {
            glyph: '^',
            hue: Hue::Blue,
            dash: Dash::Solid,
        },
        chi: None,
        similar: true,
    };
    KuwabaraKonoTension = proposed::Proposed::build_kuwabara_kono,
    LawSpec {
        id: "kuwabara-kono-tension",
        label: "Kuwabara–Kono tension",
        short: "K–K±",
        source: "Kuwabara & Kono, Jpn. J. Appl. Phys. 26 (1987); Brilliantov et al., Phys. Rev. E 53 (1996); docs/physics.md §6.5",
        family: Family::Viscous,
        damping: Some(KK_A),
        contact: ContactRule::TensionAllowed,
        style: LawStyle {
            glyph: 'v',
            hue: Hue::Green,
            dash: Dash::Dashed,
        },
        chi: None,
        similar: true,
    };
    AdamsImpact = adams_impact::AdamsImpact::build,
    LawSpec {
        id: "adams-impact",
        label: "Adams IMPACT F≥0",
        short: "IMPACT",
        source: "MSC Adams/Solver function reference, IMPACT; docs/physics.md §6.8",
        family: Family::Viscous,
        damping: Some(DampingParam {
            symbol: "c_max",
            key: "c_max",
            unit: "N·s/m",
        }),
        contact: ContactRule::ForceZero,
        // The one hue and pattern no other law has: yellow takes all three patterns already.
        style: LawStyle {
            glyph: 'a',
            hue: Hue::Foreground,
            dash: Dash::Dotted,
        },
        chi: None,
        similar: true,
    };
    Thornton = thornton::Thornton::build,
    LawSpec {
        id: "thornton",
        label: "Thornton 1997",
        short: "Thorn.",
        source: "Thornton, J. Appl. Mech. 64 (1997), elastic–perfectly-plastic spheres (cylinders: the same construction on a strip); docs/physics.md §6.6",
        family: Family::Plastic,
        damping: Some(DampingParam {
            symbol: "v_y",
            key: "v_yield",
            unit: "m/s",
        }),
        contact: ContactRule::ForceZero,
        style: LawStyle {
            glyph: 's',
            hue: Hue::Yellow,
            dash: Dash::Solid,
        },
        chi: None,
        similar: false,
    };
    HuntCrossley = hysteresis::Hysteresis::build,
    LawSpec {
        id: "hunt-crossley",
        label: "Hunt–Crossley (eq 19)",
        short: "H–C",
        source: "eq 19; Hunt & Crossley, J. Appl. Mech. 42 (1975)",
        family: Family::HuntCrossley,
        damping: Some(CHI),
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: 'x',
            hue: Hue::Cyan,
            dash: Dash::Dotted,
        },
        chi: Some(|e| 1.5 * (1.0 - e)),
        similar: true,
    };
    LankaraniNikravesh = hysteresis::Hysteresis::build,
    LawSpec {
        id: "lankarani-nikravesh",
        label: "Lankarani–Nikravesh (eq 20)",
        short: "L–N",
        source: "eq 20; Lankarani & Nikravesh, J. Mech. Des. 112 (1990)",
        family: Family::HuntCrossley,
        damping: Some(CHI),
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: '#',
            hue: Hue::Magenta,
            dash: Dash::Dashed,
        },
        chi: Some(|e| 0.75 * (1.0 - e * e)),
        similar: true,
    };
    HerbertMcWhannell = hysteresis::Hysteresis::build,
    LawSpec {
        id: "herbert-mcwhannell",
        label: "Herbert–McWhannell",
        short: "H–McW",
        source: "χ = 6(1−e)/((2e−1)² + 3); Herbert & McWhannell, J. Eng. Ind. 99 (1977)",
        family: Family::HuntCrossley,
        damping: Some(CHI),
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: 'd',
            hue: Hue::Foreground,
            dash: Dash::Dashed,
        },
        chi: Some(|e| 6.0 * (1.0 - e) / ((2.0 * e - 1.0).powi(2) + 3.0)),
        similar: true,
    };
    LeeWang = hysteresis::Hysteresis::build,
    LawSpec {
        id: "lee-wang",
        label: "Lee–Wang",
        short: "L–W",
        source: "χ = 3(1−e)/4; Lee & Wang, J. Mech. Transm. Autom. Des. 105 (1983)",
        family: Family::HuntCrossley,
        damping: Some(CHI),
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: 'k',
            hue: Hue::Red,
            dash: Dash::Dotted,
        },
        chi: Some(|e| 0.75 * (1.0 - e)),
        similar: true,
    };
    Gonthier = hysteresis::Hysteresis::build,
    LawSpec {
        id: "gonthier",
        label: "Gonthier et al.",
        short: "Gon.",
        source: "χ = (1−e²)/e; Gonthier, McPhee, Lange & Piedbœuf, Multibody Syst. Dyn. 11 (2004)",
        family: Family::HuntCrossley,
        damping: Some(CHI),
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: 'z',
            hue: Hue::Cyan,
            dash: Dash::Dashed,
        },
        chi: Some(|e| (1.0 - e * e) / e),
        similar: true,
    };
    ZhiyingQishao = hysteresis::Hysteresis::build,
    LawSpec {
        id: "zhiying-qishao",
        label: "Zhiying–Qishao",
        short: "Z–Q",
        source: "χ = (3/4)(1−e²)·exp(2(1−e)); Zhiying & Qishao, Acta Mech. Sin. 22 (2006); docs/physics.md §6.1",
        family: Family::HuntCrossley,
        damping: Some(CHI),
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: 'w',
            hue: Hue::Magenta,
            dash: Dash::Solid,
        },
        chi: Some(|e| 0.75 * (1.0 - e * e) * (2.0 * (1.0 - e)).exp()),
        similar: true,
    };
    Flores = hysteresis::Hysteresis::build,
    LawSpec {
        id: "flores",
        label: "Flores et al.",
        short: "Flo.",
        source: "χ = 8(1−e)/(5e); Flores, Machado, Silva & Martins, Multibody Syst. Dyn. 25 (2011)",
        family: Family::HuntCrossley,
        damping: Some(CHI),
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: 'h',
            hue: Hue::Blue,
            dash: Dash::Dotted,
        },
        chi: Some(|e| 1.6 * (1.0 - e) / e),
        similar: true,
    };
    HuGuo = hysteresis::Hysteresis::build,
    LawSpec {
        id: "hu-guo",
        label: "Hu–Guo",
        short: "H–G",
        source: "χ = 3(1−e)/(2e); Hu & Guo, Mech. Mach. Theory 85 (2015); docs/physics.md §6.1",
        family: Family::HuntCrossley,
        damping: Some(CHI),
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: 'n',
            hue: Hue::Green,
            dash: Dash::Dotted,
        },
        chi: Some(|e| 1.5 * (1.0 - e) / e),
        similar: true,
    };
    GharibHurmuzlu = hysteresis::Hysteresis::build,
    LawSpec {
        id: "gharib-hurmuzlu",
        label: "Gharib–Hurmuzlu",
        short: "G–H",
        source: "χ = 1/e − 1; Gharib & Hurmuzlu, J. Appl. Mech. 79 (2012)",
        family: Family::HuntCrossley,
        damping: Some(CHI),
        contact: ContactRule::ApproachZero,
        style: LawStyle {
            glyph: 'q',
            hue: Hue::Yellow,
            dash: Dash::Dashed,
        },
        chi: Some(|e| 1.0 / e - 1.0),
        similar: true,
    };
}

/// The number of laws: the size of every per-law array.
pub const LAW_COUNT: usize = LAWS.len();

// `ForceModel` holds a row's index in a u8: a 257th row fails the build instead of wrapping.
const _: () = assert!(LAW_COUNT <= u8::MAX as usize + 1);

/// The row whose id is `id`, at compile time (a missing id fails the build).
pub const fn index_of(id: &str) -> usize {
    let mut i = 0;
    while i < LAW_COUNT {
        if str_eq(LAWS[i].id, id) {
            return i;
        }
        i += 1;
    }
    panic!("no law with this id in LAWS")
}

const fn str_eq(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every row draws with a glyph of its own, so that two laws' curves never look alike even
    /// where they share a hue or colour is off (`NO_COLOR`, a figure printed in grey).
    #[test]
    fn every_law_has_a_printable_glyph_of_its_own() {
        for (i, a) in LAWS.iter().enumerate() {
            assert!(a.style.glyph.is_ascii_graphic(), "{}: {:?}", a.id, a.style);
            for b in &LAWS[i + 1..] {
                assert_ne!(a.style.glyph, b.style.glyph, "{} and {}", a.id, b.id);
            }
        }
    }

    /// Two laws of one hue differ in pattern while the 21 pairs of a hue (seven with the
    /// foreground) and a pattern last, so that colour and pattern alone tell every pair apart;
    /// the two closest of the paper's curves (Hunt–Crossley and Lankarani–Nikravesh) and Fig. 4's
    /// pair (elastic Hertz and dry friction) differ in pattern too.
    #[test]
    fn no_two_laws_share_a_hue_and_a_pattern() {
        let pairs: std::collections::HashSet<(Hue, Dash)> =
            LAWS.iter().map(|a| (a.style.hue, a.style.dash)).collect();
        assert_eq!(
            pairs.len(),
            LAWS.len().min(7 * 3),
            "a hue and a pattern shared"
        );
        for (a, b) in [
            ("hunt-crossley", "lankarani-nikravesh"),
            ("quasistatic", "dry-friction"),
        ] {
            assert_ne!(
                LAWS[index_of(a)].style.dash,
                LAWS[index_of(b)].style.dash,
                "{a} {b}"
            );
        }
    }

    /// The paper's five, drawn together in its Fig. 5 and the default scene, take five hues.
    #[test]
    fn the_papers_five_laws_take_five_hues() {
        let five = [
            "quasistatic",
            "dry-friction",
            "proposed",
            "hunt-crossley",
            "lankarani-nikravesh",
        ]
        .map(|id| LAWS[index_of(id)].style.hue);
        for (i, a) in five.iter().enumerate() {
            assert!(!five[i + 1..].contains(a), "{five:?}");
        }
    }
}

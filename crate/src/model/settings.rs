//! What directives set: the turtle's and derivation's settings, the palette, the limits, and the
//! growth attributes. Defaults are those of the vocabulary's directive table.

use super::{ModuleId, Program};
use crate::syntax::Span;
use crate::vocabulary::{DirectiveKind, Season};
use glam::DVec3;

/// Values set by directives, with the defaults of LANGUAGE.md section 2.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// `#angle`: the default turn angle δ in degrees.
    pub angle: f64,
    /// The grammar has a `#width` directive.
    pub width_given: bool,
    /// `#heading`: the turn of the turtle's starting frame about U, in degrees (as `+` turns).
    pub heading: f64,
    /// `#iterations` / `derivation length:`: the default number of derivation steps.
    pub iterations: u32,
    /// `#seed`: the seed of the random generator.
    pub seed: u64,
    /// `#step`: the default length of `F` and `f`.
    pub step: f64,
    /// `#width`: the initial segment width, in width units (see `mesh`).
    pub width: f64,
    /// `#width_step`: how much `!` without a parameter decreases the width.
    pub width_step: f64,
    /// `#width_unit`: model units per width unit, so that widths are diameters in the model's own
    /// units (as cpfg draws cylinders); `None`: the mesh's unit, relative to the plant's size.
    pub width_unit: Option<f64>,
    /// `#tropism x y z e`: the tropism vector T and susceptibility e (ABOP 2.3); e = 0 is none.
    pub tropism: (DVec3, f64),
    /// `#max_modules`: derivation stops with an error when a string would grow past this.
    pub max_modules: usize,
    /// `#max_steps`: the largest number of derivation steps a build may run.
    pub max_steps: u32,
    /// `#draw A B`: further modules that draw a segment like `F`.
    pub draw: Vec<ModuleId>,
    /// The colours of the colour index (`'`, `;`), linear RGB in 0..=1: [`DEFAULT_PALETTE`]
    /// with the entries `#color` set. An index past the end wraps modulo the length.
    pub palette: Vec<[f32; 3]>,
    /// A `#color` directive set entry 0, the turtle's starting colour: organs then start with it
    /// like everything else (see [`ORGAN_COLOR`]).
    pub start_color_given: bool,
    /// Span of the `#iterations` directive, where step-related diagnostics point.
    pub iterations_span: Option<Span>,
    /// `#terminal_age`: the timed modules (ABOP 6.1) and their terminal ages, in source order;
    /// empty for a grammar that is not timed.
    pub terminal_ages: Vec<(ModuleId, f64)>,
    /// Span of the first `#terminal_age`, where timed derivation's diagnostics point.
    pub terminal_age_span: Option<Span>,
    /// `#dt`: the time one derivation step covers.
    pub dt: f64,
    /// The grammar has a `#dt` directive.
    pub dt_given: bool,
    /// The surfaces `#surface` and `#patch` declare, by letter (what `~X` draws); empty without
    /// the feature `surfaces`.
    pub surfaces: Vec<std::sync::Arc<super::SurfaceShape>>,
    /// The grammar has a `#surface` or `#patch` line (read or not: see the feature `surfaces`).
    pub surfaces_declared: bool,
    /// The grammar has an `#environment`, `#stand` or `#plant` line (read or not: see the feature
    /// `environment`).
    pub environment_declared: bool,
}

/// The colour index's default colours: a ramp from bark brown (0) through olive and greens to
/// light green (7), then flower and fruit colours. Index 0 is the turtle's starting colour, so
/// stems start brown and `'` steps them towards leaf green.
pub const DEFAULT_PALETTE: [[f32; 3]; 16] = [
    [0.40, 0.27, 0.15], // 0 bark brown
    [0.44, 0.34, 0.17], // 1 light bark
    [0.43, 0.42, 0.18], // 2 olive
    [0.36, 0.48, 0.16], // 3 green olive
    [0.27, 0.54, 0.15], // 4 green
    [0.20, 0.58, 0.16], // 5 leaf green
    [0.28, 0.66, 0.20], // 6 fresh green
    [0.48, 0.74, 0.28], // 7 light green
    [0.92, 0.80, 0.28], // 8 yellow
    [0.93, 0.55, 0.20], // 9 orange
    [0.90, 0.02, 0.02], // 10 signal red: saturated, far from every bark and leaf colour
    [0.90, 0.50, 0.65], // 11 pink
    [0.55, 0.28, 0.68], // 12 purple
    [0.30, 0.45, 0.85], // 13 blue
    [0.95, 0.95, 0.92], // 14 white
    [0.50, 0.50, 0.50], // 15 grey
];

/// The colour index of an organ (a polygon `{…}`, a predefined leaf `~l` or petal `~p`) drawn
/// while no `'` or `;` on the turtle's path has chosen a colour: leaf green, not the starting
/// bark brown of entry 0, so a leaf is green when the grammar says nothing about colours. A
/// grammar that sets entry 0 (`#color 0 …`, as imported colour maps do) has chosen its starting
/// colour, and its organs start with it as its segments do (cpfg's rule).
pub const ORGAN_COLOR: u16 = 5;

impl Settings {
    /// The value of a directive that takes one number (`#step`, `#angle`, …), as the settings
    /// hold it; 0 for the others.
    pub fn value(&self, directive: DirectiveKind) -> f64 {
        match directive {
            DirectiveKind::Angle => self.angle,
            DirectiveKind::Heading => self.heading,
            DirectiveKind::Step => self.step,
            DirectiveKind::Width => self.width,
            DirectiveKind::WidthStep => self.width_step,
            DirectiveKind::WidthUnit => self.width_unit.unwrap_or(0.0),
            DirectiveKind::Iterations => self.iterations as f64,
            DirectiveKind::Seed => self.seed as f64,
            DirectiveKind::MaxModules => self.max_modules as f64,
            DirectiveKind::MaxSteps => self.max_steps as f64,
            DirectiveKind::Dt => self.dt,
            _ => 0.0,
        }
    }

    /// The grammar has timed modules (`#terminal_age`, ABOP 6.1): it derives in continuous time.
    pub fn timed(&self) -> bool {
        !self.terminal_ages.is_empty()
    }

    /// The grammar declares its time step (`#dt`) and has no timed modules: the continuous-growth
    /// idiom of L-Py and cpfg, whose modules carry their age and change it at every step. Its
    /// plant at growth time t is its derivation's at step ⌊t⌋ (docs/LANGUAGE.md, "Growth in time"),
    /// not the whole plant's mesh grown in, which would show every organ at its final size.
    pub fn stepwise(&self) -> bool {
        self.dt_given && !self.timed()
    }
}

/// The default of a directive's `k`-th argument (in its longest form), from the vocabulary.
pub fn directive_default(kind: DirectiveKind, k: usize) -> f64 {
    kind.info()
        .params()
        .get(k)
        .and_then(|p| p.default_value(|_| 0.0))
        .unwrap_or(0.0)
}

/// The default of a directive that takes one value.
fn default_of(kind: DirectiveKind) -> f64 {
    directive_default(kind, 0)
}

impl Default for Settings {
    /// Every setting at the default its directive's row declares.
    fn default() -> Self {
        let tropism = |k| directive_default(DirectiveKind::Tropism, k);
        Settings {
            angle: default_of(DirectiveKind::Angle),
            width_given: false,
            heading: default_of(DirectiveKind::Heading),
            iterations: default_of(DirectiveKind::Iterations) as u32,
            seed: default_of(DirectiveKind::Seed) as u64,
            step: default_of(DirectiveKind::Step),
            width: default_of(DirectiveKind::Width),
            width_step: default_of(DirectiveKind::WidthStep),
            width_unit: None,
            tropism: (DVec3::new(tropism(0), tropism(1), tropism(2)), tropism(3)),
            max_modules: default_of(DirectiveKind::MaxModules) as usize,
            max_steps: default_of(DirectiveKind::MaxSteps) as u32,
            draw: Vec::new(),
            palette: DEFAULT_PALETTE.to_vec(),
            start_color_given: false,
            iterations_span: None,
            terminal_ages: Vec::new(),
            terminal_age_span: None,
            dt: default_of(DirectiveKind::Dt),
            dt_given: false,
            surfaces: Vec::new(),
            surfaces_declared: false,
            environment_declared: false,
        }
    }
}

/// `#lifetime MB VB [pu pm pl]`: MB and VB may use `NumIt` (the step about to run).
#[derive(Clone, Debug, PartialEq)]
pub struct Lifetime {
    pub mean: Program,
    pub variance: Program,
    /// The share of survivors given to the upper, middle and lower thirds.
    pub probabilities: [f64; 3],
}

/// `#speed SM VR [PFu PFm PFl]`: SM and VR may use `NumIt`.
#[derive(Clone, Debug, PartialEq)]
pub struct Speed {
    pub mean: Program,
    pub variance: Program,
    /// The positional factor PF of the upper, middle and lower thirds.
    pub positional: [f64; 3],
}

/// `#shape GR m [VR]`: segment lengths by age.
#[derive(Clone, Debug, PartialEq)]
pub struct Shape {
    pub rate: f64,
    pub maturity: u32,
    pub variance: f64,
}

/// `#shape_width [VR [PFu PFm PFl]]`: segment widths by age.
#[derive(Clone, Debug, PartialEq)]
pub struct ShapeWidth {
    pub variance: f64,
    pub positional: [f64; 3],
}

/// `#sun latitude season angle`.
#[derive(Clone, Debug, PartialEq)]
pub struct Sun {
    pub latitude: f64,
    pub season: Season,
    /// Degrees per step towards the sun (negative: away from it).
    pub angle: f64,
}

/// `#gravity angle [variation]` and `#wind x z angle [variation]`: every segment turns towards
/// `direction` by its own angle, `angle` + Round(Rand() × variation) degrees, at every step.
#[derive(Clone, Debug, PartialEq)]
pub struct Bend {
    pub direction: DVec3,
    pub angle: f64,
    pub variance: f64,
}

/// The particle attributes of a grammar (Jou, Park and Bahng; all off by default), and which
/// modules are apices and segments (docs/LANGUAGE.md, "Growth"). `growth` turns them into each
/// module's state and the turtle's adjustments.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GrowthAttributes {
    /// For each module id: an apex.
    pub apex: Vec<bool>,
    /// For each module id: a segment.
    pub segment: Vec<bool>,
    pub lifetime: Option<Lifetime>,
    pub speed: Option<Speed>,
    pub shape: Option<Shape>,
    pub shape_width: Option<ShapeWidth>,
    pub sun: Option<Sun>,
    pub gravity: Option<Bend>,
    pub wind: Option<Bend>,
}

impl GrowthAttributes {
    /// True when any attribute is on.
    pub fn is_active(&self) -> bool {
        self.lifetime.is_some()
            || self.speed.is_some()
            || self.shape.is_some()
            || self.shape_width.is_some()
            || self.sun.is_some()
            || self.gravity.is_some()
            || self.wind.is_some()
    }

    /// True when a step needs to know where the modules stand (their thirds).
    pub fn needs_heights(&self) -> bool {
        self.lifetime.is_some() || self.speed.is_some() || self.sun.is_some()
    }

    pub fn is_apex(&self, id: ModuleId) -> bool {
        self.apex.get(id.index()).copied().unwrap_or(false)
    }

    pub fn is_segment(&self, id: ModuleId) -> bool {
        self.segment.get(id.index()).copied().unwrap_or(false)
    }
}

#[cfg(test)]
mod tests {
    use super::DEFAULT_PALETTE;
    use crate::maths;

    /// sRGB (0..=255) of a linear colour, as the studio and the writers show it.
    fn srgb(c: [f32; 3]) -> [f64; 3] {
        c.map(|v| {
            let v = f64::from(v);
            255.0
                * if v <= 0.003_130_8 {
                    12.92 * v
                } else {
                    1.055 * maths::powf(v, 1.0 / 2.4) - 0.055
                }
        })
    }

    #[test]
    fn the_signal_red_stands_out_from_the_barks_and_greens() {
        // ABOP 1.30 draws its signal in colour 10 beside bark-brown internodes (colour 0).
        let red = srgb(DEFAULT_PALETTE[10]);
        assert!(
            red[0] > 200.0 && red[1] < 0.3 * red[0] && red[2] < 0.3 * red[0],
            "{red:?}"
        );
        for other in &DEFAULT_PALETTE[..8] {
            let o = srgb(*other);
            let distance: f64 = red.iter().zip(o).map(|(a, b)| (a - b).abs()).sum();
            assert!(
                distance > 180.0,
                "{other:?} is {distance} from the signal red"
            );
        }
    }
}

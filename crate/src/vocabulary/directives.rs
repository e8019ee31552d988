//! The directives: `#name arguments` lines, each with the forms its arguments may take.

use super::params::{text, Param, ParamKind};
use serde::{Serialize, Serializer};

/// Every directive. `#colour` is another spelling of [`DirectiveKind::Color`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DirectiveKind {
    Angle,
    Heading,
    Iterations,
    Step,
    Width,
    WidthStep,
    WidthUnit,
    Tropism,
    Color,
    Seed,
    Define,
    Random,
    Curve,
    Table,
    Ignore,
    Consider,
    Module,
    Draw,
    MaxModules,
    MaxSteps,
    HomomorphismDepth,
    DecompositionDepth,
    Apex,
    Lifetime,
    Speed,
    Shape,
    ShapeWidth,
    Sun,
    Gravity,
    Wind,
    TerminalAge,
    Dt,
    Surface,
    Patch,
    Environment,
    Stand,
    Plant,
}

impl DirectiveKind {
    /// Its row (the first, for `#color`).
    pub fn info(self) -> &'static DirectiveInfo {
        directive(self)
    }

    /// Its name without `#` (`angle`).
    pub fn name(self) -> &'static str {
        self.info().name
    }

    /// As written in a grammar, `#angle`.
    pub fn written(self) -> String {
        format!("#{}", self.name())
    }
}

impl Serialize for DirectiveKind {
    /// The kind's identifier (`Angle`, `ShapeWidth`): what code refers to a directive by, so that
    /// its spelling lives only in the table.
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(&format!("{self:?}"))
    }
}

/// A season of `#sun`: the sun's noon altitude is 23.5° higher in summer, 23.5° lower in winter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Season {
    Summer,
    Equinox,
    Winter,
}

/// The season names `#sun` accepts, with the season each means.
const SEASONS: [(&str, Season); 6] = [
    ("summer", Season::Summer),
    ("spring", Season::Equinox),
    ("autumn", Season::Equinox),
    ("winter", Season::Winter),
    ("fall", Season::Equinox),
    ("equinox", Season::Equinox),
];

impl Season {
    /// `summer`, `winter`, and `spring`, `autumn`, `fall` or `equinox` for the equinox, in any case.
    pub fn named(name: &str) -> Option<Season> {
        SEASONS
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|&(_, s)| s)
    }
}

/// Which part of the language a directive belongs to (for the reference and the studio's panels).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum DirectiveGroup {
    Turtle,
    Derivation,
    Names,
    Limits,
    Growth,
}

/// One row of the directive table.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct DirectiveInfo {
    /// The name without `#`.
    pub name: &'static str,
    pub kind: DirectiveKind,
    /// A few words for a field or switch in the studio (`Lifetime`, `Length by age`).
    pub label: &'static str,
    /// The argument lists it accepts, shortest first; each shorter form is the start of the
    /// longer ones, except `#color`'s (`index r g b` or `first last r g b r g b`).
    pub forms: &'static [&'static [Param]],
    /// What the arguments mean, for messages about their number.
    #[serde(skip)]
    pub usage: &'static str,
    /// The diagnostic code when the number of arguments is wrong.
    #[serde(skip)]
    pub count_code: &'static str,
    /// True when it may be written several times (each adds to the others).
    pub repeatable: bool,
    pub group: DirectiveGroup,
    /// The arguments the studio writes when the directive is switched on (the Growth panel).
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    pub enable: &'static [&'static str],
    pub doc: &'static str,
}

impl DirectiveInfo {
    /// The longest argument list.
    pub fn params(&self) -> &'static [Param] {
        self.forms
            .iter()
            .max_by_key(|f| f.len())
            .copied()
            .unwrap_or(&[])
    }

    /// The argument lists as written in docs and messages: `'MB VB' or 'MB VB pu pm pl'`.
    pub fn forms_text(&self) -> String {
        let form = |f: &[Param]| {
            let names: Vec<&str> = f.iter().map(|p| p.name).collect();
            format!("'{}'", names.join(" "))
        };
        let forms: Vec<String> = self
            .forms
            .iter()
            .filter(|f| !f.is_empty())
            .map(|f| form(f))
            .collect();
        let mut text = forms.join(" or ");
        if self.forms.iter().any(|f| f.is_empty()) {
            text = format!("nothing, {}", forms.join(" or "));
        }
        text
    }

    /// True when its arguments are one value written as a whole (spaces allowed: `#angle 360 / n`).
    pub fn takes_one_value(&self) -> bool {
        matches!(self.forms, [[p]] if matches!(p.kind, ParamKind::Number | ParamKind::Whole))
    }
}

const fn row(
    name: &'static str,
    kind: DirectiveKind,
    label: &'static str,
    forms: &'static [&'static [Param]],
    group: DirectiveGroup,
    doc: &'static str,
) -> DirectiveInfo {
    DirectiveInfo {
        name,
        kind,
        label: text(label),
        forms,
        usage: "",
        count_code: "E0209",
        repeatable: false,
        group,
        enable: &[],
        doc: text(doc),
    }
}

impl DirectiveInfo {
    const fn repeatable(mut self) -> DirectiveInfo {
        self.repeatable = true;
        self
    }

    const fn usage(mut self, code: &'static str, usage: &'static str) -> DirectiveInfo {
        self.count_code = code;
        self.usage = usage;
        self
    }

    const fn enable(mut self, args: &'static [&'static str]) -> DirectiveInfo {
        self.enable = args;
        self
    }
}

const MODULE_LIST: &[&[Param]] = &[&[Param::new("modules", ParamKind::Modules, "module names")]];
const DEFINE: &[&[Param]] = &[&[
    Param::new("name", ParamKind::Name, "the constant's name"),
    Param::new("expression", ParamKind::Expression, "its value"),
]];
const RANDOM: &[&[Param]] = &[&[
    Param::new("name", ParamKind::Name, "the variable's name"),
    Param::new(
        "distribution",
        ParamKind::Expression,
        "a random function such as uniform(0, 1)",
    ),
]];
const CURVE: &[&[Param]] = &[&function_of_points(
    "control points x y, at least 4, x from the first to the last",
)];
const TABLE: &[&[Param]] = &[&function_of_points("points x y, at least 2, x increasing")];

/// The arguments of `#curve` and `#table`, which both define a function of x by points: its name,
/// then the points.
const fn function_of_points(points: &'static str) -> [Param; 2] {
    [
        Param::new("name", ParamKind::Name, "the function's name"),
        Param::new("points", ParamKind::Points, points),
    ]
}
const SURFACE: &[&[Param]] = &[&[
    Param::new("X", ParamKind::Name, "the surface's letter: ~X draws it"),
    Param::new(
        "shape",
        ParamKind::Surface,
        "a shape of the library, then frame words: contact x y z, heading x y z, up x y z, end x y z, size s, scale s, precision s t",
    ),
]];
const PATCH: &[&[Param]] = &[&[
    Param::new("X", ParamKind::Name, "the surface's letter: ~X draws it"),
    Param::new(
        "points",
        ParamKind::Points,
        "16 control points x y z, row by row of the 4 × 4 grid, separated by commas; then, if wanted, color top [bottom]: the patch's colour indices (0: the turtle's)",
    ),
]];
const ENVIRONMENT: &[&[Param]] = &[&[Param::new(
    "program",
    ParamKind::Words,
    "a program (light, obstacle, space, attractors), a shape if it takes one (box, sphere, plane), then setting words with their numbers",
)]];
const STAND: &[&[Param]] = &[&[Param::new(
    "layout",
    ParamKind::Words,
    "row N spacing D, grid NX NZ spacing D, or random N size W D [seed S] [spacing MIN]",
)]];
const PLANT: &[&[Param]] = &[&[
    Param::number("x", "x of the plant's base"),
    Param::number("y", "y of the plant's base"),
    Param::number("z", "z of the plant's base"),
]];
const TERMINAL_AGES: &[&[Param]] = &[&[Param::new(
    "ages",
    ParamKind::Ages,
    "pairs of a module name and its terminal age: a_r 2 b_r 1",
)]];
const DEPTH: &[&[Param]] = &[&[Param::whole("n", 0.0, 10_000.0, "the depth").default(16.0)]];
const U32_MAX: f64 = u32::MAX as f64;

// Parameters of the growth directives: the paper's names (`MB`, `PFu`) with a label and a doc a
// student reads in the Growth panel.
const fn thirds(what: &'static [&'static str; 3], defaults: [f64; 3]) -> [Param; 3] {
    [
        Param::number("PFu", what[0])
            .label("upper third")
            .default(defaults[0]),
        Param::number("PFm", what[1])
            .label("middle third")
            .default(defaults[1]),
        Param::number("PFl", what[2])
            .label("lower third")
            .default(defaults[2]),
    ]
}
const PF_SPEED: [Param; 3] = thirds(
    &[
        "The rewritings per step of a growing tip in the upper third of the plant, before SM and VR (its positional factor).",
        "The rewritings per step of a growing tip in the middle third, before SM and VR (its positional factor).",
        "The rewritings per step of a growing tip in the lower third, before SM and VR (its positional factor).",
    ],
    [2.0, 1.0, 1.0],
);
const PF_WIDTH: [Param; 3] = thirds(
    &[
        "Added to the age of a segment in the upper third to give how many times as wide it is.",
        "Added to the age of a segment in the middle third to give how many times as wide it is.",
        "Added to the age of a segment in the lower third to give how many times as wide it is.",
    ],
    [2.0, 1.0, 0.0],
);
/// A random addition, `Round(Rand() × name)`.
const fn random_more(name: &'static str, doc: &'static str) -> Param {
    Param::new(name, ParamKind::StepExpression, doc).label("+ random")
}
const LIFETIME: [Param; 5] = [
    Param::new(
        "MB",
        ParamKind::StepExpression,
        "How many branch tips keep growing at each step, at least; the others stop for good.",
    )
    .label("at least"),
    random_more(
        "VB",
        "Up to this many more tips keep growing, drawn at random at each step: Round(Rand() × VB).",
    ),
    Param::number(
        "pu",
        "The share of the growing tips that are in the upper third of the plant's height.",
    )
    .label("upper third")
    .default(0.6),
    Param::number(
        "pm",
        "The share of the growing tips that are in the middle third.",
    )
    .label("middle third")
    .default(0.3),
    Param::number(
        "pl",
        "The share of the growing tips that are in the lower third.",
    )
    .label("lower third")
    .default(0.1),
];
const SPEED: [Param; 5] = [
    Param::new(
        "SM",
        ParamKind::StepExpression,
        "Rewritings per step added for every growing tip, on top of its third's factor (negative: slower).",
    )
    .label("extra rewritings"),
    random_more(
        "VR",
        "Up to this many more rewritings, drawn at random for each tip at each step: Round(Rand() × VR).",
    ),
    PF_SPEED[0],
    PF_SPEED[1],
    PF_SPEED[2],
];
const SHAPE: [Param; 3] = [
    Param::number(
        "GR",
        "How fast young segments lengthen: a segment of age i is GR^i times as long (above 0, not 1).",
    )
    .label("growth rate"),
    Param::whole(
        "m",
        0.0,
        1_000.0,
        "The age from which segments only lengthen slowly (logarithmically).",
    )
    .label("mature at")
    .unit("steps"),
    Param::number(
        "VR",
        "Each segment's length differs by up to this much, either way, drawn at random: ± Round(Rand() × VR).",
    )
    .label("± random")
    .default(0.0),
];
const SHAPE_WIDTH: [Param; 4] = [
    Param::number(
        "VR",
        "Each segment is up to this much wider, drawn at random: Round(Rand() × VR).",
    )
    .label("+ random")
    .default(0.0),
    PF_WIDTH[0],
    PF_WIDTH[1],
    PF_WIDTH[2],
];
const SUN: [Param; 3] = [
    Param::number(
        "latitude",
        "Where the plant grows, in degrees north (negative: south): how high the noon sun stands.",
    )
    .label("latitude")
    .range(-90.0, 90.0)
    .unit("degrees"),
    Param::new(
        "season",
        ParamKind::Season,
        "The season: the noon sun stands 23.5° higher in summer and 23.5° lower in winter than at the equinoxes.",
    )
    .label("season")
    .choices(&["summer", "spring", "autumn", "winter", "fall", "equinox"]),
    Param::number(
        "angle",
        "How many degrees the upper and middle segments turn towards the sun at each step.",
    )
    .label("turn per step")
    .unit("degrees"),
];
/// The random part of a bend, `Round(Rand() × variation)` degrees, drawn for each segment.
const BEND_VARIATION: Param = Param::number(
    "variation",
    "Up to this many more degrees, drawn at random for each segment: Round(Rand() × variation).",
)
.label("+ random")
.default(0.0)
.unit("degrees");
const GRAVITY: [Param; 2] = [
    Param::number(
        "angle",
        "How many degrees every segment turns down at each step.",
    )
    .label("turn per step")
    .unit("degrees"),
    BEND_VARIATION,
];
const WIND: [Param; 4] = [
    Param::number("x", "The wind blows towards (x, 0, z): its x part.").label("towards x"),
    Param::number("z", "The wind blows towards (x, 0, z): its z part.").label("towards z"),
    Param::number(
        "angle",
        "How many degrees every segment turns with the wind at each step.",
    )
    .label("turn per step")
    .unit("degrees"),
    BEND_VARIATION,
];
const APICES: &[&[Param]] = &[&[Param::new(
    "modules",
    ParamKind::Modules,
    "The modules that are branch tips (apices), separated by spaces.",
)
.label("tip modules")]];
const COLOR: &[&[Param]] = &[
    &[
        Param::number("index", "the palette entry (a whole number)").range(0.0, 255.0),
        Param::number("r", "red").range(0.0, 255.0),
        Param::number("g", "green").range(0.0, 255.0),
        Param::number("b", "blue").range(0.0, 255.0),
    ],
    &[
        Param::number(
            "first",
            "the first palette entry of the ramp (a whole number)",
        )
        .range(0.0, 255.0),
        Param::number(
            "last",
            "the last palette entry of the ramp (a whole number)",
        )
        .range(0.0, 255.0),
        Param::number("r", "red of the first entry").range(0.0, 255.0),
        Param::number("g", "green of the first entry").range(0.0, 255.0),
        Param::number("b", "blue of the first entry").range(0.0, 255.0),
        Param::number("r", "red of the last entry").range(0.0, 255.0),
        Param::number("g", "green of the last entry").range(0.0, 255.0),
        Param::number("b", "blue of the last entry").range(0.0, 255.0),
    ],
];
const COLOR_USAGE: &str = "(indices 0 to 255, components 0 to 255)";

use DirectiveGroup as G;
use DirectiveKind as D;

/// Every directive, in the order of docs/LANGUAGE.md.
#[rustfmt::skip]
pub const DIRECTIVES: &[DirectiveInfo] = &[
    row("angle", D::Angle, "Angle", &[&[Param::number("degrees", "the turn angle δ").default(90.0).unit("degrees")]], G::Turtle,
        "The default turn angle δ of + - & ^ \\ / (default 90)."),
    row("heading", D::Heading, "Heading", &[&[Param::number("degrees", "the turn of the starting heading").default(0.0).unit("degrees")]], G::Turtle,
        "Turns the turtle's starting heading by this many degrees, as + would: 90 starts to the left, -90 to the right (default 0: up)."),
    row("iterations", D::Iterations, "Iterations", &[&[Param::whole("n", 0.0, U32_MAX, "derivation steps").default(0.0)]], G::Derivation,
        "The number of derivation steps (default 0)."),
    row("step", D::Step, "Step", &[&[Param::number("length", "the length of F, f, G and g").default(1.0).unit("units")]], G::Turtle,
        "The default length of F, f, G and g (default 1)."),
    row("width", D::Width, "Width", &[&[Param::number("w", "the initial width").default(1.0).unit("width units")]], G::Turtle,
        "The initial segment width, in width units (default 1)."),
    row("width_step", D::WidthStep, "Width step", &[&[Param::number("d", "how much ! narrows").default(0.1).unit("width units")]], G::Turtle,
        "How much ! without a parameter decreases the width (default 0.1)."),
    row("width_unit", D::WidthUnit, "Width unit", &[&[Param::number("u", "model units per width unit").unit("units")]], G::Turtle,
        "Widths in the model's own units, as cpfg draws cylinders: a width w is a diameter of w·u units (#width_unit 1: !(w) is the diameter). Without it, one width unit is 1/300 of the plant's diagonal."),
    row("tropism", D::Tropism, "Tropism", &[&[
            Param::number("x", "tropism vector, x").default(0.0),
            Param::number("y", "tropism vector, y").default(-1.0),
            Param::number("z", "tropism vector, z").default(0.0),
            Param::number("e", "susceptibility").default(0.0),
        ]], G::Turtle,
        "The tropism vector T and susceptibility e (ABOP 2.3; default 0 -1 0 0).")
        .usage("E0207", ""),
    row("color", D::Color, "Colour", COLOR, G::Turtle,
        "Set a palette entry, or a ramp of entries (components 0 to 255).")
        .usage("E0208", COLOR_USAGE).repeatable(),
    row("colour", D::Color, "Colour", COLOR, G::Turtle, "The same as #color.")
        .usage("E0208", COLOR_USAGE).repeatable(),
    row("seed", D::Seed, "Seed", &[&[Param::whole("n", 0.0, u64::MAX as f64, "the seed").default(1.0)]], G::Derivation,
        "The seed of the random generator (default 1)."),
    row("define", D::Define, "Constant", DEFINE, G::Names,
        "A named constant or expression, inlined where it is used.").repeatable(),
    row("random", D::Random, "Random variable", RANDOM, G::Names,
        "A random variable (Green): one deviate per module while matching.").repeatable(),
    row("curve", D::Curve, "Curve function", CURVE, G::Names,
        "A function of one variable, name(x): the smooth curve of these control points (cpfg's function: a cubic B-spline), read at x.").repeatable(),
    row("table", D::Table, "Table function", TABLE, G::Names,
        "A function of one variable, name(x): straight lines between these points, level beyond the first and the last.").repeatable(),
    row("ignore", D::Ignore, "Ignored modules", MODULE_LIST, G::Derivation,
        "Modules that context matching skips.").repeatable(),
    row("consider", D::Consider, "Considered modules", MODULE_LIST, G::Derivation,
        "The only modules context matching sees (not with #ignore)."),
    row("module", D::Module, "Module names", MODULE_LIST, G::Names,
        "Declare multi-letter module names.").repeatable(),
    row("draw", D::Draw, "Drawn modules", MODULE_LIST, G::Turtle,
        "Further modules that draw a segment like F.").repeatable(),
    row("terminal_age", D::TerminalAge, "Terminal ages", TERMINAL_AGES, G::Derivation,
        "Timed modules (ABOP 6.1) and their terminal ages: a timed module carries its age as its first parameter and is replaced when the age reaches the terminal age.")
        .usage("E0211", "(pairs of a module name and a terminal age from 0.000001 up)").repeatable(),
    row("dt", D::Dt, "Time step", &[&[Param::number("dt", "the time one derivation step covers").default(1.0).unit("time units")]], G::Derivation,
        "The time one derivation step covers (default 1): a timed grammar at step n shows time n·dt; expressions read it as dt."),
    row("surface", D::Surface, "Surface", SURFACE, G::Turtle,
        "Declares what ~X draws: a shape of the organ library (leaf, petal, sepal, disk, ray_floret), and the frame of its #patch points as a cpfg .s file gives it.")
        .usage("E0221", "(a letter, then a shape of the library and frame words with their numbers)").repeatable(),
    row("patch", D::Patch, "Bézier patch", PATCH, G::Turtle,
        "One bicubic Bézier patch of the surface ~X: 16 control points x y z, row by row, then optionally color top [bottom] (colour indices as ;(n) sets them, 0 the turtle's); several lines make a surface of several patches.")
        .usage("E0220", "(a letter, then 16 points x y z, then optionally color and one or two colour indices)").repeatable(),
    row("environment", D::Environment, "Environment program", ENVIRONMENT, G::Derivation,
        "An environmental program that answers the communication modules ?E between derivation steps: light, obstacle, space or attractors, its shape, and its settings.")
        .usage("E0230", text("(a program, a shape if it takes one, then setting words with their numbers)")).repeatable(),
    row("stand", D::Stand, "Stand of plants", STAND, G::Derivation,
        "Plants the grammar N times sharing one environment, each with its own seed: in a row, a grid, or at random places.")
        .usage("E0233", text("(row N spacing D, grid NX NZ spacing D, or random N size W D [seed S] [spacing MIN])")).repeatable(),
    row("plant", D::Plant, "Plant at", PLANT, G::Derivation,
        "One more plant of the stand, its base at x y z; several lines plant several.")
        .usage("E0234", text("(the base's x y z)")).repeatable(),
    row("max_modules", D::MaxModules, "Module limit", &[&[Param::whole("n", 0.0, U32_MAX, "modules at most").default(5_000_000.0)]], G::Limits,
        "Stop with an error when the string would grow past n modules (default 5,000,000)."),
    row("max_steps", D::MaxSteps, "Step limit", &[&[Param::whole("n", 0.0, U32_MAX, "steps at most").default(10_000.0)]], G::Limits,
        "The largest number of derivation steps a build may run (default 10,000)."),
    row("homomorphism_depth", D::HomomorphismDepth, "Homomorphism depth", DEPTH, G::Limits,
        "The maximum depth of homomorphism rules (default 16)."),
    row("decomposition_depth", D::DecompositionDepth, "Decomposition depth", DEPTH, G::Limits,
        "The maximum depth of decomposition rules (default 16)."),
    row("lifetime", D::Lifetime, "Lifetime of tips", &[&[LIFETIME[0], LIFETIME[1]], &LIFETIME], G::Growth,
        "Growth: only some branch tips (apices) keep growing at each step, MB + Round(Rand()·VB) of them, shared by the upper, middle and lower thirds (default 0.6 0.3 0.1); the others stop for good.")
        .usage("E0209", "(the mean and variance of the surviving branches, then the shares of the upper, middle and lower thirds)")
        .enable(&["34", "32"]),
    row("speed", D::Speed, "Growth speed", &[&[SPEED[0], SPEED[1]], &SPEED], G::Growth,
        "Growth: each growing tip is rewritten PF + SM + Round(Rand()·VR) times per step, PF by the third it is in (default 2 1 1: the top grows fastest).")
        .usage("E0209", "(the seasonal mean and variance of the rewritings, then the positional factors of the thirds)")
        .enable(&["0", "1"]),
    row("shape", D::Shape, "Length by age", &[&[SHAPE[0], SHAPE[1]], &SHAPE], G::Growth,
        "Growth: segments lengthen with age, GR^i times as long at age i up to maturity m, then slowly: log_GR(i) − log_GR(m) + GR^m, ± Round(Rand()·VR).")
        .usage("E0209", ": a growth rate above 0 other than 1, a maturity from 1 and the variance of the length")
        .enable(&["1.5", "3"]),
    row("shape_width", D::ShapeWidth, "Width by age", &[&[], &[SHAPE_WIDTH[0]], &SHAPE_WIDTH], G::Growth,
        "Growth: segments thicken with age, i + PF + Round(Rand()·VR) times as wide at age i, PF by the third they are in (default 2 1 0).")
        .usage("E0209", "(the variance of the width, then the positional factors of the thirds)")
        .enable(&["1"]),
    row("sun", D::Sun, "Sun", &[&SUN], G::Growth,
        "Growth: upper and middle segments turn towards the noon sun (+X side) by angle degrees per step; season summer, equinox or winter.")
        .usage("E0209", ": a latitude from -90 to 90, a season (summer, winter, spring, autumn, fall or equinox) and the degrees per step")
        .enable(&["38", "summer", "2"]),
    row("gravity", D::Gravity, "Gravity", &[&[GRAVITY[0]], &GRAVITY], G::Growth,
        "Growth: every segment bends down by angle + Round(Rand()·variation) degrees per step.")
        .usage("E0209", ": the degrees per step")
        .enable(&["5", "3"]),
    row("wind", D::Wind, "Wind", &[&[WIND[0], WIND[1], WIND[2]], &WIND], G::Growth,
        "Growth: every segment bends towards the horizontal direction (x, 0, z) by angle + Round(Rand()·variation) degrees per step.")
        .usage("E0209", ": a horizontal direction other than 0 0, and the degrees per step")
        .enable(&["1", "0", "2"]),
    row("apex", D::Apex, "Branch tips", APICES, G::Growth,
        "Growth: the modules that are branch tips, the apices that lifetime and speed act on (default: modules with productions that are not turtle commands).")
        .repeatable().enable(&["A"]),
];

/// The row of `kind` (the first of its spellings).
pub fn directive(kind: DirectiveKind) -> &'static DirectiveInfo {
    DIRECTIVES
        .iter()
        .find(|d| d.kind == kind)
        .unwrap_or(&DIRECTIVES[0])
}

/// The row of a directive name (without `#`).
pub fn directive_named(name: &str) -> Option<&'static DirectiveInfo> {
    DIRECTIVES.iter().find(|d| d.name == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_has_a_row_and_forms_grow() {
        for d in DIRECTIVES {
            assert_eq!(directive(d.kind).kind, d.kind);
            assert!(!d.forms.is_empty(), "#{}", d.name);
            if d.kind != DirectiveKind::Color {
                for pair in d.forms.windows(2) {
                    assert!(pair[0].len() < pair[1].len(), "#{}", d.name);
                    assert!(
                        pair[1].starts_with(pair[0]),
                        "#{}: a shorter form starts the longer",
                        d.name
                    );
                }
            }
        }
        assert_eq!(
            directive_named("colour").map(|d| d.kind),
            Some(DirectiveKind::Color)
        );
        assert_eq!(DirectiveKind::Color.name(), "color");
    }

    #[test]
    fn seasons_are_read_in_any_case() {
        assert_eq!(Season::named("Spring"), Some(Season::Equinox));
        assert_eq!(Season::named("monsoon"), None);
        let choices = DirectiveKind::Sun.info().params()[1].choices;
        assert!(choices.iter().all(|c| Season::named(c).is_some()));
        assert_eq!(choices.len(), SEASONS.len());
    }

    #[test]
    fn every_field_of_the_growth_panel_has_a_label_and_a_sentence() {
        for d in DIRECTIVES
            .iter()
            .filter(|d| d.group == DirectiveGroup::Growth)
        {
            for p in d.params() {
                assert!(!p.label.is_empty(), "#{} {}", d.name, p.name);
                assert!(p.doc.ends_with('.'), "#{} {}: a sentence", d.name, p.name);
            }
        }
    }

    #[test]
    fn forms_are_written_for_messages() {
        assert_eq!(
            DirectiveKind::Lifetime.info().forms_text(),
            "'MB VB' or 'MB VB pu pm pl'"
        );
        assert_eq!(
            DirectiveKind::ShapeWidth.info().forms_text(),
            "nothing, 'VR' or 'VR PFu PFm PFl'"
        );
    }
}

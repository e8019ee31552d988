//! The modules with a meaning: turtle commands, cut and Green's control modules.

use super::params::{text, Param, ParamKind};
use super::DirectiveKind;
use serde::{Serialize, Serializer};

/// What the turtle does when it reads a module (serialized as the variant's identifier).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Command {
    /// `F`: move forward and draw a segment (records a polygon vertex inside `{ }`).
    Forward,
    /// `f`: move forward without drawing (records a polygon vertex inside `{ }`).
    Move,
    /// `G`: draw forward without recording a polygon vertex.
    ForwardNoVertex,
    /// `g`: move forward without drawing or recording a polygon vertex.
    MoveNoVertex,
    TurnLeft,
    TurnRight,
    PitchDown,
    PitchUp,
    RollLeft,
    RollRight,
    TurnAround,
    /// `$`, `@v`: roll so that L is horizontal.
    RollToVertical,
    Push,
    Pop,
    StartPolygon,
    PolygonVertex,
    EndPolygon,
    /// `!`: decrease the width, or set it.
    Width,
    /// `'`: next colour index (or add the parameter).
    NextColor,
    /// `;`: set the colour index (or next, without a parameter).
    SetColor,
    Leaf,
    Petal,
    /// `~X`: the surface declared for the letter X (`#surface`, `#patch`).
    Surface,
    Sphere,
    MoveTo,
    /// `@LineTo`: draw a segment to a point; the frame is unchanged.
    LineTo,
    /// `@LineRel`: draw a segment by a vector; the frame is unchanged.
    LineRel,
    /// `@OLineTo`: draw a segment to a point, turning H along it.
    OrientedLineTo,
    /// `@OLineRel`: draw a segment by a vector, turning H along it.
    OrientedLineRel,
    /// `@R`: set the heading, and the up vector when given.
    SetHeading,
    /// `@Frame`: draw the turtle's frame, H, L and U, as three segments.
    Frame,
    TropismVector,
    TropismStrength,
    StartSmooth,
    EndSmooth,
    QueryPosition,
    QueryHeading,
    QueryUp,
    QueryLeft,
    /// `?E`: a communication module, answered by the environment's programs between steps
    /// (docs/LANGUAGE.md, "Environment"); the turtle draws nothing for it.
    QueryEnvironment,
}

impl Command {
    /// True for the query modules (`?P ?H ?U ?L`): derivation writes the turtle's reading into
    /// their parameters after every step.
    pub fn is_query(self) -> bool {
        matches!(
            self,
            Command::QueryPosition | Command::QueryHeading | Command::QueryUp | Command::QueryLeft
        )
    }

    /// True for L-Py's commands that place the turtle by coordinates or draw its frame (the
    /// feature `placing`; [`PLACING`] names them).
    pub fn places_by_coordinates(self) -> bool {
        matches!(
            self,
            Command::LineTo
                | Command::LineRel
                | Command::OrientedLineTo
                | Command::OrientedLineRel
                | Command::SetHeading
                | Command::Frame
        )
    }

    /// True for the moves that draw a segment (`F`, `G`).
    pub fn draws(self) -> bool {
        matches!(self, Command::Forward | Command::ForwardNoVertex)
    }
}

/// Green's control modules: their parentheses hold modules, not expressions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GroupKind {
    Switch,
    Pendulum,
    Repeat,
}

/// What a module means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Meaning {
    /// The turtle reads it.
    Turtle(Command),
    /// Cut: after each step the rest of its branch is removed.
    Cut,
    /// A control module, acting during derivation.
    Group(GroupKind),
}

impl Serialize for Meaning {
    /// The identifier of what the module means: its turtle command (`Forward`, `Push`), `Cut`, or
    /// its control module (`Switch`, `Pendulum`, `Repeat`).
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Meaning::Turtle(c) => c.serialize(serializer),
            Meaning::Cut => serializer.serialize_str("Cut"),
            Meaning::Group(g) => serializer.serialize_str(&format!("{g:?}")),
        }
    }
}

/// Groups of modules, for the editor's colours and the reference page.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Category {
    Move,
    Rotate,
    Branch,
    Polygon,
    Appearance,
    Surface,
    Tropism,
    Query,
    Derivation,
}

/// One row of the module table.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ModuleInfo {
    /// The module's name as written (`F`, `+`, `@O`, `?P`, `~l`).
    pub name: &'static str,
    pub meaning: Meaning,
    /// Its parameters, all optional: a parameter left out takes its default (or, without one,
    /// what the doc says).
    pub params: &'static [Param],
    pub doc: &'static str,
    pub category: Category,
}

impl ModuleInfo {
    /// The turtle command, for modules the turtle reads.
    pub fn command(&self) -> Option<Command> {
        match self.meaning {
            Meaning::Turtle(c) => Some(c),
            _ => None,
        }
    }
}

const fn row(
    name: &'static str,
    meaning: Meaning,
    params: &'static [Param],
    doc: &'static str,
    category: Category,
) -> ModuleInfo {
    ModuleInfo {
        name,
        meaning,
        params,
        doc: text(doc),
        category,
    }
}

const LENGTH: &[Param] = &[Param::number("l", "the distance moved")
    .default_from(DirectiveKind::Step)
    .unit("units")];
const ANGLE: &[Param] = &[Param::number("a", "the angle turned")
    .default_from(DirectiveKind::Angle)
    .unit("degrees")];
const POINT: &[Param] = &[
    Param::number("x", "x coordinate"),
    Param::number("y", "y coordinate"),
    Param::number("z", "z coordinate"),
];
/// The width after a line to a point (`@LineTo`'s fourth parameter).
#[cfg(any(feature = "placing", not(target_arch = "wasm32")))]
const WIDTH_AFTER: Param = Param::number(
    "w",
    "the width from the segment's end on; without it, the width stays",
)
.unit("width units");
#[cfg(any(feature = "placing", not(target_arch = "wasm32")))]
const LINE: &[Param] = &[POINT[0], POINT[1], POINT[2], WIDTH_AFTER];
#[cfg(any(feature = "placing", not(target_arch = "wasm32")))]
const LINE_BY: &[Param] = &[VECTOR[0], VECTOR[1], VECTOR[2], WIDTH_AFTER];
#[cfg(any(feature = "placing", not(target_arch = "wasm32")))]
const HEADING_UP: &[Param] = &[
    Param::number("hx", "the heading's x component"),
    Param::number("hy", "the heading's y component"),
    Param::number("hz", "the heading's z component"),
    Param::number(
        "ux",
        "the up vector's x component; without the up vector, the frame turns the least way",
    ),
    Param::number("uy", "the up vector's y component"),
    Param::number("uz", "the up vector's z component"),
];
const VECTOR: &[Param] = &[
    Param::number("x", "x component"),
    Param::number("y", "y component"),
    Param::number("z", "z component"),
];
const QUERIED: &[Param] = &[
    Param::number("x", "x, set by the turtle"),
    Param::number("y", "y, set by the turtle"),
    Param::number("z", "z, set by the turtle"),
];
const SCALE: &[Param] = &[Param::number("s", "the length of the surface").default(1.0)];
const SURFACE_SCALES: &[Param] = &[
    Param::number("s", "the scale; with sy and sz, the scale along L").default(1.0),
    Param::number("sy", "the scale along H"),
    Param::number("sz", "the scale along U"),
];

use Category as K;
use Command as C;
use Meaning::Turtle;

/// The names of the commands [`Command::places_by_coordinates`] is true for. The first plant's
/// core (wasm32 without the feature `placing`) has no rows for them, so that its first load
/// carries none of their tables: it reads them as modules without a meaning, and tells the build
/// worker by these names that the studio core must build the grammar.
pub const PLACING: &str = "@LineTo @LineRel @OLineTo @OLineRel @R @Frame";

/// Every module of LANGUAGE.md section 6 and the derivation-time modules of sections 6 and 7.
#[rustfmt::skip]
pub const MODULES: &[ModuleInfo] = &[
    row("F", Turtle(C::Forward), LENGTH, "Move forward by l and draw a segment.", K::Move),
    row("f", Turtle(C::Move), LENGTH, "Move forward by l without drawing.", K::Move),
    row("G", Turtle(C::ForwardNoVertex), LENGTH, "Draw forward by l without recording a polygon vertex.", K::Move),
    row("g", Turtle(C::MoveNoVertex), LENGTH, "Move forward by l without drawing or recording a polygon vertex.", K::Move),
    row("@M", Turtle(C::MoveTo), POINT, "Move to the point (x, y, z) without drawing.", K::Move),
    #[cfg(any(feature = "placing", not(target_arch = "wasm32")))]
    row("@LineTo", Turtle(C::LineTo), LINE, "Draw a segment from the turtle to the point (x, y, z); H, L and U do not turn.", K::Move),
    #[cfg(any(feature = "placing", not(target_arch = "wasm32")))]
    row("@LineRel", Turtle(C::LineRel), LINE_BY, "Draw a segment from the turtle by the vector (x, y, z); H, L and U do not turn.", K::Move),
    #[cfg(any(feature = "placing", not(target_arch = "wasm32")))]
    row("@OLineTo", Turtle(C::OrientedLineTo), LINE, "Draw a segment from the turtle to the point (x, y, z), turning H along it the least way.", K::Move),
    #[cfg(any(feature = "placing", not(target_arch = "wasm32")))]
    row("@OLineRel", Turtle(C::OrientedLineRel), LINE_BY, "Draw a segment from the turtle by the vector (x, y, z), turning H along it the least way.", K::Move),
    row("+", Turtle(C::TurnLeft), ANGLE, "Turn left by a degrees around the up vector U.", K::Rotate),
    row("-", Turtle(C::TurnRight), ANGLE, "Turn right by a degrees around the up vector U.", K::Rotate),
    row("&", Turtle(C::PitchDown), ANGLE, "Pitch down by a degrees around the left vector L.", K::Rotate),
    row("^", Turtle(C::PitchUp), ANGLE, "Pitch up by a degrees around the left vector L.", K::Rotate),
    row("\\", Turtle(C::RollLeft), ANGLE, "Roll left by a degrees around the heading H.", K::Rotate),
    row("/", Turtle(C::RollRight), ANGLE, "Roll right by a degrees around the heading H.", K::Rotate),
    row("|", Turtle(C::TurnAround), &[], "Turn around: 180° around the up vector U.", K::Rotate),
    #[cfg(any(feature = "placing", not(target_arch = "wasm32")))]
    row("@R", Turtle(C::SetHeading), HEADING_UP, "Set the heading H to (hx, hy, hz) and, when given, the up vector U to (ux, uy, uz) made square to H.", K::Rotate),
    row("$", Turtle(C::RollToVertical), &[], "Roll around H so that L is horizontal (ABOP p. 57).", K::Rotate),
    row("@v", Turtle(C::RollToVertical), &[], "Roll around H so that L is horizontal; the same as $.", K::Rotate),
    row("[", Turtle(C::Push), &[], "Start a branch: push the turtle state.", K::Branch),
    row("]", Turtle(C::Pop), &[], "End a branch: pop the turtle state.", K::Branch),
    row("{", Turtle(C::StartPolygon), &[], "Start a polygon: the turtle's position and later F, f and . moves are its vertices.", K::Polygon),
    row(".", Turtle(C::PolygonVertex), &[], "Record the turtle's position as a polygon vertex.", K::Polygon),
    row("}", Turtle(C::EndPolygon), &[], "Close and fill the polygon.", K::Polygon),
    row("!", Turtle(C::Width), &[Param::number("w", "the new width; without it, the width decreases by #width_step").unit("width units")],
        "Set the width to w; without w, decrease it by #width_step.", K::Appearance),
    row("'", Turtle(C::NextColor), &[Param::number("n", "how many colour indices to step").default(1.0)],
        "Increase the colour index by n.", K::Appearance),
    row(";", Turtle(C::SetColor), &[Param::number("c", "the colour index; without it, the next one")],
        "Set the colour index to c; without c, increase it by 1.", K::Appearance),
    row("~l", Turtle(C::Leaf), SCALE, "Draw the predefined leaf, s long, along H.", K::Surface),
    row("~p", Turtle(C::Petal), SCALE, "Draw the predefined petal, s long, along H.", K::Surface),
    row("~X", Turtle(C::Surface), SURFACE_SCALES,
        "Draw the surface declared for the letter X (#surface X, #patch X), scaled by s, or by s along L, sy along H and sz along U.", K::Surface),
    #[cfg(any(feature = "placing", not(target_arch = "wasm32")))]
    row("@Frame", Turtle(C::Frame), &[Param::number("s", "the length of each axis").default(1.0).unit("units")],
        "Draw the turtle's frame: H in colour 10 (red), L in colour 5 (green), U in colour 13 (blue), each s long, at the current width.", K::Appearance),
    row("@O", Turtle(C::Sphere), &[Param::number("r", "the radius; without it, half the current width")],
        "Draw a sphere of radius r (without r: as wide as the current width).", K::Surface),
    row("@Tp", Turtle(C::TropismVector), VECTOR, "Set this branch's tropism vector T.", K::Tropism),
    row("@Ts", Turtle(C::TropismStrength), &[Param::number("e", "the susceptibility")], "Set this branch's tropism susceptibility e.", K::Tropism),
    row("@Gc", Turtle(C::StartSmooth), &[], "Start a smooth branch: segments until @Ge form one generalized cylinder.", K::Surface),
    row("@Ge", Turtle(C::EndSmooth), &[], "End a smooth branch.", K::Surface),
    row("?P", Turtle(C::QueryPosition), QUERIED, "Query: after each step, set to the turtle's position here.", K::Query),
    row("?H", Turtle(C::QueryHeading), QUERIED, "Query: after each step, set to the turtle's heading here.", K::Query),
    row("?U", Turtle(C::QueryUp), QUERIED, "Query: after each step, set to the turtle's up vector here.", K::Query),
    row("?L", Turtle(C::QueryLeft), QUERIED, "Query: after each step, set to the turtle's left vector here.", K::Query),
    row("?E", Turtle(C::QueryEnvironment), &[],
        "Communication module (any number of parameters): after each step, the #environment programs write their replies into its parameters, in the order they are declared.", K::Query),
    row("%", Meaning::Cut, &[], "Cut: remove the rest of this branch from the string (during derivation).", K::Derivation),
    row("@Prune", Meaning::Cut, &[], "Cut, as %.", K::Derivation),
    row("@Switch", Meaning::Group(GroupKind::Switch), &[],
        "@Switch(A B C): only one member is rewritten per step, in turn.", K::Derivation),
    row("@Pendulum", Meaning::Group(GroupKind::Pendulum), &[],
        "@Pendulum(A B C): every member is rewritten; the order reverses on even steps.", K::Derivation),
    row("@Repeat", Meaning::Group(GroupKind::Repeat),
        &[Param::new("k", ParamKind::Whole, "how many times the modules inside are derived per step")],
        "@Repeat(k, A B): the string inside is derived k times per step.", K::Derivation),
];

/// The row of a module name, if the name has a meaning. Every grammar's parse and resolve ask
/// this of each module they read, so single-byte names (most of them) are found by one table
/// look-up and longer names are compared only when their first byte starts a longer row's name.
pub fn module_named(name: &str) -> Option<&'static ModuleInfo> {
    let row = match *name.as_bytes() {
        [byte] => LOOKUP.single.get(usize::from(byte)).copied()?,
        [first, _, ..] if LOOKUP.longer_first.get(usize::from(first)) == Some(&true) => {
            return MODULES.iter().find(|m| m.name == name);
        }
        _ => return None,
    };
    row.checked_sub(1).map(|i| &MODULES[usize::from(i)])
}

/// [`module_named`]'s tables, made from [`MODULES`] when compiling.
struct Lookup {
    /// For each ASCII byte, 1 + the index of the first row with that one-byte name (0: none).
    single: [u8; 128],
    /// For each ASCII byte, whether a row's name of two bytes or more starts with it.
    longer_first: [bool; 128],
}

static LOOKUP: Lookup = lookup();

const fn lookup() -> Lookup {
    assert!(MODULES.len() < 255, "row indices fit in a byte");
    let mut t = Lookup {
        single: [0; 128],
        longer_first: [false; 128],
    };
    let mut i = 0;
    while i < MODULES.len() {
        let name = MODULES[i].name.as_bytes();
        let first = name[0] as usize;
        assert!(first < 128, "module names start with an ASCII byte");
        if name.len() == 1 {
            if t.single[first] == 0 {
                t.single[first] = i as u8 + 1;
            }
        } else {
            t.longer_first[first] = true;
        }
        i += 1;
    }
    t
}

/// Every name with `meaning`, in table order (`%` and `@Prune` for cut).
pub fn names_of(meaning: Meaning) -> impl Iterator<Item = &'static str> {
    MODULES
        .iter()
        .filter(move |m| m.meaning == meaning)
        .map(|m| m.name)
}

/// The name of the first module with `meaning` (`Meaning::Cut` is `%`; `@Prune` is a synonym).
pub fn name_of(meaning: Meaning) -> &'static str {
    MODULES
        .iter()
        .find(|m| m.meaning == meaning)
        .map_or("", |m| m.name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn module_named_finds_each_name_s_row_and_nothing_else() {
        // Names are unique (`no_name_is_declared_twice`); rows are compared by what they hold
        // (`MODULES` is a constant: its rows need not have one address).
        for row in MODULES {
            let found = module_named(row.name).unwrap();
            assert_eq!(
                (found.name, found.meaning, found.doc),
                (row.name, row.meaning, row.doc)
            );
        }
        let others = "X A FF @ @m @Prunes ~ ~x ? ?p é \u{1F331} 1";
        for name in others.split(' ').chain([""]) {
            assert!(module_named(name).is_none(), "{name:?}");
        }
    }

    #[test]
    fn placing_names_exactly_the_rows_that_place_by_coordinates() {
        let mut rows: Vec<&str> = MODULES
            .iter()
            .filter(|m| m.command().is_some_and(Command::places_by_coordinates))
            .map(|m| m.name)
            .collect();
        let mut listed: Vec<&str> = PLACING.split(' ').collect();
        rows.sort_unstable();
        listed.sort_unstable();
        assert_eq!(rows, listed);
    }

    #[test]
    fn every_meaning_has_a_name() {
        for m in MODULES {
            assert_eq!(module_named(m.name).map(|r| r.meaning), Some(m.meaning));
            assert!(!name_of(m.meaning).is_empty());
        }
        assert_eq!(name_of(Meaning::Turtle(Command::Push)), "[");
        assert_eq!(name_of(Meaning::Cut), "%");
    }
}

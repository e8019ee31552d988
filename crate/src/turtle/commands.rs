//! The turtle command table: every command is declared once here, with its parameters, a one-line
//! doc and a category. It drives the interpreter and is exported to TypeScript as data (for the
//! editor's highlighting, completion and hover docs). Modules that act during derivation rather
//! than interpretation (`%`, the control modules) are listed too, so the editor documents them.

use serde::Serialize;

/// What a module does when the turtle reads it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
    /// `{`
    StartPolygon,
    /// `.`
    PolygonVertex,
    /// `}`
    EndPolygon,
    /// `!`: decrease the width, or set it.
    Width,
    /// `'`: next colour index (or add the parameter).
    NextColor,
    /// `;`: set the colour index (or next, without a parameter).
    SetColor,
    /// `~l`: the predefined leaf surface.
    Leaf,
    /// `~p`: the predefined petal surface.
    Petal,
    /// `@O`: a sphere.
    Sphere,
    /// `@M`: move to a point.
    MoveTo,
    /// `@Tp`: set the tropism vector of this branch.
    TropismVector,
    /// `@Ts`: set the tropism susceptibility of this branch.
    TropismStrength,
    /// `@Gc`: start a smooth branch.
    StartSmooth,
    /// `@Ge`: end a smooth branch.
    EndSmooth,
    QueryPosition,
    QueryHeading,
    QueryUp,
    QueryLeft,
    /// Acts during derivation (cut, control modules); the turtle skips it.
    Derivation,
}

/// Groups of commands, for the editor's colours and the reference page.
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

/// One row of the command table.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct CommandInfo {
    pub name: &'static str,
    #[serde(skip)]
    pub command: Command,
    /// Parameter names with their defaults (`["l = #step"]`); all are optional unless the doc says.
    pub params: &'static [&'static str],
    pub doc: &'static str,
    pub category: Category,
}

const fn row(
    name: &'static str,
    command: Command,
    params: &'static [&'static str],
    doc: &'static str,
    category: Category,
) -> CommandInfo {
    CommandInfo {
        name,
        command,
        params,
        doc,
        category,
    }
}

use Category as K;
use Command as C;

/// Every command of LANGUAGE.md section 6, and the derivation-time modules of sections 6 and 7.
#[rustfmt::skip]
pub const COMMANDS: &[CommandInfo] = &[
    row("F", C::Forward, &["l = #step"], "Move forward by l and draw a segment.", K::Move),
    row("f", C::Move, &["l = #step"], "Move forward by l without drawing.", K::Move),
    row("G", C::ForwardNoVertex, &["l = #step"], "Draw forward by l without recording a polygon vertex.", K::Move),
    row("g", C::MoveNoVertex, &["l = #step"], "Move forward by l without drawing or recording a polygon vertex.", K::Move),
    row("@M", C::MoveTo, &["x", "y", "z"], "Move to the point (x, y, z) without drawing.", K::Move),
    row("+", C::TurnLeft, &["a = #angle"], "Turn left by a degrees around the up vector U.", K::Rotate),
    row("-", C::TurnRight, &["a = #angle"], "Turn right by a degrees around the up vector U.", K::Rotate),
    row("&", C::PitchDown, &["a = #angle"], "Pitch down by a degrees around the left vector L.", K::Rotate),
    row("^", C::PitchUp, &["a = #angle"], "Pitch up by a degrees around the left vector L.", K::Rotate),
    row("\\", C::RollLeft, &["a = #angle"], "Roll left by a degrees around the heading H.", K::Rotate),
    row("/", C::RollRight, &["a = #angle"], "Roll right by a degrees around the heading H.", K::Rotate),
    row("|", C::TurnAround, &[], "Turn around: 180° around the up vector U.", K::Rotate),
    row("$", C::RollToVertical, &[], "Roll around H so that L is horizontal (ABOP p. 57).", K::Rotate),
    row("@v", C::RollToVertical, &[], "Roll around H so that L is horizontal; the same as $.", K::Rotate),
    row("[", C::Push, &[], "Start a branch: push the turtle state.", K::Branch),
    row("]", C::Pop, &[], "End a branch: pop the turtle state.", K::Branch),
    row("{", C::StartPolygon, &[], "Start a polygon: the turtle's position and later F, f and . moves are its vertices.", K::Polygon),
    row(".", C::PolygonVertex, &[], "Record the turtle's position as a polygon vertex.", K::Polygon),
    row("}", C::EndPolygon, &[], "Close and fill the polygon.", K::Polygon),
    row("!", C::Width, &["w"], "Set the width to w; without w, decrease it by #width_step.", K::Appearance),
    row("'", C::NextColor, &["n = 1"], "Increase the colour index by n.", K::Appearance),
    row(";", C::SetColor, &["c"], "Set the colour index to c; without c, increase it by 1.", K::Appearance),
    row("~l", C::Leaf, &["s = 1"], "Draw the predefined leaf, s long, along H.", K::Surface),
    row("~p", C::Petal, &["s = 1"], "Draw the predefined petal, s long, along H.", K::Surface),
    row("@O", C::Sphere, &["r"], "Draw a sphere of radius r (without r: as wide as the current width).", K::Surface),
    row("@Tp", C::TropismVector, &["x", "y", "z"], "Set this branch's tropism vector T.", K::Tropism),
    row("@Ts", C::TropismStrength, &["e"], "Set this branch's tropism susceptibility e.", K::Tropism),
    row("@Gc", C::StartSmooth, &[], "Start a smooth branch: segments until @Ge form one generalized cylinder.", K::Surface),
    row("@Ge", C::EndSmooth, &[], "End a smooth branch.", K::Surface),
    row("?P", C::QueryPosition, &["x", "y", "z"], "Query: after each step, set to the turtle's position here.", K::Query),
    row("?H", C::QueryHeading, &["x", "y", "z"], "Query: after each step, set to the turtle's heading here.", K::Query),
    row("?U", C::QueryUp, &["x", "y", "z"], "Query: after each step, set to the turtle's up vector here.", K::Query),
    row("?L", C::QueryLeft, &["x", "y", "z"], "Query: after each step, set to the turtle's left vector here.", K::Query),
    row("%", C::Derivation, &[], "Cut: remove the rest of this branch from the string (during derivation).", K::Derivation),
    row("@Prune", C::Derivation, &[], "Cut, as %.", K::Derivation),
    row("@Switch", C::Derivation, &[], "@Switch(A B C): only one member is rewritten per step, in turn.", K::Derivation),
    row("@Pendulum", C::Derivation, &[], "@Pendulum(A B C): every member is rewritten; the order reverses on even steps.", K::Derivation),
    row("@Repeat", C::Derivation, &["k"], "@Repeat(k, A B): the string inside is derived k times per step.", K::Derivation),
];

/// The command table as JSON, for the TypeScript side.
pub fn commands_json() -> String {
    serde_json::to_string(COMMANDS).unwrap_or_else(|_| "[]".into())
}

/// The row of a module name, if it is a command.
pub fn command_named(name: &str) -> Option<&'static CommandInfo> {
    COMMANDS.iter().find(|c| c.name == name)
}

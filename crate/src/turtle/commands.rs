//! The turtle command table: every command is declared once here, with its parameters, a one-line
//! doc and a category. It drives the interpreter and is exported to TypeScript as data (for the
//! editor's highlighting, completion and hover docs).

use serde::Serialize;

/// What a turtle command does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    /// `F`: move forward and draw a segment.
    Forward,
    /// `f`: move forward without drawing.
    Move,
    /// `+`: turn left around U.
    TurnLeft,
    /// `-`: turn right around U.
    TurnRight,
    /// `&`: pitch down around L.
    PitchDown,
    /// `^`: pitch up around L.
    PitchUp,
    /// `\`: roll left around H.
    RollLeft,
    /// `/`: roll right around H.
    RollRight,
    /// `|`: turn around (180° around U).
    TurnAround,
    /// `[`: push the turtle state.
    Push,
    /// `]`: pop the turtle state.
    Pop,
}

/// Groups of commands, for the editor's colours and the reference page.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Category {
    Move,
    Rotate,
    Branch,
}

/// One row of the command table.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct CommandInfo {
    pub name: &'static str,
    #[serde(skip)]
    pub command: Command,
    /// Parameter names with their defaults in words (`["l = #step"]`).
    pub params: &'static [&'static str],
    pub doc: &'static str,
    pub category: Category,
}

/// Every turtle command of this version (LANGUAGE.md section 6).
pub const COMMANDS: &[CommandInfo] = &[
    CommandInfo {
        name: "F",
        command: Command::Forward,
        params: &["l = #step"],
        doc: "Move forward by l and draw a segment.",
        category: Category::Move,
    },
    CommandInfo {
        name: "f",
        command: Command::Move,
        params: &["l = #step"],
        doc: "Move forward by l without drawing.",
        category: Category::Move,
    },
    CommandInfo {
        name: "+",
        command: Command::TurnLeft,
        params: &["a = #angle"],
        doc: "Turn left by a degrees around the up vector U.",
        category: Category::Rotate,
    },
    CommandInfo {
        name: "-",
        command: Command::TurnRight,
        params: &["a = #angle"],
        doc: "Turn right by a degrees around the up vector U.",
        category: Category::Rotate,
    },
    CommandInfo {
        name: "&",
        command: Command::PitchDown,
        params: &["a = #angle"],
        doc: "Pitch down by a degrees around the left vector L.",
        category: Category::Rotate,
    },
    CommandInfo {
        name: "^",
        command: Command::PitchUp,
        params: &["a = #angle"],
        doc: "Pitch up by a degrees around the left vector L.",
        category: Category::Rotate,
    },
    CommandInfo {
        name: "\\",
        command: Command::RollLeft,
        params: &["a = #angle"],
        doc: "Roll left by a degrees around the heading H.",
        category: Category::Rotate,
    },
    CommandInfo {
        name: "/",
        command: Command::RollRight,
        params: &["a = #angle"],
        doc: "Roll right by a degrees around the heading H.",
        category: Category::Rotate,
    },
    CommandInfo {
        name: "|",
        command: Command::TurnAround,
        params: &[],
        doc: "Turn around: 180° around the up vector U.",
        category: Category::Rotate,
    },
    CommandInfo {
        name: "[",
        command: Command::Push,
        params: &[],
        doc: "Start a branch: push the turtle state.",
        category: Category::Branch,
    },
    CommandInfo {
        name: "]",
        command: Command::Pop,
        params: &[],
        doc: "End a branch: pop the turtle state.",
        category: Category::Branch,
    },
];

/// The command table as JSON, for the TypeScript side.
pub fn commands_json() -> String {
    serde_json::to_string(COMMANDS).unwrap_or_else(|_| "[]".into())
}

//! A grammar's environment as plain data (docs/LANGUAGE.md, "Environment"): the programs its
//! `#environment` lines declare and where the plants of a stand stand (`#stand`, `#plant`).
//! Read by `resolve/environment.rs`; run by `crate::environment` between derivation steps.

use crate::vocabulary::{EnvironmentProgram, EnvironmentProgramInfo, EnvironmentShape};
use std::ops::Range;

/// One `#environment` line: a program, its shape if it takes one, and its settings as written
/// (each checked against the program's row: a known word with its count of numbers).
#[derive(Clone, Debug, PartialEq)]
pub struct ProgramSpec {
    pub program: EnvironmentProgram,
    pub shape: Option<EnvironmentShape>,
    pub settings: Vec<SettingValue>,
    /// The whole line, for messages about the program.
    pub span: Range<usize>,
}

/// One setting word and its numbers.
#[derive(Clone, Debug, PartialEq)]
pub struct SettingValue {
    pub name: &'static str,
    pub values: Vec<f64>,
    /// The word and its numbers, for messages.
    pub span: Range<usize>,
}

impl ProgramSpec {
    /// The program's row of the vocabulary.
    pub fn info(&self) -> &'static EnvironmentProgramInfo {
        self.program.info()
    }

    /// The setting `name` as written, if it is.
    pub fn setting(&self, name: &str) -> Option<&SettingValue> {
        self.settings.iter().rev().find(|s| s.name == name)
    }

    /// The one number of setting `name`, if written.
    pub fn number(&self, name: &str) -> Option<f64> {
        self.setting(name).and_then(|s| s.values.first().copied())
    }

    /// The three numbers of setting `name`, if written.
    pub fn vector(&self, name: &str) -> Option<[f64; 3]> {
        let s = self.setting(name)?;
        match s.values[..] {
            [x, y, z] => Some([x, y, z]),
            _ => None,
        }
    }

    /// Where setting `name` is written, or the whole line when it is not.
    pub fn span_of(&self, name: &str) -> Range<usize> {
        self.setting(name)
            .map_or_else(|| self.span.clone(), |s| s.span.clone())
    }
}

/// Most plants a stand may have (`#stand`, `#plant` together): each is a whole derivation.
pub const MAX_STAND_PLANTS: usize = 400;

/// One plant of a stand: where it stands and which of the stand's seeds it derives with.
#[derive(Clone, Debug, PartialEq)]
pub struct PlantPlace {
    pub position: [f64; 3],
    /// Its index in the stand: plant `i` derives with the seed `seed + i` (docs/LANGUAGE.md).
    pub index: u32,
}

/// What a grammar declares of its environment. Empty (no program, no stand): the plant grows in
/// empty space, and derivation is exactly as without this module.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EnvironmentSpec {
    pub programs: Vec<ProgramSpec>,
    /// The plants of a stand; empty: one plant at the origin.
    pub plants: Vec<PlantPlace>,
}

impl EnvironmentSpec {
    /// True when the grammar declares neither a program nor a stand.
    pub fn is_empty(&self) -> bool {
        self.programs.is_empty() && self.plants.is_empty()
    }

    /// How many values a `?E` is answered with: every program's reply, in the order declared.
    pub fn reply_len(&self) -> usize {
        self.programs.iter().map(|p| p.info().reply.len()).sum()
    }
}

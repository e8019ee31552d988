//! Lparser `.ls` (Laurens Lapré's L-System Parser/Mutator) -> Meristem.
//!
//! Two file formats: the positional one of Lparser 1.x-4.x (recursion depth, basic angle and
//! thickness on the first three lines, then the axiom, then rules `X=…` up to a line starting
//! with `@`; `#` starts a comment) and the keyword one of Lparser 2.x (`recursion`, `angle`,
//! `thickness`, `min_thickness`, `color`, `axiom`, `rule X = …`, …). Every meaning below is taken
//! from the two sources found: Lparser 2.1's `L_init`/`L_draw` (`Lparser2.c` in jvail/L-System)
//! and the port of the positional-format Lparser in K-3D (`modules/lsystem/l_parser.cpp`).
//!
//! Lparser rewrites characters; its turtle keeps a current length, angle and thickness that
//! `' " ; : ! ?` multiply. Meristem's turtle has no such state, so the importer threads it
//! through parameters: every symbol with a rule carries the length, angle and thickness in force
//! where it stands (only those its expansion reads), and every drawing command gets explicit
//! values — which turns the file into the parametric L-system it implies (ABOP p. 56 style).
//! A symbol whose expansion changes the state for the symbols after it (`S='(.8)!(.9)`,
//! `F='(1.3)F'(.77)`) multiplies their values by the net factor of its expansion after the steps
//! left, `MaxIt - NumIt`; the factor is exact when it follows a fixed law (constant after some
//! steps, or geometric), and reported otherwise. The derived string has one module per Lparser
//! symbol that means something (scaling commands are absorbed into parameters, inert characters
//! dropped); a `homomorphism:` section turns the symbols Meristem cannot draw directly into
//! turtle commands (widths, `Z`, `~`, `t`).

mod read;
#[cfg(test)]
mod tests;
mod translate;
mod values;
mod write;

use super::{Import, Output};
use read::parse;
use std::collections::HashMap;
use values::Net;

/// Lparser 2.1's defaults (`static` initialisers of `Lparser2.c`).
const DEFAULT_RECURSION: f64 = 1.0;
const DEFAULT_ANGLE: f64 = 45.0;
const DEFAULT_THICKNESS: f64 = 100.0;
/// `~` without a value turns by up to 6 *radians* (`r = (r32) 6.0`, no degree conversion).
const TILDE_DEFAULT_DEGREES: f64 = 6.0 * 180.0 / std::f64::consts::PI;
/// `t` without a value: `tr = 0.2`.
const TROPISM_DEFAULT: f64 = 0.2;
/// Meristem width units per model unit of Lparser diameter (length × thickness) when the plant
/// cannot be measured (see [`measure_width_scale`]).
const WIDTH_SCALE: f64 = 10.0;
/// The largest string, and the most steps, the importer derives to measure the plant.
const MEASURE_MODULES: usize = 1_000_000;
const MEASURE_STEPS: u32 = 64;
/// The positional format's Lparser (4.x, as its K-3D and L-Neuron ports show) draws `F` 100
/// units long (`dis = 100.0`), so its explicit lengths `F(20)` are in those units; Meristem's
/// translation takes `F` as 1.
const POSITIONAL_LENGTH_UNIT: f64 = 0.01;
/// Commands that read a `(value)` right after them (`next == '('` in `L_draw`).
const VALUE_COMMANDS: &str = "+-~t&^<>!?:;'\"ZFfgzc";
/// Characters that keep themselves (Lparser's default rules `+=+` … `_=_`); any other character
/// without a rule becomes `_` after one step, and nothing draws it.
const SELF_RULES: &str = "+-&^<>%|!?:;'\"c[]{}FftgZz*$~.0123456789()_";
/// Structural characters whose rules the importer ignores.
const NOT_REWRITABLE: &str = "[](){}.";
/// Steps for which the net scaling of each expansion is computed to find its law.
const NET_SAMPLES: usize = 40;

const L: usize = 0;
const A: usize = 1;
const T: usize = 2;
const PARAM_NAMES: [&str; 3] = ["len", "ang", "wid"];

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    Positional,
    Keyword,
}

/// One symbol of an Lparser string: a character and the value in `(…)` after a command.
#[derive(Clone, Debug, PartialEq)]
struct Tok {
    ch: char,
    value: Option<f64>,
    /// The characters between the parentheses, as written.
    written: String,
}

#[derive(Clone, Debug)]
struct Rule {
    pred: char,
    succ: Vec<Tok>,
    line: usize,
    comment: String,
}

#[derive(Debug)]
struct LsFile {
    format: Format,
    recursion: f64,
    recursion_line: usize,
    angle: f64,
    thickness: f64,
    thickness_line: usize,
    min_thickness: f64,
    axiom: Vec<Tok>,
    axiom_line: usize,
    axiom_comment: String,
    rules: Vec<Rule>,
    colors: Vec<(usize, [f64; 3])>,
    header: Vec<String>,
}

pub(super) fn import(text: &str) -> Import {
    let mut out = Output::default();
    let file = parse(text, &mut out);
    if file.axiom_line == 0 {
        out.note(0, "no axiom found");
        return out.finish();
    }
    Translator::new(&file, &mut out).write();
    out.finish()
}

/// What the homomorphism section must define.
#[derive(Default)]
struct Uses {
    forward: bool,
    half: bool,
    tilde: bool,
    tropism: bool,
}

struct Translator<'f, 'o> {
    file: &'f LsFile,
    out: &'o mut Output,
    /// The rule of each rewritten character (the first one, as Lparser's rule table keeps).
    rule_of: HashMap<char, usize>,
    used: [bool; 3],
    start: [f64; 3],
    needs: HashMap<char, [bool; 3]>,
    nets: HashMap<char, [Net; 3]>,
    uses: Uses,
    noted: Vec<String>,
    /// Where the `#define width_scale` line is, once written.
    width_line: Option<usize>,
}

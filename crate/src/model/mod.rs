//! Stage 2, `model` (resolve): the syntax tree becomes a validated [`Model`] with interned module
//! ids, so that derivation and interpretation never look at text or re-check anything.

mod alphabet;
mod lstring;
mod resolve;

pub use alphabet::{Alphabet, ModuleId};
pub use lstring::LString;
pub use resolve::resolve;

use crate::syntax::Span;

/// A production after resolution: `predecessor -> successor` over module ids.
#[derive(Clone, Debug, PartialEq)]
pub struct Production {
    pub label: Option<String>,
    pub predecessor: ModuleId,
    pub successor: Vec<ModuleId>,
    /// The production's line in the source.
    pub span: Span,
}

/// Values set by directives, with the defaults of LANGUAGE.md section 2.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// `#angle`: the default turn angle δ in degrees.
    pub angle: f64,
    /// `#iterations` / `derivation length:`: the default number of derivation steps.
    pub iterations: u32,
    /// `#step`: the default length of `F` and `f`.
    pub step: f64,
    /// `#width`: the initial segment width, in width units (see `mesh`).
    pub width: f64,
    /// `#max_modules`: derivation stops with an error when a string would grow past this.
    pub max_modules: usize,
    /// `#max_steps`: the largest number of derivation steps a build may run.
    pub max_steps: u32,
    /// `#draw A B`: further modules that draw a segment like `F`.
    pub draw: Vec<ModuleId>,
    /// Span of the `#iterations` directive, where step-related diagnostics point.
    pub iterations_span: Option<Span>,
}

/// Limits that protect the page from grammars that explode (overridable per grammar).
pub const DEFAULT_MAX_MODULES: usize = 5_000_000;
/// The default limit on derivation steps.
pub const DEFAULT_MAX_STEPS: u32 = 10_000;

impl Default for Settings {
    fn default() -> Self {
        Settings {
            angle: 90.0,
            iterations: 0,
            step: 1.0,
            width: 1.0,
            max_modules: DEFAULT_MAX_MODULES,
            max_steps: DEFAULT_MAX_STEPS,
            draw: Vec::new(),
            iterations_span: None,
        }
    }
}

/// A validated grammar: everything later stages need, nothing they must check again.
#[derive(Clone, Debug, PartialEq)]
pub struct Model {
    pub alphabet: Alphabet,
    pub axiom: LString,
    /// Span of the `axiom:` line.
    pub axiom_span: Span,
    /// In source order.
    pub productions: Vec<Production>,
    /// For each module id, the index of the production that rewrites it (`None`: copied).
    pub rule_of: Vec<Option<u32>>,
    pub settings: Settings,
}

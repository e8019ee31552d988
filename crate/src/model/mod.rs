//! Stage 2, `model` (resolve): the syntax tree becomes a validated [`Model`] with interned module
//! ids, checked arities and compiled expressions, so that derivation and interpretation never look
//! at text or re-check anything.

mod alphabet;
pub mod directives;
mod lstring;
mod program;
mod resolve;

pub use alphabet::{Alphabet, ModuleId};
pub use lstring::LString;
pub use program::{Env, EvalError, Function, Program, Scope, MAX_STACK};
pub use resolve::resolve;

use crate::syntax::{Section, Span};

/// A module in a predecessor or context: its formal parameters bind slots
/// `first_slot .. first_slot + arity` of the production.
#[derive(Clone, Debug, PartialEq)]
pub struct PatternModule {
    pub id: ModuleId,
    pub arity: usize,
    pub first_slot: u16,
    pub span: Span,
}

/// One element of a right context, which may contain branches.
#[derive(Clone, Debug, PartialEq)]
pub enum PatternItem {
    Module(PatternModule),
    /// `[`: the string must branch here.
    Open,
    /// `]`: the rest of the string's current branch is skipped.
    Close,
}

/// One module of a successor, with its argument expressions.
#[derive(Clone, Debug, PartialEq)]
pub struct SuccessorModule {
    pub id: ModuleId,
    pub args: Vec<Program>,
    /// The members of a control module (`@Switch`, `@Pendulum`, `@Repeat`).
    pub group: Option<Vec<Vec<SuccessorModule>>>,
    /// Where the module is written.
    pub span: Span,
}

/// Green's control modules (LANGUAGE.md section 7) and how their groups sit in a string:
/// `@Switch(cursor) @< A @| B @| C @>`, `@Pendulum(reversed) @< … @>`, `@Repeat(k) @< … @>`.
/// The markers `@<`, `@|`, `@>` are internal names that no grammar can write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GroupIds {
    pub switch: ModuleId,
    pub pendulum: ModuleId,
    pub repeat: ModuleId,
    pub open: ModuleId,
    pub separator: ModuleId,
    pub close: ModuleId,
}

impl GroupIds {
    /// True for the three control modules.
    pub fn is_group(&self, id: ModuleId) -> bool {
        id == self.switch || id == self.pendulum || id == self.repeat
    }

    /// True for the three markers.
    pub fn is_marker(&self, id: ModuleId) -> bool {
        id == self.open || id == self.separator || id == self.close
    }
}

/// A production after resolution.
#[derive(Clone, Debug, PartialEq)]
pub struct Production {
    pub label: Option<String>,
    pub section: Section,
    pub left: Vec<PatternModule>,
    pub predecessor: PatternModule,
    pub right: Vec<PatternItem>,
    pub condition: Option<Program>,
    pub weight: Option<Program>,
    pub successor: Vec<SuccessorModule>,
    /// Number of formal-parameter slots (predecessor and contexts).
    pub slots: usize,
    /// The production's line in the source.
    pub span: Span,
}

impl Production {
    /// True when matching needs more than the predecessor's id and arity.
    pub fn has_context(&self) -> bool {
        !self.left.is_empty() || !self.right.is_empty()
    }
}

/// The productions of one section, indexed by predecessor.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RuleSet {
    pub productions: Vec<Production>,
    /// For each module id, the indices of the productions whose predecessor it is, in source order.
    pub by_predecessor: Vec<Vec<u32>>,
    /// `maximum depth:` for homomorphism and decomposition.
    pub max_depth: u32,
}

impl RuleSet {
    pub fn is_empty(&self) -> bool {
        self.productions.is_empty()
    }

    /// True when any production has a left or right context.
    pub fn has_contexts(&self) -> bool {
        self.productions.iter().any(Production::has_context)
    }
}

/// Values set by directives, with the defaults of LANGUAGE.md section 2.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// `#angle`: the default turn angle δ in degrees.
    pub angle: f64,
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
    /// `#tropism x y z e`: the tropism vector T and susceptibility e (ABOP 2.3); e = 0 is none.
    pub tropism: (glam::DVec3, f64),
    /// `#max_modules`: derivation stops with an error when a string would grow past this.
    pub max_modules: usize,
    /// `#max_steps`: the largest number of derivation steps a build may run.
    pub max_steps: u32,
    /// `#draw A B`: further modules that draw a segment like `F`.
    pub draw: Vec<ModuleId>,
    /// The colours of the colour index (`'`, `;`), linear RGB in 0..=1: [`DEFAULT_PALETTE`]
    /// with the entries `#color` set. An index past the end wraps modulo the length.
    pub palette: Vec<[f32; 3]>,
    /// Span of the `#iterations` directive, where step-related diagnostics point.
    pub iterations_span: Option<Span>,
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
    [0.82, 0.22, 0.18], // 10 red
    [0.90, 0.50, 0.65], // 11 pink
    [0.55, 0.28, 0.68], // 12 purple
    [0.30, 0.45, 0.85], // 13 blue
    [0.95, 0.95, 0.92], // 14 white
    [0.50, 0.50, 0.50], // 15 grey
];

/// The largest colour index `#color` may set.
pub const MAX_COLOR_INDEX: usize = 255;

/// Limits that protect the page from grammars that explode (overridable per grammar).
pub const DEFAULT_MAX_MODULES: usize = 5_000_000;
/// The default limit on derivation steps.
pub const DEFAULT_MAX_STEPS: u32 = 10_000;
/// The default `maximum depth:` of homomorphism and decomposition.
pub const DEFAULT_MAX_DEPTH: u32 = 16;

impl Default for Settings {
    fn default() -> Self {
        Settings {
            angle: 90.0,
            iterations: 0,
            seed: 1,
            step: 1.0,
            width: 1.0,
            width_step: 0.1,
            tropism: (glam::DVec3::NEG_Y, 0.0),
            max_modules: DEFAULT_MAX_MODULES,
            max_steps: DEFAULT_MAX_STEPS,
            draw: Vec::new(),
            palette: DEFAULT_PALETTE.to_vec(),
            iterations_span: None,
        }
    }
}

/// A `#random` variable: a name and the distribution each deviate is drawn from.
#[derive(Clone, Debug, PartialEq)]
pub struct RandomVariable {
    pub name: String,
    pub distribution: Program,
}

/// A validated grammar: everything later stages need, nothing they must check again.
#[derive(Clone, Debug, PartialEq)]
pub struct Model {
    pub alphabet: Alphabet,
    /// The axiom as modules with argument expressions (evaluated when derivation starts).
    pub axiom: Vec<SuccessorModule>,
    /// Span of the `axiom:` line.
    pub axiom_span: Span,
    pub productions: RuleSet,
    pub homomorphism: RuleSet,
    pub decomposition: RuleSet,
    pub random_variables: Vec<RandomVariable>,
    /// For each module id: skipped when matching contexts (`#ignore`, or not in `#consider`).
    pub ignored: Vec<bool>,
    /// The ids of `[`, `]`, and of the cut modules `%` and `@Prune` (always interned).
    pub open: ModuleId,
    pub close: ModuleId,
    pub cut: [ModuleId; 2],
    pub groups: GroupIds,
    /// True when any successor or the axiom holds a control module group.
    pub has_groups: bool,
    /// True when any module of the axiom or a successor has parameters.
    pub parametric: bool,
    pub settings: Settings,
    /// The particle attributes (`#lifetime`, `#speed`, `#shape`, `#sun`, …) and which modules are
    /// apices and segments; all off by default.
    pub growth: crate::growth::Attributes,
}

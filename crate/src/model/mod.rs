//! Stage 2, `model` (resolve): the syntax tree becomes a validated [`Model`] with interned module
//! ids, checked arities and compiled expressions, so that derivation and interpretation never look
//! at text or re-check anything.

mod alphabet;
mod curve;
mod environment;
mod lstring;
mod program;
mod resolve;
mod settings;
mod surface;

pub use alphabet::{Alphabet, ModuleId};
pub use curve::{Curve, CurveKind};
pub use environment::{EnvironmentSpec, PlantPlace, ProgramSpec, SettingValue, MAX_STAND_PLANTS};
pub use lstring::LString;
pub use program::{Env, EvalError, Program, RandomVariable, Scope, Simple, MAX_OPS, MAX_STACK};
pub use resolve::resolve;
pub use settings::{
    directive_default, Bend, GrowthAttributes, Lifetime, Settings, Shape, ShapeWidth, Speed, Sun,
    DEFAULT_PALETTE, ORGAN_COLOR,
};
#[cfg(feature = "surfaces")]
pub use surface::{organ_patches, Frame, LIBRARY_PRECISION};
pub use surface::{Patch, SurfaceShape, WrittenPoint, MAX_PATCHES, MAX_PRECISION};

use crate::syntax::{Section, Span};
use crate::vocabulary::{Command, ModuleInfo};

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
/// The markers ([`GroupIds::MARKERS`]) are internal names that no grammar can write.
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
    /// The names of the markers that open a group, separate its members and close it: not names
    /// of the language (the tokenizer never reads them), so no grammar can write them.
    pub const MARKERS: [&'static str; 3] = ["@<", "@|", "@>"];

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

/// A validated grammar: everything later stages need, nothing they must check again.
#[derive(Clone, Debug, PartialEq)]
pub struct Model {
    pub alphabet: Alphabet,
    /// The axiom as modules with argument expressions (evaluated when derivation starts).
    pub axiom: Vec<SuccessorModule>,
    /// Span of the `axiom:` line.
    pub axiom_span: Span,
    /// The ids of the axiom's modules (of a control module, its header): without parameters, the
    /// axiom's string, which derivation then copies instead of walking [`Model::axiom`].
    pub axiom_ids: Vec<ModuleId>,
    /// For each module id, whether the axiom writes it (in a control module's members too).
    pub in_axiom: Vec<bool>,
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
    /// For each module id: its row of the vocabulary (what the turtle and derivation do with it),
    /// `None` for a module without meaning. `#draw` modules have `F`'s row.
    pub meanings: Vec<Option<&'static ModuleInfo>>,
    /// The particle attributes (`#lifetime`, `#speed`, `#shape`, `#sun`, …) and which modules are
    /// apices and segments; all off by default.
    pub growth: GrowthAttributes,
    /// `#environment`, `#stand` and `#plant`. Only with the feature `environment`: without it (the
    /// first plant's core) the resolver only notes that the grammar declares them
    /// ([`Settings::environment_declared`]).
    #[cfg(feature = "environment")]
    pub environment: EnvironmentSpec,
}

impl Model {
    /// What the turtle does with module `id`.
    pub fn command(&self, id: ModuleId) -> Option<Command> {
        self.meanings.get(id.index()).copied().flatten()?.command()
    }

    /// The index in [`Settings::surfaces`] of the declared surface module `id` draws (`~X`).
    pub fn surface_of(&self, id: ModuleId) -> Option<usize> {
        resolve::surface_index(self.alphabet.name(id), &self.settings.surfaces)
    }

    /// The id of the communication module `?E`, when the grammar writes it.
    #[cfg(feature = "environment")]
    pub fn environment_query(&self) -> Option<ModuleId> {
        (0..self.alphabet.len())
            .map(|i| ModuleId(i as u32))
            .find(|&id| self.command(id) == Some(Command::QueryEnvironment))
    }

    /// True when the grammar writes one of L-Py's commands that place the turtle by coordinates
    /// or draw its frame (`@LineTo`, `@LineRel`, `@OLineTo`, `@OLineRel`, `@R`, `@Frame`), which
    /// only a core with the feature `placing` draws (the first plant's core reads them as
    /// modules without a meaning: by their names, [`crate::vocabulary::PLACING`]).
    pub fn places_by_coordinates(&self) -> bool {
        (0..self.alphabet.len()).any(|i| {
            let name = self.alphabet.name(ModuleId(i as u32));
            crate::vocabulary::PLACING.split(' ').any(|p| p == name)
        })
    }

    /// True when a query module (`?P ?H ?U ?L`) is in the grammar's alphabet.
    pub fn has_queries(&self) -> bool {
        (0..self.alphabet.len()).any(|i| {
            self.command(ModuleId(i as u32))
                .is_some_and(Command::is_query)
        })
    }
}

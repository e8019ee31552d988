//! The environment stage (docs/LANGUAGE.md, "Environment"; issue 47): programs that answer the
//! communication modules `?E` between derivation steps, as lpfg's environmental programs and the
//! open L-systems of Měch and Prusinkiewicz (1996) do.
//!
//! The cycle: after step n (and after the axiom) every plant's string is interpreted; the parts
//! the turtle drew, of all plants, are given to each program ([`Responder::update`]); then every
//! `?E` is a [`Probe`] at its turtle position and each program writes its reply
//! ([`Responder::answer`]); the replies, concatenated in the order the programs are declared,
//! become the `?E`'s parameters, which step n + 1's productions read.
//!
//! Plain data in ([`Part`], [`Probe`]), plain data out (replies, a [`Field`] for the studio's
//! views). Deterministic: a program that draws random numbers takes its seed from its settings.

pub mod light;
pub mod obstacle;
pub mod programs;

pub use programs::{responder, ProgramDefaults};

/// Most bytes the programs of one build may hold at once (their grids and points): a grid that
/// would pass it stops the build with a diagnostic, never a trap.
pub const MAX_ENVIRONMENT_BYTES: usize = 64 << 20;

/// Most work one program may do in one build, all its passes together, for each module of
/// `#max_modules` (so 10⁹ by default, and a grammar raises it as it raises the derivation's
/// work): a test of the distance between a point and a part, an attraction point or another `?E`
/// (every candidate the grids give, near or not), a voxel a part is spread over, and four
/// voxels the light's propagation sweeps (seconds of work: 10⁹ of them take 1.5 to 12 s natively). A
/// program that passes it stops where it is and the build stops with `E0418`, so that many `?E`
/// crowded in one cell with many parts, points or other `?E` (a quadratic pass) ends in the
/// command line and an embedded plant too, where no Stop button is at hand.
pub const ENVIRONMENT_WORK_PER_MODULE: u64 = 200;

/// The work a program has done in a build and the most it may do ([`ENVIRONMENT_WORK_PER_MODULE`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Work {
    pub done: u64,
    pub most: u64,
}

impl Default for Work {
    /// None done, the most of the default `#max_modules`.
    fn default() -> Work {
        Work::for_modules(crate::model::Settings::default().max_modules)
    }
}

impl Work {
    /// None done, the most of a grammar whose `#max_modules` is `max_modules`.
    pub fn for_modules(max_modules: usize) -> Work {
        Work {
            done: 0,
            most: (max_modules as u64).saturating_mul(ENVIRONMENT_WORK_PER_MODULE),
        }
    }

    /// True once it has done more than its most: the program does no more.
    pub fn over(&self) -> bool {
        self.done > self.most
    }

    /// Counts `n` more.
    pub fn add(&mut self, n: u64) {
        self.done = self.done.saturating_add(n);
    }
}

/// One part of a plant as the environment sees it: a segment from `from` to `to` of radius
/// `radius`, or a flat organ (a polygon, a surface, a leaf) at its centre (`from` = `to`) with its
/// area in `area` (0 for a segment).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Part {
    pub from: [f64; 3],
    pub to: [f64; 3],
    pub radius: f64,
    pub area: f64,
    /// Which plant of the stand drew it (0 for a single plant).
    pub plant: u32,
}

/// One `?E` asking: where the turtle is, its frame, and the module's parameters as the
/// productions wrote them (a program may read them as inputs).
#[derive(Clone, Copy, Debug)]
pub struct Probe<'a> {
    pub position: [f64; 3],
    pub heading: [f64; 3],
    pub up: [f64; 3],
    pub args: &'a [f64],
    pub plant: u32,
}

/// A grid of values for the studio's views (the light grid as a slice or heat map): `values` has
/// `dims[0] × dims[1] × dims[2]` entries, x fastest; voxel (i, j, k) spans
/// `origin + cell × (i, j, k)` to `origin + cell × (i + 1, j + 1, k + 1)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    pub origin: [f64; 3],
    pub cell: f64,
    pub dims: [usize; 3],
    pub values: Vec<f32>,
}

/// A program would need more than its share of [`MAX_ENVIRONMENT_BYTES`].
#[derive(Clone, Debug, PartialEq)]
pub struct Exceeded {
    /// What it would have allocated ("a light grid of 512 × 512 × 300 voxels").
    pub what: String,
    pub bytes: usize,
}

/// An environmental program.
pub trait Responder {
    /// How many values it replies with (its row's `reply` in the vocabulary).
    fn reply_len(&self) -> usize;

    /// The plants changed: take in every plant's parts. Checks its memory against `budget`
    /// bytes before it allocates.
    fn update(&mut self, parts: &[Part], budget: usize) -> Result<(), Exceeded>;

    /// Answers every probe: probe `i`'s reply goes to `replies[i * stride + offset ..][..reply_len]`.
    /// All probes at once, since some replies depend on the others (an attraction point goes to
    /// the nearest bud).
    fn answer(&mut self, probes: &[Probe<'_>], replies: &mut [f64], stride: usize, offset: usize);

    /// Bytes it holds now (for the budget of the programs together).
    fn bytes(&self) -> usize;

    /// The work it has done in this build and its most ([`ENVIRONMENT_WORK_PER_MODULE`]); `None`
    /// for a program whose work is one step a `?E`. Once past its most it does no more (its
    /// replies and state are left as they are) and the build stops with `E0418`.
    fn work(&mut self) -> Option<&mut Work> {
        None
    }

    /// What the studio can draw of it: a grid of values, if it keeps one.
    fn field(&self) -> Option<Field> {
        None
    }

    /// What the studio can draw of it as points (the attraction points left), if it keeps some.
    fn points(&self) -> &[[f64; 3]] {
        &[]
    }
}

pub mod attractors;
pub mod collision;
mod grid;
pub(crate) mod settings;
pub mod space;

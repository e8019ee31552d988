//! Particle attributes on top of any branching grammar: Jou, Park and Bahng, "L-system tree with
//! particle attributes" (shared/seeds/002). Each branch is treated as a living particle with a
//! lifetime, a speed, a shape that changes with age, and attractors (the sun, gravity, wind).
//!
//! A stage between derive and the turtle, in three parts:
//! - [`formulas`]: the paper's formulas as pure functions ([`surviving_branches`],
//!   [`share_survivors`], [`rewritings`], [`branch_length`], [`branch_width`], [`variation`],
//!   [`solar_altitude`]) and the thirds of a plant's height;
//! - [`state`]: what each module of the derived string carries ([`ModuleGrowth`]) and how a step
//!   changes it ([`bend`] and [`plan`] before the productions pass, [`follow`] after each pass);
//! - [`GrowthTracker`]: the state of one derivation, which the pipeline drives from derive's
//!   observer, and which gives the turtle its [`Adjustments`]: plain numbers per module (turns
//!   towards the attractors, length and width factors), so the turtle knows nothing of growth.
//!
//! The attributes a grammar sets are resolved by `model` ([`crate::model::GrowthAttributes`]).
//!
//! What the words mean for an arbitrary grammar (docs/LANGUAGE.md, "Growth"):
//! - an **apex** is a module of a kind listed by `#apex`, by default a module that has a production
//!   and that the turtle does not read as a command (`X`, `A`), or, when there is none, any module
//!   that has a production (`F` in edge rewriting); the **branch** of an apex is what it grows into;
//! - a **segment** is a module the turtle draws (`F`, `G`, `#draw` modules, and the modules a
//!   homomorphism rewrites); segments age, stretch, thicken and bend;
//! - the **upper, middle and lower thirds** divide the plant's height (the turtle's Y) between the
//!   lowest and the highest point the turtle reaches; a module's height is the turtle's Y there
//!   (the middle of the move for `F`, `f`, `G`, `g`).
//!
//! No randomness here is free: every `Rand()` comes from the derivation's generator, passed in.

mod adjustments;
pub mod formulas;
pub mod state;
mod tracker;

pub use adjustments::{Adjustments, ModuleAdjustment};
pub use formulas::{
    branch_length, branch_width, paper_round, rewritings, share_survivors, solar_altitude,
    sun_direction, surviving_branches, variation, Heights, Third, MAX_REWRITINGS, TILT,
};
pub use state::{
    bend, born, born_all, follow, plan, GrowthRecord, GrowthState, ModuleGrowth, StepReport,
    StepValues,
};
pub use tracker::GrowthTracker;

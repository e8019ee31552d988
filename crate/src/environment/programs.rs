//! The factory of programs: a resolved `#environment` line ([`ProgramSpec`]) becomes the
//! [`Responder`] that runs it. One arm a program; a program this build does not have yet gives
//! `None`, and the cycle says so with a diagnostic.

use super::obstacle::{Obstacle, Solid};
use super::Responder;
use crate::model::ProgramSpec;
use crate::vocabulary::EnvironmentProgram;

/// What a program may take from the grammar when its settings leave something out.
#[derive(Clone, Copy, Debug)]
pub struct ProgramDefaults {
    /// The grammar's step length (`#step`): the default cell of a light grid, a space radius.
    pub step: f64,
    /// The seed of the build: the default seed of random attraction points.
    pub seed: u64,
}

/// The responder of `spec`, or `None` when this build has no such program.
pub fn responder(spec: &ProgramSpec, defaults: &ProgramDefaults) -> Option<Box<dyn Responder>> {
    match spec.program {
        EnvironmentProgram::Obstacle => Some(Box::new(Obstacle {
            solid: Solid::of(spec)?,
        })),
        // Provisional (the studio's base branch): settings' diagnostics are lost here until the
        // factory returns them.
        EnvironmentProgram::Light => Some(Box::new(
            super::light::Light::new(spec, defaults.step).ok()?,
        )),
        EnvironmentProgram::Space => Some(Box::new(
            super::space::Space::new(spec, defaults.step).ok()?,
        )),
        EnvironmentProgram::Attractors => Some(Box::new(
            super::attractors::Attractors::new(spec, defaults.step, defaults.seed).ok()?,
        )),
    }
}

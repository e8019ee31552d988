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
    let _ = defaults;
    match spec.program {
        EnvironmentProgram::Obstacle => Some(Box::new(Obstacle {
            solid: Solid::of(spec)?,
        })),
        // The light grid (`light.rs`) and the space programs (`space.rs`, `attractors.rs`) add
        // their arms here.
        EnvironmentProgram::Light | EnvironmentProgram::Space | EnvironmentProgram::Attractors => {
            None
        }
    }
}

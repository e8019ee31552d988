//! The factory of programs: a resolved `#environment` line ([`ProgramSpec`]) becomes the
//! [`Responder`] that runs it, one arm a program; a setting a program cannot use is a diagnostic
//! at the setting.

use super::attractors::Attractors;
use super::collision::Collision;
use super::light::Light;
use super::obstacle::{Obstacle, Solid};
use super::space::Space;
use super::Responder;
use crate::diagnostics::Diagnostic;
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

/// The responder of `spec`, or the diagnostic of a setting it cannot use (at the setting).
pub fn responder(
    spec: &ProgramSpec,
    defaults: &ProgramDefaults,
) -> Result<Box<dyn Responder>, Diagnostic> {
    Ok(match spec.program {
        EnvironmentProgram::Obstacle => {
            // The resolver has checked the shape's settings (E0231, E0232): a solid is always
            // made; the message is for a model built by hand without them.
            let solid = Solid::of(spec).ok_or_else(|| {
                Diagnostic::error(
                    "E0232",
                    spec.span.clone(),
                    "this obstacle has no whole shape",
                )
            })?;
            Box::new(Obstacle { solid })
        }
        EnvironmentProgram::Light => Box::new(Light::new(spec, defaults.step)?),
        EnvironmentProgram::Space => Box::new(Space::new(spec, defaults.step)?),
        EnvironmentProgram::Attractors => {
            Box::new(Attractors::new(spec, defaults.step, defaults.seed)?)
        }
        EnvironmentProgram::Collision => Box::new(Collision::new(spec, defaults.step)?),
    })
}

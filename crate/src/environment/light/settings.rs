//! The light program's settings, read from its `#environment light …` line and checked: a
//! setting out of range is an error at the setting (E0239), never a grid of zero cells, a
//! division by zero or a shadow that grows with depth.

use crate::diagnostics::Diagnostic;
use crate::model::ProgramSpec;

use crate::environment::settings::number;
pub use crate::environment::settings::BAD_SETTING;

/// The deepest a shadow may reach, in layers (the `depth` setting's most).
pub const MOST_DEPTH: usize = 64;

/// What the light program computes with, every number checked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSettings {
    /// The voxel's edge, above 0.
    pub cell: f64,
    /// The weights of the diffuse and the direct light, at least 0 and not both 0.
    pub sky: f64,
    pub sun: f64,
    /// The unit direction towards the sun.
    pub sun_direction: [f64; 3],
    /// The shadow one part casts on its own voxel (Palubicki et al.'s a), at least 0.
    pub shadow: f64,
    /// How much the shadow fades a layer down (b), at least 1.
    pub spread: f64,
    /// How many layers below a part its shadow reaches, 1 to [`MOST_DEPTH`].
    pub depth: usize,
    /// The fraction of the sun's beam one part stops, 0 to 1.
    pub absorb: f64,
}

impl LightSettings {
    /// Reads `spec`'s settings; `step_length` is the default cell.
    pub fn read(spec: &ProgramSpec, step_length: f64) -> Result<LightSettings, Diagnostic> {
        let above_zero = |x: f64| x > 0.0;
        let cell = number(spec, "cell", step_length, above_zero, "a number above 0")?;
        let sky = number(spec, "sky", 1.0, |x| x >= 0.0, "a number from 0 up")?;
        let sun = number(spec, "sun", 0.0, |x| x >= 0.0, "a number from 0 up")?;
        if sky + sun <= 0.0 {
            let message = "the light program needs some light: `sky` and `sun` are both 0";
            return Err(Diagnostic::error(BAD_SETTING, spec.span_of("sky"), message));
        }
        let shadow = number(spec, "shadow", 1.0, |x| x >= 0.0, "a number from 0 up")?;
        let spread = number(spec, "spread", 2.0, |x| x >= 1.0, "a number from 1 up")?;
        let absorb = number(
            spec,
            "absorb",
            0.5,
            |x| (0.0..=1.0).contains(&x),
            "from 0 to 1",
        )?;
        let depth = number(
            spec,
            "depth",
            8.0,
            |x| x.fract() == 0.0 && (1.0..=MOST_DEPTH as f64).contains(&x),
            "a whole number from 1 to 64",
        )? as usize;
        Ok(LightSettings {
            cell,
            sky,
            sun,
            sun_direction: direction(spec)?,
            shadow,
            spread,
            depth,
            absorb,
        })
    }
}

/// `sun_direction` as a unit vector (default straight up).
fn direction(spec: &ProgramSpec) -> Result<[f64; 3], Diagnostic> {
    let d = spec.vector("sun_direction").unwrap_or([0.0, 1.0, 0.0]);
    let length = d.iter().map(|x| x * x).sum::<f64>().sqrt();
    if d.iter().all(|x| x.is_finite() && x.abs() <= 1e30) && length > 1e-12 {
        return Ok(d.map(|x| x / length));
    }
    Err(Diagnostic::error(
        BAD_SETTING,
        spec.span_of("sun_direction"),
        "the light's `sun_direction` must be three finite numbers, not all 0",
    ))
}

//! Reading a program's settings into numbers it can use: a setting out of range is an error
//! (E0239) at the setting, never a grid of zero cells or an endless loop.

use crate::diagnostics::Diagnostic;
use crate::model::ProgramSpec;

/// The code of a setting a program cannot use (docs/LANGUAGE.md, "Diagnostic codes").
pub const BAD_SETTING: &str = "E0239";

/// `x` for a message: as written when it is 0 or from 0.001 to below 10^9, else in scientific
/// notation (`1.000e300`, not three hundred digits).
pub fn shown(x: f64) -> String {
    if x == 0.0 || (1e-3..1e9).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:.3e}")
    }
}

/// The number of setting `name`, or `default` when it is not written; finite, at most 1e30, and
/// `ok`, or an error at the setting saying it must be `what` (the program named in the message).
pub fn number(
    spec: &ProgramSpec,
    name: &str,
    default: f64,
    ok: impl Fn(f64) -> bool,
    what: &str,
) -> Result<f64, Diagnostic> {
    let value = spec.number(name).unwrap_or(default);
    if value.is_finite() && value.abs() <= 1e30 && ok(value) {
        return Ok(value);
    }
    let program = spec.info().name;
    let shown = shown(value);
    let message = if spec.number(name).is_some() && ok(value) && value.is_finite() {
        format!("the {program}'s `{name}` must be at most 1e30 (it is {shown})")
    } else if spec.number(name).is_some() {
        format!("the {program}'s `{name}` must be {what} (it is {shown})")
    } else {
        format!("the {program}'s `{name}` is not written and its default ({shown}) is not {what}: write `{name}` and {what}")
    };
    Err(Diagnostic::error(BAD_SETTING, spec.span_of(name), message))
}

/// The number of `name`, or `default` when not written: finite and above 0.
pub fn positive(spec: &ProgramSpec, name: &str, default: f64) -> Result<f64, Diagnostic> {
    number(spec, name, default, |x| x > 0.0, "a number above 0")
}

/// The whole number of `name` from 0 to `most`, or `default` when not written.
pub fn whole(spec: &ProgramSpec, name: &str, default: u64, most: u64) -> Result<u64, Diagnostic> {
    let Some(value) = spec.number(name) else {
        return Ok(default);
    };
    if value.fract() == 0.0 && (0.0..=most as f64).contains(&value) {
        return Ok(value as u64);
    }
    Err(Diagnostic::error(
        BAD_SETTING,
        spec.span_of(name),
        format!(
            "`{name}` must be a whole number from 0 to {most} (it is {})",
            shown(value)
        ),
    ))
}

/// The three numbers of `name`, finite; `None` when not written.
pub fn point(spec: &ProgramSpec, name: &str) -> Result<Option<[f64; 3]>, Diagnostic> {
    match spec.vector(name) {
        Some(p) if p.iter().all(|x| x.is_finite() && x.abs() <= 1e30) => Ok(Some(p)),
        Some(_) => Err(Diagnostic::error(
            BAD_SETTING,
            spec.span_of(name),
            format!("`{name}` must be three finite numbers within ±1e30"),
        )),
        None => Ok(None),
    }
}

#[cfg(test)]
pub mod tests {
    use crate::model::{ProgramSpec, SettingValue};
    use crate::vocabulary::{EnvironmentProgram, EnvironmentShape};

    /// A program's line as the resolver would give it: `settings` as (word, numbers).
    pub fn spec(
        program: EnvironmentProgram,
        shape: Option<EnvironmentShape>,
        settings: &[(&'static str, &[f64])],
    ) -> ProgramSpec {
        ProgramSpec {
            program,
            shape,
            settings: settings
                .iter()
                .enumerate()
                .map(|(i, (name, values))| SettingValue {
                    name,
                    values: values.to_vec(),
                    span: 10 * i..10 * i + 5,
                })
                .collect(),
            span: 0..100,
        }
    }
}

#[cfg(test)]
mod messages {
    use super::tests::spec;
    use super::*;
    use crate::vocabulary::EnvironmentProgram;

    #[test]
    fn a_huge_setting_is_said_to_be_too_large_in_a_few_digits() {
        let huge = spec(EnvironmentProgram::Space, None, &[("radius", &[1e300])]);
        let e = positive(&huge, "radius", 1.0).unwrap_err();
        // It is above 0: the message names the bound it passed, not the one it meets.
        assert!(e.message.contains("must be at most 1e30"), "{}", e.message);
        assert!(e.message.ends_with("(it is 1.000e300)"), "{}", e.message);
        let negative = spec(EnvironmentProgram::Space, None, &[("radius", &[-1e300])]);
        let e = positive(&negative, "radius", 1.0).unwrap_err();
        assert!(
            e.message
                .contains("must be a number above 0 (it is -1.000e300)"),
            "{}",
            e.message
        );
        assert_eq!(shown(0.25), "0.25");
        assert_eq!(shown(0.0), "0");
        assert_eq!(shown(4e20), "4.000e20");
    }
}

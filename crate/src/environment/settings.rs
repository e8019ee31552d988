//! Reading a program's settings into numbers it can use: a setting out of range is an error
//! (E0239) at the setting, never a grid of zero cells or an endless loop.

use crate::diagnostics::Diagnostic;
use crate::model::ProgramSpec;

/// The code of a setting a program cannot use (docs/LANGUAGE.md, "Diagnostic codes").
pub const BAD_SETTING: &str = "E0239";

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
    let message = if spec.number(name).is_some() {
        format!("the {program}'s `{name}` must be {what} (it is {value})")
    } else {
        format!("the {program}'s `{name}` is not written and its default ({value}) is not {what}: write `{name}` and {what}")
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
        format!("`{name}` must be a whole number from 0 to {most} (it is {value})"),
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

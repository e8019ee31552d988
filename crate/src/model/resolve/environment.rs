//! `#environment`, `#stand` and `#plant` (docs/LANGUAGE.md, "Environment"): the programs that
//! answer `?E` and the places of a stand's plants, read into [`EnvironmentSpec`] by the words of
//! the vocabulary (`ENVIRONMENT_PROGRAMS`, `STAND_LAYOUTS`), with a diagnostic at the word that is
//! wrong.

use super::directives::words;
use super::Resolver;
use crate::diagnostics::Diagnostic;
use crate::maths;
use crate::model::{EnvironmentSpec, PlantPlace, ProgramSpec, SettingValue, MAX_STAND_PLANTS};
use crate::syntax::{Directive, SourceFile, Span};
use crate::vocabulary::{
    environment_program_named, environment_shape_named, stand_layout_named, DirectiveKind,
    EnvironmentSetting, EnvironmentShape, StandLayout, StandLayoutInfo,
};
use rand::{RngExt, SeedableRng};

/// Tries to place one random plant before a random stand gives up (its spacing too wide).
const PLACE_TRIES: usize = 2_000;

impl Resolver {
    /// The file's environment: its programs, in the order written, and its plants (every
    /// `#stand`'s, then every `#plant`'s, in the order written). `seed`: the grammar's, for a random
    /// stand without a seed of its own.
    pub(super) fn environment(&mut self, file: &SourceFile, seed: u64) -> EnvironmentSpec {
        let mut spec = EnvironmentSpec::default();
        let mut places: Vec<[f64; 3]> = Vec::new();
        let mut last_stand: Option<Span> = None;
        for d in &file.directives {
            match d.kind {
                Some(DirectiveKind::Environment) => {
                    if let Some(program) = self.program_line(d) {
                        spec.programs.push(program);
                    }
                }
                Some(DirectiveKind::Stand) => {
                    last_stand = Some(line_span(d));
                    if let Some(stand) = self.stand_line(d, seed) {
                        places.extend(stand);
                    }
                }
                Some(DirectiveKind::Plant) => {
                    last_stand = Some(line_span(d));
                    if let Some(place) = self.plant_line(d) {
                        places.push(place);
                    }
                }
                _ => {}
            }
            if places.len() > MAX_STAND_PLANTS {
                let span = last_stand.clone().unwrap_or_else(|| line_span(d));
                self.diagnostics.push(Diagnostic::error(
                    "E0235",
                    span,
                    format!(
                        "the stand has {} plants or more, above the limit of {MAX_STAND_PLANTS}; \
                         plant fewer (each plant is a whole derivation)",
                        places.len()
                    ),
                ));
                places.clear();
                break;
            }
        }
        spec.plants = places
            .into_iter()
            .enumerate()
            .map(|(i, position)| PlantPlace {
                position,
                index: i as u32,
            })
            .collect();
        spec
    }

    /// One `#environment PROGRAM [SHAPE] word numbers…` line.
    fn program_line(&mut self, d: &Directive) -> Option<ProgramSpec> {
        let words = words(d);
        let Some(first) = words.first() else {
            self.directive_error("E0230", d, program_usage(d));
            return None;
        };
        let Some(info) = environment_program_named(&first.args) else {
            let message = format!(
                "unknown environment program '{}'; {}",
                first.args,
                program_usage(d)
            );
            self.directive_error("E0230", first, message);
            return None;
        };
        let mut rest = &words[1..];
        let named = rest
            .first()
            .and_then(|w| environment_shape_named(&w.args).map(|s| (s, w)));
        let shape = match named {
            Some((s, w)) if !info.shapes.contains(&s.shape) => {
                let message = format!(
                    "{} takes {}, not '{}'",
                    info.name,
                    shapes_of(info.shapes),
                    s.name
                );
                self.directive_error("E0230", w, message);
                return None;
            }
            Some((s, _)) => {
                rest = &rest[1..];
                Some(s.shape)
            }
            None if !info.shapes.is_empty() => {
                let message = format!("{} needs a shape: {}", info.name, shapes_of(info.shapes));
                self.directive_error("E0230", first, message);
                return None;
            }
            None => None,
        };
        let settings = self.settings(d, rest, info.settings, info.name)?;
        let spec = ProgramSpec {
            program: info.program,
            shape,
            settings,
            span: line_span(d),
        };
        self.check_shape(&spec)?;
        Some(spec)
    }

    /// Setting words with their numbers, each checked against `known`; `None` (with the
    /// diagnostics) when one is wrong.
    fn settings(
        &mut self,
        d: &Directive,
        words: &[Directive],
        known: &[EnvironmentSetting],
        owner: &str,
    ) -> Option<Vec<SettingValue>> {
        let mut settings = Vec::new();
        let mut k = 0;
        while k < words.len() {
            let word = &words[k];
            let Some(setting) = known.iter().find(|s| s.name == word.args) else {
                let names: Vec<&str> = known.iter().map(|s| s.name).collect();
                let message = format!(
                    "'{}' is not a setting of {owner}; it takes {}",
                    word.args,
                    names.join(", ")
                );
                self.directive_error("E0231", word, message);
                return None;
            };
            let numbers = words[k + 1..]
                .iter()
                .take_while(|w| known.iter().all(|s| s.name != w.args))
                .count();
            let end = words.get(k + numbers).unwrap_or(word).args_span.end;
            let span = word.args_span.start..end;
            if numbers != setting.numbers {
                let message = format!(
                    "{} '{}' takes {} number{}, found {numbers}",
                    d.written,
                    setting.name,
                    setting.numbers,
                    if setting.numbers == 1 { "" } else { "s" }
                );
                self.diagnostics
                    .push(Diagnostic::error("E0231", span, message));
                return None;
            }
            let mut values = Vec::with_capacity(numbers);
            for w in &words[k + 1..=k + numbers] {
                values.push(self.number(w)?);
            }
            settings.push(SettingValue {
                name: setting.name,
                values,
                span,
            });
            k += numbers + 1;
        }
        Some(settings)
    }

    /// `E0232` for a shape without the settings it needs; `E0231` for a radius not above 0, a box
    /// whose corners are not in order, a zero normal.
    fn check_shape(&mut self, spec: &ProgramSpec) -> Option<()> {
        let Some(shape) = spec.shape else {
            return Some(());
        };
        let missing: Vec<&str> = shape
            .required()
            .iter()
            .copied()
            .filter(|name| spec.setting(name).is_none())
            .collect();
        if !missing.is_empty() {
            self.diagnostics.push(Diagnostic::error(
                "E0232",
                spec.span.clone(),
                format!(
                    "a {} needs {}: write '{}'",
                    shape.name(),
                    missing.join(" and "),
                    missing
                        .iter()
                        .map(|m| format!("{m} …"))
                        .collect::<Vec<_>>()
                        .join(" ")
                ),
            ));
            return None;
        }
        let bad = match shape {
            EnvironmentShape::Box => {
                let (min, max) = (spec.vector("min")?, spec.vector("max")?);
                (0..3)
                    .any(|i| min[i] > max[i])
                    .then_some(("max", "a box's max must not be below its min on any axis"))
            }
            EnvironmentShape::Sphere => (spec.number("radius")? <= 0.0)
                .then_some(("radius", "a sphere's radius must be above 0")),
            EnvironmentShape::Plane => spec
                .vector("normal")?
                .iter()
                .all(|&c| c == 0.0)
                .then_some(("normal", "a plane's normal must not be 0 0 0")),
        };
        if let Some((name, message)) = bad {
            let span = spec.span_of(name);
            self.diagnostics
                .push(Diagnostic::error("E0231", span, message.to_string()));
            return None;
        }
        Some(())
    }

    /// One `#stand LAYOUT counts… settings…` line: the places of its plants.
    fn stand_line(&mut self, d: &Directive, seed: u64) -> Option<Vec<[f64; 3]>> {
        let words = words(d);
        let usage = || format!("{} needs {}", d.written, DirectiveKind::Stand.info().usage);
        let Some(layout) = words.first().and_then(|w| stand_layout_named(&w.args)) else {
            let message = match words.first() {
                Some(w) => format!("unknown stand '{}'; {}", w.args, usage()),
                None => usage(),
            };
            let at = words.first().unwrap_or(d);
            self.directive_error("E0233", at, message);
            return None;
        };
        let counts = self.stand_counts(d, &words, layout)?;
        let rest = &words[1 + layout.counts.len()..];
        let settings = self.settings(d, rest, layout.settings, layout.name)?;
        if let Some(name) = layout
            .required
            .iter()
            .find(|name| settings.iter().all(|s| s.name != **name))
        {
            let message = format!(
                "{} {} needs '{name} …'; {}",
                d.written,
                layout.name,
                usage()
            );
            self.directive_error("E0233", d, message);
            return None;
        }
        // In u64: two counts of up to u32::MAX multiply without overflow on wasm32.
        let total = counts.iter().fold(1u64, |t, &n| t.saturating_mul(n as u64));
        if total > MAX_STAND_PLANTS as u64 {
            self.directive_error(
                "E0235",
                d,
                format!(
                    "a stand of {total} plants is above the limit of {MAX_STAND_PLANTS}; plant \
                     fewer (each plant is a whole derivation)"
                ),
            );
            return None;
        }
        let value = |name: &str| {
            settings
                .iter()
                .find(|s| s.name == name)
                .map(|s| &s.values[..])
        };
        let spacing = value("spacing").map_or(0.0, |v| v[0]);
        match layout.layout {
            StandLayout::Row => Some(lattice(counts[0], 1, spacing)),
            StandLayout::Grid => Some(lattice(counts[0], counts[1], spacing)),
            StandLayout::Random => {
                let size = value("size").map_or([0.0, 0.0], |v| [v[0], v[1]]);
                let seed = value("seed").map_or(seed, |v| v[0].max(0.0) as u64);
                let placed = random_places(counts[0], size, spacing, seed);
                if placed.len() < counts[0] {
                    self.random_stand_error(d, layout, placed.len(), counts[0]);
                    return None;
                }
                Some(placed)
            }
        }
    }

    /// The whole numbers after a `#stand`'s layout word (`N`, or `NX NZ`), each at least 1.
    fn stand_counts(
        &mut self,
        d: &Directive,
        words: &[Directive],
        layout: &StandLayoutInfo,
    ) -> Option<Vec<usize>> {
        let usage = || format!("{} needs {}", d.written, DirectiveKind::Stand.info().usage);
        let mut counts = Vec::new();
        for (k, name) in layout.counts.iter().enumerate() {
            let Some(w) = words.get(k + 1) else {
                self.directive_error(
                    "E0233",
                    d,
                    format!("{} {} needs {name}; {}", d.written, layout.name, usage()),
                );
                return None;
            };
            // Any count is read (up to u32::MAX), so that one past the limit is `E0235` with the
            // stand's size, as two whose product is.
            let n = self.whole(w, u32::MAX as u64)?;
            if n == 0 {
                self.directive_error(
                    "E0233",
                    w,
                    format!("{} {} needs at least one plant", d.written, layout.name),
                );
                return None;
            }
            counts.push(n as usize);
        }
        Some(counts)
    }

    /// `E0235`: a random stand whose plants do not fit `spacing` apart.
    fn random_stand_error(
        &mut self,
        d: &Directive,
        layout: &StandLayoutInfo,
        placed: usize,
        n: usize,
    ) {
        self.directive_error(
            "E0235",
            d,
            format!(
                "{} {}: only {placed} of {n} plants fit at least 'spacing' apart in 'size'; \
                 lower the spacing, enlarge the size or plant fewer",
                d.written, layout.name
            ),
        );
    }

    /// One `#plant x y z` line.
    fn plant_line(&mut self, d: &Directive) -> Option<[f64; 3]> {
        let words = words(d);
        if words.len() != 3 {
            let message = format!("{} needs x y z, found {} values", d.written, words.len());
            self.directive_error("E0234", d, message);
            return None;
        }
        let mut place = [0.0; 3];
        for (p, w) in place.iter_mut().zip(&words) {
            *p = self.number(w)?;
        }
        Some(place)
    }
}

/// The line from `#` to its last argument.
fn line_span(d: &Directive) -> Span {
    d.name_span.start..d.args_span.end.max(d.name_span.end)
}

/// What `#environment` takes, for messages.
fn program_usage(d: &Directive) -> String {
    format!(
        "{} needs {}",
        d.written,
        DirectiveKind::Environment.info().usage
    )
}

/// `box, sphere or plane`.
fn shapes_of(shapes: &[EnvironmentShape]) -> String {
    let names: Vec<&str> = shapes.iter().map(|s| s.name()).collect();
    match names.split_last() {
        Some((last, [])) => last.to_string(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
        None => "no shape".to_string(),
    }
}

/// `nx × nz` places `spacing` apart in the x–z plane, centred on the origin, x fastest.
fn lattice(nx: usize, nz: usize, spacing: f64) -> Vec<[f64; 3]> {
    let centre = |n: usize, i: usize| (i as f64 - (n as f64 - 1.0) / 2.0) * spacing;
    (0..nz)
        .flat_map(|k| (0..nx).map(move |i| [centre(nx, i), 0.0, centre(nz, k)]))
        .collect()
}

/// Up to `n` places in a `size[0]` × `size[1]` rectangle centred on the origin, each at least
/// `spacing` from the others (dart throwing: fewer than `n` when they do not fit).
fn random_places(n: usize, size: [f64; 2], spacing: f64, seed: u64) -> Vec<[f64; 3]> {
    let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(seed);
    let mut places: Vec<[f64; 3]> = Vec::with_capacity(n);
    let far_enough = |p: &[f64; 3], places: &[[f64; 3]]| {
        places
            .iter()
            .all(|q| maths::hypot(p[0] - q[0], p[2] - q[2]) >= spacing)
    };
    for _ in 0..n {
        let found = (0..PLACE_TRIES).find_map(|_| {
            let x = (rng.random::<f64>() - 0.5) * size[0].abs();
            let z = (rng.random::<f64>() - 0.5) * size[1].abs();
            let p = [x, 0.0, z];
            far_enough(&p, &places).then_some(p)
        });
        match found {
            Some(p) => places.push(p),
            None => break,
        }
    }
    places
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_lattice_is_centred_and_spaced() {
        let row = lattice(3, 1, 2.0);
        assert_eq!(
            row,
            vec![[-2.0, 0.0, 0.0], [0.0, 0.0, 0.0], [2.0, 0.0, 0.0]]
        );
        let grid = lattice(2, 2, 1.0);
        assert_eq!(grid[0], [-0.5, 0.0, -0.5]);
        assert_eq!(grid[3], [0.5, 0.0, 0.5]);
    }

    #[test]
    fn random_places_keep_their_spacing_and_their_seed() {
        let a = random_places(20, [10.0, 10.0], 1.0, 7);
        assert_eq!(a.len(), 20);
        assert_eq!(a, random_places(20, [10.0, 10.0], 1.0, 7));
        assert_ne!(a, random_places(20, [10.0, 10.0], 1.0, 8));
        for (i, p) in a.iter().enumerate() {
            assert!(p[0].abs() <= 5.0 && p[2].abs() <= 5.0);
            for q in &a[..i] {
                assert!(maths::hypot(p[0] - q[0], p[2] - q[2]) >= 1.0);
            }
        }
        assert!(random_places(50, [1.0, 1.0], 1.0, 7).len() < 50);
    }
}

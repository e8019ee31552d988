//! Directive arguments, read by the kinds the vocabulary declares for them
//! ([`crate::vocabulary::DIRECTIVES`]) and applied to the settings.

use super::scope::Slots;
use super::Resolver;
use crate::diagnostics::Diagnostic;
use crate::model::settings::directive_default;
use crate::model::{
    Bend, Env, GrowthAttributes, Lifetime, ModuleId, Program, Settings, Shape, ShapeWidth, Speed,
    Sun,
};
use crate::number::Decimal;
use crate::syntax::{Directive, SourceFile};
use crate::vocabulary::{DirectiveInfo, DirectiveKind, ParamKind, Season};
use glam::DVec3;
use std::collections::HashMap;

/// Everything the directives of a file set.
pub(super) struct DirectiveValues {
    pub settings: Settings,
    pub homomorphism_depth: u32,
    pub decomposition_depth: u32,
    pub ignore: Vec<ModuleId>,
    pub consider: Option<Vec<ModuleId>>,
    pub apex: Vec<ModuleId>,
    pub growth: GrowthAttributes,
}

impl Default for DirectiveValues {
    fn default() -> Self {
        DirectiveValues {
            settings: Settings::default(),
            homomorphism_depth: directive_default(DirectiveKind::HomomorphismDepth, 0) as u32,
            decomposition_depth: directive_default(DirectiveKind::DecompositionDepth, 0) as u32,
            ignore: Vec::new(),
            consider: None,
            apex: Vec::new(),
            growth: GrowthAttributes::default(),
        }
    }
}

/// One argument, read by its parameter's kind.
enum Arg {
    Number(f64),
    Program(Program),
    Season(Season),
}

/// The arguments of one directive, the longest form's length (missing optional ones take their
/// defaults).
struct Args(Vec<Arg>);

impl Args {
    fn number(&self, k: usize) -> f64 {
        match self.0.get(k) {
            Some(Arg::Number(v)) => *v,
            _ => 0.0,
        }
    }

    fn numbers<const N: usize>(&self, first: usize) -> [f64; N] {
        std::array::from_fn(|k| self.number(first + k))
    }

    fn program(&mut self, k: usize) -> Option<Program> {
        match std::mem::replace(self.0.get_mut(k)?, Arg::Number(0.0)) {
            Arg::Program(p) => Some(p),
            _ => None,
        }
    }

    fn season(&self, k: usize) -> Season {
        match self.0.get(k) {
            Some(Arg::Season(s)) => *s,
            _ => Season::Equinox,
        }
    }
}

/// The words of a directive's arguments, each as a directive of its own (for spans). Each word
/// carries only its own text: a copy of the whole arguments (and points, modules) per word made a
/// directive of a million numbers take minutes (issue 50).
pub(super) fn words(d: &Directive) -> Vec<Directive> {
    let bare = Directive {
        args: String::new(),
        expr: None,
        modules: Vec::new(),
        points: Vec::new(),
        point_spans: Vec::new(),
        ..d.clone()
    };
    d.args
        .split_whitespace()
        .map(|word| {
            let offset = word.as_ptr() as usize - d.args.as_ptr() as usize;
            Directive {
                args: word.to_string(),
                args_span: d.args_span.start + offset..d.args_span.start + offset + word.len(),
                ..bare.clone()
            }
        })
        .collect()
}

/// 2^64, the first whole number above `u64::MAX`.
const TWO_TO_64: f64 = 18_446_744_073_709_551_616.0;

/// Longest excerpt of a directive's argument a message quotes (bytes: 40 characters of ASCII).
const MAX_QUOTED: usize = 40;

/// `text` as a message quotes it: whole when short, else its first [`MAX_QUOTED`] bytes (to a
/// character's start) and an ellipsis (a 200 KB argument is not repeated in a message; the span
/// shows it all).
pub(super) fn excerpt(text: &str) -> String {
    if text.len() <= MAX_QUOTED {
        return text.to_string();
    }
    let mut cut = MAX_QUOTED;
    while !text.is_char_boundary(cut) {
        cut -= 1;
    }
    let mut quoted = text[..cut].to_string();
    quoted.push('…');
    quoted
}

/// `#name needs 'A B' or 'A B C' (what they mean)`: the forms and their explanation.
fn usage(d: &Directive, info: &DirectiveInfo) -> String {
    let explanation = if info.usage.starts_with('(') {
        format!(" {}", info.usage)
    } else {
        info.usage.to_string()
    };
    format!("{} needs {}{explanation}", d.written, info.forms_text())
}

impl Resolver {
    /// Reads every directive of `file` into settings, limits, module lists and growth attributes.
    pub(super) fn directives(&mut self, file: &SourceFile) -> DirectiveValues {
        let mut values = DirectiveValues::default();
        // The last directive of each name that is not repeatable: a hash, not a search of the
        // directives before (issue 50, 7: 50,000 `#ignore` lines took 9 s in the first plant's
        // core, whose optimisation for size does not take the search out of the loop).
        let mut last_set: HashMap<&str, &Directive> = HashMap::new();
        for d in &file.directives {
            let repeatable = d.kind.is_some_and(|k| k.info().repeatable);
            if !repeatable {
                if let Some(previous) = last_set.insert(&d.name, d) {
                    self.diagnostics.push(Diagnostic::warning(
                        "E0201",
                        d.name_span.clone(),
                        format!(
                            "#{} is set twice; this one replaces the value on line {}",
                            d.name,
                            file.line(previous.name_span.start)
                        ),
                    ));
                }
            }
            match d.kind {
                Some(kind) => self.directive(kind, d, &mut values),
                None => self.diagnostics.push(Diagnostic::error(
                    "E0200",
                    d.name_span.clone(),
                    format!("unknown directive '#{}'", d.name),
                )),
            }
        }
        if !values.ignore.is_empty() && values.consider.is_some() {
            let last = file.directives.iter().rev().find(|d| {
                matches!(
                    d.kind,
                    Some(DirectiveKind::Ignore | DirectiveKind::Consider)
                )
            });
            self.diagnostics.push(Diagnostic::error(
                "E0206",
                last.map_or(0..0, |d| d.name_span.clone()),
                "#ignore and #consider cannot both be used: one says what to skip, the other what to keep",
            ));
        }
        values
    }

    /// Applies one directive.
    fn directive(&mut self, kind: DirectiveKind, d: &Directive, v: &mut DirectiveValues) {
        use DirectiveKind as K;
        let s = &mut v.settings;
        let whole_max =
            |kind: DirectiveKind| kind.info().params()[0].range.map_or(0, |r| r.1 as u64);
        match kind {
            K::Angle => s.angle = self.number(d).unwrap_or(s.angle),
            K::Heading => s.heading = self.number(d).unwrap_or(s.heading),
            K::Step => s.step = self.number(d).unwrap_or(s.step),
            K::Width => {
                s.width = self.number(d).unwrap_or(s.width);
                s.width_given = true;
            }
            K::WidthStep => s.width_step = self.number(d).unwrap_or(s.width_step),
            K::WidthUnit => s.width_unit = self.width_unit(d).or(s.width_unit),
            K::Tropism => {
                if let Some(a) = self.arguments(d) {
                    let [x, y, z, e] = a.numbers(0);
                    s.tropism = (DVec3::new(x, y, z), e);
                }
            }
            K::Color => {
                s.start_color_given |= self.color(d, kind.info(), &mut s.palette);
            }
            K::Iterations => {
                if let Some(n) = self.whole(d, whole_max(kind)) {
                    s.iterations = n as u32;
                    s.iterations_span = Some(d.name_span.start..d.args_span.end);
                }
            }
            K::Seed => s.seed = self.whole(d, whole_max(kind)).unwrap_or(s.seed),
            K::MaxModules => {
                s.max_modules = self
                    .whole(d, whole_max(kind))
                    .map_or(s.max_modules, |n| n.max(1) as usize)
            }
            K::MaxSteps => {
                s.max_steps = self
                    .whole(d, whole_max(kind))
                    .map_or(s.max_steps, |n| n as u32)
            }
            K::HomomorphismDepth => {
                v.homomorphism_depth = self
                    .whole(d, whole_max(kind))
                    .map_or(v.homomorphism_depth, |n| n as u32)
            }
            K::DecompositionDepth => {
                v.decomposition_depth = self
                    .whole(d, whole_max(kind))
                    .map_or(v.decomposition_depth, |n| n as u32)
            }
            K::Module | K::Define | K::Random | K::Curve | K::Table => {}
            K::Surface | K::Patch => {}
            K::Environment | K::Stand | K::Plant => {}
            K::Draw => s.draw.extend(self.module_ids(d)),
            K::Ignore => v.ignore.extend(self.module_ids(d)),
            K::Apex => v.apex.extend(self.module_ids(d)),
            K::Consider => v.consider = Some(self.module_ids(d)),
            K::Lifetime => v.growth.lifetime = self.lifetime(d),
            K::Speed => v.growth.speed = self.speed(d),
            K::Shape => v.growth.shape = self.shape(d),
            K::ShapeWidth => v.growth.shape_width = self.shape_width(d),
            K::Sun => v.growth.sun = self.sun(d),
            K::Gravity => v.growth.gravity = self.bend(d, kind),
            K::Wind => v.growth.wind = self.bend(d, kind),
            K::TerminalAge => self.terminal_ages(d, s),
            K::Dt => self.dt_directive(d, s),
        }
    }

    fn module_ids(&mut self, d: &Directive) -> Vec<ModuleId> {
        d.modules
            .iter()
            .map(|m| self.alphabet.intern(&m.name))
            .collect()
    }

    /// Reads the arguments of a directive written as words, by the kinds of the form whose length
    /// they have; the missing optional ones of a shorter form take their defaults. Reports a wrong
    /// number of words, and every word that is not of its kind.
    fn arguments(&mut self, d: &Directive) -> Option<Args> {
        let info = d.kind?.info();
        let words = words(d);
        let Some(form) = info.forms.iter().find(|f| f.len() == words.len()) else {
            let message = format!("{}, found {} values", usage(d, info), words.len());
            self.directive_error(info.count_code, d, message);
            return None;
        };
        let mut args = Vec::new();
        let mut ok = true;
        for (word, param) in words.iter().zip(form.iter()) {
            let arg = match param.kind {
                ParamKind::Number => self.number(word).map(Arg::Number),
                ParamKind::Whole => {
                    let max = param.range.map_or(u64::MAX, |r| r.1 as u64);
                    self.whole(word, max).map(|n| Arg::Number(n as f64))
                }
                ParamKind::StepExpression => self.step_program(word).map(Arg::Program),
                ParamKind::Season => match Season::named(&word.args) {
                    Some(s) => Some(Arg::Season(s)),
                    None => {
                        let message =
                            format!("{}; '{}' is not a season", usage(d, info), word.args);
                        self.directive_error(info.count_code, word, message);
                        None
                    }
                },
                ParamKind::Expression
                | ParamKind::Name
                | ParamKind::Modules
                | ParamKind::Points
                | ParamKind::Ages
                | ParamKind::Surface
                | ParamKind::Words => None,
            };
            match arg {
                Some(arg) => args.push(arg),
                None => ok = false,
            }
        }
        if !ok {
            return None;
        }
        // A shorter form is the start of the longest: the rest take their defaults.
        let longest = info.params();
        if longest.starts_with(form) {
            for param in &longest[form.len()..] {
                if let Some(value) = param.default_value(|_| 0.0) {
                    args.push(Arg::Number(value));
                }
            }
        }
        Some(Args(args))
    }

    /// `#color i r g b` sets one entry of the palette; `#color i j r g b r g b` sets entries
    /// i..=j to a linear ramp between two colours. True when it set entry 0.
    fn color(&mut self, d: &Directive, info: &DirectiveInfo, palette: &mut Vec<[f32; 3]>) -> bool {
        let Some(args) = self.arguments(d) else {
            return false;
        };
        let (first, last, from, to) = match args.0.len() {
            4 => {
                let [i, r, g, b] = args.numbers(0);
                (i, i, [r, g, b], [r, g, b])
            }
            _ => {
                let [i, j, r0, g0, b0, r1, g1, b1] = args.numbers(0);
                (i, j, [r0, g0, b0], [r1, g1, b1])
            }
        };
        let in_range = |v: f64, k: usize| {
            info.params()[k]
                .range
                .is_some_and(|(lo, hi)| v >= lo && v <= hi)
        };
        let index_ok = |v: f64| v.fract() == 0.0 && in_range(v, 0);
        let component_ok = |v: &f64| in_range(*v, 2);
        if !index_ok(first)
            || !index_ok(last)
            || last < first
            || !from.iter().all(component_ok)
            || !to.iter().all(component_ok)
        {
            let message = format!("{}, with first <= last", usage(d, info));
            self.directive_error(info.count_code, d, message);
            return false;
        }
        let (first, last) = (first as usize, last as usize);
        // Entries between the old end and `first` keep the colours they had by wrapping.
        let old = palette.len();
        while palette.len() <= last {
            let wrapped = palette[palette.len() % old];
            palette.push(wrapped);
        }
        for (offset, entry) in palette[first..=last].iter_mut().enumerate() {
            let t = if last == first {
                0.0
            } else {
                offset as f64 / (last - first) as f64
            };
            *entry = std::array::from_fn(|k| ((from[k] + (to[k] - from[k]) * t) / 255.0) as f32);
        }
        first == 0
    }

    /// `#lifetime MB VB [pu pm pl]`.
    fn lifetime(&mut self, d: &Directive) -> Option<Lifetime> {
        let mut a = self.arguments(d)?;
        let probabilities = a.numbers(2);
        if probabilities.iter().any(|x| *x < 0.0) || probabilities.iter().all(|x| *x == 0.0) {
            let message = format!(
                "{}'s shares of the thirds must be 0 or more, and not all 0",
                d.written
            );
            self.directive_error("E0209", d, message);
            return None;
        }
        Some(Lifetime {
            mean: a.program(0)?,
            variance: a.program(1)?,
            probabilities,
        })
    }

    /// `#speed SM VR [PFu PFm PFl]`.
    fn speed(&mut self, d: &Directive) -> Option<Speed> {
        let mut a = self.arguments(d)?;
        Some(Speed {
            positional: a.numbers(2),
            mean: a.program(0)?,
            variance: a.program(1)?,
        })
    }

    /// `#shape GR m [VR]`: a growth rate above 0 other than 1 and a maturity from 1.
    fn shape(&mut self, d: &Directive) -> Option<Shape> {
        let a = self.arguments(d)?;
        let [rate, maturity, variance] = a.numbers(0);
        if rate <= 0.0 || rate == 1.0 || maturity == 0.0 {
            let info = d.kind?.info();
            self.directive_error(info.count_code, d, usage(d, info));
            return None;
        }
        Some(Shape {
            rate,
            maturity: maturity as u32,
            variance,
        })
    }

    /// `#shape_width [VR [PFu PFm PFl]]`.
    fn shape_width(&mut self, d: &Directive) -> Option<ShapeWidth> {
        let a = self.arguments(d)?;
        Some(ShapeWidth {
            variance: a.number(0),
            positional: a.numbers(1),
        })
    }

    /// `#sun latitude season angle`, the latitude within its range.
    fn sun(&mut self, d: &Directive) -> Option<Sun> {
        let a = self.arguments(d)?;
        let info = d.kind?.info();
        let latitude = a.number(0);
        let within = info.params()[0]
            .range
            .is_none_or(|(lo, hi)| (lo..=hi).contains(&latitude));
        if !within {
            let word = &words(d)[0];
            self.directive_error(info.count_code, word, usage(d, info));
            return None;
        }
        Some(Sun {
            latitude,
            season: a.season(1),
            angle: a.number(2),
        })
    }

    /// `#gravity angle [variation]` (towards −Y), or `#wind x z angle [variation]` (towards the
    /// horizontal direction (x, 0, z), which must not be 0 0).
    fn bend(&mut self, d: &Directive, kind: DirectiveKind) -> Option<Bend> {
        let a = self.arguments(d)?;
        let (direction, first) = if kind == DirectiveKind::Wind {
            let v = DVec3::new(a.number(0), 0.0, a.number(1));
            if v.length() == 0.0 {
                let info = kind.info();
                self.directive_error(info.count_code, d, usage(d, info));
                return None;
            }
            (v.normalize(), 2)
        } else {
            (DVec3::NEG_Y, 0)
        };
        Some(Bend {
            direction,
            angle: a.number(first),
            variance: a.number(first + 1),
        })
    }

    /// An argument that may change from step to step: an expression over `NumIt` (the step about
    /// to run), `MaxIt` and `#define`d names, drawing no random number.
    fn step_program(&mut self, word: &Directive) -> Option<Program> {
        let expr = match crate::syntax::parse_expression(&word.args, word.args_span.start) {
            Ok(e) => e,
            Err(e) => {
                self.diagnostics.push(e);
                return None;
            }
        };
        let program = self.compile(&expr, &Slots::default())?;
        if program.random {
            self.directive_error(
                "E0209",
                word,
                format!(
                    "{} cannot draw random numbers here: its own Rand() is drawn at every step",
                    word.written
                ),
            );
            return None;
        }
        Some(program)
    }

    /// The value of a directive's argument: a number or a constant expression (`#angle 360 / n`
    /// with `#define n 7`); the reason when it is not one.
    fn constant(&mut self, d: &Directive) -> Result<f64, String> {
        if d.args.is_empty() {
            return Err("nothing".into());
        }
        let written = excerpt(&d.args);
        if let Some(v) = crate::number::parse_f64(&d.args) {
            return if v.is_finite() {
                Ok(v)
            } else {
                Err(format!("'{written}', which is too large"))
            };
        }
        let quoted = |message: String| format!("'{written}' ({message})");
        let expr = crate::syntax::parse_expression(&d.args, d.args_span.start)
            .map_err(|e| quoted(e.message))?;
        let program = self
            .compile_constant(&expr)
            .map_err(|e| quoted(e.message))?;
        if program.random {
            return Err(format!("'{written}', which draws random numbers"));
        }
        if program.reads_step() {
            // Evaluated once, before any step, NumIt and MaxIt would silently be 0 (issue 50, 11).
            return Err(format!(
                "'{written}', which reads NumIt or MaxIt: a directive's value is read once, \
                 before the first step"
            ));
        }
        let mut rng = rand_pcg::Pcg64Mcg::new(0);
        let mut env = Env {
            slots: &[],
            num_it: 0.0,
            max_it: 0.0,
            vars: &mut [],
            fresh_vars: true,
            variables: &[],
            rng: &mut rng,
        };
        program.eval(&mut env).map_err(|e| e.message)
    }

    pub(super) fn directive_error(&mut self, code: &'static str, d: &Directive, message: String) {
        let span = if d.args.is_empty() {
            d.name_span.clone()
        } else {
            d.args_span.clone()
        };
        self.diagnostics
            .push(Diagnostic::error(code, span, message));
    }

    /// A number (or constant expression), or `E0203`.
    pub(super) fn number(&mut self, d: &Directive) -> Option<f64> {
        match self.constant(d) {
            Ok(v) => Some(v),
            Err(found) => {
                self.directive_error(
                    "E0203",
                    d,
                    format!("{} needs a number, found {found}", d.written),
                );
                None
            }
        }
    }

    /// `#width_unit`'s model units per width unit: a finite number above 0, or `E0215`.
    fn width_unit(&mut self, d: &Directive) -> Option<f64> {
        let value = self.number(d)?;
        // The turtle's largest coordinate (`turtle::MAX_COORDINATE`): a larger unit would make
        // a width of 1 wider than any drawing is allowed to be.
        const MAX_WIDTH_UNIT: f64 = 1e30;
        if value > 0.0 && value <= MAX_WIDTH_UNIT {
            return Some(value);
        }
        let message = format!(
            "{} must be above 0 and at most 1e30 (model units per width unit), found {}",
            d.written,
            Decimal(value)
        );
        self.directive_error("E0215", d, message);
        None
    }

    /// A whole number from 0 to `max`, or `E0204`.
    pub(super) fn whole(&mut self, d: &Directive, max: u64) -> Option<u64> {
        // Digits alone are read exactly: as a float, 18446744073709551616 (2^64) passed for
        // u64::MAX and was cut to it (issue 50, 11).
        let digits = !d.args.is_empty() && d.args.bytes().all(|b| b.is_ascii_digit());
        let (value, found) = if digits {
            // By hand, not `str::parse`: the first plant's core carries no integer parser.
            let exact = d.args.bytes().try_fold(0u64, |n, b| {
                n.checked_mul(10)?.checked_add(u64::from(b - b'0'))
            });
            (exact, excerpt(&d.args))
        } else {
            match self.constant(d) {
                // Below 2^64, `as` is exact for a whole number.
                Ok(v) if v >= 0.0 && v.fract() == 0.0 && v < TWO_TO_64 => {
                    (Some(v as u64), Decimal(v).to_string())
                }
                Ok(v) => (None, Decimal(v).to_string()),
                Err(why) => (None, why),
            }
        };
        if let Some(v) = value.filter(|&v| v <= max) {
            return Some(v);
        }
        self.directive_error(
            "E0204",
            d,
            format!(
                "{} needs a whole number from 0 to {max}, found {found}",
                d.written
            ),
        );
        None
    }
}

//! The environment's cycle in a build (docs/LANGUAGE.md, "Environment"; issue 47): every plant
//! of the grammar (one, or a stand's) is derived by a [`Stepper`], all in lockstep; after the
//! axiom and after every step each plant's string is interpreted, every program takes in all
//! plants' parts, and every `?E` is answered at its place. Derive and the turtle know nothing of
//! it: this file is where they meet the programs of [`crate::environment`].

use super::environment_answers::{self as answers, Answers, Asker};
use super::environment_reading as reading;
use super::environment_view::EnvironmentView;
use super::observer::{Lent, StageObserver};
use super::stand::Stand;
use super::{Build, Progress};
use crate::derive::{DeriveOptions, Generator, Stepper, TracedStep};
use crate::diagnostics::Diagnostic;
use crate::environment::{
    responder, Exceeded, Part, Probe, ProgramDefaults, Responder, Work,
    ENVIRONMENT_WORK_PER_MODULE, MAX_ENVIRONMENT_BYTES,
};
use crate::growth::Adjustments;
use crate::model::{LString, Model, ModuleId, ProgramSpec};
use crate::turtle::{self, Skeleton};
use crate::vocabulary::EnvironmentProgram;
use glam::DVec3;
use rand::SeedableRng;
use std::cell::RefCell;

/// True when the build runs the cycle: the grammar declares a program or a stand.
pub(super) fn runs(model: &Model) -> bool {
    !model.environment.is_empty()
}

/// The observers of a stand's plants, each lent to its plant's derivation and read between steps.
type Observers<'m> = [RefCell<StageObserver<'m, 'static>>];

/// The programs of one build and the places of its plants.
struct Environment<'m> {
    model: &'m Model,
    programs: Vec<(Box<dyn Responder>, &'m ProgramSpec)>,
    /// Where each plant stands (the origin for a grammar without a stand).
    places: Vec<DVec3>,
    /// The values one `?E` is answered with: every program's reply, in the order declared.
    stride: usize,
    query: Option<ModuleId>,
    /// The build's seed: each plant's reading draws from its own generator (a stochastic
    /// homomorphism), seeded from it.
    seed: u64,
    /// The answer passes' buffers, kept between passes.
    answers: Answers,
    /// The modules of the plants' strings the passes have read so far (each pass draws every
    /// plant): a timed grammar's whole steps without a round rewrite nothing, so the
    /// derivation's work budget does not see them.
    read: u64,
}

impl<'m> Environment<'m> {
    /// The environment of `model`, derived with `seed`; the diagnostic of a setting a program
    /// cannot use.
    fn new(model: &'m Model, seed: u64) -> Result<Self, Diagnostic> {
        let defaults = ProgramDefaults {
            step: model.settings.step,
            seed,
        };
        let mut programs = Vec::new();
        let mut held = 0;
        for spec in &model.environment.programs {
            let mut program = responder(spec, &defaults)?;
            // What it starts with (a million attraction points: 24 MB) counts at once, so that a
            // hundred such lines stop here, not after 2.4 GB.
            held += program.bytes();
            if held > MAX_ENVIRONMENT_BYTES {
                let exceeded = Exceeded {
                    what: beside("what it starts with", held - program.bytes()),
                    bytes: held,
                };
                return Err(over_budget(spec, &exceeded));
            }
            if let Some(work) = program.work() {
                *work = Work::for_modules(model.settings.max_modules);
            }
            programs.push((program, spec));
        }
        let places = match &model.environment.plants[..] {
            [] => vec![DVec3::ZERO],
            plants => plants
                .iter()
                .map(|p| DVec3::from_array(p.position))
                .collect(),
        };
        Ok(Environment {
            model,
            stride: programs.iter().map(|(p, _)| p.reply_len()).sum(),
            programs,
            places,
            query: model.environment_query(),
            seed,
            answers: Answers::default(),
            read: 0,
        })
    }

    /// Answers every `?E` of every plant's string now, after step `step` (0: the axiom): the
    /// `?E` counted against the budget first, then each plant read as it is drawn, every program
    /// updated with all the parts, then asked. Nothing when no string holds a `?E`.
    fn answer<R: rand::Rng>(
        &mut self,
        plants: &mut [Stepper<'_, '_, R>],
        observers: &Observers<'_>,
        step: u32,
        answering: &mut dyn FnMut(u32),
    ) -> Result<(), Diagnostic> {
        let Some(query) = self.query else {
            return Ok(());
        };
        if self.programs.is_empty() {
            return Ok(());
        }
        let strings = plants.iter().map(|p| p.string());
        let n = answers::check(self.model, query, strings, self.stride, step)?;
        if n == 0 {
            return Ok(());
        }
        self.count_reading(plants.iter().map(|p| p.string().len()), step)?;
        answering(step);
        self.answers.reset(n, self.stride);
        let mut parts = Vec::new();
        let mut probes: Vec<Probe<'_>> = Vec::with_capacity(n);
        for (k, plant) in plants.iter().enumerate() {
            let seed = self.seed.wrapping_add(k as u64) ^ (u64::from(step) << 32);
            let shown = plant.shown(seed)?;
            let (string, origin) = match &shown {
                Some(shown) => (&shown.string, &shown.origin[..]),
                None => (plant.string(), &[][..]),
            };
            let adjustments = observers[k].borrow().adjustments(origin);
            let size = reading::before_drawing(self.model, string, parts.len(), step)?;
            let adjusted = adjustments.as_ref();
            let skeleton = turtle::interpret_sized(self.model, string, adjusted, size.segments);
            reading::before_parts(self.model, &skeleton, size.skeleton, &mut parts, step)?;
            add_parts(&skeleton, self.places[k], k as u32, &mut parts);
            let mut last = None;
            for q in &skeleton.environment_queries {
                // The `?E` of the derived string it is drawn from: its first image answers it.
                let module = match origin {
                    [] => q.module,
                    _ => origin[q.module as usize],
                };
                if plant.string().ids.get(module as usize) != Some(&query) || last == Some(module) {
                    continue;
                }
                last = Some(module);
                probes.push(Probe {
                    position: (DVec3::from_array(q.position) + self.places[k]).to_array(),
                    heading: q.heading,
                    up: q.up,
                    args: plant.string().params_of(module as usize),
                    plant: k as u32,
                });
                self.answers.askers.push(Asker {
                    plant: k as u32,
                    module,
                });
            }
        }
        self.update(&parts, step, probes.len())?;
        let crowd = Crowd {
            step,
            probes: probes.len(),
            parts: parts.len(),
        };
        drop(parts);
        let replies = &mut self.answers.replies[..probes.len() * self.stride];
        let mut offset = 0;
        for (program, spec) in &mut self.programs {
            overworked(spec, program.as_mut(), &crowd)?;
            program.answer(&probes, replies, self.stride, offset);
            overworked(spec, program.as_mut(), &crowd)?;
            offset += program.reply_len();
        }
        drop(probes);
        for (i, asker) in self.answers.askers.iter().enumerate() {
            let reply = &self.answers.replies[i * self.stride..][..self.stride];
            let string = plants[asker.plant as usize].string_mut();
            write_reply(string, asker.module as usize, reply);
        }
        for plant in plants.iter_mut() {
            plant.written();
        }
        Ok(())
    }

    /// Counts a pass's reading of strings of `lengths` modules; `E0418` once the passes have read
    /// more than 20 × `#max_modules` modules (the derivation's work budget): a timed grammar of a
    /// million modules held for 10,000 whole steps without a round read them all at every step
    /// (minutes), while the derivation wrote nothing.
    fn count_reading(
        &mut self,
        lengths: impl Iterator<Item = usize>,
        step: u32,
    ) -> Result<(), Diagnostic> {
        let modules: u64 = lengths.map(|l| l as u64).sum();
        self.read = self.read.saturating_add(modules);
        let most = crate::derive::work_budget(self.model);
        if self.read <= most {
            return Ok(());
        }
        let span = self
            .programs
            .first()
            .map_or(0..0, |(_, spec)| spec.span.clone());
        Err(Diagnostic::error(
            "E0418",
            span,
            format!(
                "by step {step} the environment has read {} modules of the plants (every plant \
                 drawn at every step its `?E` are answered), above its work limit of {most} (20 \
                 times the module limit); use fewer steps or a smaller plant, or raise the limit \
                 with '#max_modules N'",
                self.read
            ),
        ))
    }

    /// Every program takes in the parts, each within what the others leave of the budget.
    fn update(&mut self, parts: &[Part], step: u32, probes: usize) -> Result<(), Diagnostic> {
        for k in 0..self.programs.len() {
            let others: usize = (self.programs.iter().enumerate())
                .filter(|(j, _)| *j != k)
                .map(|(_, (p, _))| p.bytes())
                .sum();
            let budget = MAX_ENVIRONMENT_BYTES.saturating_sub(others);
            let (program, spec) = &mut self.programs[k];
            if let Err(mut exceeded) = program.update(parts, budget) {
                exceeded.what = beside(&exceeded.what, others);
                return Err(over_budget(spec, &exceeded));
            }
            let crowd = Crowd {
                step,
                probes,
                parts: parts.len(),
            };
            overworked(spec, program.as_mut(), &crowd)?;
        }
        Ok(())
    }
}

/// What one answer pass holds, for the message of a program that worked too long.
struct Crowd {
    step: u32,
    probes: usize,
    parts: usize,
}

/// `E0418` when `program` has done more than the environment's work limit in this build.
fn overworked(
    spec: &ProgramSpec,
    program: &mut dyn Responder,
    crowd: &Crowd,
) -> Result<(), Diagnostic> {
    let Some(work) = program.work().filter(|w| w.over()).copied() else {
        return Ok(());
    };
    let way_out = match spec.program {
        EnvironmentProgram::Light => "a larger `cell` (fewer voxels) or fewer iterations",
        EnvironmentProgram::Space => {
            "a smaller `radius` (fewer parts near each `?E`) or fewer `?E`"
        }
        EnvironmentProgram::Attractors => {
            "a smaller `influence` or `kill`, a smaller `count`, or fewer `?E`"
        }
        EnvironmentProgram::Collision => "a smaller `radius` or fewer `?E` crowded together",
        EnvironmentProgram::Obstacle => "fewer iterations",
    };
    Err(Diagnostic::error(
        "E0418",
        spec.span.clone(),
        format!(
            "the {} program passed the environment's work limit of {} tests by step {}, \
             answering {} `?E` among {} parts: the `?E`, parts or points crowd too closely \
             for its settings; use {way_out} (or raise `#max_modules`: {} tests a module)",
            spec.info().name,
            work.most,
            crowd.step,
            crowd.probes,
            crowd.parts,
            ENVIRONMENT_WORK_PER_MODULE,
        ),
    ))
}

/// `what` a program would hold, and the bytes the other programs hold beside it when they hold
/// some (a budget passed by many programs together, not by the one named).
fn beside(what: &str, others: usize) -> String {
    match others.div_ceil(1 << 20) {
        0 => what.to_string(),
        mb => format!("{what} beside the {mb} MB the other programs hold"),
    }
}

/// `E0408`: a program would need more than the environment's memory budget.
fn over_budget(spec: &ProgramSpec, exceeded: &Exceeded) -> Diagnostic {
    let mb = |b: usize| b.div_ceil(1 << 20);
    Diagnostic::error(
        "E0408",
        spec.span.clone(),
        format!(
            "the {} program would hold {} ({} MB), above the environment's budget of {} MB; \
             use coarser settings (a larger cell, fewer points) or a smaller plant",
            spec.info().name,
            exceeded.what,
            mb(exceeded.bytes),
            mb(MAX_ENVIRONMENT_BYTES)
        ),
    )
}

/// Writes `reply` into the parameters of module `i`: the first k values for a `?E` of k
/// parameters; one with more parameters than the reply keeps the rest as written.
fn write_reply(s: &mut LString, i: usize, reply: &[f64]) {
    if s.offsets.is_empty() || i + 1 >= s.offsets.len() {
        return;
    }
    let (from, to) = (s.offsets[i] as usize, s.offsets[i + 1] as usize);
    let n = (to - from).min(reply.len());
    s.params[from..from + n].copy_from_slice(&reply[..n]);
}

/// The parts the environment sees of one plant's skeleton, moved to its place: segments (their
/// radius half their width, in the model's units with `#width_unit`), and polygons, surfaces and
/// spheres at their centres with their areas.
fn add_parts(skeleton: &Skeleton, place: DVec3, plant: u32, parts: &mut Vec<Part>) {
    let unit = skeleton.width_unit.unwrap_or(1.0);
    let at = |p: DVec3| (p + place).to_array();
    let flat = |centre: DVec3, area: f64| Part {
        from: at(centre),
        to: at(centre),
        radius: 0.0,
        area,
        plant,
    };
    parts.extend(skeleton.segments.iter().map(|s| Part {
        from: at(s.start),
        to: at(s.end),
        radius: 0.5 * s.width * unit,
        area: 0.0,
        plant,
    }));
    for p in &skeleton.polygons {
        let Some(&first) = p.points.first() else {
            continue;
        };
        let centre = p.points.iter().sum::<DVec3>() / p.points.len() as f64;
        // Half the length of the sum of the fan's cross products: the polygon's area.
        let mut twice = DVec3::ZERO;
        for w in p.points.windows(2) {
            twice += (w[0] - first).cross(w[1] - first);
        }
        parts.push(flat(centre, 0.5 * twice.length()));
    }
    for s in &skeleton.surfaces {
        // A leaf-like organ: half its length along H times its width along L.
        let area = 0.5 * (s.scale.x * s.scale.y).abs();
        parts.push(flat(s.place(DVec3::new(0.0, 0.5, 0.0)), area));
    }
    for s in &skeleton.spheres {
        parts.push(flat(s.center, std::f64::consts::PI * s.radius * s.radius));
    }
}

/// Derives every plant of `model` in lockstep with the environment answering between steps, into
/// `result`, telling `stepped` each step done and each answer pass as it starts;
/// returns the turtle's adjustments (growth's, for a single plant), or `None` when it failed.
pub(super) fn derive_stage(
    model: &Model,
    options: DeriveOptions,
    count: bool,
    result: &mut Build,
    stepped: &mut dyn FnMut(Progress),
) -> Option<Option<Adjustments>> {
    result.diagnostics.extend(warnings(model));
    match lockstep(model, &options, count, false, stepped) {
        Ok(Derived {
            mut observers,
            derivations,
            view,
            ..
        }) => {
            result.environment = Some(view);
            let stand = model.environment.plants.len();
            if stand == 0 {
                let (derivation, observer) = (derivations.into_iter().next()?, observers.pop()?);
                return Some(observer.record(derivation, options, result));
            }
            let mut counts: Vec<f64> = Vec::new();
            for (observer, d) in observers.iter_mut().zip(&derivations) {
                for (i, c) in observer
                    .step_counts(&d.string)
                    .unwrap_or_default()
                    .into_iter()
                    .enumerate()
                {
                    match counts.get_mut(i) {
                        Some(sum) => *sum += c,
                        None => counts.push(c),
                    }
                }
            }
            result.step_counts = counts;
            let stand = Stand::new(model);
            let adjustments = (observers.iter().zip(&derivations))
                .map(|(o, d)| o.adjustments(&d.turtle_origin))
                .collect();
            let adjustments = stand.adjustments(adjustments);
            let placed = stand.place(derivations);
            result.plant_offsets = model
                .environment
                .plants
                .iter()
                .map(|p| p.position)
                .collect();
            result.derivation = placed;
            result.derived_with = options;
            Some(adjustments)
        }
        Err(diagnostic) => {
            result.diagnostics.push(diagnostic);
            None
        }
    }
}

/// The derivation as a sequence (the studio's derivation view), with the environment answering
/// between steps: a stand's steps show all its plants, placed.
pub(super) fn trace(model: &Model, options: &DeriveOptions) -> Result<Vec<TracedStep>, Diagnostic> {
    let derived = lockstep(model, options, false, true, &mut |_| {})?;
    let mut traces = derived.traces;
    if model.environment.plants.is_empty() {
        return Ok(traces.pop().unwrap_or_default());
    }
    Ok(Stand::new(model).place_traces(traces))
}

/// What [`lockstep`] derived: each plant's derivation, observer and trace.
struct Derived<'m> {
    derivations: Vec<crate::derive::Derivation>,
    observers: Vec<StageObserver<'m, 'static>>,
    traces: Vec<Vec<TracedStep>>,
    /// The environment after the last step, for the views.
    view: EnvironmentView,
}

/// Every plant derived in lockstep, the environment answering after the axiom and every step
/// (a timed grammar's step: one step of growth time). Plant i derives with the seed `seed + i`,
/// its growth attributes followed by its own observer.
fn lockstep<'m>(
    model: &'m Model,
    options: &DeriveOptions,
    count: bool,
    traced: bool,
    stepped: &mut dyn FnMut(Progress),
) -> Result<Derived<'m>, Diagnostic> {
    let seed = options.seed.unwrap_or(model.settings.seed);
    let mut environment = Environment::new(model, seed)?;
    let n = environment.places.len();
    let mut rngs: Vec<Generator> = (0..n as u64)
        .map(|i| Generator::seed_from_u64(seed.wrapping_add(i)))
        .collect();
    let observers: Vec<RefCell<StageObserver<'m, 'static>>> = (0..n)
        .map(|_| RefCell::new(StageObserver::new(model, options.steps, count, true)))
        .collect();
    let mut lent: Vec<Lent<'_, 'm, 'static>> = observers.iter().map(Lent).collect();
    let mut plants = Vec::with_capacity(n);
    let when = (options.steps, options.time);
    for (rng, observer) in rngs.iter_mut().zip(lent.iter_mut()) {
        plants.push(Stepper::start(model, when, rng, observer, traced)?);
    }
    let steps = options.steps;
    environment.answer(&mut plants, &observers, 0, &mut |step| {
        stepped(Progress::Environment { step, steps })
    })?;
    for step in 1..=steps {
        for plant in &mut plants {
            plant.step()?;
        }
        check_stand_size(model, step, &plants)?;
        stepped(Progress::Derived { step, steps });
        environment.answer(&mut plants, &observers, step, &mut |step| {
            stepped(Progress::Environment { step, steps })
        })?;
    }
    let mut derivations = Vec::with_capacity(n);
    let mut traces = Vec::with_capacity(n);
    for plant in plants {
        let (derivation, trace) = plant.finish()?;
        derivations.push(derivation);
        traces.push(trace);
    }
    drop(lent);
    Ok(Derived {
        derivations,
        observers: observers.into_iter().map(RefCell::into_inner).collect(),
        traces,
        view: EnvironmentView::of(&environment.programs),
    })
}

/// `E0400` / `E0401` when a stand's plants together pass `#max_modules` or the memory budget of
/// one string at `step`: the views read them as one string.
fn check_stand_size<R: rand::Rng>(
    model: &Model,
    step: u32,
    plants: &[Stepper<'_, '_, R>],
) -> Result<(), Diagnostic> {
    if plants.len() < 2 {
        return Ok(());
    }
    let len: usize = plants.iter().map(|p| p.string().len()).sum();
    let bytes: usize = plants.iter().map(|p| p.string().bytes()).sum();
    let max = model.settings.max_modules;
    let span = || model.settings.iterations_span.clone().unwrap_or(0..0);
    let n = plants.len();
    if len > max {
        return Err(Diagnostic::error(
            "E0400",
            span(),
            format!(
                "step {step} would make the stand's {n} plants {len} modules together, above the \
                 limit of {max}; use fewer iterations or plants, or raise the limit with \
                 '#max_modules N'"
            ),
        ));
    }
    if bytes > crate::derive::MAX_STRING_BYTES {
        let mb = |b: usize| b.div_ceil(1 << 20);
        return Err(Diagnostic::error(
            "E0401",
            span(),
            format!(
                "step {step} would make the stand's {n} plants take {} MB together, above the \
                 memory budget of {} MB for one string; use fewer iterations or plants",
                mb(bytes),
                mb(crate::derive::MAX_STRING_BYTES)
            ),
        ));
    }
    Ok(())
}

/// Warnings about an environment that will not answer: programs declared and no `?E` written
/// (`E0409`).
fn warnings(model: &Model) -> Vec<Diagnostic> {
    let mut warnings = Vec::new();
    let first = model.environment.programs.first();
    if let (Some(spec), None) = (first, model.environment_query()) {
        warnings.push(Diagnostic::warning(
            "E0409",
            spec.span.clone(),
            "no communication module ?E asks the environment: the programs are not run; write \
             ?E(…) where the plant should read their replies"
                .to_string(),
        ));
    }
    warnings
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A program that asks for more than it is given.
    struct Greedy;

    impl Responder for Greedy {
        fn reply_len(&self) -> usize {
            1
        }
        fn update(&mut self, _parts: &[Part], budget: usize) -> Result<(), Exceeded> {
            Err(Exceeded {
                what: "a light grid of 1024 × 1024 × 1024 voxels".into(),
                bytes: budget + 1,
            })
        }
        fn answer(&mut self, _: &[Probe<'_>], _: &mut [f64], _: usize, _: usize) {}
        fn bytes(&self) -> usize {
            0
        }
    }

    #[test]
    fn a_program_over_the_budget_is_a_diagnostic_at_its_line() {
        let source = "#environment obstacle sphere center 0 0 0 radius 1\naxiom: F ?E(0)";
        let (file, _) = crate::syntax::parse(source);
        let model = crate::model::resolve(&file).0.expect("a model");
        let mut environment = Environment::new(&model, 1).expect("an environment");
        environment.programs[0].0 = Box::new(Greedy);
        let mut rng = Generator::seed_from_u64(1);
        let mut observer = crate::derive::Unobserved;
        let when = (1, None);
        let mut plants =
            vec![Stepper::start(&model, when, &mut rng, &mut observer, false).unwrap()];
        let observers = [RefCell::new(StageObserver::new(&model, 1, false, true))];
        let error = environment
            .answer(&mut plants, &observers, 0, &mut |_| {})
            .expect_err("over the budget");
        assert_eq!(error.code, "E0408");
        assert_eq!(&source[error.span.clone()], source.lines().next().unwrap());
        assert!(
            error.message.contains("1024 × 1024 × 1024 voxels"),
            "{}",
            error.message
        );
        assert!(error.message.contains("64 MB"), "{}", error.message);
    }
}

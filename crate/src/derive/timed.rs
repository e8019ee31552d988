//! Timed derivation (ABOP section 6.1, timed D0L-systems): the string at a time t.
//!
//! A timed module (`#terminal_age`) carries its age as its first parameter. Time runs from 0 to
//! t; every timed module ages with it, and a module whose age reaches its terminal age is
//! replaced by its production's successor, whose timed modules start at the ages written there.
//! The derivation goes from one replacement to the next (a round): it finds the nearest time at
//! which some module reaches its terminal age, ages every module by that much, and rewrites
//! exactly the modules that reached it (the others are copied), then decomposes and cuts as
//! after any step. Several replacements in one interval are several rounds; modules reaching
//! their terminal ages at the same moment are replaced in the same round. After the last round
//! before t, every module ages by what is left. Modules that are not timed are never rewritten
//! by the productions (they are copied, as turtle commands are).

use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model};

/// Two times closer than this, relative to the terminal age, are the same moment: ages summed
/// from fractions (0.1 + 0.2) still reach their terminal age together.
const SAME_MOMENT: f64 = 1e-9;

/// Whether this build of the core has the clock. `crate/pkg-core` (wasm32 without `studio-extras`,
/// the first plant's core) leaves it out (issue 22, the first load: 1.2 KB gzipped): it derives a
/// timed grammar's whole steps as a parametric one, says so (`PlantBuild.timed`), and the build
/// worker builds it again with the studio core (`web/src/build/worker.ts`).
const HAS_CLOCK: bool = cfg!(any(feature = "studio-extras", not(target_arch = "wasm32")));

/// The clock of a timed derivation: each module id's terminal age, the time reached, the end.
pub(super) struct Clock {
    /// Indexed by module id; infinite for a module that is not timed.
    terminal: Vec<f64>,
    now: f64,
    end: f64,
    /// The end of the whole derivation (`end` is nearer while it is stepped, [`Clock::until`]).
    last: f64,
    /// `#dt`: model time per step.
    dt: f64,
}

impl Clock {
    /// The clock of a timed grammar derived to growth time `time` (in steps; `steps` when not
    /// given): model time `time · #dt`. `None` when the grammar has no timed module.
    pub(super) fn new(model: &Model, steps: u32, time: Option<f64>) -> Option<Clock> {
        let settings = &model.settings;
        if !HAS_CLOCK || settings.terminal_ages.is_empty() {
            return None;
        }
        let mut terminal = vec![f64::INFINITY; model.alphabet.len()];
        for &(id, age) in &settings.terminal_ages {
            terminal[id.index()] = age;
        }
        let end = time.unwrap_or(steps as f64).max(0.0) * settings.dt;
        Some(Clock {
            terminal,
            now: 0.0,
            end,
            last: end,
            dt: settings.dt,
        })
    }

    /// Stops the next rounds at growth time `t` (in steps), or at the derivation's end when that
    /// comes first: a derivation stepped from outside ([`super::Stepper`]) goes one step of
    /// time at a time.
    pub(super) fn until(&mut self, t: f64) {
        self.end = (t * self.dt).min(self.last);
    }

    /// The time reached, as a growth time (in steps: model time / `#dt`), kept to 12 decimals
    /// below 1000 as ages are (rounds at 0.1 + 0.2 are at 0.3).
    pub(super) fn growth_time(&self) -> f64 {
        let t = self.now / self.dt;
        if t.abs() < 1e3 {
            (t * 1e12).round() / 1e12
        } else {
            t
        }
    }

    /// The terminal age of module `i` of `s` and its age, when it is timed and has its age.
    fn timed(&self, s: &LString, i: usize) -> Option<(f64, f64)> {
        let beta = *self.terminal.get(s.ids[i].index())?;
        let age = *s.params_of(i).first()?;
        beta.is_finite().then_some((beta, age))
    }

    /// Moves time on to the next replacement, or to the end when none comes before it: every
    /// timed module of `s` ages. Returns the plan of the round (1 for each module that reached
    /// its terminal age, 0 for the others), or `None` when the end is reached.
    pub(super) fn next_round(&mut self, s: &mut LString) -> Option<Vec<u32>> {
        let mut wait = f64::INFINITY;
        for i in 0..s.len() {
            if let Some((beta, age)) = self.timed(s, i) {
                if age < beta - SAME_MOMENT * beta.max(1.0) {
                    wait = wait.min(beta - age);
                }
            }
        }
        let left = self.end - self.now;
        if wait > left + SAME_MOMENT * self.end.max(1.0) {
            self.age(s, left.max(0.0));
            self.now = self.end;
            return None;
        }
        self.age(s, wait);
        self.now += wait;
        let mut plan = vec![0; s.len()];
        for (i, due) in plan.iter_mut().enumerate() {
            if let Some((beta, age)) = self.timed(s, i) {
                if (age - beta).abs() <= SAME_MOMENT * beta.max(1.0) {
                    *due = 1;
                    s.params[s.offsets[i] as usize] = beta;
                }
            }
        }
        Some(plan)
    }

    /// Every timed module of `s` grows `by` older, its age kept to 12 decimals (below 1000) so
    /// that times written with fractions give the ages a person writes: 3.2 − 3 is 0.2, not
    /// 0.20000000000000018.
    fn age(&self, s: &mut LString, by: f64) {
        for i in 0..s.len() {
            if self.timed(s, i).is_some() {
                let age = &mut s.params[s.offsets[i] as usize];
                *age += by;
                if age.abs() < 1e3 {
                    *age = (*age * 1e12).round() / 1e12;
                }
            }
        }
    }

    /// `E0407`: reaching the end takes more rounds than `#max_steps`.
    pub(super) fn too_many_rounds(&self, model: &Model) -> Diagnostic {
        let span = model
            .settings
            .terminal_age_span
            .clone()
            .unwrap_or_else(|| model.axiom_span.clone());
        Diagnostic::error(
            "E0407",
            span,
            format!(
                "the timed derivation needs more than {} rounds of replacements to reach time \
                 {} (it reached {}); use longer terminal ages, an earlier time, or raise '{} N'",
                model.settings.max_steps,
                rounded(self.end),
                rounded(self.now),
                crate::vocabulary::DirectiveKind::MaxSteps.written()
            ),
        )
    }
}

/// `x` to 9 decimals, for messages (0.010000999999999104 is 0.010001).
fn rounded(x: f64) -> f64 {
    (x * 1e9).round() / 1e9
}

impl<R: rand::Rng> super::Run<'_, '_, R> {
    /// The rounds of a timed derivation from the clock's time to its end, counted on from
    /// `round`; every module aged to the end.
    pub(super) fn rounds(
        &mut self,
        clock: &mut Clock,
        round: &mut u32,
        tracked: bool,
    ) -> Result<(), Diagnostic> {
        let model = self.rewriter.model;
        while let Some(plan) = clock.next_round(&mut self.current) {
            if *round == model.settings.max_steps {
                return Err(clock.too_many_rounds(model));
            }
            *round += 1;
            self.timed_plan = Some(plan);
            self.step(*round, tracked)?;
            self.stamp_trace(clock);
        }
        self.trace_ageing(clock, *round)?;
        Ok(())
    }
}

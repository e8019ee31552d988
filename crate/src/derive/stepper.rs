//! [`Stepper`]: a derivation stepped from outside, one step at a time, so that a caller can
//! change the string between steps (the environment answering `?E`, docs/LANGUAGE.md,
//! "Environment") and step several derivations in lockstep (the plants of a stand). Derive
//! itself knows nothing of what the caller does between steps.

use super::rewriter::Rewriter;
use super::timed::Clock;
use super::{Derivation, Generator, Observer, Run, TracedStep};
use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model};
use rand::SeedableRng;

/// A derivation under way, stepped by its caller. Every step is the same as [`super::derive`]'s
/// (the productions, decomposition, cut, the query modules `?P ?H ?U ?L`); the last step is
/// tracked as [`super::derive_tracked`] tracks it. A timed grammar's step is one step of growth
/// time (`#dt` of model time): the rounds of replacements within it, then every module aged to
/// its end.
pub struct Stepper<'m, 'o, R: rand::Rng> {
    run: Run<'m, 'o, R>,
    steps: u32,
    done: u32,
    /// A timed grammar's clock, and the rounds of replacements so far.
    clock: Option<Clock>,
    rounds: u32,
}

/// The string the turtle reads ([`Stepper::shown`]): the homomorphism image of the derived
/// string, and for each of its modules the module of the derived string it comes from.
pub struct Shown {
    pub string: LString,
    pub origin: Vec<u32>,
}

impl<'m, 'o, R: rand::Rng> Stepper<'m, 'o, R> {
    /// Writes and decomposes the axiom of a derivation of `steps` steps (a timed grammar's to
    /// growth time `time`, when given, as [`super::DeriveOptions::time`]), drawing every random
    /// number from `rng`. `traced`: record every step ([`TracedStep`]), as
    /// [`super::derive_traced`] does.
    pub fn start(
        model: &'m Model,
        (steps, time): (u32, Option<f64>),
        rng: &'m mut R,
        observer: &'o mut dyn Observer,
        traced: bool,
    ) -> Result<Self, Diagnostic> {
        let mut run = Run::start(model, steps, rng, observer)?;
        if traced {
            run.trace = Some(vec![run.traced_axiom()]);
        }
        let clock = Clock::new(model, steps, time);
        if let Some(clock) = &clock {
            run.stamp_trace(clock);
        }
        Ok(Stepper {
            run,
            steps,
            done: 0,
            clock,
            rounds: 0,
        })
    }

    /// The steps done so far.
    pub fn done(&self) -> u32 {
        self.done
    }

    /// Runs the next step; nothing once all `steps` are done.
    pub fn step(&mut self) -> Result<(), Diagnostic> {
        if self.done == self.steps {
            return Ok(());
        }
        self.done += 1;
        if let Some(clock) = &mut self.clock {
            clock.until(f64::from(self.done));
            return self.run.rounds(clock, &mut self.rounds, true);
        }
        let tracked = self.run.trace.is_some() || self.done == self.steps;
        self.run.step(self.done, tracked)
    }

    /// The string the turtle reads now, as it will at the end: the homomorphism image of
    /// [`Stepper::string`] (`None` without a homomorphism: the string itself). A stochastic
    /// homomorphism draws from a generator of its own, seeded with `seed`, so that reading the
    /// plant between steps changes none of the derivation's draws.
    pub fn shown(&self, seed: u64) -> Result<Option<Shown>, Diagnostic> {
        let model = self.run.rewriter.model;
        if model.homomorphism.is_empty() {
            return Ok(None);
        }
        let mut rng = Generator::seed_from_u64(seed);
        let mut rewriter = Rewriter::new(model, self.done, &mut rng);
        let mut now = Derivation {
            string: self.run.current.clone(),
            ..Derivation::default()
        };
        super::homomorphism(&mut rewriter, self.done, &mut now, true)?;
        Ok(now.interpreted.map(|string| Shown {
            string,
            origin: now.turtle_origin,
        }))
    }

    /// The string now (after the axiom, or after the last step).
    pub fn string(&self) -> &LString {
        &self.run.current
    }

    /// The string now, to be written into (the parameters of its modules: not its length, which
    /// the provenance follows). A traced derivation records what is written as this step's string
    /// when [`Stepper::written`] is called.
    pub fn string_mut(&mut self) -> &mut LString {
        &mut self.run.current
    }

    /// The caller wrote into the string: a traced derivation's record of this step shows it.
    pub fn written(&mut self) {
        if let Some(last) = self.run.trace.as_mut().and_then(|t| t.last_mut()) {
            last.string.clone_from(&self.run.current);
        }
    }

    /// The derivation (its last step's provenance, the string the turtle reads) and, when traced,
    /// every step.
    pub fn finish(mut self) -> Result<(Derivation, Vec<TracedStep>), Diagnostic> {
        let trace = self.run.trace.take().unwrap_or_default();
        let steps = if self.clock.is_some() {
            self.rounds
        } else {
            self.done
        };
        let derivation = self.run.finish(steps, true)?;
        Ok((derivation, trace))
    }
}

/// A derivation put together outside derive from others' (the plants of a stand placed side by
/// side, `crate::pipeline`): its strings and provenance, as [`Derivation`]'s accessors give them.
#[derive(Clone, Debug, Default)]
pub struct Assembled {
    pub string: LString,
    pub interpreted: Option<LString>,
    pub origin: Vec<u32>,
    pub parent: Vec<u32>,
    pub previous: LString,
    pub turtle_origin: Vec<u32>,
    pub warnings: Vec<Diagnostic>,
}

impl From<Assembled> for Derivation {
    fn from(a: Assembled) -> Derivation {
        Derivation {
            string: a.string,
            interpreted: a.interpreted,
            warnings: a.warnings,
            provenance: super::Provenance {
                written: (a.origin, a.parent).into(),
                pending: None,
            },
            turtle_origin: a.turtle_origin,
            previous: a.previous,
            id_counts: Vec::new(),
            resume: None,
        }
    }
}

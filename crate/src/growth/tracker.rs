//! Growth during a derivation: the state of every module followed pass by pass, each step planned
//! (which apices stop, how often each grows), and the turtle's adjustments read off the state.
//! The pipeline drives it from derive's observer.

use super::adjustments::{Adjustments, ModuleAdjustment};
use super::formulas::{branch_length, branch_width, sun_direction, Heights, Third};
use super::state::{
    bend, born_all, follow, plan, GrowthRecord, GrowthState, ModuleGrowth, StepValues,
};
use crate::derive::{Written, NOT_REWRITTEN};
use crate::diagnostics::Diagnostic;
use crate::model::{Env, LString, Model, Program};

/// The growth of one derivation under way.
pub struct GrowthTracker<'m> {
    model: &'m Model,
    /// The derivation's number of steps (`MaxIt` in the attributes' expressions).
    steps: u32,
    record: GrowthRecord,
}

impl<'m> GrowthTracker<'m> {
    /// A tracker for a derivation of `steps` steps, when the grammar sets a growth attribute.
    pub fn new(model: &'m Model, steps: u32) -> Option<Self> {
        model.growth.is_active().then(|| GrowthTracker {
            model,
            steps,
            record: GrowthRecord::default(),
        })
    }

    /// The axiom's modules are born at step 0.
    pub fn axiom(&mut self, axiom: &LString, rng: &mut dyn rand::Rng) {
        let modules = born_all(&self.model.growth, axiom, 0, rng);
        self.record.state = GrowthState { step: 0, modules };
    }

    /// Step `step` begins on `current`: the modules' thirds (from `heights`, the turtle run on the
    /// string so far), the segments' bending, and how many times each module is rewritten.
    pub fn plan(
        &mut self,
        step: u32,
        current: &LString,
        heights: &mut dyn FnMut(&LString, &Adjustments) -> Heights,
        rng: &mut dyn rand::Rng,
    ) -> Result<Vec<u32>, Diagnostic> {
        let attributes = &self.model.growth;
        let mut values = StepValues::default();
        if let Some(l) = &attributes.lifetime {
            values.lifetime = Some((
                self.eval(&l.mean, step, rng)?,
                self.eval(&l.variance, step, rng)?,
            ));
        }
        if let Some(s) = &attributes.speed {
            values.speed = Some((
                self.eval(&s.mean, step, rng)?,
                self.eval(&s.variance, step, rng)?,
            ));
        }
        let state = &mut self.record.state;
        state.step = step - 1;
        // Every pass is followed, so the state matches the string; never index past it anyway.
        debug_assert_eq!(state.modules.len(), current.len());
        state.modules.resize(current.len(), ModuleGrowth::default());
        let thirds = if attributes.needs_heights() {
            let measured = heights(current, &self.adjustments(&[]));
            if measured.modules.len() == current.len() {
                measured.thirds()
            } else {
                vec![Third::Middle; current.len()]
            }
        } else {
            vec![Third::Middle; current.len()]
        };
        let modules = &mut self.record.state.modules;
        bend(attributes, &current.ids, &thirds, modules);
        let (times, report) = plan(
            attributes,
            step,
            &current.ids,
            &thirds,
            modules,
            values,
            rng,
        );
        self.record.steps.push(report);
        Ok(times)
    }

    /// A pass wrote `written` (see [`crate::derive::Observer::followed`]): the states follow it.
    pub fn follow(&mut self, written: &Written<'_>, rng: &mut dyn rand::Rng) {
        let state = &mut self.record.state;
        let origin = written.origin;
        state.modules = follow(
            &self.model.growth,
            &state.modules,
            written.string,
            written.parent,
            |j| origin[j] != NOT_REWRITTEN,
            written.birth,
            rng,
        );
    }

    /// Cut kept the modules `kept`: their states stay.
    pub fn cut(&mut self, kept: &[u32]) {
        let old = std::mem::take(&mut self.record.state.modules);
        self.record.state.modules = kept.iter().map(|&k| old[k as usize]).collect();
    }

    /// Step `step` is complete.
    pub fn stepped(&mut self, step: u32) {
        self.record.state.step = step;
    }

    /// The turtle's adjustments for the derived string (`turtle_origin` empty) or for the string
    /// a homomorphism made of it (each of its modules takes the state of the derived module it
    /// comes from, and only the first from each keeps its rotations, so a module drawn as several
    /// segments turns once).
    pub fn adjustments(&self, turtle_origin: &[u32]) -> Adjustments {
        let attributes = &self.model.growth;
        let state = &self.record.state;
        let adjust = |g: &ModuleGrowth, turns: bool| {
            let age = g.age(state.step);
            ModuleAdjustment {
                turns: if turns {
                    [g.sun, g.wind, g.gravity]
                } else {
                    [0.0; 3]
                },
                length: attributes.shape.as_ref().map_or(1.0, |s| {
                    (branch_length(s.rate, s.maturity, age) + g.length_variation).max(0.0)
                }),
                width: attributes.shape_width.as_ref().map_or([1.0; 3], |w| {
                    w.positional
                        .map(|pf| (branch_width(age, pf) + g.width_variation).max(0.0))
                }),
            }
        };
        let modules = if turtle_origin.is_empty() {
            state.modules.iter().map(|g| adjust(g, true)).collect()
        } else {
            turtle_origin
                .iter()
                .enumerate()
                .map(|(j, &o)| {
                    let g = state.modules.get(o as usize).copied().unwrap_or_default();
                    adjust(&g, j == 0 || turtle_origin[j - 1] != o)
                })
                .collect()
        };
        Adjustments {
            attractors: [
                attributes
                    .sun
                    .as_ref()
                    .and_then(|s| sun_direction(s.latitude, s.season)),
                attributes.wind.as_ref().map(|w| w.direction),
                attributes.gravity.as_ref().map(|g| g.direction),
            ],
            scales_length: attributes.shape.is_some(),
            scales_width: attributes.shape_width.is_some(),
            modules,
        }
    }

    /// The final state and every step's report.
    pub fn finish(self) -> GrowthRecord {
        self.record
    }

    /// Evaluates a per-step argument (`NumIt` is `step`).
    fn eval(
        &self,
        program: &Program,
        step: u32,
        rng: &mut dyn rand::Rng,
    ) -> Result<f64, Diagnostic> {
        let mut env = Env {
            slots: &[],
            num_it: step as f64,
            max_it: self.steps as f64,
            vars: &mut [],
            fresh_vars: false,
            variables: &[],
            rng,
        };
        program
            .eval(&mut env)
            .map_err(|e| e.into_diagnostic(&format!(" (at step {step})")))
    }
}

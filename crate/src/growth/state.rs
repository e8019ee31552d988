//! What each module of the derived string carries (its birth, whether it stopped, the rotations it
//! accumulated, its own random terms), and how a step changes it: [`bend`] and [`plan`] before the
//! productions pass, [`follow`] after each pass.

use super::formulas::{
    rewritings, share_survivors, sun_direction, surviving_branches, variation, Third,
};
use crate::model::{GrowthAttributes, LString, ModuleId};
use rand::RngExt;
use serde::Serialize;

/// The growth state of one module of the derived string.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct ModuleGrowth {
    /// The step that wrote the module (0: the axiom). Its age after n steps is n − birth + 1.
    pub birth: u32,
    /// An apex that the lifetime stopped: it is never rewritten again.
    pub stopped: bool,
    /// Rotation accumulated towards the sun, the wind and the ground, in degrees.
    pub sun: f64,
    pub wind: f64,
    pub gravity: f64,
    /// This segment's own angles per step for the wind and gravity, drawn when it was written.
    pub wind_step: f64,
    pub gravity_step: f64,
    /// This segment's ±Round(Rand() × VR) of `#shape` and Round(Rand() × VR) of `#shape_width`,
    /// drawn when it was written.
    pub length_variation: f64,
    pub width_variation: f64,
}

impl ModuleGrowth {
    /// The number of steps the module has lived after `step` steps, counting the one that wrote
    /// it (a module written by the last step has age 1; the axiom's have age n + 1).
    pub fn age(&self, step: u32) -> u32 {
        step.saturating_sub(self.birth) + 1
    }

    /// True when the module carries a rotation for the turtle.
    pub fn is_bent(&self) -> bool {
        self.sun != 0.0 || self.wind != 0.0 || self.gravity != 0.0
    }
}

/// The growth state of a whole string after `step` steps: one [`ModuleGrowth`] per module.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct GrowthState {
    pub step: u32,
    pub modules: Vec<ModuleGrowth>,
}

/// What the growth attributes did in one step, per third (upper, middle, lower).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct StepReport {
    pub step: u32,
    /// Apices still growing before the step.
    pub apices: [u32; 3],
    /// NB_i of `#lifetime` (before it is capped by the number of apices).
    pub survivors: Option<u32>,
    /// Apices that the lifetime stopped at this step.
    pub stopped: [u32; 3],
    /// Apices rewritten at least once in this step.
    pub growing: [u32; 3],
    /// Rewritings of apices in this step (NR_i summed; equal to `growing` without `#speed`).
    pub rewritings: [u32; 3],
}

/// The growth of a whole derivation: the final state and a report per step.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct GrowthRecord {
    pub state: GrowthState,
    pub steps: Vec<StepReport>,
}

impl GrowthRecord {
    /// The per-step reports as JSON (the CLI's `--growth`).
    pub fn steps_json(&self) -> String {
        serde_json::to_string(&self.steps).unwrap_or_else(|_| "[]".into())
    }
}

/// The state of a module written at step `birth`: its own random terms are drawn now, for
/// segments only, in the order length, width, wind, gravity (each only when its attribute has a
/// variation).
pub fn born<R: rand::Rng + ?Sized>(
    attributes: &GrowthAttributes,
    id: ModuleId,
    birth: u32,
    rng: &mut R,
) -> ModuleGrowth {
    let mut g = ModuleGrowth {
        birth,
        ..ModuleGrowth::default()
    };
    if !attributes.is_segment(id) {
        return g;
    }
    if let Some(shape) = attributes.shape.as_ref().filter(|s| s.variance != 0.0) {
        // ± Round(Rand() × VR): one draw in [-1, 1) gives the sign and Rand().
        let r = 2.0 * rng.random::<f64>() - 1.0;
        g.length_variation = r.signum() * variation(r.abs(), shape.variance);
    }
    if let Some(width) = attributes
        .shape_width
        .as_ref()
        .filter(|s| s.variance != 0.0)
    {
        g.width_variation = variation(rng.random::<f64>(), width.variance);
    }
    for (bend, step) in [
        (&attributes.wind, &mut g.wind_step),
        (&attributes.gravity, &mut g.gravity_step),
    ] {
        if let Some(b) = bend {
            *step = b.angle;
            if b.variance != 0.0 {
                *step += variation(rng.random::<f64>(), b.variance);
            }
        }
    }
    g
}

/// The state of a string that the axiom (or anything written at `birth`) made.
pub fn born_all<R: rand::Rng + ?Sized>(
    attributes: &GrowthAttributes,
    s: &LString,
    birth: u32,
    rng: &mut R,
) -> Vec<ModuleGrowth> {
    s.ids
        .iter()
        .map(|&id| born(attributes, id, birth, rng))
        .collect()
}

/// Step i begins: every segment that exists turns once more, by `#sun`'s angle when it is in the
/// upper or middle third and by its own wind and gravity angles. The rotations accumulate in the
/// module; the turtle applies them (so what grows from a segment grows from the bent segment).
pub fn bend(
    attributes: &GrowthAttributes,
    ids: &[ModuleId],
    thirds: &[Third],
    modules: &mut [ModuleGrowth],
) {
    let sun = attributes
        .sun
        .as_ref()
        .filter(|s| sun_direction(s.latitude, s.season).is_some());
    for (i, g) in modules.iter_mut().enumerate() {
        if !attributes.is_segment(ids[i]) {
            continue;
        }
        if let Some(sun) = sun {
            if thirds.get(i).copied().unwrap_or(Third::Middle) != Third::Lower {
                g.sun += sun.angle;
            }
        }
        g.wind += g.wind_step;
        g.gravity += g.gravity_step;
    }
}

/// The values of the per-step parameters at one step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepValues {
    /// MB_i and VB_i of `#lifetime`.
    pub lifetime: Option<(f64, f64)>,
    /// SM_i and VR_i of `#speed`.
    pub speed: Option<(f64, f64)>,
}

/// Lifetime and speed for one step: how many times each module of the string is rewritten
/// (1 for modules that are not apices, 0 for stopped apices), with the step's report. Stops
/// apices for good (in `modules`). Draws, in order: Rand() of NB_i, then the survivors of each
/// third (upper, middle, lower; none when all survive), then Rand() of NR_i for each growing apex
/// in string order.
pub fn plan<R: rand::Rng + ?Sized>(
    attributes: &GrowthAttributes,
    step: u32,
    ids: &[ModuleId],
    thirds: &[Third],
    modules: &mut [ModuleGrowth],
    values: StepValues,
    rng: &mut R,
) -> (Vec<u32>, StepReport) {
    let third = |i: usize| thirds.get(i).copied().unwrap_or(Third::Middle) as usize;
    let mut report = StepReport {
        step,
        ..StepReport::default()
    };
    let mut times = vec![1u32; ids.len()];
    let mut live: [Vec<usize>; 3] = Default::default();
    for (i, &id) in ids.iter().enumerate() {
        if !attributes.is_apex(id) {
            continue;
        }
        if modules[i].stopped {
            times[i] = 0;
        } else {
            live[third(i)].push(i);
        }
    }
    report.apices = [0, 1, 2].map(|k| live[k].len() as u32);
    if let (Some(lifetime), Some((mean, variance))) = (&attributes.lifetime, values.lifetime) {
        let survivors = surviving_branches(mean, variance, rng.random::<f64>());
        report.survivors = Some(survivors);
        let share = share_survivors(survivors, lifetime.probabilities, report.apices);
        for k in 0..3 {
            let apices = &mut live[k];
            let keep = share[k] as usize;
            if keep < apices.len() {
                // A partial Fisher–Yates shuffle: the first `keep` are chosen uniformly.
                for j in 0..keep {
                    let pick = j
                        + ((rng.random::<f64>() * (apices.len() - j) as f64) as usize)
                            .min(apices.len() - j - 1);
                    apices.swap(j, pick);
                }
            }
            for &i in &apices[keep.min(apices.len())..] {
                modules[i].stopped = true;
                times[i] = 0;
                report.stopped[k] += 1;
            }
            apices.truncate(keep);
            crate::sort::sort(apices);
        }
    }
    let mut growing: Vec<usize> = live.iter().flatten().copied().collect();
    crate::sort::sort(&mut growing);
    for i in growing {
        if let (Some(speed), Some((mean, variance))) = (&attributes.speed, values.speed) {
            times[i] = rewritings(
                speed.positional[third(i)],
                mean,
                variance,
                rng.random::<f64>(),
            );
        }
        if times[i] > 0 {
            report.growing[third(i)] += 1;
            report.rewritings[third(i)] += times[i];
        }
    }
    (times, report)
}

/// The state of a string written by one pass from `old`: for each new module, the module of the
/// old string it comes from (`parent`) and whether a production wrote it (`produced`). A copied
/// module keeps its state; a written one is new, born at `birth` (or at its parent's birth when
/// `birth` is `None`: decomposition finishes the step that wrote the parent), and the first module
/// written from a parent inherits the parent's accumulated rotations, so a branch replaced by its
/// successor stays bent (edge rewriting).
pub fn follow<R: rand::Rng + ?Sized>(
    attributes: &GrowthAttributes,
    old: &[ModuleGrowth],
    new: &LString,
    parent: &[u32],
    produced: impl Fn(usize) -> bool,
    birth: Option<u32>,
    rng: &mut R,
) -> Vec<ModuleGrowth> {
    let mut out = Vec::with_capacity(new.len());
    for (j, &p) in parent.iter().enumerate().take(new.len()) {
        let from = old.get(p as usize).copied().unwrap_or_default();
        let first = j == 0 || parent[j - 1] != p;
        if !produced(j) {
            // A copy; the modules of a control-module group all come from its header, and only
            // the first of them keeps the header's rotations.
            out.push(if first {
                from
            } else {
                ModuleGrowth {
                    sun: 0.0,
                    wind: 0.0,
                    gravity: 0.0,
                    ..from
                }
            });
            continue;
        }
        let mut g = born(attributes, new.ids[j], birth.unwrap_or(from.birth), rng);
        if first {
            g.sun = from.sun;
            g.wind = from.wind;
            g.gravity = from.gravity;
        }
        out.push(g);
    }
    out
}

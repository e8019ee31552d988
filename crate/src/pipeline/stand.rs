//! A stand's plants as one derivation for the views (docs/LANGUAGE.md, "Stands"): each plant's
//! string inside `[ @M(x, y, z) … ]` at its place, one after the other, so that the turtle, the
//! mesh, the exports and picking read one string as they do for a single plant. The provenance
//! (which production wrote each module, which module it comes from) is each plant's, moved to
//! where that plant sits in the placed strings; the modules that place the plants were written by
//! no production.

use crate::derive::{Assembled, Derivation, TracedStep, NOT_REWRITTEN};
use crate::growth::{Adjustments, ModuleAdjustment};
use crate::model::{LString, Model, ModuleId};
use crate::vocabulary::{name_of, Command, Meaning};

/// The modules that place a stand's plants, and where the plants stand.
pub(super) struct Stand {
    open: ModuleId,
    close: ModuleId,
    /// `@M`, interned by the resolver for every grammar with a stand.
    move_to: Option<ModuleId>,
    places: Vec<[f64; 3]>,
}

/// Modules before a plant's own in the placed string: `[` and `@M(x, y, z)`.
const BEFORE: usize = 2;

impl Stand {
    pub(super) fn new(model: &Model) -> Stand {
        Stand {
            open: model.open,
            close: model.close,
            move_to: model
                .alphabet
                .get(name_of(Meaning::Turtle(Command::MoveTo))),
            places: model
                .environment
                .plants
                .iter()
                .map(|p| p.position)
                .collect(),
        }
    }

    /// The plants' strings, each at its place; and where each plant's first module is.
    fn strings(&self, strings: &[&LString]) -> (LString, Vec<usize>) {
        let mut placed = LString::default();
        placed.clear(true);
        let mut starts = Vec::with_capacity(strings.len());
        for (s, place) in strings.iter().zip(&self.places) {
            placed.push(self.open, &[]);
            if let Some(move_to) = self.move_to {
                placed.push(move_to, place);
            } else {
                placed.push(self.open, &[]);
            }
            starts.push(placed.len());
            placed.extend_from(s);
            placed.push(self.close, &[]);
            if self.move_to.is_none() {
                placed.push(self.close, &[]);
            }
        }
        (placed, starts)
    }

    /// Each plant's values for its modules (which production wrote each), placed: the modules
    /// that place the plants take [`NOT_REWRITTEN`].
    fn values(&self, values: &[&[u32]]) -> Vec<u32> {
        let mut out = Vec::new();
        for v in values {
            out.extend([NOT_REWRITTEN; BEFORE]);
            out.extend_from_slice(v);
            out.extend(self.after().map(|_| NOT_REWRITTEN));
        }
        out
    }

    /// Each plant's indices into another of its strings (its string before the step, or its
    /// derived string), placed: plant i's index j becomes `there[i] + j`, and the modules that
    /// place it point at those that place it there. `lens`: the plants' lengths there.
    fn indices(&self, indices: &[&[u32]], there: &[usize], lens: &[usize]) -> Vec<u32> {
        let mut out = Vec::new();
        for (k, v) in indices.iter().enumerate() {
            let start = there[k] as u32;
            out.extend((1..=BEFORE as u32).rev().map(|b| start - b));
            out.extend(v.iter().map(|&j| start + j));
            let end = start + lens[k] as u32;
            out.extend(self.after().map(|a| end + a as u32));
        }
        out
    }

    /// The modules after a plant's own: `]` (and a second one without `@M`).
    fn after(&self) -> std::ops::Range<usize> {
        0..if self.move_to.is_some() { 1 } else { 2 }
    }

    /// The plants' derivations as one.
    pub(super) fn place(&self, plants: Vec<Derivation>) -> Derivation {
        let strings: Vec<&LString> = plants.iter().map(|d| &d.string).collect();
        let (string, starts) = self.strings(&strings);
        let origins: Vec<&[u32]> = plants.iter().map(|d| d.origin()).collect();
        let origin = self.values(&origins);
        let complete = plants.iter().all(|d| d.parent().len() == d.string.len());
        let (previous, parent) = if complete {
            let previous: Vec<&LString> = plants.iter().map(|d| &d.previous).collect();
            let (placed, there) = self.strings(&previous);
            let lens: Vec<usize> = previous.iter().map(|s| s.len()).collect();
            let parents: Vec<&[u32]> = plants.iter().map(|d| d.parent()).collect();
            (placed, self.indices(&parents, &there, &lens))
        } else {
            (LString::default(), Vec::new())
        };
        let (interpreted, turtle_origin) = if plants.iter().any(|d| d.interpreted.is_some()) {
            let shown: Vec<&LString> = plants.iter().map(|d| d.turtle_string()).collect();
            let (placed, _) = self.strings(&shown);
            let identity: Vec<Vec<u32>> = plants
                .iter()
                .map(|d| match d.turtle_origin.len() {
                    0 => (0..d.turtle_string().len() as u32).collect(),
                    _ => d.turtle_origin.clone(),
                })
                .collect();
            let origins: Vec<&[u32]> = identity.iter().map(Vec::as_slice).collect();
            let lens: Vec<usize> = strings.iter().map(|s| s.len()).collect();
            (Some(placed), self.indices(&origins, &starts, &lens))
        } else {
            (None, Vec::new())
        };
        let mut warnings: Vec<_> = plants.iter().flat_map(|d| d.warnings.clone()).collect();
        warnings.dedup();
        Assembled {
            string,
            interpreted,
            origin,
            parent,
            previous,
            turtle_origin,
            warnings,
        }
        .into()
    }

    /// Growth's adjustments of the placed string the turtle reads, from each plant's own (of its
    /// own turtle string, in order): the modules that place the plants are not adjusted. `None`
    /// when no plant has any (a grammar without growth attributes).
    pub(super) fn adjustments(&self, plants: Vec<Option<Adjustments>>) -> Option<Adjustments> {
        let first = plants.iter().flatten().next()?;
        let mut placed = Adjustments {
            attractors: first.attractors,
            scales_length: first.scales_length,
            scales_width: first.scales_width,
            modules: Vec::new(),
        };
        let still = ModuleAdjustment::default;
        for plant in plants.into_iter().flatten() {
            placed.modules.extend((0..BEFORE).map(|_| still()));
            placed.modules.extend(plant.modules);
            placed.modules.extend(self.after().map(|_| still()));
        }
        Some(placed)
    }

    /// The plants' traces (the same number of steps each) as one: step k shows every plant at
    /// step k, placed.
    pub(super) fn place_traces(&self, traces: Vec<Vec<TracedStep>>) -> Vec<TracedStep> {
        let steps = traces.iter().map(Vec::len).min().unwrap_or(0);
        let mut placed: Vec<TracedStep> = Vec::with_capacity(steps);
        for k in 0..steps {
            let at: Vec<&TracedStep> = traces.iter().map(|t| &t[k]).collect();
            let strings: Vec<&LString> = at.iter().map(|t| &t.string).collect();
            let (string, _) = self.strings(&strings);
            let origins: Vec<&[u32]> = at.iter().map(|t| t.origin.as_slice()).collect();
            let parent = if k == 0 {
                Vec::new()
            } else {
                let before: Vec<&LString> = traces.iter().map(|t| &t[k - 1].string).collect();
                let (_, there) = self.strings(&before);
                let lens: Vec<usize> = before.iter().map(|s| s.len()).collect();
                let parents: Vec<&[u32]> = at.iter().map(|t| t.parent.as_slice()).collect();
                self.indices(&parents, &there, &lens)
            };
            placed.push(TracedStep {
                string,
                origin: self.values(&origins),
                parent,
                time: None,
            });
        }
        placed
    }
}

//! What a caller lends a build: [`Hooks`] (a clock, a progress callback), the [`Stage`]s and
//! [`Progress`] it is told, and the [`StageTimings`] its clock measures.

use serde::Serialize;

/// A stage of a build or an export, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    Parse,
    Derive,
    Interpret,
    Mesh,
    /// Exports only, with branch edits.
    ApplyEdits,
    /// Exports only.
    Write,
}

impl Stage {
    /// Every stage, in order.
    pub const ALL: [Stage; 6] = [
        Stage::Parse,
        Stage::Derive,
        Stage::Interpret,
        Stage::Mesh,
        Stage::ApplyEdits,
        Stage::Write,
    ];

    /// What a progress line says while the stage runs: `parsing`, `deriving`, …
    pub fn label(self) -> &'static str {
        match self {
            Stage::Parse => "parsing",
            Stage::Derive => "deriving",
            Stage::Interpret => "interpreting",
            Stage::Mesh => "meshing",
            Stage::ApplyEdits => "applying edits",
            Stage::Write => "writing",
        }
    }
}

/// Where a build or an export is, as its progress callback is told.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Progress {
    /// A stage starts.
    Started(Stage),
    /// `step` of the derivation's `steps` steps are done: told with 0 as derivation starts, then
    /// after each step, so a long derivation can say "step k of n".
    Derived { step: u32, steps: u32 },
    /// The environment answers the `?E` of the plant of `step` (0: the axiom) of `steps`: told
    /// as each answer pass starts (only when one runs), so the progress line can say
    /// "environment, step k of n" while the programs work.
    #[cfg(feature = "environment")]
    Environment { step: u32, steps: u32 },
}

impl Progress {
    /// What a progress line calls it: the stage's label, `environment` for an answer pass.
    pub fn label(self) -> &'static str {
        match self {
            Progress::Started(stage) => stage.label(),
            Progress::Derived { .. } => Stage::Derive.label(),
            #[cfg(feature = "environment")]
            Progress::Environment { .. } => "environment",
        }
    }

    /// The same progress with its step kept within `steps` (a timed grammar's rounds of
    /// replacements may outnumber its steps), out of `steps`.
    #[cfg(feature = "environment")]
    pub(super) fn within(self, steps: u32) -> Progress {
        match self {
            Progress::Derived { step, .. } => Progress::Derived {
                step: step.min(steps),
                steps,
            },
            Progress::Environment { step, .. } => Progress::Environment {
                step: step.min(steps),
                steps,
            },
            started => started,
        }
    }
}

/// What a caller lends a build. Both are optional; neither changes the result.
#[derive(Default)]
pub struct Hooks<'a> {
    /// Any monotonic clock (the studio's and the CLI's are in milliseconds), read before and after
    /// each stage to fill [`Build::timings`](super::Build::timings).
    pub clock: Option<&'a mut dyn FnMut() -> f64>,
    /// Told each stage as it starts and each derivation step as it ends.
    pub progress: Option<&'a mut dyn FnMut(Progress)>,
}

impl Hooks<'_> {
    /// Tells the progress callback that `stage` starts.
    pub fn start(&mut self, stage: Stage) {
        self.tell(Progress::Started(stage));
    }

    pub(super) fn tell(&mut self, progress: Progress) {
        if let Some(callback) = self.progress.as_mut() {
            callback(progress);
        }
    }
}

/// The hooks of one run, with the time of the last lap.
pub(super) struct Watch<'h, 'a> {
    pub(super) hooks: &'h mut Hooks<'a>,
    last: Option<f64>,
    pub(super) timings: StageTimings,
}

impl<'h, 'a> Watch<'h, 'a> {
    pub(super) fn new(hooks: &'h mut Hooks<'a>) -> Self {
        let last = hooks.clock.as_mut().map(|now| now());
        Watch {
            hooks,
            last,
            timings: StageTimings::default(),
        }
    }

    pub(super) fn start(&mut self, stage: Stage) {
        self.hooks.start(stage);
    }

    /// The time since the previous lap (0 without a clock).
    pub(super) fn lap(&mut self) -> f64 {
        let (Some(now), Some(last)) = (self.hooks.clock.as_mut(), self.last) else {
            return 0.0;
        };
        let time = now();
        self.last = Some(time);
        (time - last).max(0.0)
    }

    /// The timings, when there is a clock.
    pub(super) fn timings(&self) -> Option<StageTimings> {
        self.last.map(|_| self.timings)
    }
}

/// Wall-clock time of each stage of one build, in the unit of the caller's clock (milliseconds
/// for the studio and the CLI). A stage that did not run (after an error) took 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct StageTimings {
    /// Parsing the text and resolving it into a model.
    pub parse_resolve: f64,
    /// Deriving the string (including the turtle runs that feed query modules and growth).
    pub derive: f64,
    /// Interpreting the string with the turtle into a skeleton.
    pub interpret: f64,
    /// Building the mesh from the skeleton.
    pub mesh: f64,
}

impl StageTimings {
    /// One JSON object, e.g. `{"parseResolve":0.1,"derive":0.4,"interpret":0.9,"mesh":2.5}`.
    /// Written by hand with `Display` (which the module texts need anyway), not serde_json: its
    /// float writer would be one more in the first plant's core (issue 22). The text is serde_json's
    /// for every time a clock gives (a whole number keeps its `.0`; only below 1e-5 or from 1e16
    /// up would serde_json write an exponent, the same number); a time that is not finite is
    /// `null`, as serde_json writes it.
    pub fn to_json(&self) -> String {
        let number = |v: f64| {
            if !v.is_finite() {
                "null".to_string()
            } else if v.fract() == 0.0 {
                format!("{}.0", crate::number::Decimal(v))
            } else {
                crate::number::Decimal(v).to_string()
            }
        };
        format!(
            "{{\"parseResolve\":{},\"derive\":{},\"interpret\":{},\"mesh\":{}}}",
            number(self.parse_resolve),
            number(self.derive),
            number(self.interpret),
            number(self.mesh)
        )
    }
}

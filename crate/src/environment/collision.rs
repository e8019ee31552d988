//! `collision`: Honda's (1981) test of whether a bud may grow, as vlab's `honda81` program runs
//! it (`ENVIRO/honda81/honda81.c`; docs/LANGUAGE.md, "Environment"). A `?E(vigor, kind)` replies 1
//! when no other `?E` of the same kind (its second parameter, 0 without one) and of at least its
//! vigor (its first parameter, 0 without one) stands within `radius` of it, and 0 otherwise: two
//! buds of equal vigor that meet both stop; a weaker one yields to a stronger one. All plants'
//! `?E` meet. With `flat 1` distances are measured in the horizontal plane (x and z), as
//! `honda81`'s `3d case: off`.
//!
//! The probes are sorted into cells one radius wide; a probe looks only at its own and the
//! neighbouring cells, strongest first, and stops at the first that stops it.

use super::settings::number;
use super::{Exceeded, Part, Probe, Responder, Work};
use crate::diagnostics::Diagnostic;
use crate::model::ProgramSpec;
use std::collections::HashMap;

/// The `collision` program.
#[derive(Clone, Debug)]
pub struct Collision {
    radius: f64,
    /// Compare x and z only.
    flat: bool,
    /// The `?E` it has tested against another in this build.
    work: Work,
}

/// A probe as the test reads it: its place (x, y, z, or x, z, 0 when flat), kind and vigor.
#[derive(Clone, Copy, Debug)]
struct Bud {
    at: [f64; 3],
    kind: u64,
    vigor: f64,
}

impl Collision {
    /// The program of an `#environment collision` line; `radius` defaults to the step length.
    pub fn new(spec: &ProgramSpec, step_length: f64) -> Result<Collision, Diagnostic> {
        let radius = number(spec, "radius", step_length, |r| r >= 0.0, "0 or more")?;
        let flat = number(spec, "flat", 0.0, |f| f == 0.0 || f == 1.0, "0 or 1")?;
        Ok(Collision {
            radius,
            flat: flat == 1.0,
            work: Work::default(),
        })
    }

    fn bud(&self, probe: &Probe<'_>) -> Bud {
        let [x, y, z] = probe.position;
        let arg = |k: usize| probe.args.get(k).copied().filter(|v| v.is_finite());
        Bud {
            at: if self.flat { [x, z, 0.0] } else { [x, y, z] },
            kind: arg(1).unwrap_or(0.0).to_bits(),
            vigor: arg(0).unwrap_or(0.0),
        }
    }

    /// The cell of a point: its coordinates divided by the radius, clamped to ±2^52 (a point
    /// at infinity or NaN falls in a cell of its own and meets nothing).
    fn cell(&self, at: [f64; 3]) -> Option<[i64; 3]> {
        let size = self.radius.max(f64::MIN_POSITIVE);
        let c = at.map(|v| (v / size).floor());
        c.iter()
            .all(|v| v.is_finite() && v.abs() < 4.5e15)
            .then(|| c.map(|v| v as i64))
    }
}

impl Responder for Collision {
    fn reply_len(&self) -> usize {
        1
    }

    fn update(&mut self, _parts: &[Part], _budget: usize) -> Result<(), Exceeded> {
        // Only the `?E` themselves meet: the plants' parts do not count.
        Ok(())
    }

    fn answer(&mut self, probes: &[Probe<'_>], replies: &mut [f64], stride: usize, offset: usize) {
        let buds: Vec<Bud> = probes.iter().map(|p| self.bud(p)).collect();
        let mut cells: HashMap<(u64, [i64; 3]), Vec<u32>> = HashMap::new();
        for (i, bud) in buds.iter().enumerate() {
            if let Some(c) = self.cell(bud.at) {
                cells.entry((bud.kind, c)).or_default().push(i as u32);
            }
        }
        for members in cells.values_mut() {
            // Strongest first: a probe reads only those of at least its vigor.
            members.sort_by(|&a, &b| buds[b as usize].vigor.total_cmp(&buds[a as usize].vigor));
        }
        let r2 = self.radius * self.radius;
        let reach: &[i64] = &[-1, 0, 1];
        let mut work = self.work;
        for (i, bud) in buds.iter().enumerate() {
            if work.over() {
                break;
            }
            let stopped = self.cell(bud.at).is_some_and(|c| {
                let z_reach: &[i64] = if self.flat { &[0] } else { reach };
                reach.iter().any(|&dx| {
                    reach.iter().any(|&dy| {
                        z_reach.iter().any(|&dz| {
                            let key = (bud.kind, [c[0] + dx, c[1] + dy, c[2] + dz]);
                            cells.get(&key).is_some_and(|members| {
                                members
                                    .iter()
                                    .take_while(|&&j| buds[j as usize].vigor >= bud.vigor)
                                    .any(|&j| {
                                        work.add(1);
                                        j as usize != i
                                            && squared(bud.at, buds[j as usize].at) <= r2
                                    })
                            })
                        })
                    })
                })
            });
            if let Some(slot) = replies.get_mut(i * stride + offset) {
                *slot = if stopped { 0.0 } else { 1.0 };
            }
        }
        self.work = work;
    }

    fn bytes(&self) -> usize {
        0
    }

    fn work(&mut self) -> Option<&mut Work> {
        Some(&mut self.work)
    }
}

fn squared(a: [f64; 3], b: [f64; 3]) -> f64 {
    (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::settings::tests::spec;
    use crate::vocabulary::EnvironmentProgram;

    fn replies(program: &mut Collision, probes: &[([f64; 3], &'static [f64])]) -> Vec<f64> {
        let probes: Vec<Probe<'static>> = probes
            .iter()
            .map(|&(position, args)| Probe {
                position,
                heading: [0.0, 1.0, 0.0],
                up: [0.0, 0.0, 1.0],
                args,
                plant: 0,
            })
            .collect();
        let mut out = vec![f64::NAN; probes.len() * 3];
        program.answer(&probes, &mut out, 3, 1);
        out.chunks(3)
            .map(|c| {
                assert!(c[0].is_nan() && c[2].is_nan(), "wrote outside its place");
                c[1]
            })
            .collect()
    }

    fn program(settings: &[(&'static str, &[f64])]) -> Collision {
        Collision::new(&spec(EnvironmentProgram::Collision, None, settings), 1.0).expect("valid")
    }

    #[test]
    fn buds_that_meet_stop_and_a_weaker_one_yields() {
        let mut c = program(&[("radius", &[0.5])]);
        // Two of equal vigor 0.3 apart: both stop; one 2 away from them is free.
        let got = replies(
            &mut c,
            &[
                ([0.0; 3], &[1.0]),
                ([0.3, 0.0, 0.0], &[1.0]),
                ([2.0, 0.0, 0.0], &[1.0]),
            ],
        );
        assert_eq!(got, [0.0, 0.0, 1.0]);
        // The stronger goes on, the weaker stops.
        let got = replies(&mut c, &[([0.0; 3], &[2.0]), ([0.0, 0.4, 0.0], &[1.0])]);
        assert_eq!(got, [1.0, 0.0]);
        // Another kind does not meet; the radius is inclusive, as honda81's `<=`.
        let got = replies(
            &mut c,
            &[([0.0; 3], &[1.0, 0.0]), ([0.0, 0.5, 0.0], &[1.0, 1.0])],
        );
        assert_eq!(got, [1.0, 1.0]);
        let got = replies(&mut c, &[([0.0; 3], &[]), ([0.0, 0.5, 0.0], &[])]);
        assert_eq!(got, [0.0, 0.0]);
    }

    #[test]
    fn flat_measures_in_the_horizontal_plane_and_bad_numbers_meet_nothing() {
        let mut c = program(&[("radius", &[0.5]), ("flat", &[1.0])]);
        let got = replies(&mut c, &[([0.0; 3], &[]), ([0.0, 9.0, 0.0], &[])]);
        assert_eq!(got, [0.0, 0.0], "heights do not count");
        let mut c = program(&[("radius", &[0.5])]);
        let got = replies(
            &mut c,
            &[
                ([f64::NAN; 3], &[]),
                ([f64::NAN; 3], &[]),
                ([1e300, 0.0, 0.0], &[]),
            ],
        );
        assert_eq!(got, [1.0, 1.0, 1.0]);
        assert!(Collision::new(
            &spec(EnvironmentProgram::Collision, None, &[("radius", &[-1.0])]),
            1.0
        )
        .is_err());
        assert!(Collision::new(
            &spec(EnvironmentProgram::Collision, None, &[("flat", &[2.0])]),
            1.0
        )
        .is_err());
    }

    #[test]
    fn many_buds_in_one_cell_are_answered_without_comparing_every_pair() {
        // 200,000 buds of rising vigor on one point: each is stopped by the strongest, the
        // strongest by none; sorted by vigor, each probe reads one or two others.
        let args: Vec<f64> = (0..200_000).map(|i| i as f64).collect();
        let leaked: &'static [f64] = Box::leak(args.into_boxed_slice());
        let probes: Vec<([f64; 3], &'static [f64])> =
            (0..200_000).map(|i| ([0.0; 3], &leaked[i..=i])).collect();
        let mut c = program(&[("radius", &[1e30])]);
        let got = replies(&mut c, &probes);
        assert_eq!(got.iter().filter(|&&r| r == 1.0).count(), 1);
        assert_eq!(got[199_999], 1.0);
    }
}

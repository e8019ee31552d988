//! `attractors`: space colonisation (Runions, Lane and Prusinkiewicz 2007, "Modeling trees with
//! a space colonization algorithm"; docs/LANGUAGE.md, "Crowding and space
//! colonisation").
//!
//! `count` attraction points fill a box or a ball, placed uniformly at random by the program's
//! own generator (seeded by `seed`, else the grammar's seed): the same seed gives the same
//! points. They persist from step to step: after each step every point within `kill` of a part of
//! any plant (a segment's axis, an organ's centre) is removed for good. Each `?E` then takes the
//! remaining points whose nearest `?E` it is within `influence` (a point as far from two takes
//! the first in the string, plants in the stand's order); it replies how many and the unit mean
//! of the unit directions towards them, Runions et al.'s direction of growth ((0, 0, 0) when it
//! takes none).

use super::grid::{distance, nearest_on_segment, sub, unit, Near, SegmentGrid};
use super::settings::{point, positive, whole, BAD_SETTING};
use super::{Exceeded, Part, Probe, Responder, Work};
use crate::derive::Generator;
use crate::diagnostics::Diagnostic;
use crate::model::ProgramSpec;
use crate::vocabulary::EnvironmentShape;
use rand::{RngExt, SeedableRng};

/// Most attraction points one program holds (24 MB).
pub const MAX_ATTRACTORS: u64 = 1_000_000;

/// The `attractors` program.
#[derive(Clone, Debug)]
pub struct Attractors {
    influence: f64,
    kill: f64,
    points: Vec<[f64; 3]>,
    /// The parts and `?E` it has tested against a point in this build.
    work: Work,
}

/// The volume the points fill.
enum Volume {
    Box { min: [f64; 3], max: [f64; 3] },
    Ball { center: [f64; 3], radius: f64 },
}

/// The setting `name`'s three numbers, required.
fn required_point(spec: &ProgramSpec, name: &str, shape: &str) -> Result<[f64; 3], Diagnostic> {
    point(spec, name)?.ok_or_else(|| {
        Diagnostic::error(
            BAD_SETTING,
            spec.span.clone(),
            format!("attractors in a {shape} need `{name}` x y z"),
        )
    })
}

fn volume(spec: &ProgramSpec) -> Result<Volume, Diagnostic> {
    match spec.shape {
        Some(EnvironmentShape::Box) => {
            let min = required_point(spec, "min", "box")?;
            let max = required_point(spec, "max", "box")?;
            if (0..3).any(|i| min[i] > max[i]) {
                return Err(Diagnostic::error(
                    BAD_SETTING,
                    spec.span_of("max"),
                    "a box's `max` must be at least its `min` in x, y and z",
                ));
            }
            Ok(Volume::Box { min, max })
        }
        Some(EnvironmentShape::Sphere) => {
            let center = required_point(spec, "center", "sphere")?;
            if spec.number("radius").is_none() {
                return Err(Diagnostic::error(
                    BAD_SETTING,
                    spec.span.clone(),
                    "attractors in a sphere need its `radius`",
                ));
            }
            let radius = positive(spec, "radius", 0.0)?;
            Ok(Volume::Ball { center, radius })
        }
        _ => Err(Diagnostic::error(
            BAD_SETTING,
            spec.span.clone(),
            "attractors fill a shape: write `box min x y z max x y z` or `sphere center x y z radius r` after `attractors`",
        )),
    }
}

impl Volume {
    /// `count` points placed uniformly at random inside it.
    fn fill(&self, count: usize, rng: &mut Generator) -> Vec<[f64; 3]> {
        let mut points = Vec::with_capacity(count);
        let mut draw = |lo: f64, hi: f64| lo + (hi - lo) * rng.random::<f64>();
        while points.len() < count {
            match *self {
                Volume::Box { min, max } => {
                    points.push([0, 1, 2].map(|i| draw(min[i], max[i])));
                }
                Volume::Ball { center, radius } => {
                    // In the cube around the ball, kept when inside it (52% of draws).
                    let v = [0; 3].map(|_| draw(-1.0, 1.0));
                    if v[0] * v[0] + v[1] * v[1] + v[2] * v[2] <= 1.0 {
                        points.push([0, 1, 2].map(|i| center[i] + radius * v[i]));
                    }
                }
            }
        }
        points
    }
}

impl Attractors {
    /// The program of an `#environment attractors …` line: `influence` defaults to 4 step
    /// lengths, `kill` to one, `count` to 1000, `seed` to `grammar_seed`.
    pub fn new(
        spec: &ProgramSpec,
        step_length: f64,
        grammar_seed: u64,
    ) -> Result<Attractors, Diagnostic> {
        let volume = volume(spec)?;
        let count = whole(spec, "count", 1000, MAX_ATTRACTORS)? as usize;
        let influence = positive(spec, "influence", 4.0 * step_length)?;
        let kill = positive(spec, "kill", step_length)?;
        let seed = whole(spec, "seed", grammar_seed, 1 << 53)?;
        let mut rng = Generator::seed_from_u64(seed);
        Ok(Attractors {
            influence,
            kill,
            points: volume.fill(count, &mut rng),
            work: Work::default(),
        })
    }

    /// The attraction points that remain, for the studio to draw.
    pub fn points(&self) -> &[[f64; 3]] {
        &self.points
    }

    /// For each probe, the number of points it takes and the sum of the unit directions to them.
    fn takes(&mut self, probes: &[Probe<'_>]) -> Vec<[f64; 4]> {
        let at: Vec<[[f64; 3]; 2]> = probes.iter().map(|p| [p.position; 2]).collect();
        let grid = SegmentGrid::of_points(&at, self.influence);
        let mut taken = vec![[0.0; 4]; probes.len()];
        let mut near = Near::default();
        for &p in &self.points {
            self.work.add(std::mem::take(&mut near.scanned));
            if self.work.over() {
                break;
            }
            grid.near(p, &mut near);
            let mut best: Option<(f64, usize)> = None;
            for &i in &near.found {
                let (d, i) = (distance(p, at[i as usize][0]), i as usize);
                if d <= self.influence && best.is_none_or(|(b, j)| d < b || (d == b && i < j)) {
                    best = Some((d, i));
                }
            }
            if let Some((_, i)) = best {
                let towards = unit(sub(p, at[i][0]));
                let t = &mut taken[i];
                *t = [
                    t[0] + 1.0,
                    t[1] + towards[0],
                    t[2] + towards[1],
                    t[3] + towards[2],
                ];
            }
        }
        self.work.add(near.scanned);
        taken
    }
}

impl Responder for Attractors {
    fn points(&self) -> &[[f64; 3]] {
        &self.points
    }

    fn reply_len(&self) -> usize {
        4
    }

    fn update(&mut self, parts: &[Part], budget: usize) -> Result<(), Exceeded> {
        let held = self.bytes();
        let axes_bytes = parts.len() * std::mem::size_of::<[[f64; 3]; 2]>();
        if held + axes_bytes > budget {
            return Err(Exceeded {
                what: format!(
                    "{} attraction points and {} parts",
                    self.points.len(),
                    parts.len()
                ),
                bytes: held + axes_bytes,
            });
        }
        let axes: Vec<[[f64; 3]; 2]> = parts.iter().map(|p| [p.from, p.to]).collect();
        let grid = SegmentGrid::build(
            &axes,
            self.kill,
            budget.saturating_sub(held + axes_bytes),
            "a grid for the attraction points' kill distance",
        )?;
        let mut near = Near::default();
        let (kill, mut work) = (self.kill, self.work);
        self.points.retain(|&p| {
            work.add(std::mem::take(&mut near.scanned));
            if work.over() {
                return true;
            }
            grid.near(p, &mut near);
            !near.found.iter().any(|&i| {
                let [a, b] = axes[i as usize];
                distance(nearest_on_segment(p, a, b), p) <= kill
            })
        });
        work.add(near.scanned);
        self.work = work;
        Ok(())
    }

    fn answer(&mut self, probes: &[Probe<'_>], replies: &mut [f64], stride: usize, offset: usize) {
        for (i, [count, x, y, z]) in self.takes(probes).into_iter().enumerate() {
            let [dx, dy, dz] = unit([x, y, z]);
            if let Some(slot) = replies.get_mut(i * stride + offset..i * stride + offset + 4) {
                slot.copy_from_slice(&[count, dx, dy, dz]);
            }
        }
    }

    fn bytes(&self) -> usize {
        self.points.capacity() * std::mem::size_of::<[f64; 3]>()
    }

    fn work(&mut self) -> Option<&mut Work> {
        Some(&mut self.work)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::settings::tests::spec;
    use crate::maths;
    use crate::vocabulary::EnvironmentProgram;

    fn cube(settings: &[(&'static str, &[f64])]) -> ProgramSpec {
        let mut all: Vec<(&'static str, &[f64])> =
            vec![("min", &[-1.0, -1.0, -1.0]), ("max", &[1.0, 1.0, 1.0])];
        all.extend_from_slice(settings);
        spec(
            EnvironmentProgram::Attractors,
            Some(EnvironmentShape::Box),
            &all,
        )
    }

    fn probe(position: [f64; 3]) -> Probe<'static> {
        Probe {
            position,
            heading: [0.0, 1.0, 0.0],
            up: [0.0, 0.0, 1.0],
            args: &[],
            plant: 0,
        }
    }

    fn replies(a: &mut Attractors, probes: &[Probe<'_>]) -> Vec<[f64; 4]> {
        let mut out = vec![f64::NAN; probes.len() * 4];
        a.answer(probes, &mut out, 4, 0);
        out.chunks(4).map(|c| [c[0], c[1], c[2], c[3]]).collect()
    }

    fn segment(from: [f64; 3], to: [f64; 3]) -> Part {
        Part {
            from,
            to,
            radius: 0.05,
            area: 0.0,
            plant: 0,
        }
    }

    #[test]
    fn points_fill_their_shape_and_the_same_seed_places_them_again() {
        let a = Attractors::new(&cube(&[("count", &[500.0])]), 1.0, 7).unwrap();
        assert_eq!(a.points().len(), 500);
        assert!(a.points().iter().flatten().all(|x| x.abs() <= 1.0));
        // Uniform: about half the points on each side of every axis.
        let right = a.points().iter().filter(|p| p[0] > 0.0).count();
        assert!((200..300).contains(&right), "{right}");
        let again = Attractors::new(&cube(&[("count", &[500.0])]), 1.0, 7).unwrap();
        assert_eq!(a.points(), again.points());
        let other = Attractors::new(&cube(&[("count", &[500.0])]), 1.0, 8).unwrap();
        assert_ne!(a.points(), other.points());
        // `seed` overrides the grammar's.
        let seeded = Attractors::new(&cube(&[("count", &[500.0]), ("seed", &[7.0])]), 1.0, 99);
        assert_eq!(a.points(), seeded.unwrap().points());
        let ball = spec(
            EnvironmentProgram::Attractors,
            Some(EnvironmentShape::Sphere),
            &[("center", &[5.0, 0.0, 0.0]), ("radius", &[2.0])],
        );
        let b = Attractors::new(&ball, 1.0, 1).unwrap();
        assert_eq!(b.points().len(), 1000);
        assert!(b
            .points()
            .iter()
            .all(|&p| distance(p, [5.0, 0.0, 0.0]) <= 2.0));
        assert!(b
            .points()
            .iter()
            .any(|&p| distance(p, [5.0, 0.0, 0.0]) > 1.9));
    }

    #[test]
    fn points_a_part_reaches_are_removed_for_good() {
        let mut a = Attractors::new(&cube(&[("kill", &[0.3])]), 1.0, 3).unwrap();
        let stem = [segment([0.0, -1.0, 0.0], [0.0, 0.0, 0.0])];
        let near_stem =
            |p: &[f64; 3]| distance(nearest_on_segment(*p, [0.0, -1.0, 0.0], [0.0; 3]), *p) <= 0.3;
        let before: Vec<[f64; 3]> = a.points().to_vec();
        let killed = before.iter().filter(|p| near_stem(p)).count();
        assert!(killed > 10, "{killed}");
        a.update(&stem, 1 << 24).unwrap();
        assert_eq!(a.points().len(), before.len() - killed);
        assert!(!a.points().iter().any(near_stem));
        // The plant gone (a step that cut it), the points stay gone.
        a.update(&[], 1 << 24).unwrap();
        assert_eq!(a.points().len(), before.len() - killed);
        // The ones left are the ones that were there, in their order.
        let kept: Vec<[f64; 3]> = before.into_iter().filter(|p| !near_stem(p)).collect();
        assert_eq!(a.points(), &kept[..]);
    }

    #[test]
    fn a_bud_with_points_on_one_side_turns_to_them() {
        let s = spec(
            EnvironmentProgram::Attractors,
            Some(EnvironmentShape::Box),
            &[
                ("min", &[1.0, -0.5, -0.5]),
                ("max", &[2.0, 0.5, 0.5]),
                ("influence", &[3.0]),
            ],
        );
        let mut a = Attractors::new(&s, 1.0, 5).unwrap();
        let r = replies(&mut a, &[probe([0.0; 3]), probe([0.0, 10.0, 0.0])]);
        assert_eq!(r[0][0], 1000.0);
        assert!(r[0][1] > 0.95, "towards +x: {:?}", r[0]);
        let length = (r[0][1] * r[0][1] + r[0][2] * r[0][2] + r[0][3] * r[0][3]).sqrt();
        assert!((length - 1.0).abs() < 1e-12);
        // Out of reach: nothing and no direction.
        assert_eq!(r[1], [0.0; 4]);
    }

    #[test]
    fn two_buds_share_the_points_by_nearness() {
        let mut a = Attractors::new(
            &cube(&[("influence", &[1.5]), ("count", &[2000.0])]),
            1.0,
            11,
        )
        .unwrap();
        let (left, right) = ([-0.9, 0.0, 0.0], [0.9, 0.0, 0.0]);
        let r = replies(&mut a, &[probe(left), probe(right)]);
        // Counted by hand: each point to the nearer bud within 1.5, a tie to the first.
        let (mut l, mut rr) = (0.0, 0.0);
        for &p in a.points() {
            let (dl, dr) = (distance(p, left), distance(p, right));
            if dl <= 1.5 && (dl <= dr || dr > 1.5) {
                l += 1.0;
            } else if dr <= 1.5 {
                rr += 1.0;
            }
        }
        assert_eq!((r[0][0], r[1][0]), (l, rr));
        assert!(l + rr > 1000.0 && (l - rr).abs() < 200.0, "{l} {rr}");
        // Each takes the half of the cube on its side, whose middle is between them: they turn
        // towards each other.
        assert!(r[0][1] > 0.5 && r[1][1] < -0.5, "{r:?}");
    }

    #[test]
    fn a_point_as_far_from_two_buds_goes_to_the_first() {
        let s = spec(
            EnvironmentProgram::Attractors,
            Some(EnvironmentShape::Box),
            &[
                ("min", &[0.0, 1.0, 0.0]),
                ("max", &[0.0, 1.0, 0.0]),
                ("count", &[1.0]),
            ],
        );
        let mut a = Attractors::new(&s, 1.0, 0).unwrap();
        let r = replies(&mut a, &[probe([1.0, 0.0, 0.0]), probe([-1.0, 0.0, 0.0])]);
        assert_eq!((r[0][0], r[1][0]), (1.0, 0.0));
        let r = replies(&mut a, &[probe([-1.0, 0.0, 0.0]), probe([1.0, 0.0, 0.0])]);
        assert_eq!((r[0][0], r[1][0]), (1.0, 0.0));
    }

    #[test]
    fn ten_thousand_points_and_ten_thousand_buds_agree_with_a_plain_count() {
        let s = cube(&[("count", &[10000.0]), ("influence", &[0.1])]);
        let mut a = Attractors::new(&s, 1.0, 2).unwrap();
        let buds: Vec<[f64; 3]> = (0..10000)
            .map(|i| {
                let t = i as f64 / 10000.0;
                [2.0 * t - 1.0, maths::sin(37.0 * t), maths::cos(91.0 * t)]
            })
            .collect();
        let probes: Vec<Probe> = buds.iter().map(|&b| probe(b)).collect();
        let r = replies(&mut a, &probes);
        let total: f64 = r.iter().map(|x| x[0]).sum();
        // Every point within 0.1 of some bud is taken exactly once.
        let reachable = a
            .points()
            .iter()
            .filter(|&&p| buds.iter().any(|&b| distance(p, b) <= 0.1))
            .count();
        assert_eq!(total, reachable as f64);
        assert!(reachable > 50, "{reachable}");
    }

    #[test]
    fn past_the_budget_it_stops_with_what_it_would_need() {
        let mut a = Attractors::new(&cube(&[("count", &[100_000.0])]), 1.0, 1).unwrap();
        let e = a.update(&[], 1 << 20).unwrap_err();
        assert!(
            e.bytes >= 2_400_000 && e.what.contains("100000 attraction points"),
            "{e:?}"
        );
        let mut a = Attractors::new(&cube(&[("kill", &[1e-7])]), 1.0, 1).unwrap();
        let e = a
            .update(&[segment([0.0; 3], [1.0, 0.0, 0.0])], 1 << 20)
            .unwrap_err();
        assert!(e.what.contains("kill distance"), "{e:?}");
    }

    #[test]
    fn settings_it_cannot_use_are_errors_at_the_setting() {
        let no_shape = spec(EnvironmentProgram::Attractors, None, &[]);
        assert_eq!(
            Attractors::new(&no_shape, 1.0, 1).unwrap_err().code,
            "E0239"
        );
        let no_max = spec(
            EnvironmentProgram::Attractors,
            Some(EnvironmentShape::Box),
            &[("min", &[0.0; 3])],
        );
        assert!(Attractors::new(&no_max, 1.0, 1)
            .unwrap_err()
            .message
            .contains("`max`"));
        let inside_out = spec(
            EnvironmentProgram::Attractors,
            Some(EnvironmentShape::Box),
            &[("min", &[0.0; 3]), ("max", &[1.0, -1.0, 1.0])],
        );
        assert_eq!(
            Attractors::new(&inside_out, 1.0, 1).unwrap_err().span,
            10..15
        );
        for (word, value) in [
            ("count", 2.5),
            ("count", 2e6),
            ("kill", 0.0),
            ("influence", -1.0),
            ("seed", -1.0),
        ] {
            let e = Attractors::new(&cube(&[(word, &[value])]), 1.0, 1).unwrap_err();
            assert_eq!((e.code, e.span), ("E0239", 20..25), "{word} {value}");
        }
        let ball = spec(
            EnvironmentProgram::Attractors,
            Some(EnvironmentShape::Sphere),
            &[("center", &[0.0; 3])],
        );
        assert!(Attractors::new(&ball, 1.0, 1)
            .unwrap_err()
            .message
            .contains("radius"));
    }
}

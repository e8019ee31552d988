//! `space`: how crowded space is around each `?E`, for competition within a plant and between
//! the plants of a stand (docs/LANGUAGE.md, "Crowding and space colonisation").
//!
//! Every part of every plant is a capsule: a segment counts as a neighbour of a point when the
//! nearest point of its axis is within `radius`, an organ when its centre is. The reply is the
//! number of neighbours and the unit direction away from them: the sum of (point − nearest point
//! of each neighbour), scaled to length 1; (0, 0, 0) alone.
//!
//! A bud sits on its own axis: a part that touches the `?E`'s position (a segment that ends or
//! starts there, within 1e-9 of the scene's size) is the segment the bud grows from, the one it
//! continues or a branch of the same node, and is not counted.

use super::grid::{distance, nearest_on_segment, sub, unit, Near, SegmentGrid};
use super::settings::positive;
use super::{Exceeded, Part, Probe, Responder, Work};
use crate::diagnostics::Diagnostic;
use crate::model::ProgramSpec;

/// Points closer than this times the scene's size are the same point.
const SAME_POINT: f64 = 1e-9;

/// The `space` program.
#[derive(Clone, Debug)]
pub struct Space {
    radius: f64,
    /// Every part's axis, `[from, to]`, by index.
    axes: Vec<[[f64; 3]; 2]>,
    grid: SegmentGrid,
    /// The distance under which a part touches a probe.
    touching: f64,
    /// The parts it has tested against a probe in this build.
    work: Work,
}

impl Space {
    /// The program of an `#environment space` line; `radius` defaults to the step length.
    pub fn new(spec: &ProgramSpec, step_length: f64) -> Result<Space, Diagnostic> {
        Ok(Space {
            radius: positive(spec, "radius", step_length)?,
            axes: Vec::new(),
            grid: SegmentGrid::default(),
            touching: 0.0,
            work: Work::default(),
        })
    }

    /// The neighbours' count and the direction away from them, for a point at `p`.
    fn crowding(&self, p: [f64; 3], near: &mut Near) -> [f64; 4] {
        self.grid.near(p, near);
        let mut count = 0.0;
        let mut away = [0.0; 3];
        for &index in &near.found {
            let [from, to] = self.axes[index as usize];
            if distance(from, p) <= self.touching || distance(to, p) <= self.touching {
                continue;
            }
            let nearest = nearest_on_segment(p, from, to);
            if distance(nearest, p) <= self.radius {
                count += 1.0;
                let d = sub(p, nearest);
                away = [away[0] + d[0], away[1] + d[1], away[2] + d[2]];
            }
        }
        let [x, y, z] = unit(away);
        [count, x, y, z]
    }
}

/// The size of the scene: the largest coordinate of any part, at least 1.
fn scene_size(axes: &[[[f64; 3]; 2]]) -> f64 {
    axes.iter().flatten().flatten().fold(
        1.0_f64,
        |m, x| if x.is_finite() { m.max(x.abs()) } else { m },
    )
}

impl Responder for Space {
    fn reply_len(&self) -> usize {
        4
    }

    fn update(&mut self, parts: &[Part], budget: usize) -> Result<(), Exceeded> {
        let axes_bytes = parts.len() * std::mem::size_of::<[[f64; 3]; 2]>();
        if axes_bytes > budget {
            return Err(Exceeded {
                what: format!("the crowding of {} parts", parts.len()),
                bytes: axes_bytes,
            });
        }
        self.axes = parts.iter().map(|p| [p.from, p.to]).collect();
        self.touching = SAME_POINT * scene_size(&self.axes);
        self.grid = SegmentGrid::default();
        self.grid = SegmentGrid::build(
            &self.axes,
            self.radius,
            budget - axes_bytes,
            "a crowding grid",
        )?;
        Ok(())
    }

    fn answer(&mut self, probes: &[Probe<'_>], replies: &mut [f64], stride: usize, offset: usize) {
        let mut near = Near::default();
        for (i, probe) in probes.iter().enumerate() {
            if self.work.over() {
                return;
            }
            let reply = self.crowding(probe.position, &mut near);
            self.work.add(std::mem::take(&mut near.scanned));
            if let Some(slot) = replies.get_mut(i * stride + offset..i * stride + offset + 4) {
                slot.copy_from_slice(&reply);
            }
        }
    }

    fn bytes(&self) -> usize {
        self.axes.capacity() * std::mem::size_of::<[[f64; 3]; 2]>() + self.grid.bytes()
    }

    fn work(&mut self) -> Option<&mut Work> {
        Some(&mut self.work)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::settings::tests::spec;
    use crate::vocabulary::EnvironmentProgram;

    fn segment(from: [f64; 3], to: [f64; 3], plant: u32) -> Part {
        Part {
            from,
            to,
            radius: 0.1,
            area: 0.0,
            plant,
        }
    }

    fn probe(position: [f64; 3], plant: u32) -> Probe<'static> {
        Probe {
            position,
            heading: [0.0, 1.0, 0.0],
            up: [0.0, 0.0, 1.0],
            args: &[],
            plant,
        }
    }

    /// Each probe's reply: count, dx, dy, dz.
    fn replies(space: &mut Space, probes: &[Probe<'_>]) -> Vec<[f64; 4]> {
        let mut out = vec![f64::NAN; probes.len() * 6];
        space.answer(probes, &mut out, 6, 1);
        out.chunks(6)
            .map(|c| {
                assert!(c[0].is_nan() && c[5].is_nan(), "wrote outside its place");
                [c[1], c[2], c[3], c[4]]
            })
            .collect()
    }

    fn space(radius: f64) -> Space {
        Space::new(
            &spec(EnvironmentProgram::Space, None, &[("radius", &[radius])]),
            1.0,
        )
        .unwrap()
    }

    #[test]
    fn a_bud_counts_the_parts_around_it_but_not_its_own_segment() {
        let mut s = space(1.0);
        let parts = [
            segment([0.0, 0.0, 0.0], [0.0, 1.0, 0.0], 0), // the bud's own segment
            segment([0.0, 1.0, 0.0], [0.0, 1.0, 0.0], 0), // a leaf at the bud: touching too
            segment([0.0, 1.0, 0.0], [0.0, 1.5, 0.3], 0), // the axis going on from the bud
            segment([0.5, 0.0, 0.0], [0.5, 2.0, 0.0], 0), // 0.5 to the right (+x)
            segment([0.0, 1.0, 0.8], [3.0, 1.0, 0.8], 0), // 0.8 in front (+z)
            segment([-1.5, 1.0, 0.0], [-1.5, 3.0, 0.0], 0), // 1.5 to the left: too far
        ];
        s.update(&parts, 1 << 20).unwrap();
        let [[count, dx, dy, dz]] = replies(&mut s, &[probe([0.0, 1.0, 0.0], 0)])[..] else {
            unreachable!()
        };
        assert_eq!(count, 2.0);
        // Away from (0.5, 0, 0) and (0, 0, 0.8): (-0.5, 0, -0.8) scaled to 1.
        let l = (0.25f64 + 0.64).sqrt();
        assert!((dx + 0.5 / l).abs() < 1e-12 && dy.abs() < 1e-12 && (dz + 0.8 / l).abs() < 1e-12);
    }

    #[test]
    fn alone_it_replies_nothing_and_no_direction() {
        let mut s = space(1.0);
        s.update(&[segment([0.0; 3], [0.0, 1.0, 0.0], 0)], 1 << 20)
            .unwrap();
        let r = replies(
            &mut s,
            &[probe([0.0, 1.0, 0.0], 0), probe([5.0, 5.0, 5.0], 0)],
        );
        assert_eq!(r, vec![[0.0; 4], [0.0; 4]]);
    }

    #[test]
    fn the_parts_of_other_plants_crowd_a_bud_as_its_own_do() {
        // Two plants 1.5 apart; a bud of plant 0 on its side facing plant 1.
        let parts = [
            segment([0.0; 3], [0.0, 2.0, 0.0], 0),
            segment([0.0, 1.0, 0.0], [0.6, 1.6, 0.0], 0),
            segment([1.5, 0.0, 0.0], [1.5, 2.0, 0.0], 1),
        ];
        let mut s = space(1.0);
        s.update(&parts, 1 << 20).unwrap();
        let r = replies(
            &mut s,
            &[probe([0.6, 1.6, 0.0], 0), probe([1.5, 2.0, 0.0], 1)],
        );
        // The bud at (0.6, 1.6): its own stem 0.6 away, the other plant 0.9 away (its own
        // branch ends at it).
        assert_eq!(r[0][0], 2.0);
        // Away from both: (0.6 - 0.9, 0, 0) scaled to 1.
        assert_eq!(r[0][1..], [-1.0, 0.0, 0.0]);
        // Plant 1's bud at its top: plant 0's stem 1.5 away is too far, its branch's tip is 0.98.
        assert_eq!(r[1][0], 1.0);
        assert!(r[1][1] > 0.9, "pushed to +x, away from plant 0: {:?}", r[1]);
        // Without plant 1 the first bud is less crowded.
        s.update(&parts[..2], 1 << 20).unwrap();
        assert_eq!(
            replies(&mut s, &[probe([0.6, 1.6, 0.0], 0)])[0],
            [1.0, 1.0, 0.0, 0.0]
        );
    }

    #[test]
    fn a_long_segment_counts_by_its_nearest_point_once() {
        let mut s = space(0.5);
        s.update(&[segment([-50.0, 0.0, 0.0], [50.0, 0.0, 0.0], 0)], 1 << 20)
            .unwrap();
        let r = replies(
            &mut s,
            &[probe([20.3, 0.4, 0.0], 0), probe([20.3, 0.6, 0.0], 0)],
        );
        assert_eq!(r[0][0], 1.0);
        assert!((r[0][2] - 1.0).abs() < 1e-12, "away is +y: {:?}", r[0]);
        assert_eq!(r[1][0], 0.0);
    }

    #[test]
    fn a_grid_past_the_budget_is_an_error_not_a_trap() {
        let mut s = space(1e-6);
        let e = s
            .update(&[segment([0.0; 3], [100.0, 0.0, 0.0], 0)], 1 << 20)
            .unwrap_err();
        assert!(
            e.bytes > 1 << 20 && e.what.contains("crowding grid"),
            "{e:?}"
        );
        assert!(s.bytes() <= 1 << 20);
    }

    #[test]
    fn a_radius_that_is_not_above_zero_is_an_error_at_the_setting() {
        for r in [0.0, -1.0, f64::INFINITY] {
            let e = Space::new(
                &spec(EnvironmentProgram::Space, None, &[("radius", &[r])]),
                1.0,
            )
            .unwrap_err();
            assert_eq!((e.code, e.span), ("E0239", 0..5));
        }
        let plain = spec(EnvironmentProgram::Space, None, &[]);
        assert_eq!(Space::new(&plain, 0.25).unwrap().radius, 0.25);
        assert_eq!(Space::new(&plain, 0.0).unwrap_err().span, 0..100);
    }
}

//! The obstacle program (`#environment obstacle box|sphere|plane …`): a solid shape that tells
//! each `?E` whether it is free and how far it is from the surface, as vlab's topiary does. The
//! turtle does not stop at an obstacle: the grammar decides what a plant does with the reply (it
//! prunes with `%` when `free == 0`).

use super::{Exceeded, Part, Probe, Responder};
use crate::model::ProgramSpec;
use crate::vocabulary::EnvironmentShape;
use glam::DVec3;

/// A solid shape, in the model's coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Solid {
    /// An axis-aligned box from `min` to `max`.
    Box {
        min: DVec3,
        max: DVec3,
    },
    Sphere {
        center: DVec3,
        radius: f64,
    },
    /// The half-space behind the plane through `point`; `normal` (unit) points to the free side.
    Plane {
        point: DVec3,
        normal: DVec3,
    },
}

impl Solid {
    /// The solid a resolved `#environment obstacle …` line describes (the resolver checked its
    /// settings; `None` if they are missing all the same).
    pub fn of(spec: &ProgramSpec) -> Option<Solid> {
        let v = |name: &str| spec.vector(name).map(DVec3::from_array);
        Some(match spec.shape? {
            EnvironmentShape::Box => {
                let (a, b) = (v("min")?, v("max")?);
                Solid::Box {
                    min: a.min(b),
                    max: a.max(b),
                }
            }
            EnvironmentShape::Sphere => Solid::Sphere {
                center: v("center")?,
                radius: spec.number("radius")?.abs(),
            },
            EnvironmentShape::Plane => Solid::Plane {
                point: v("point")?,
                normal: v("normal")?.try_normalize()?,
            },
        })
    }

    /// The signed distance from `p` to the surface: positive outside (free), negative inside.
    pub fn distance(&self, p: DVec3) -> f64 {
        match *self {
            Solid::Box { min, max } => {
                let centre = (min + max) * 0.5;
                let half = (max - min) * 0.5;
                let q = (p - centre).abs() - half;
                q.max(DVec3::ZERO).length() + q.max_element().min(0.0)
            }
            Solid::Sphere { center, radius } => (p - center).length() - radius,
            Solid::Plane { point, normal } => (p - point).dot(normal),
        }
    }
}

/// The obstacle program: one solid. Replies `free` (1 outside or on the surface, 0 inside) and
/// the signed `distance` to the surface.
#[derive(Clone, Debug)]
pub struct Obstacle {
    pub solid: Solid,
}

impl Responder for Obstacle {
    fn reply_len(&self) -> usize {
        2
    }

    fn update(&mut self, _parts: &[Part], _budget: usize) -> Result<(), Exceeded> {
        Ok(())
    }

    fn answer(&mut self, probes: &[Probe<'_>], replies: &mut [f64], stride: usize, offset: usize) {
        for (i, probe) in probes.iter().enumerate() {
            let d = self.solid.distance(DVec3::from_array(probe.position));
            let at = i * stride + offset;
            replies[at] = if d >= 0.0 { 1.0 } else { 0.0 };
            replies[at + 1] = d;
        }
    }

    fn bytes(&self) -> usize {
        size_of::<Self>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn near(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-12
    }

    #[test]
    fn distances_are_signed_and_exact() {
        let b = Solid::Box {
            min: DVec3::ZERO,
            max: DVec3::new(2.0, 2.0, 2.0),
        };
        assert!(near(b.distance(DVec3::new(1.0, 1.0, 1.0)), -1.0));
        assert!(near(b.distance(DVec3::new(1.0, 3.5, 1.0)), 1.5));
        // Beyond a corner: the distance to the corner.
        assert!(near(b.distance(DVec3::new(3.0, 3.0, 2.0)), 2f64.sqrt()));
        let s = Solid::Sphere {
            center: DVec3::Y,
            radius: 2.0,
        };
        assert!(near(s.distance(DVec3::new(0.0, 4.0, 0.0)), 1.0));
        assert!(near(s.distance(DVec3::Y), -2.0));
        let p = Solid::Plane {
            point: DVec3::new(0.0, 5.0, 0.0),
            normal: DVec3::NEG_Y,
        };
        assert!(near(p.distance(DVec3::new(7.0, 3.0, 1.0)), 2.0));
        assert!(near(p.distance(DVec3::new(0.0, 6.0, 0.0)), -1.0));
    }

    #[test]
    fn it_answers_each_probe_in_its_slot() {
        let mut o = Obstacle {
            solid: Solid::Sphere {
                center: DVec3::ZERO,
                radius: 1.0,
            },
        };
        let probe = |x: f64| Probe {
            position: [x, 0.0, 0.0],
            heading: [0.0, 1.0, 0.0],
            up: [0.0, 0.0, 1.0],
            args: &[],
            plant: 0,
        };
        let mut replies = vec![9.0; 6];
        o.answer(&[probe(0.5), probe(3.0)], &mut replies, 3, 1);
        assert_eq!(replies, vec![9.0, 0.0, -0.5, 9.0, 1.0, 2.0]);
    }
}

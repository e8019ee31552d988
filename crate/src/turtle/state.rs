//! The turtle's state and its rotations (docs/LANGUAGE.md, "Turtle").

use crate::maths;
use crate::model::{Settings, ORGAN_COLOR};
use glam::DVec3;

/// The world's up direction, for `$` (ABOP's V).
const VERTICAL: DVec3 = DVec3::Y;

/// The turtle: where it stands, its frame (heading H, left L, up U), and what it draws with.
#[derive(Clone, Copy, Debug)]
pub(super) struct TurtleState {
    pub position: DVec3,
    pub heading: DVec3,
    pub left: DVec3,
    pub up: DVec3,
    pub width: f64,
    pub color: u16,
    /// A `'` or `;` on the turtle's path chose the colour, or the grammar set the starting one
    /// (`#color 0 …`): organs take `color`, not [`ORGAN_COLOR`].
    pub color_chosen: bool,
    pub tropism: DVec3,
    pub susceptibility: f64,
    pub smooth: bool,
    /// The last segment drawn on this axis, if the turtle still stands at its end.
    pub last_segment: Option<u32>,
    /// The last segment drawn on the turtle's path (`Segment::anchor` of what it draws next).
    pub anchor: Option<u32>,
}

impl TurtleState {
    /// Where every reading of a string starts: at the origin, H = +Y, L = −X, U = +Z, turned by
    /// `#heading` as `+` would turn it.
    pub fn start(settings: &Settings) -> TurtleState {
        let (tropism, susceptibility) = settings.tropism;
        let mut start = TurtleState {
            position: DVec3::ZERO,
            heading: DVec3::Y,
            left: DVec3::NEG_X,
            up: DVec3::Z,
            width: settings.width,
            color: 0,
            color_chosen: settings.start_color_given,
            tropism,
            susceptibility,
            smooth: false,
            last_segment: None,
            anchor: None,
        };
        if settings.heading != 0.0 {
            start.yaw(maths::sin_cos(settings.heading.to_radians()));
        }
        start
    }

    /// The colour index of an organ drawn here (a polygon, a leaf or a petal): the turtle's, once
    /// a colour was chosen; leaf green before.
    pub fn organ_color(&self) -> u16 {
        if self.color_chosen {
            self.color
        } else {
            ORGAN_COLOR
        }
    }

    /// Right-handed rotation about U by the angle whose sine and cosine are `(s, c)`: H turns
    /// towards L.
    pub fn yaw(&mut self, (s, c): (f64, f64)) {
        let h = self.heading * c + self.left * s;
        let l = self.left * c - self.heading * s;
        self.set_frame(h, l);
    }

    /// Right-handed rotation about L by the angle of `(s, c)`: H turns away from U (down).
    pub fn pitch(&mut self, (s, c): (f64, f64)) {
        let h = self.heading * c - self.up * s;
        self.set_frame(h, self.left);
    }

    /// Right-handed rotation about H by the angle of `(s, c)`: L turns towards U.
    pub fn roll(&mut self, (s, c): (f64, f64)) {
        let l = self.left * c + self.up * s;
        self.set_frame(self.heading, l);
    }

    /// `$`: L = V × H / |V × H|, U = H × L (unchanged when H is vertical).
    pub fn roll_to_vertical(&mut self) {
        let l = VERTICAL.cross(self.heading);
        if l.length() > 1e-9 {
            self.set_frame(self.heading, l);
        }
    }

    /// ABOP 2.3: after a step, H bends towards T by e·|H × T| (L and U follow).
    pub fn bend(&mut self) {
        if self.susceptibility == 0.0 {
            return;
        }
        let axis = self.heading.cross(self.tropism);
        let strength = axis.length();
        if strength < 1e-12 {
            return;
        }
        let angle = self.susceptibility * strength;
        let rotation = maths::rotation(axis / strength, angle);
        self.set_frame(rotation * self.heading, rotation * self.left);
    }

    /// Turns H towards `target` by `degrees` (away from it when negative) about H × target,
    /// never past it (nor past pointing straight away from it); L and U follow. Nothing happens
    /// when H points along the target (the pull has no side to turn to).
    pub fn turn_towards(&mut self, target: DVec3, degrees: f64) {
        let axis = self.heading.cross(target);
        let s = axis.length();
        if degrees == 0.0 || s < 1e-9 {
            return;
        }
        let between = maths::angle_between(self.heading, target);
        let angle = maths::clamp(
            degrees.to_radians(),
            between - std::f64::consts::PI,
            between,
        );
        let rotation = maths::rotation(axis / s, angle);
        self.set_frame(rotation * self.heading, rotation * self.left);
    }

    #[cfg(feature = "placing")]
    /// Turns the frame the least way so that H points along `direction` (about U by 180° when
    /// it points straight back); nothing for a zero or non-finite direction.
    pub fn point_to(&mut self, direction: DVec3) {
        let length = direction.length();
        if !(length.is_finite() && length > 0.0) {
            return;
        }
        let target = direction / length;
        let axis = self.heading.cross(target);
        let s = axis.length();
        if s < 1e-12 {
            if self.heading.dot(target) < 0.0 {
                self.set_frame(target, -self.left);
            }
            return;
        }
        let rotation = maths::rotation(axis / s, maths::angle_between(self.heading, target));
        self.set_frame(target, rotation * self.left);
    }

    #[cfg(feature = "placing")]
    /// `@R(hx, hy, hz, ux, uy, uz)`: H along the first vector; U along the second made square to
    /// H (L = U × H), or, without it (or with one along H), the least turn onto H.
    pub fn set_heading(&mut self, params: &[f64]) {
        let finite = |k: usize| {
            let v = DVec3::new(params[k], params[k + 1], params[k + 2]);
            v.is_finite().then_some(v)
        };
        let Some(heading) = (params.len() >= 3).then(|| finite(0)).flatten() else {
            return;
        };
        let up = (params.len() >= 6).then(|| finite(3)).flatten();
        match up {
            Some(u) if u.cross(heading).length() > 1e-9 * u.length() * heading.length() => {
                self.set_frame(heading, u.cross(heading))
            }
            _ => self.point_to(heading),
        }
    }

    /// Sets H and L, re-orthonormalising so that rounding never accumulates; U = H × L.
    fn set_frame(&mut self, heading: DVec3, left: DVec3) {
        let h = heading.normalize();
        let l = (left - h * h.dot(left)).normalize();
        if !(h.is_finite() && l.is_finite()) {
            return;
        }
        self.heading = h;
        self.left = l;
        self.up = h.cross(l);
    }
}

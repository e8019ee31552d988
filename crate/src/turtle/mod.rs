//! Stage 4, `turtle`: the derived string becomes a [`Skeleton`] of segments in 3D.
//!
//! Frame conventions (docs/LANGUAGE.md, "Turtle"): the turtle starts at the origin with heading
//! H = +Y, left L = −X and up U = +Z (H × L = U), so plants grow up the Y axis (three.js's up)
//! and a flat grammar lies in the XY plane facing +Z. `+`, `&` and `/` are right-handed rotations
//! by δ about U, L and H respectively; `-`, `^` and `\` rotate by −δ. So `+` turns towards L
//! (left, counter-clockwise seen from +Z) and `&` tips H away from U (down).

mod commands;

pub use commands::{commands_json, Category, Command, CommandInfo, COMMANDS};

use crate::model::{LString, Model};
use glam::DVec3;

/// One drawn segment, from `start` to `end`, with the turtle's frame at the time.
#[derive(Clone, Debug, PartialEq)]
pub struct Segment {
    pub start: DVec3,
    pub end: DVec3,
    /// The turtle's left and up vectors while drawing (unit, orthogonal to the segment).
    pub left: DVec3,
    pub up: DVec3,
    pub width: f64,
    pub color: u16,
    /// Index in the derived string of the module that drew this segment.
    pub module: u32,
}

/// The turtle's output: plain geometry, no mesh yet.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Skeleton {
    pub segments: Vec<Segment>,
    /// Where the turtle stood after the last module.
    pub end: DVec3,
}

#[derive(Clone, Copy, Debug)]
struct TurtleState {
    position: DVec3,
    heading: DVec3,
    left: DVec3,
    up: DVec3,
    width: f64,
    color: u16,
}

impl TurtleState {
    fn initial(width: f64) -> Self {
        TurtleState {
            position: DVec3::ZERO,
            heading: DVec3::Y,
            left: DVec3::NEG_X,
            up: DVec3::Z,
            width,
            color: 0,
        }
    }

    /// Right-handed rotation by `a` radians about U: H turns towards L.
    fn yaw(&mut self, a: f64) {
        let (s, c) = a.sin_cos();
        let h = self.heading * c + self.left * s;
        let l = self.left * c - self.heading * s;
        self.set_frame(h, l);
    }

    /// Right-handed rotation by `a` radians about L: H turns away from U (down).
    fn pitch(&mut self, a: f64) {
        let (s, c) = a.sin_cos();
        let h = self.heading * c - self.up * s;
        self.set_frame(h, self.left);
    }

    /// Right-handed rotation by `a` radians about H: L turns towards U.
    fn roll(&mut self, a: f64) {
        let (s, c) = a.sin_cos();
        let l = self.left * c + self.up * s;
        self.set_frame(self.heading, l);
    }

    /// Sets H and L, re-orthonormalising so that rounding never accumulates; U = H × L.
    fn set_frame(&mut self, heading: DVec3, left: DVec3) {
        let h = heading.normalize();
        let l = (left - h * h.dot(left)).normalize();
        self.heading = h;
        self.left = l;
        self.up = h.cross(l);
    }
}

/// Runs the turtle over `string`.
pub fn interpret(model: &Model, string: &LString) -> Skeleton {
    let settings = &model.settings;
    let mut table: Vec<Option<Command>> = vec![None; model.alphabet.len()];
    for info in COMMANDS {
        if let Some(id) = model.alphabet.get(info.name) {
            table[id.index()] = Some(info.command);
        }
    }
    for &id in &settings.draw {
        table[id.index()] = Some(Command::Forward);
    }
    let delta = settings.angle.to_radians();
    let mut turtle = TurtleState::initial(settings.width);
    let mut stack: Vec<TurtleState> = Vec::new();
    let mut segments = Vec::new();

    for (index, id) in string.ids.iter().enumerate() {
        let Some(command) = table[id.index()] else {
            continue;
        };
        // A first parameter replaces the default length or angle: `F(l)`, `+(a)`.
        let first = string.params_of(index).first().copied();
        let length = first.unwrap_or(settings.step);
        let angle = first.map_or(delta, f64::to_radians);
        match command {
            Command::Forward => {
                let start = turtle.position;
                turtle.position += turtle.heading * length;
                segments.push(Segment {
                    start,
                    end: turtle.position,
                    left: turtle.left,
                    up: turtle.up,
                    width: turtle.width,
                    color: turtle.color,
                    module: index as u32,
                });
            }
            Command::Move => turtle.position += turtle.heading * length,
            Command::TurnLeft => turtle.yaw(angle),
            Command::TurnRight => turtle.yaw(-angle),
            Command::PitchDown => turtle.pitch(angle),
            Command::PitchUp => turtle.pitch(-angle),
            Command::RollRight => turtle.roll(angle),
            Command::RollLeft => turtle.roll(-angle),
            Command::TurnAround => turtle.yaw(std::f64::consts::PI),
            Command::Push => stack.push(turtle),
            Command::Pop => {
                if let Some(saved) = stack.pop() {
                    turtle = saved;
                }
            }
        }
    }
    Skeleton {
        segments,
        end: turtle.position,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{model, syntax};

    fn run(src: &str) -> Skeleton {
        let (file, diags) = syntax::parse(src);
        assert!(diags.is_empty(), "{diags:?}");
        let (model, diags) = model::resolve(&file);
        assert!(diags.is_empty(), "{diags:?}");
        let model = model.expect("model");
        let derivation = crate::derive::derive(
            &model,
            &crate::derive::DeriveOptions {
                steps: 0,
                seed: None,
            },
        );
        interpret(&model, &derivation.expect("derives").string)
    }

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn f_plus_f_at_90_degrees_turns_left() {
        let s = run("#angle 90\naxiom: F+F");
        assert_eq!(s.segments.len(), 2);
        assert!(close(s.segments[0].end, DVec3::new(0.0, 1.0, 0.0)));
        assert!(close(s.end, DVec3::new(-1.0, 1.0, 0.0)), "{}", s.end);
    }

    #[test]
    fn minus_turns_right_and_f_moves_without_drawing() {
        let s = run("#angle 90\naxiom: f-F");
        assert_eq!(s.segments.len(), 1);
        assert!(close(s.end, DVec3::new(1.0, 1.0, 0.0)), "{}", s.end);
    }

    #[test]
    fn pitch_down_tips_the_heading_away_from_up() {
        // H = +Y, U = +Z: '&' by 90° heads to −Z; '^' heads to +Z.
        assert!(close(
            run("#angle 90\naxiom: &F").end,
            DVec3::new(0.0, 0.0, -1.0)
        ));
        assert!(close(
            run("#angle 90\naxiom: ^F").end,
            DVec3::new(0.0, 0.0, 1.0)
        ));
    }

    #[test]
    fn roll_then_turn_leaves_the_plane() {
        // '/' by 90° rolls L (−X) to U (+Z); then '+' turns H towards the new L.
        assert!(close(
            run("#angle 90\naxiom: /+F").end,
            DVec3::new(0.0, 0.0, 1.0)
        ));
        assert!(close(
            run("#angle 90\naxiom: \\+F").end,
            DVec3::new(0.0, 0.0, -1.0)
        ));
    }

    #[test]
    fn parameters_set_length_and_angle() {
        let s = run("#angle 10\naxiom: F(2)+(90)f(3)F");
        assert!(close(s.segments[0].end, DVec3::new(0.0, 2.0, 0.0)));
        assert!(close(s.end, DVec3::new(-4.0, 2.0, 0.0)), "{}", s.end);
    }

    #[test]
    fn turn_around_and_branches_restore_the_state() {
        assert!(close(run("axiom: F|F").end, DVec3::ZERO));
        let s = run("#angle 90\naxiom: F[+F]F");
        assert!(close(s.segments[1].end, DVec3::new(-1.0, 1.0, 0.0)));
        assert!(close(s.end, DVec3::new(0.0, 2.0, 0.0)));
    }

    #[test]
    fn the_frame_stays_orthonormal_after_many_rotations() {
        let s = run(&format!("#angle 13.7\naxiom: {}F", "+&/".repeat(2000)));
        let seg = &s.segments[0];
        let h = (seg.end - seg.start).normalize();
        assert!((seg.left.length() - 1.0).abs() < 1e-12 && (seg.up.length() - 1.0).abs() < 1e-12);
        assert!(
            h.dot(seg.left).abs() < 1e-12
                && h.dot(seg.up).abs() < 1e-12
                && seg.left.dot(seg.up).abs() < 1e-12
        );
    }
}

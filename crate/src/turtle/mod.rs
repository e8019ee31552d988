//! Stage 4, `turtle`: the derived string becomes a [`Skeleton`] in 3D: segments, polygons,
//! predefined surfaces and spheres, plus the values of query modules.
//!
//! Frame conventions (docs/LANGUAGE.md, "Turtle"): the turtle starts at the origin with heading
//! H = +Y, left L = −X and up U = +Z (H × L = U), so plants grow up the Y axis (three.js's up)
//! and a flat grammar lies in the XY plane facing +Z. `+`, `&` and `/` are right-handed rotations
//! by δ about U, L and H respectively; `-`, `^` and `\` rotate by −δ. So `+` turns towards L
//! (left, counter-clockwise seen from +Z) and `&` tips H away from U (down).
//!
//! With growth attributes ([`interpret_grown`]), each module's [`crate::growth::ModuleGrowth`]
//! scales moves by the segment's age (`#shape`), scales widths by age and third
//! (`#shape_width`), and turns the turtle towards the sun, the wind and the ground before the
//! module by the rotation the module has accumulated (`#sun`, `#wind`, `#gravity`).

mod commands;

pub use commands::{command_named, commands_json, Category, Command, CommandInfo, COMMANDS};

use crate::growth::{self, GrowthState, Heights, Third};
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
    /// Index in the interpreted string of the module that drew this segment.
    pub module: u32,
    /// The segment this one continues on the same axis (it starts where that one ended, with no
    /// branch, move or jump between): the mesh shares their joint.
    pub previous: Option<u32>,
    /// Drawn between `@Gc` and `@Ge`: part of a smooth generalized cylinder.
    pub smooth: bool,
    /// The segment this one grows from: the last segment drawn before it on the turtle's path
    /// from the start of the string (a closed `[…]` branch does not count, `f` keeps it, `@M`
    /// clears it). Equal to `previous` when the segment continues an axis; otherwise the segment
    /// at whose end joint a branch leaves. `None` for a segment that starts a new root. See
    /// [`crate::branches`].
    pub anchor: Option<u32>,
}

/// A filled polygon (`{ … }`), vertices in drawing order.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    pub points: Vec<DVec3>,
    pub color: u16,
    /// Index of the `{` module.
    pub module: u32,
    /// The segment the turtle's state at `{` grew from (as [`Segment::anchor`]).
    pub anchor: Option<u32>,
}

/// Which predefined surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SurfaceKind {
    Leaf,
    Petal,
}

/// A predefined surface (`~l`, `~p`) placed at the turtle.
#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    pub kind: SurfaceKind,
    pub origin: DVec3,
    pub heading: DVec3,
    pub left: DVec3,
    pub scale: f64,
    pub color: u16,
    pub module: u32,
    /// The segment the turtle's state here grew from (as [`Segment::anchor`]).
    pub anchor: Option<u32>,
}

/// A sphere (`@O`). Its radius is in model units (`@O(r)`), or half the width in width units
/// when `@O` has no parameter (`radius_width`).
#[derive(Clone, Debug, PartialEq)]
pub struct Sphere {
    pub center: DVec3,
    pub radius: f64,
    pub radius_width: Option<f64>,
    pub color: u16,
    pub module: u32,
    /// The segment the turtle's state here grew from (as [`Segment::anchor`]).
    pub anchor: Option<u32>,
}

/// The value a query module (`?P`, `?H`, `?U`, `?L`) reads at its place in the string.
#[derive(Clone, Debug, PartialEq)]
pub struct QueryValue {
    pub module: u32,
    pub value: [f64; 3],
}

/// The turtle's output: plain geometry, no mesh yet.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Skeleton {
    pub segments: Vec<Segment>,
    pub polygons: Vec<Polygon>,
    pub surfaces: Vec<Surface>,
    pub spheres: Vec<Sphere>,
    pub queries: Vec<QueryValue>,
    /// Where the turtle stood after the last module.
    pub end: DVec3,
    /// The colours of the colour indices (the grammar's palette); empty means
    /// [`crate::model::DEFAULT_PALETTE`].
    pub palette: Vec<[f32; 3]>,
}

impl Skeleton {
    /// The colour of a colour index: the palette entry, wrapping modulo the palette's length.
    pub fn color(&self, index: u16) -> [f32; 3] {
        let palette: &[[f32; 3]] = if self.palette.is_empty() {
            &crate::model::DEFAULT_PALETTE
        } else {
            &self.palette
        };
        palette[index as usize % palette.len()]
    }

    /// True when something was drawn and all of it lies in the plane z = 0 (the plane a grammar
    /// that only turns with `+` and `-` draws in), up to a millionth of the drawing's size: the
    /// studio then shows it face-on in an orthographic view. Widths do not count (tubes always
    /// have thickness); spheres count by their centres.
    pub fn is_flat(&self) -> bool {
        // Two passes over the points without collecting them (a big plant has millions).
        let mut bounds: Option<(DVec3, DVec3)> = None;
        self.for_each_point(&mut |p| {
            bounds = Some(bounds.map_or((p, p), |(lo, hi)| (lo.min(p), hi.max(p))));
            true
        });
        let Some((min, max)) = bounds else {
            return false;
        };
        let size = (max - min).max_element();
        let tolerance = 1e-6 * size.max(1e-12);
        self.for_each_point(&mut |p| p.z.abs() <= tolerance)
    }

    /// Calls `f` on every point that counts for [`Skeleton::is_flat`] until it returns false;
    /// returns whether it never did.
    fn for_each_point(&self, f: &mut dyn FnMut(DVec3) -> bool) -> bool {
        self.segments.iter().all(|s| f(s.start) && f(s.end))
            && self.polygons.iter().all(|p| p.points.iter().all(|&q| f(q)))
            // A surface's outline spans heading and left from the origin.
            && self.surfaces.iter().all(|s| {
                f(s.origin) && f(s.origin + s.heading * s.scale) && f(s.origin + s.left * s.scale)
            })
            && self.spheres.iter().all(|s| f(s.center))
    }
}

/// The world's up direction, for `$` (ABOP's V).
const VERTICAL: DVec3 = DVec3::Y;

#[derive(Clone, Copy, Debug)]
struct TurtleState {
    position: DVec3,
    heading: DVec3,
    left: DVec3,
    up: DVec3,
    width: f64,
    color: u16,
    tropism: DVec3,
    susceptibility: f64,
    smooth: bool,
    /// The last segment drawn on this axis, if the turtle still stands at its end.
    last_segment: Option<u32>,
    /// The last segment drawn on the turtle's path (`Segment::anchor` of what it draws next).
    anchor: Option<u32>,
}

impl TurtleState {
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

    /// `$`: L = V × H / |V × H|, U = H × L (unchanged when H is vertical).
    fn roll_to_vertical(&mut self) {
        let l = VERTICAL.cross(self.heading);
        if l.length() > 1e-9 {
            self.set_frame(self.heading, l);
        }
    }

    /// ABOP 2.3: after a step, H bends towards T by e·|H × T| (L and U follow).
    fn bend(&mut self) {
        if self.susceptibility == 0.0 {
            return;
        }
        let axis = self.heading.cross(self.tropism);
        let strength = axis.length();
        if strength < 1e-12 {
            return;
        }
        let angle = self.susceptibility * strength;
        let rotation = glam::DQuat::from_axis_angle(axis / strength, angle);
        self.set_frame(rotation * self.heading, rotation * self.left);
    }

    /// Turns H towards `target` by `degrees` (away from it when negative) about H × target,
    /// never past it (nor past pointing straight away from it); L and U follow. Nothing happens
    /// when H points along the target (the pull has no side to turn to).
    fn turn_towards(&mut self, target: DVec3, degrees: f64) {
        let axis = self.heading.cross(target);
        let s = axis.length();
        if degrees == 0.0 || s < 1e-9 {
            return;
        }
        let between = self.heading.angle_between(target);
        let angle = degrees
            .to_radians()
            .clamp(between - std::f64::consts::PI, between);
        let rotation = glam::DQuat::from_axis_angle(axis / s, angle);
        self.set_frame(rotation * self.heading, rotation * self.left);
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

/// Runs the turtle over `string`.
pub fn interpret(model: &Model, string: &LString) -> Skeleton {
    run(model, string, None, None)
}

/// Runs the turtle over `string` with its growth state (one module state per module of
/// `string`; ignored when the lengths differ).
pub fn interpret_grown(model: &Model, string: &LString, growth: Option<&GrowthState>) -> Skeleton {
    run(model, string, growth, None)
}

/// The height (Y) of the turtle at every module of `string` (the middle of the move for
/// `F f G g`), and the lowest and highest Y it reaches, its start included: what the growth
/// attributes divide into thirds.
pub fn heights(model: &Model, string: &LString, growth: Option<&GrowthState>) -> Heights {
    let mut heights = Heights::default();
    run(model, string, growth, Some(&mut heights));
    heights
}

fn run(
    model: &Model,
    string: &LString,
    growth: Option<&GrowthState>,
    mut heights: Option<&mut Heights>,
) -> Skeleton {
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
    let (tropism, susceptibility) = settings.tropism;
    let mut turtle = TurtleState {
        position: DVec3::ZERO,
        heading: DVec3::Y,
        left: DVec3::NEG_X,
        up: DVec3::Z,
        width: settings.width,
        color: 0,
        tropism,
        susceptibility,
        smooth: false,
        last_segment: None,
        anchor: None,
    };
    let mut stack: Vec<TurtleState> = Vec::new();
    let mut open_polygons: Vec<(Vec<DVec3>, u16, u32, Option<u32>)> = Vec::new();
    let mut skeleton = Skeleton {
        palette: settings.palette.clone(),
        ..Skeleton::default()
    };
    let grown = growth.filter(|g| g.modules.len() == string.len());
    let attributes = &model.growth;
    let (sun, gravity) = (attributes.sun_direction(), attributes.gravity.is_some());
    let wind = attributes.wind.as_ref().map(|w| w.direction);
    // The lowest and highest Y the turtle reaches, and each module's Y (for `heights`).
    let (mut low, mut high) = (0.0f64, 0.0f64);
    let mut note = |y: f64, at: f64| {
        low = low.min(y);
        high = high.max(y);
        if let Some(h) = heights.as_deref_mut() {
            h.modules.push(at);
        }
    };

    for (index, id) in string.ids.iter().enumerate() {
        // Growth: the rotation this module has accumulated turns the turtle before it.
        let module_growth = grown.map(|g| &g.modules[index]);
        if let Some(g) = module_growth.filter(|g| g.is_bent()) {
            if let Some(sun) = sun {
                turtle.turn_towards(sun, g.sun);
            }
            if let Some(wind) = wind {
                turtle.turn_towards(wind, g.wind);
            }
            if gravity {
                turtle.turn_towards(DVec3::NEG_Y, g.gravity);
            }
        }
        let Some(command) = table[id.index()] else {
            note(turtle.position.y, turtle.position.y);
            continue;
        };
        let before = turtle.position.y;
        let params = string.params_of(index);
        // A first parameter replaces the default length or angle: `F(l)`, `+(a)`.
        let first = params.first().copied().filter(|v| v.is_finite());
        let mut length = first.unwrap_or(settings.step);
        // `#shape`: moves outside polygons stretch with the module's age.
        if let (Some(shape), Some(g), Some(state)) = (&attributes.shape, module_growth, grown) {
            if open_polygons.is_empty() {
                length *= (growth::branch_length(shape.rate, shape.maturity, g.age(state.step))
                    + g.length_variation)
                    .max(0.0);
            }
        }
        let angle = first.map_or(delta, f64::to_radians);
        let vector = || {
            (params.len() >= 3)
                .then(|| DVec3::new(params[0], params[1], params[2]))
                .filter(|v| v.is_finite())
        };
        let index = index as u32;
        match command {
            Command::Forward | Command::ForwardNoVertex | Command::Move | Command::MoveNoVertex => {
                let start = turtle.position;
                turtle.position += turtle.heading * length;
                let draws = matches!(command, Command::Forward | Command::ForwardNoVertex);
                let records = matches!(command, Command::Forward | Command::Move);
                if let Some((points, ..)) = open_polygons.last_mut() {
                    // Inside a polygon, F and f trace its outline instead of drawing.
                    if records {
                        points.push(turtle.position);
                    }
                    turtle.last_segment = None;
                } else if draws && length != 0.0 {
                    let previous = turtle
                        .last_segment
                        .filter(|&s| skeleton.segments[s as usize].end == start);
                    let anchor = turtle.anchor;
                    skeleton.segments.push(Segment {
                        start,
                        end: turtle.position,
                        left: turtle.left,
                        up: turtle.up,
                        width: turtle.width,
                        color: turtle.color,
                        module: index,
                        previous,
                        smooth: turtle.smooth,
                        anchor,
                    });
                    turtle.last_segment = Some(skeleton.segments.len() as u32 - 1);
                    turtle.anchor = turtle.last_segment;
                } else {
                    turtle.last_segment = None;
                }
                if draws {
                    turtle.bend();
                }
            }
            Command::TurnLeft => turtle.yaw(angle),
            Command::TurnRight => turtle.yaw(-angle),
            Command::PitchDown => turtle.pitch(angle),
            Command::PitchUp => turtle.pitch(-angle),
            Command::RollRight => turtle.roll(angle),
            Command::RollLeft => turtle.roll(-angle),
            Command::TurnAround => turtle.yaw(std::f64::consts::PI),
            Command::RollToVertical => turtle.roll_to_vertical(),
            Command::Push => {
                stack.push(turtle);
                // A branch starts a new axis: its first segment does not continue the parent's.
                turtle.last_segment = None;
            }
            Command::Pop => {
                if let Some(saved) = stack.pop() {
                    turtle = saved;
                }
            }
            Command::StartPolygon => {
                open_polygons.push((vec![turtle.position], turtle.color, index, turtle.anchor))
            }
            Command::PolygonVertex => {
                if let Some((points, ..)) = open_polygons.last_mut() {
                    points.push(turtle.position);
                }
            }
            Command::EndPolygon => {
                if let Some((points, color, module, anchor)) = open_polygons.pop() {
                    skeleton.polygons.push(Polygon {
                        points,
                        color,
                        module,
                        anchor,
                    });
                }
            }
            Command::Width => {
                turtle.width = match first {
                    Some(w) => w.max(0.0),
                    None => (turtle.width - settings.width_step).max(0.0),
                }
            }
            Command::NextColor => {
                let step = first.map_or(1, |n| n.round().clamp(-1000.0, 1000.0) as i32);
                turtle.color = (turtle.color as i32 + step).clamp(0, u16::MAX as i32) as u16;
            }
            Command::SetColor => {
                turtle.color = match first {
                    Some(c) => c.round().clamp(0.0, u16::MAX as f64) as u16,
                    None => turtle.color.saturating_add(1),
                }
            }
            Command::Leaf | Command::Petal => {
                let scale = first.unwrap_or(1.0);
                if scale > 0.0 {
                    skeleton.surfaces.push(Surface {
                        kind: if command == Command::Leaf {
                            SurfaceKind::Leaf
                        } else {
                            SurfaceKind::Petal
                        },
                        origin: turtle.position,
                        heading: turtle.heading,
                        left: turtle.left,
                        scale,
                        color: turtle.color,
                        module: index,
                        anchor: turtle.anchor,
                    });
                }
            }
            Command::Sphere => skeleton.spheres.push(Sphere {
                center: turtle.position,
                radius: first.unwrap_or(0.0).max(0.0),
                radius_width: first.is_none().then_some(turtle.width * 0.5),
                color: turtle.color,
                module: index,
                anchor: turtle.anchor,
            }),
            Command::MoveTo => {
                if let Some(p) = vector() {
                    turtle.position = p;
                    turtle.last_segment = None;
                    // What is drawn from an absolute position does not grow from a joint.
                    turtle.anchor = None;
                }
            }
            Command::TropismVector => {
                if let Some(t) = vector() {
                    turtle.tropism = t;
                }
            }
            Command::TropismStrength => {
                if let Some(e) = first {
                    turtle.susceptibility = e;
                }
            }
            Command::StartSmooth => turtle.smooth = true,
            Command::EndSmooth => turtle.smooth = false,
            Command::QueryPosition
            | Command::QueryHeading
            | Command::QueryUp
            | Command::QueryLeft => {
                let v = match command {
                    Command::QueryPosition => turtle.position,
                    Command::QueryHeading => turtle.heading,
                    Command::QueryUp => turtle.up,
                    _ => turtle.left,
                };
                skeleton.queries.push(QueryValue {
                    module: index,
                    value: [v.x, v.y, v.z],
                });
            }
            Command::Derivation => {}
        }
        let y = turtle.position.y;
        let moved = matches!(
            command,
            Command::Forward | Command::ForwardNoVertex | Command::Move | Command::MoveNoVertex
        );
        note(y, if moved { (before + y) * 0.5 } else { y });
    }
    if let Some(h) = heights {
        h.low = low;
        h.high = high;
    }
    // `#shape_width`: widths by age and by the third the segment's middle stands in.
    if let (Some(width), Some(g)) = (&attributes.shape_width, grown) {
        for segment in &mut skeleton.segments {
            let m = &g.modules[segment.module as usize];
            let third = Third::of((segment.start.y + segment.end.y) * 0.5, low, high);
            let factor = growth::branch_width(m.age(g.step), width.positional[third as usize])
                + m.width_variation;
            segment.width *= factor.max(0.0);
        }
    }
    skeleton.end = turtle.position;
    skeleton
}

#[cfg(test)]
mod tests;

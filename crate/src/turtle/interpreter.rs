//! The interpreter: reads the string module by module and draws.

use super::skeleton::{
    segment_within_bounds, Polygon, QueryValue, Segment, Skeleton, Sphere, Surface, SurfaceKind,
};
use super::state::TurtleState;
use crate::growth::{Adjustments, Heights, Third};
use crate::maths;
use crate::model::{LString, Model, Settings};
use crate::vocabulary::{Command, ModuleInfo};
use glam::DVec3;

/// A polygon being traced: its points, colour, the `{` module and the segment it grows from.
type OpenPolygon = (Vec<DVec3>, u16, u32, Option<u32>);

/// What the turtle does with one module id: the command, and its first parameter's default.
type Action = (Command, Option<f64>);

/// Where the turtle draws: the whole [`Skeleton`], or only what a sketch shows
/// (`super::sketch::Sketch`: the segments as lines, written straight into flat arrays). One
/// interpreter serves both, so a sketch's lines are the skeleton's segments exactly.
pub(super) trait Canvas {
    /// A segment from `start` to the turtle's position, drawn by module `index` of the string; the
    /// turtle's `last_segment` is the segment it may continue. Returns the new segment's index.
    fn segment(&mut self, start: DVec3, t: &TurtleState, index: u32) -> u32;
    fn polygon(&mut self, polygon: Polygon);
    fn surface(&mut self, surface: Surface);
    fn sphere(&mut self, sphere: Sphere);
    /// Whether the canvas keeps query values (a sketch does not).
    fn wants_queries(&self) -> bool;
    fn query(&mut self, query: QueryValue);
    /// A communication module `?E` (kept when [`Canvas::wants_queries`]).
    #[cfg(feature = "environment")]
    fn environment_query(&mut self, query: super::skeleton::EnvironmentQuery);
    /// The grammar set a width (`!`).
    fn widths_set(&mut self);
    /// The string is read: the turtle ended at `end`; `widths` are growth's width factors by third
    /// with the extent `low..high` of the turtle's heights, when growth scales widths;
    /// `segments_within_bounds`: no segment was drawn with a number that
    /// [`Skeleton::clamp_to_finite`] would change (the interpreter checks each as it draws it).
    fn finish(
        &mut self,
        end: DVec3,
        widths: Option<(&Adjustments, f64, f64)>,
        segments_within_bounds: bool,
    );
}

impl Canvas for Skeleton {
    #[inline]
    fn segment(&mut self, start: DVec3, t: &TurtleState, index: u32) -> u32 {
        let segments = &mut self.segments;
        let previous = t
            .last_segment
            .filter(|&s| segments[s as usize].end == start);
        segments.push(Segment {
            start,
            end: t.position,
            left: t.left,
            up: t.up,
            width: t.width,
            color: t.color,
            module: index,
            previous,
            smooth: t.smooth,
            anchor: t.anchor,
        });
        segments.len() as u32 - 1
    }

    fn polygon(&mut self, polygon: Polygon) {
        self.polygons.push(polygon);
    }

    fn surface(&mut self, surface: Surface) {
        self.surfaces.push(surface);
    }

    fn sphere(&mut self, sphere: Sphere) {
        self.spheres.push(sphere);
    }

    fn wants_queries(&self) -> bool {
        true
    }

    fn query(&mut self, query: QueryValue) {
        self.queries.push(query);
    }

    #[cfg(feature = "environment")]
    fn environment_query(&mut self, query: super::skeleton::EnvironmentQuery) {
        self.environment_queries.push(query);
    }

    fn widths_set(&mut self) {
        self.widths_set = true;
    }

    fn finish(
        &mut self,
        end: DVec3,
        widths: Option<(&Adjustments, f64, f64)>,
        segments_within_bounds: bool,
    ) {
        // Growth's widths change the segments after they were checked.
        let check_segments = widths.is_some() || !segments_within_bounds;
        if let Some((a, low, high)) = widths {
            for segment in &mut self.segments {
                let middle = (segment.start.y + segment.end.y) * 0.5;
                let third = Third::of(middle, low, high);
                segment.width *= a.modules[segment.module as usize].width[third as usize];
            }
        }
        self.end = end;
        self.clamp(check_segments);
    }
}

pub(super) struct Interpreter<'a, C: Canvas> {
    settings: &'a Settings,
    /// For each module id, the declared surface it draws (`~X`), if any (none without the
    /// feature `surfaces`, whose model declares none: the first plant's core).
    #[cfg(feature = "surfaces")]
    surface_of: Vec<Option<u16>>,
    /// The declared surfaces.
    shapes: &'a [std::sync::Arc<crate::model::SurfaceShape>],
    /// For each module id, what the turtle does with it.
    actions: Vec<Option<Action>>,
    turtle: TurtleState,
    stack: Vec<TurtleState>,
    open_polygons: Vec<OpenPolygon>,
    canvas: C,
    adjustments: Option<&'a Adjustments>,
    /// The lowest and highest Y the turtle reaches.
    low: f64,
    high: f64,
    /// When asked, the turtle's Y at each module.
    heights: Option<&'a mut Heights>,
    /// The last two angles turned by (their bits) with their sines and cosines: a grammar turns by
    /// a few angles, over and over.
    turns: [(u64, (f64, f64)); 2],
    /// No segment drawn so far holds a number the skeleton clamps ([`segment_within_bounds`]):
    /// then the skeleton's pass over every segment to clamp them is left out (about a tenth of
    /// the interpret stage of 1.24d at n = 10 natively).
    segments_within_bounds: bool,
}

/// The first parameter's default of a module, reading directives' values from the settings.
fn first_default(info: &ModuleInfo, settings: &Settings) -> Option<f64> {
    info.params
        .first()?
        .default_value(|directive| settings.value(directive))
}

/// The skeleton a turtle with `settings` starts drawing (its palette, whether widths are set).
pub(super) fn empty_skeleton(settings: &Settings, adjustments: bool) -> Skeleton {
    Skeleton {
        palette: settings.palette.clone(),
        shapes: settings.surfaces.clone(),
        widths_set: settings.width_given || adjustments,
        width_unit: settings.width_unit,
        ..Skeleton::default()
    }
}

impl<'a, C: Canvas> Interpreter<'a, C> {
    pub fn new(
        model: &'a Model,
        string: &LString,
        adjustments: Option<&'a Adjustments>,
        heights: Option<&'a mut Heights>,
        canvas: C,
    ) -> Self {
        let settings = &model.settings;
        let actions = model
            .meanings
            .iter()
            .map(|m| m.and_then(|info| Some((info.command()?, first_default(info, settings)))))
            .collect();
        let start = TurtleState::start(settings);
        #[cfg(feature = "surfaces")]
        let surface_of = (0..model.alphabet.len())
            .map(|i| {
                model
                    .surface_of(crate::model::ModuleId(i as u32))
                    .map(|k| k as u16)
            })
            .collect();
        Interpreter {
            settings,
            #[cfg(feature = "surfaces")]
            surface_of,
            shapes: &settings.surfaces,
            actions,
            turtle: start,
            stack: Vec::new(),
            open_polygons: Vec::new(),
            canvas,
            adjustments: adjustments.filter(|a| a.modules.len() == string.len()),
            low: 0.0,
            high: 0.0,
            heights,
            turns: [(0f64.to_bits(), (0.0, 1.0)); 2],
            segments_within_bounds: true,
        }
    }

    pub fn run(mut self, string: &LString) -> C {
        // The extent is read by heights and by growth's widths by third only.
        let extent = self.heights.is_some() || self.adjustments.is_some_and(|a| a.scales_width);
        for (index, id) in string.ids.iter().enumerate() {
            self.turn_by_growth(index);
            let before = self.turtle.position.y;
            let moved = match self.actions[id.index()] {
                Some((Command::Surface, _)) => {
                    self.declared_surface(id.index(), string.params_of(index), index as u32);
                    false
                }
                Some((command, default)) => {
                    let params = string.params_of(index);
                    // A first parameter replaces the default length or angle: `F(l)`, `+(a)`.
                    let first = params.first().copied().filter(|v| v.is_finite());
                    self.command(command, first, first.or(default), params, index as u32)
                }
                None => false,
            };
            if extent {
                let y = self.turtle.position.y;
                self.note(y, if moved { (before + y) * 0.5 } else { y });
            }
        }
        self.finish()
    }

    /// `~X` of module `id`: the surface declared for X (an undeclared one draws nothing: E0222;
    /// without the feature `surfaces` the model declares none).
    fn declared_surface(&mut self, id: usize, params: &[f64], index: u32) {
        #[cfg(feature = "surfaces")]
        if let Some(k) = self.surface_of[id] {
            self.surface(SurfaceKind::Declared(k), params, index);
        }
        #[cfg(not(feature = "surfaces"))]
        let _ = (id, params, index);
    }

    /// Records the turtle's height at a module (`at`, the middle of a move) and the extent.
    fn note(&mut self, y: f64, at: f64) {
        self.low = self.low.min(y);
        self.high = self.high.max(y);
        if let Some(h) = self.heights.as_deref_mut() {
            h.modules.push(at);
        }
    }

    /// Growth: the rotation the module has accumulated turns the turtle before it.
    fn turn_by_growth(&mut self, index: usize) {
        let Some(adjustments) = self.adjustments else {
            return;
        };
        let m = &adjustments.modules[index];
        if !m.turns() {
            return;
        }
        for (attractor, degrees) in adjustments.attractors.iter().zip(m.turns) {
            if let Some(direction) = attractor {
                self.turtle.turn_towards(*direction, degrees);
            }
        }
    }

    /// Does one command. `first` is the module's first parameter (when finite), `value` that or
    /// the parameter's default. Returns whether the turtle moved forward.
    fn command(
        &mut self,
        command: Command,
        first: Option<f64>,
        value: Option<f64>,
        params: &[f64],
        index: u32,
    ) -> bool {
        match command {
            Command::Forward | Command::ForwardNoVertex | Command::Move | Command::MoveNoVertex => {
                self.forward(command, value.unwrap_or(0.0), index);
                return true;
            }
            Command::TurnLeft
            | Command::TurnRight
            | Command::PitchDown
            | Command::PitchUp
            | Command::RollRight
            | Command::RollLeft
            | Command::TurnAround
            | Command::RollToVertical => self.rotate(command, value.unwrap_or(0.0).to_radians()),
            Command::Push => {
                self.stack.push(self.turtle);
                // A branch starts a new axis: its first segment does not continue the parent's.
                self.turtle.last_segment = None;
            }
            Command::Pop => {
                if let Some(saved) = self.stack.pop() {
                    self.turtle = saved;
                }
            }
            Command::StartPolygon | Command::PolygonVertex | Command::EndPolygon => {
                self.polygon(command, index)
            }
            Command::Width | Command::NextColor | Command::SetColor => {
                self.appearance(command, first, value)
            }
            Command::Leaf => self.surface(SurfaceKind::Leaf, params, index),
            Command::Petal => self.surface(SurfaceKind::Petal, params, index),
            // A declared `~X` is drawn by `run` (`declared_surface`), which knows its module.
            Command::Surface => {}
            Command::Sphere => self.sphere(first, index),
            #[cfg(feature = "placing")]
            Command::LineTo
            | Command::LineRel
            | Command::OrientedLineTo
            | Command::OrientedLineRel => return self.line(command, params, index),
            #[cfg(feature = "placing")]
            Command::SetHeading => self.turtle.set_heading(params),
            #[cfg(feature = "placing")]
            Command::Frame => self.frame(value.unwrap_or(1.0), index),
            // The first plant's core: the build worker builds such a grammar again with the
            // studio core (`Model::places_by_coordinates`).
            #[cfg(not(feature = "placing"))]
            Command::LineTo
            | Command::LineRel
            | Command::OrientedLineTo
            | Command::OrientedLineRel
            | Command::SetHeading
            | Command::Frame => {}
            Command::MoveTo
            | Command::TropismVector
            | Command::TropismStrength
            | Command::StartSmooth
            | Command::EndSmooth => self.set(command, first, params),
            Command::QueryPosition
            | Command::QueryHeading
            | Command::QueryUp
            | Command::QueryLeft => self.query(command, index),
            // Only the environment reads where `?E` stands (the first plant's core runs none).
            #[cfg(feature = "environment")]
            Command::QueryEnvironment => self.environment_query(index),
            #[cfg(not(feature = "environment"))]
            Command::QueryEnvironment => {}
        }
        false
    }

    /// The rotations, by `angle` radians where they take one.
    fn rotate(&mut self, command: Command, angle: f64) {
        if command == Command::RollToVertical {
            return self.turtle.roll_to_vertical();
        }
        let a = match command {
            Command::TurnRight | Command::PitchUp | Command::RollLeft => -angle,
            Command::TurnAround => std::f64::consts::PI,
            _ => angle,
        };
        let turn = self.sin_cos(a);
        let t = &mut self.turtle;
        match command {
            Command::TurnLeft | Command::TurnRight | Command::TurnAround => t.yaw(turn),
            Command::PitchDown | Command::PitchUp => t.pitch(turn),
            _ => t.roll(turn),
        }
    }

    /// `maths::sin_cos(a)`, remembered for the last two angles.
    #[inline]
    fn sin_cos(&mut self, a: f64) -> (f64, f64) {
        let bits = a.to_bits();
        if let Some(&(_, turn)) = self.turns.iter().find(|(b, _)| *b == bits) {
            return turn;
        }
        let turn = maths::sin_cos(a);
        self.turns = [self.turns[1], (bits, turn)];
        turn
    }

    /// `!`, `'`, `;`: the width and the colour index.
    fn appearance(&mut self, command: Command, first: Option<f64>, value: Option<f64>) {
        let t = &mut self.turtle;
        if command != Command::Width {
            t.color_chosen = true;
        }
        match command {
            Command::Width => {
                self.canvas.widths_set();
                t.width = match first {
                    Some(w) => w.max(0.0),
                    None => (t.width - self.settings.width_step).max(0.0),
                }
            }
            Command::NextColor => {
                let step = value.map_or(1, |n| n.round().clamp(-1000.0, 1000.0) as i32);
                t.color = (t.color as i32 + step).clamp(0, u16::MAX as i32) as u16;
            }
            _ => {
                t.color = match first {
                    Some(c) => c.round().clamp(0.0, u16::MAX as f64) as u16,
                    None => t.color.saturating_add(1),
                }
            }
        }
    }

    /// `@M`, `@Tp`, `@Ts`, `@Gc`, `@Ge`: the position, this branch's tropism, smoothness.
    fn set(&mut self, command: Command, first: Option<f64>, params: &[f64]) {
        let t = &mut self.turtle;
        match command {
            Command::MoveTo => {
                if let Some(p) = vector(params) {
                    t.position = p;
                    t.last_segment = None;
                    // What is drawn from an absolute position does not grow from a joint.
                    t.anchor = None;
                }
            }
            Command::TropismVector => {
                if let Some(v) = vector(params) {
                    t.tropism = v;
                }
            }
            Command::TropismStrength => {
                if let Some(e) = first {
                    t.susceptibility = e;
                }
            }
            Command::StartSmooth => t.smooth = true,
            _ => t.smooth = false,
        }
    }

    /// `@O`: a sphere of radius `first`, or as wide as the turtle without one.
    fn sphere(&mut self, first: Option<f64>, index: u32) {
        let t = &self.turtle;
        self.canvas.sphere(Sphere {
            center: t.position,
            radius: first.unwrap_or(0.0).max(0.0),
            radius_width: first.is_none().then_some(t.width * 0.5),
            color: t.color,
            module: index,
            anchor: t.anchor,
        });
    }

    /// `F f G g`: move by `length` (scaled by growth outside polygons); `F` and `G` draw a
    /// segment; inside a polygon `F` and `f` record its vertices instead.
    fn forward(&mut self, command: Command, mut length: f64, index: u32) {
        if let Some(a) = self.adjustments.filter(|a| a.scales_length) {
            if self.open_polygons.is_empty() {
                length *= a.modules[index as usize].length;
            }
        }
        let t = &mut self.turtle;
        let start = t.position;
        t.position += t.heading * length;
        let draws = command.draws();
        let records = matches!(command, Command::Forward | Command::Move);
        if let Some((points, ..)) = self.open_polygons.last_mut() {
            if records {
                points.push(t.position);
            }
            t.last_segment = None;
        } else if draws && length != 0.0 {
            self.segments_within_bounds &= segment_within_bounds(start, t);
            let segment = self.canvas.segment(start, t, index);
            t.last_segment = Some(segment);
            t.anchor = t.last_segment;
        } else {
            t.last_segment = None;
        }
        if draws {
            t.bend();
        }
    }

    #[cfg(feature = "placing")]
    /// `@LineTo`, `@LineRel`, `@OLineTo`, `@OLineRel` (L-Py's commands): a segment from the
    /// turtle to a point, or by a vector, whatever the heading. The segment is drawn square to its
    /// own direction (the turtle's frame turned the least way onto it); the `O` forms keep that
    /// frame, the others keep the turtle's. A fourth parameter is the width from then on. Inside
    /// a polygon the end is a vertex, as `F`'s. Returns whether the turtle moved.
    fn line(&mut self, command: Command, params: &[f64], index: u32) -> bool {
        let Some(v) = vector(params) else {
            return false;
        };
        let t = &mut self.turtle;
        let start = t.position;
        let end = match command {
            Command::LineTo | Command::OrientedLineTo => v,
            _ => start + v,
        };
        let mut along = *t;
        along.point_to(end - start);
        along.position = end;
        if let Some((points, ..)) = self.open_polygons.last_mut() {
            points.push(end);
            along.last_segment = None;
        } else if end != start {
            self.segments_within_bounds &= segment_within_bounds(start, &along);
            let segment = self.canvas.segment(start, &along, index);
            along.last_segment = Some(segment);
            along.anchor = Some(segment);
        }
        if let Some(w) = params.get(3).filter(|w| w.is_finite()) {
            self.canvas.widths_set();
            along.width = w.max(0.0);
        }
        if matches!(command, Command::LineTo | Command::LineRel) {
            along.heading = t.heading;
            along.left = t.left;
            along.up = t.up;
        }
        *t = along;
        true
    }

    #[cfg(feature = "placing")]
    /// `@Frame(s)`: H, L and U drawn from the turtle, each `size` long, in the palette's red,
    /// green and blue entries ([`FRAME_COLORS`]); the turtle does not move.
    fn frame(&mut self, size: f64, index: u32) {
        let t = self.turtle;
        if !(size.is_finite() && size > 0.0) {
            return;
        }
        for (axis, color) in [t.heading, t.left, t.up].into_iter().zip(FRAME_COLORS) {
            let mut arm = t;
            arm.point_to(axis);
            arm.position = t.position + axis * size;
            arm.color = color;
            arm.last_segment = None;
            self.segments_within_bounds &= segment_within_bounds(t.position, &arm);
            self.canvas.segment(t.position, &arm, index);
        }
    }

    /// `{`, `.`, `}`.
    fn polygon(&mut self, command: Command, index: u32) {
        let t = &self.turtle;
        match command {
            Command::StartPolygon => {
                self.open_polygons
                    .push((vec![t.position], t.organ_color(), index, t.anchor))
            }
            Command::PolygonVertex => {
                if let Some((points, ..)) = self.open_polygons.last_mut() {
                    points.push(t.position);
                }
            }
            _ => {
                if let Some((points, color, module, anchor)) = self.open_polygons.pop() {
                    self.canvas.polygon(Polygon {
                        points,
                        color,
                        module,
                        anchor,
                    });
                }
            }
        }
    }

    /// `~l`, `~p` and a declared `~X`: a surface placed at the turtle, scaled as cpfg's `~`
    /// (interpret.c): by 1 without parameters, by the first along L, H and U with one or two, by
    /// the three along L, H and U with three. Nothing for a scale of 0 or below along H; a
    /// declared surface with an end point moves the turtle there (cpfg's `determine_end_point`,
    /// by the first parameter).
    fn surface(&mut self, kind: SurfaceKind, params: &[f64], index: u32) {
        let finite = |k: usize| params.get(k).copied().filter(|v| v.is_finite());
        let first = finite(0).unwrap_or(1.0);
        let scale = match (finite(1), finite(2)) {
            (Some(sy), Some(sz)) if params.len() >= 3 => DVec3::new(first, sy, sz),
            _ => DVec3::splat(first),
        };
        let nothing = match kind {
            SurfaceKind::Declared(_) => scale.cmpeq(DVec3::ZERO).any(),
            _ => scale.y <= 0.0,
        };
        if nothing {
            return;
        }
        let t = &self.turtle;
        let surface = Surface {
            kind,
            origin: t.position,
            heading: t.heading,
            left: t.left,
            up: t.up,
            scale,
            color: t.organ_color(),
            module: index,
            anchor: t.anchor,
        };
        let end = match kind {
            SurfaceKind::Declared(k) => self.shapes[k as usize].end,
            _ => None,
        };
        if let Some(end) = end {
            let t = &mut self.turtle;
            t.position = surface.origin
                + (surface.left * end.x + surface.heading * end.y + surface.up * end.z) * first;
            t.last_segment = None;
        }
        self.canvas.surface(surface);
    }

    /// `?P ?H ?U ?L`: what the turtle reads here.
    fn query(&mut self, command: Command, index: u32) {
        if !self.canvas.wants_queries() {
            return;
        }
        let t = &self.turtle;
        let v = match command {
            Command::QueryPosition => t.position,
            Command::QueryHeading => t.heading,
            Command::QueryUp => t.up,
            _ => t.left,
        };
        self.canvas.query(QueryValue {
            module: index,
            value: [v.x, v.y, v.z],
        });
    }

    /// `?E`: where the turtle stands and how it is turned, for the environment.
    #[cfg(feature = "environment")]
    fn environment_query(&mut self, index: u32) {
        if !self.canvas.wants_queries() {
            return;
        }
        let t = &self.turtle;
        self.canvas
            .environment_query(super::skeleton::EnvironmentQuery {
                module: index,
                position: t.position.to_array(),
                heading: t.heading.to_array(),
                up: t.up.to_array(),
            });
    }

    /// The extent for heights, growth's widths by third, and where the turtle ended.
    fn finish(mut self) -> C {
        if let Some(h) = self.heights.take() {
            h.low = self.low;
            h.high = self.high;
        }
        let widths = self
            .adjustments
            .filter(|a| a.scales_width)
            .map(|a| (a, self.low, self.high));
        self.canvas
            .finish(self.turtle.position, widths, self.segments_within_bounds);
        self.canvas
    }
}

#[cfg(feature = "placing")]
/// The colour indices `@Frame` draws H, L and U in: the default palette's signal red, leaf
/// green and blue (L-Py draws them red, green and blue).
const FRAME_COLORS: [u16; 3] = [10, 5, 13];

/// The first three parameters as a vector, when there are three and they are finite.
fn vector(params: &[f64]) -> Option<DVec3> {
    (params.len() >= 3)
        .then(|| DVec3::new(params[0], params[1], params[2]))
        .filter(|v| v.is_finite())
}

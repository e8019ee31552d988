//! What growth asks of the turtle, as plain data: for each module of the string the turtle reads,
//! how far to turn towards each attractor before it, how much longer its moves are, and how much
//! wider its segments are by the third of the plant they stand in.

use glam::DVec3;

/// The turtle's adjustments for one string (see [`crate::turtle::interpret_adjusted`]).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Adjustments {
    /// The directions segments turn towards, in order: the sun, the wind, the ground; `None` when
    /// that attractor is off (or the sun stays below the horizon).
    pub attractors: [Option<DVec3>; 3],
    /// True when moves are scaled ([`ModuleAdjustment::length`], `#shape`).
    pub scales_length: bool,
    /// True when segment widths are scaled ([`ModuleAdjustment::width`], `#shape_width`).
    pub scales_width: bool,
    /// One per module of the string, in order.
    pub modules: Vec<ModuleAdjustment>,
}

/// The adjustments of one module.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModuleAdjustment {
    /// Degrees to turn towards each of [`Adjustments::attractors`] before the module.
    pub turns: [f64; 3],
    /// The factor of the module's move (outside polygons).
    pub length: f64,
    /// The factor of the width of a segment the module draws when the segment's middle stands in
    /// the upper, middle or lower third of the plant's height.
    pub width: [f64; 3],
}

impl Default for ModuleAdjustment {
    fn default() -> Self {
        ModuleAdjustment {
            turns: [0.0; 3],
            length: 1.0,
            width: [1.0; 3],
        }
    }
}

impl ModuleAdjustment {
    /// True when the module turns the turtle.
    pub fn turns(&self) -> bool {
        self.turns.iter().any(|&t| t != 0.0)
    }
}

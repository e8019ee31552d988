//! The environment's words (docs/LANGUAGE.md, "Environment"): the programs a grammar declares
//! with `#environment PROGRAM [SHAPE] setting numbers…`, their shapes and settings, and what each
//! replies to a communication module `?E`.

use super::params::text;
use serde::Serialize;

/// A program that answers `?E` modules between derivation steps.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum EnvironmentProgram {
    /// Light from the sky (diffuse) and the sun (directional), shadowed by the plants.
    Light,
    /// A solid shape: whether a point is free and its distance to the surface.
    Obstacle,
    /// How crowded space is around a point (parts of any plant within a radius).
    Space,
    /// Attraction points for space colonisation (Runions et al. 2007).
    Attractors,
    /// Whether a bud meets another of at least its vigor (Honda 1981; vlab's `honda81`).
    Collision,
}

/// The shape of an obstacle or of the volume attraction points fill.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum EnvironmentShape {
    Box,
    Sphere,
    Plane,
}

/// One setting of a program: a word and the numbers after it.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct EnvironmentSetting {
    pub name: &'static str,
    /// How many numbers follow the word.
    pub numbers: usize,
    pub doc: &'static str,
}

/// One program: its name, the shapes it takes, its settings, and the values of its reply.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct EnvironmentProgramInfo {
    pub name: &'static str,
    pub program: EnvironmentProgram,
    /// The shape words it takes after its name (none: it takes no shape).
    pub shapes: &'static [EnvironmentShape],
    pub settings: &'static [EnvironmentSetting],
    /// The values it writes into a `?E`'s parameters, in order.
    pub reply: &'static [&'static str],
    pub doc: &'static str,
}

/// One shape word.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct EnvironmentShapeInfo {
    pub name: &'static str,
    pub shape: EnvironmentShape,
    pub doc: &'static str,
}

const fn setting(name: &'static str, numbers: usize, doc: &'static str) -> EnvironmentSetting {
    EnvironmentSetting {
        name,
        numbers,
        doc: text(doc),
    }
}

const SHAPE_SETTINGS: [EnvironmentSetting; 6] = [
    setting("min", 3, "A box's lowest corner x y z."),
    setting("max", 3, "A box's highest corner x y z."),
    setting("center", 3, "A sphere's centre x y z."),
    setting("radius", 1, "A sphere's radius."),
    setting("point", 3, "A point x y z of a plane."),
    setting(
        "normal",
        3,
        "A plane's normal x y z: the free side is the side it points to.",
    ),
];

#[rustfmt::skip]
pub const ENVIRONMENT_SHAPES: &[EnvironmentShapeInfo] = &[
    EnvironmentShapeInfo { name: "box", shape: EnvironmentShape::Box, doc: text("An axis-aligned box, from `min` to `max`.") },
    EnvironmentShapeInfo { name: "sphere", shape: EnvironmentShape::Sphere, doc: text("A ball of `radius` around `center`.") },
    EnvironmentShapeInfo { name: "plane", shape: EnvironmentShape::Plane, doc: text("A half-space: the side of the plane through `point` that `normal` points away from is solid.") },
];

#[rustfmt::skip]
pub const ENVIRONMENT_PROGRAMS: &[EnvironmentProgramInfo] = &[
    EnvironmentProgramInfo {
        name: "light",
        program: EnvironmentProgram::Light,
        shapes: &[],
        settings: &[
            setting("cell", 1, "The edge of one voxel of the light grid, in the model's units (default: the grammar's step length)."),
            setting("sky", 1, "The weight of diffuse light from the sky (default 1)."),
            setting("sun", 1, "The weight of direct light from the sun (default 0)."),
            setting("sun_direction", 3, "The direction towards the sun x y z (default 0 1 0: overhead)."),
            setting("shadow", 1, "The shadow one part casts on the voxel below it (Palubicki et al.'s a; default 1)."),
            setting("spread", 1, "How fast a shadow fades with each layer below, spreading as a pyramid (b; default 2)."),
            setting("depth", 1, "How many layers below a part its shadow reaches (default 8)."),
            setting("absorb", 1, "How much of the sun's beam one part in a voxel stops (default 0.5)."),
        ],
        reply: &["exposure", "dx", "dy", "dz"],
        doc: text("Light from the sky and the sun, shadowed by every plant's parts on a voxel grid. Replies with the exposure (0 to 1) and the unit direction of most light."),
    },
    EnvironmentProgramInfo {
        name: "obstacle",
        program: EnvironmentProgram::Obstacle,
        shapes: &[EnvironmentShape::Box, EnvironmentShape::Sphere, EnvironmentShape::Plane],
        settings: &SHAPE_SETTINGS,
        reply: &["free", "distance"],
        doc: text("A solid shape. Replies 1 when the point is outside it (0 inside) and the distance to its surface (negative inside)."),
    },
    EnvironmentProgramInfo {
        name: "space",
        program: EnvironmentProgram::Space,
        shapes: &[],
        settings: &[
            setting("radius", 1, "How far around a point parts count as neighbours (default: the grammar's step length)."),
        ],
        reply: &["crowding", "dx", "dy", "dz"],
        doc: text("The occupancy of space by every plant's parts. Replies with the number of parts within `radius` of the point and the unit direction away from them."),
    },
    EnvironmentProgramInfo {
        name: "attractors",
        program: EnvironmentProgram::Attractors,
        shapes: &[EnvironmentShape::Box, EnvironmentShape::Sphere],
        settings: &[
            SHAPE_SETTINGS[0], SHAPE_SETTINGS[1], SHAPE_SETTINGS[2], SHAPE_SETTINGS[3],
            setting("count", 1, "How many attraction points fill the shape (default 1000)."),
            setting("influence", 1, "How far an attraction point attracts a bud (default: 4 step lengths)."),
            setting("kill", 1, "An attraction point this close to a part of a plant is removed (default: 1 step length)."),
            setting("seed", 1, "The seed of the points' random places (default: the grammar's seed)."),
        ],
        reply: &["count", "dx", "dy", "dz"],
        doc: text("Space colonisation (Runions et al. 2007): attraction points fill a shape; each is taken by the nearest `?E` within `influence`. Replies with how many points the `?E` takes and the unit mean direction towards them."),
    },
    EnvironmentProgramInfo {
        name: "collision",
        program: EnvironmentProgram::Collision,
        shapes: &[],
        settings: &[
            setting("radius", 1, "How near two `?E` meet (default: the grammar's step length; 0: only at one point)."),
            setting("flat", 1, "1: measure in the horizontal plane (x and z), as honda81's `3d case: off`; 0 (default): in space."),
        ],
        reply: &["free"],
        doc: text("Honda's (1981) test, as vlab's honda81: `?E(vigor, kind)` replies 1 when no other `?E` of the same kind and at least its vigor is within `radius`, else 0 (both stop when equal). Only the `?E` meet, of every plant."),
    },
];

/// The settings each shape must be given (a box its corners), whatever program takes it.
const SHAPE_REQUIRES: [(EnvironmentShape, &[&str]); 3] = [
    (EnvironmentShape::Box, &["min", "max"]),
    (EnvironmentShape::Sphere, &["center", "radius"]),
    (EnvironmentShape::Plane, &["point", "normal"]),
];

impl EnvironmentShape {
    /// The settings a line with this shape must write.
    pub fn required(self) -> &'static [&'static str] {
        SHAPE_REQUIRES
            .iter()
            .find(|(s, _)| *s == self)
            .map_or(&[], |(_, r)| r)
    }

    /// Its word.
    pub fn name(self) -> &'static str {
        ENVIRONMENT_SHAPES
            .iter()
            .find(|s| s.shape == self)
            .map_or("", |s| s.name)
    }
}

/// How the plants of a stand are placed (`#stand`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum StandLayout {
    /// N plants along x, `spacing` apart, centred on the origin.
    Row,
    /// NX × NZ plants on a square grid in the x–z plane, `spacing` apart, centred on the origin.
    Grid,
    /// N plants at random places in a `size` W × D rectangle centred on the origin.
    Random,
}

/// One layout word of `#stand`: how many whole numbers follow it, its settings, which of them
/// must be written.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct StandLayoutInfo {
    pub name: &'static str,
    pub layout: StandLayout,
    /// What the whole numbers after the word count (`N`, or `NX NZ`).
    pub counts: &'static [&'static str],
    pub settings: &'static [EnvironmentSetting],
    /// The settings that must be written.
    pub required: &'static [&'static str],
    pub doc: &'static str,
}

const SPACING: EnvironmentSetting =
    setting("spacing", 1, "The distance between neighbouring plants.");

#[rustfmt::skip]
pub const STAND_LAYOUTS: &[StandLayoutInfo] = &[
    StandLayoutInfo { name: "row", layout: StandLayout::Row, counts: &["N"], settings: &[SPACING], required: &["spacing"],
        doc: text("N plants along x, `spacing` apart, centred on the origin.") },
    StandLayoutInfo { name: "grid", layout: StandLayout::Grid, counts: &["NX", "NZ"], settings: &[SPACING], required: &["spacing"],
        doc: text("NX × NZ plants in the x–z plane, `spacing` apart, centred on the origin.") },
    StandLayoutInfo { name: "random", layout: StandLayout::Random, counts: &["N"], required: &["size"],
        settings: &[
            setting("size", 2, "The width (along x) and depth (along z) of the rectangle the plants stand in."),
            setting("seed", 1, "The seed of the places (default: the grammar's seed)."),
            setting("spacing", 1, "The least distance between two plants (default 0)."),
        ],
        doc: text("N plants at random places in a `size` W × D rectangle centred on the origin, at least `spacing` apart.") },
];

/// The stand layout named `name`.
pub fn stand_layout_named(name: &str) -> Option<&'static StandLayoutInfo> {
    STAND_LAYOUTS.iter().find(|l| l.name == name)
}

/// The program named `name`.
pub fn environment_program_named(name: &str) -> Option<&'static EnvironmentProgramInfo> {
    ENVIRONMENT_PROGRAMS.iter().find(|p| p.name == name)
}

/// The shape named `name`.
pub fn environment_shape_named(name: &str) -> Option<&'static EnvironmentShapeInfo> {
    ENVIRONMENT_SHAPES.iter().find(|s| s.name == name)
}

impl EnvironmentProgram {
    /// Its row.
    pub fn info(self) -> &'static EnvironmentProgramInfo {
        ENVIRONMENT_PROGRAMS
            .iter()
            .find(|p| p.program == self)
            .unwrap_or(&ENVIRONMENT_PROGRAMS[0])
    }
}

impl EnvironmentProgramInfo {
    /// Its setting named `name`.
    pub fn setting(&self, name: &str) -> Option<&'static EnvironmentSetting> {
        self.settings.iter().find(|s| s.name == name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_program_and_shape_has_one_row() {
        for p in ENVIRONMENT_PROGRAMS {
            assert_eq!(
                environment_program_named(p.name).map(|r| r.program),
                Some(p.program)
            );
            assert_eq!(p.program.info().name, p.name);
            assert!(!p.reply.is_empty());
            for (i, s) in p.settings.iter().enumerate() {
                assert!(
                    p.settings[..i].iter().all(|t| t.name != s.name),
                    "{}",
                    s.name
                );
            }
        }
        for s in ENVIRONMENT_SHAPES {
            assert_eq!(
                environment_shape_named(s.name).map(|r| r.shape),
                Some(s.shape)
            );
        }
    }
}

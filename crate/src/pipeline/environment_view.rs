//! What a build keeps of its environment for the studio's views (issue 47, "Seeing the
//! environment"): after the last step, each program's grid of values (the light grid), the
//! obstacles' solids, the attraction points left and the names of a `?E`'s reply values. Plain
//! data, budgeted: a grid larger than [`MAX_VIEW_VOXELS`] is averaged over blocks of voxels, at
//! most [`MAX_VIEW_POINTS`] points are kept.

use crate::environment::obstacle::Solid;
use crate::environment::{Field, Responder};
use crate::maths;
use crate::model::ProgramSpec;
use crate::vocabulary::EnvironmentProgram;
use std::fmt::Write;

/// Most voxels of one grid the view keeps (4 MB of `f32`): a larger grid is coarsened.
pub const MAX_VIEW_VOXELS: usize = 1 << 20;

/// Most attraction points the view keeps (1.2 MB of `f32`): the first, which are in random order.
pub const MAX_VIEW_POINTS: usize = 100_000;

/// One program's grid, as the view keeps it.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldView {
    /// The program's index among the grammar's `#environment` lines.
    pub program: usize,
    /// The program's name (`light`).
    pub name: &'static str,
    pub field: Field,
}

/// The environment of a build after its last step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EnvironmentView {
    pub fields: Vec<FieldView>,
    pub solids: Vec<Solid>,
    /// The attraction points left, at most [`MAX_VIEW_POINTS`].
    pub points: Vec<[f64; 3]>,
    /// The names of the values a `?E` is answered with, every program's in the order declared.
    pub replies: Vec<&'static str>,
}

impl EnvironmentView {
    /// The view of `programs` as they are now (after the last step's answers).
    pub(super) fn of(programs: &[(Box<dyn Responder>, &ProgramSpec)]) -> EnvironmentView {
        let mut view = EnvironmentView::default();
        for (k, (program, spec)) in programs.iter().enumerate() {
            let info = spec.info();
            view.replies.extend_from_slice(info.reply);
            if let Some(field) = program.field() {
                view.fields.push(FieldView {
                    program: k,
                    name: info.name,
                    field: coarsened(field, MAX_VIEW_VOXELS),
                });
            }
            if let Some(solid) =
                Solid::of(spec).filter(|_| spec.program == EnvironmentProgram::Obstacle)
            {
                view.solids.push(solid);
            }
            let room = MAX_VIEW_POINTS.saturating_sub(view.points.len());
            view.points
                .extend(program.points().iter().take(room).copied());
        }
        view
    }

    /// The grids' values, one after the other in the order of [`Self::fields`].
    pub fn field_values(&self, i: usize) -> &[f32] {
        self.fields.get(i).map_or(&[], |f| &f.field.values)
    }

    /// The points as x, y, z floats.
    pub fn point_coordinates(&self) -> Vec<f32> {
        self.points.iter().flatten().map(|&c| c as f32).collect()
    }

    /// JSON `{fields: [{program, name, origin, cell, dims, min, max}], solids: [{shape: "box",
    /// min, max} | {shape: "sphere", center, radius} | {shape: "plane", point, normal}], points,
    /// replies}`: everything but the grids' values and the points' coordinates (`points` is their
    /// count), which cross as typed arrays.
    pub fn to_json(&self) -> String {
        let v = |p: [f64; 3]| format!("[{},{},{}]", num(p[0]), num(p[1]), num(p[2]));
        let mut fields = Vec::new();
        for f in &self.fields {
            let (lo, hi) = f
                .field
                .values
                .iter()
                .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &x| {
                    (lo.min(x), hi.max(x))
                });
            let d = f.field.dims;
            fields.push(format!(
                r#"{{"program":{},"name":"{}","origin":{},"cell":{},"dims":[{},{},{}],"min":{},"max":{}}}"#,
                f.program,
                f.name,
                v(f.field.origin),
                num(f.field.cell),
                d[0],
                d[1],
                d[2],
                num(if lo.is_finite() { lo.into() } else { 0.0 }),
                num(if hi.is_finite() { hi.into() } else { 0.0 }),
            ));
        }
        let solids: Vec<String> = (self.solids.iter())
            .map(|s| match *s {
                Solid::Box { min, max } => format!(
                    r#"{{"shape":"box","min":{},"max":{}}}"#,
                    v(min.to_array()),
                    v(max.to_array())
                ),
                Solid::Sphere { center, radius } => format!(
                    r#"{{"shape":"sphere","center":{},"radius":{}}}"#,
                    v(center.to_array()),
                    num(radius)
                ),
                Solid::Plane { point, normal } => format!(
                    r#"{{"shape":"plane","point":{},"normal":{}}}"#,
                    v(point.to_array()),
                    v(normal.to_array())
                ),
            })
            .collect();
        let mut replies = String::new();
        for (i, r) in self.replies.iter().enumerate() {
            let _ = write!(replies, "{}\"{r}\"", if i > 0 { "," } else { "" });
        }
        format!(
            r#"{{"fields":[{}],"solids":[{}],"points":{},"replies":[{}]}}"#,
            fields.join(","),
            solids.join(","),
            self.points.len(),
            replies
        )
    }
}

/// A finite number as JSON (0 for one that is not).
fn num(x: f64) -> String {
    if x.is_finite() {
        format!("{x}")
    } else {
        "0".into()
    }
}

/// `field` with at most `most` voxels: blocks of f × f × f voxels averaged into one (the last
/// block of a row over the voxels it has), the cell f times as large.
fn coarsened(field: Field, most: usize) -> Field {
    let [nx, ny, nz] = field.dims;
    let voxels = nx * ny * nz;
    if voxels <= most || voxels == 0 {
        return field;
    }
    let mut f = (maths::cbrt(voxels as f64 / most as f64).ceil() as usize).max(2);
    let dims_of = |f: usize| [nx.div_ceil(f), ny.div_ceil(f), nz.div_ceil(f)];
    while dims_of(f).iter().product::<usize>() > most {
        f += 1;
    }
    let dims = dims_of(f);
    let mut sums = vec![0.0f64; dims.iter().product()];
    let mut counts = vec![0u32; sums.len()];
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let at = (i / f) + dims[0] * ((j / f) + dims[1] * (k / f));
                sums[at] += f64::from(field.values[i + nx * (j + ny * k)]);
                counts[at] += 1;
            }
        }
    }
    Field {
        origin: field.origin,
        cell: field.cell * f as f64,
        dims,
        values: (sums.iter().zip(&counts))
            .map(|(s, &c)| (s / f64::from(c.max(1))) as f32)
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_large_grid_is_averaged_over_blocks_within_the_budget() {
        let field = Field {
            origin: [1.0, 2.0, 3.0],
            cell: 0.5,
            dims: [5, 4, 3],
            values: (0..60).map(|v| v as f32).collect(),
        };
        let small = coarsened(field.clone(), 60);
        assert_eq!(small, field, "within the budget: as it is");
        let coarse = coarsened(field, 12);
        // Blocks of 2: dims 3 × 2 × 2 = 12.
        assert_eq!(coarse.dims, [3, 2, 2]);
        assert_eq!(coarse.cell, 1.0);
        assert_eq!(coarse.origin, [1.0, 2.0, 3.0]);
        // The first block holds voxels i 0-1, j 0-1, k 0-1: 0 1 5 6 20 21 25 26, mean 13.
        assert_eq!(coarse.values[0], 13.0);
        // The last block of the first row holds i = 4 only: 4 9 24 29, mean 16.5.
        assert_eq!(coarse.values[2], 16.5);
    }

    #[test]
    fn the_view_of_a_build_names_its_replies_draws_its_box_and_keeps_the_light_grid() {
        let source = "#environment light\n#environment obstacle box min -1 0 -1 max 1 2 1\n\
                      #iterations 3\naxiom: A\nA -> F ?E(0, 0, 0, 0, 0, 0) A";
        let build = crate::pipeline::build(source, &Default::default());
        assert!(build.ok(), "{:?}", build.diagnostics);
        let view = build.environment.as_ref().expect("a view");
        assert_eq!(
            view.replies,
            ["exposure", "dx", "dy", "dz", "free", "distance"]
        );
        assert_eq!(view.fields.len(), 1);
        let grid = &view.fields[0].field;
        assert_eq!(grid.values.len(), grid.dims.iter().product::<usize>());
        assert!(grid.values.iter().all(|v| (0.0..=1.0).contains(v)));
        assert!(grid.values.iter().any(|&v| v < 1.0), "the plant shades");
        let json = view.to_json();
        assert!(
            json.contains(r#""solids":[{"shape":"box","min":[-1,0,-1],"max":[1,2,1]}]"#),
            "{json}"
        );
        assert!(json.contains(r#""name":"light""#), "{json}");
    }

    #[test]
    fn attraction_points_left_are_kept_and_a_grammar_without_environment_has_no_view() {
        let source = "#environment attractors box min -2 0 -2 max 2 4 2 count 300 kill 0.5\n\
                      #iterations 4\naxiom: A\nA -> F ?E(0, 0, 0, 0) A";
        let build = crate::pipeline::build(source, &Default::default());
        assert!(build.ok(), "{:?}", build.diagnostics);
        let view = build.environment.as_ref().expect("a view");
        assert!(
            !view.points.is_empty() && view.points.len() < 300,
            "some killed"
        );
        assert_eq!(view.point_coordinates().len(), 3 * view.points.len());
        let plain = crate::pipeline::build("axiom: F", &Default::default());
        assert!(plain.environment.is_none());
    }
}

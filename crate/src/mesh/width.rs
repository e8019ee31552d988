//! Width units: how a width value (`!`, `#width`) becomes a diameter in model units.

use crate::turtle::Skeleton;
use glam::DVec3;

/// How a width value becomes a diameter in model units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WidthUnit {
    /// One width unit is this fraction of the skeleton's bounding-box diagonal; but when the
    /// grammar sets no width (`Skeleton::widths_set`), at most [`DEFAULT_WIDTH_PER_LENGTH`] of its
    /// internodes' median length, so that a plant of many short internodes (ABOP 1.24a) is drawn
    /// thin, as in the book, not as beads as thick as they are long. A grammar's `#width_unit`
    /// ([`Skeleton::width_unit`]) takes its place.
    Relative(f64),
    /// One width unit is this many model units.
    Absolute(f64),
}

/// The default width of an internode, where the grammar sets none, as a share of the internodes'
/// median length (see [`WidthUnit::Relative`]).
pub const DEFAULT_WIDTH_PER_LENGTH: f64 = 0.1;

/// Model units per width unit for `skeleton` (see [`WidthUnit`]). A grammar's own unit
/// (`#width_unit`, [`Skeleton::width_unit`]) replaces a relative one: its widths are diameters in
/// the model's units at every size and step, as cpfg draws cylinders.
pub fn resolve_width_unit(skeleton: &Skeleton, unit: WidthUnit) -> f64 {
    match unit {
        WidthUnit::Absolute(u) => u,
        WidthUnit::Relative(fraction) => {
            if let Some(own) = skeleton.width_unit {
                return own;
            }
            let relative = fraction * skeleton_diagonal(skeleton);
            if skeleton.widths_set {
                return relative;
            }
            let mut lengths: Vec<f64> = skeleton
                .segments
                .iter()
                .map(|s| s.start.distance(s.end))
                .collect();
            if lengths.is_empty() {
                return relative;
            }
            let middle = lengths.len() / 2;
            // The element a sort would put in the middle, selected without sorting: sorting the
            // 116,050 lengths of ABOP 1.24d n = 10 was 7% of its mesh stage (issue 20).
            let median = crate::sort::select_nth_by(&mut lengths, middle, f64::total_cmp);
            if median > 0.0 && median.is_finite() {
                relative.min(DEFAULT_WIDTH_PER_LENGTH * median)
            } else {
                relative
            }
        }
    }
}

/// Length of the diagonal of the box around every segment end point.
pub(crate) fn skeleton_diagonal(skeleton: &Skeleton) -> f64 {
    let mut min = DVec3::INFINITY;
    let mut max = DVec3::NEG_INFINITY;
    for s in &skeleton.segments {
        min = min.min(s.start).min(s.end);
        max = max.max(s.start).max(s.end);
    }
    for p in skeleton.polygons.iter().flat_map(|p| &p.points) {
        min = min.min(*p);
        max = max.max(*p);
    }
    if min.x > max.x {
        0.0
    } else {
        (max - min).length()
    }
}

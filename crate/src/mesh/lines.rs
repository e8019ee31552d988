//! Every segment of a skeleton as one straight line: what the studio draws in its Lines mode
//! (constant-width lines, as the book's two-dimensional figures are drawn) and the fallback of
//! models too large to mesh.

pub use crate::turtle::SegmentLines;
use crate::turtle::Skeleton;

/// The segments of `skeleton` as lines with their colours and modules.
pub fn segment_lines(skeleton: &Skeleton) -> SegmentLines {
    SegmentLines {
        ends: segment_ends(skeleton),
        colors: segment_colors(skeleton),
        modules: segment_modules(skeleton),
    }
}

/// Each segment's two ends, x, y, z each (as `f32`): [`SegmentLines::ends`].
pub fn segment_ends(skeleton: &Skeleton) -> Vec<f32> {
    let mut ends = Vec::with_capacity(6 * skeleton.segments.len());
    for s in &skeleton.segments {
        let (a, b) = (s.start.as_vec3(), s.end.as_vec3());
        ends.extend_from_slice(&[a.x, a.y, a.z, b.x, b.y, b.z]);
    }
    ends
}

/// Each segment's colour, once per end: [`SegmentLines::colors`]. The palette is looked up once
/// per run of segments of one colour.
pub fn segment_colors(skeleton: &Skeleton) -> Vec<f32> {
    let mut colors = Vec::with_capacity(6 * skeleton.segments.len());
    let mut run: Option<(u16, [f32; 3])> = None;
    for s in &skeleton.segments {
        let [r, g, b] = match run {
            Some((index, color)) if index == s.color => color,
            _ => {
                let color = skeleton.color(s.color);
                run = Some((s.color, color));
                color
            }
        };
        colors.extend_from_slice(&[r, g, b, r, g, b]);
    }
    colors
}

/// The module that drew each segment: [`SegmentLines::modules`].
pub fn segment_modules(skeleton: &Skeleton) -> Vec<u32> {
    skeleton.segments.iter().map(|s| s.module).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::turtle::Segment;
    use glam::DVec3;

    #[test]
    fn each_segment_is_one_line_with_its_colour_and_module() {
        let segment = |start: DVec3, end: DVec3, color: u16, module: u32| Segment {
            start,
            end,
            left: DVec3::NEG_X,
            up: DVec3::Z,
            width: 1.0,
            color,
            module,
            previous: None,
            smooth: false,
            anchor: None,
        };
        let skeleton = Skeleton {
            segments: vec![
                segment(DVec3::ZERO, DVec3::Y, 0, 0),
                segment(DVec3::Y, DVec3::new(1.0, 2.0, 0.0), 1, 3),
            ],
            ..Skeleton::default()
        };
        let lines = segment_lines(&skeleton);
        assert_eq!(
            lines.ends,
            [0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 1.0, 2.0, 0.0]
        );
        assert_eq!(lines.modules, [0, 3]);
        assert_eq!(lines.colors[..3], skeleton.color(0));
        assert_eq!(lines.colors[6..9], skeleton.color(1));
        assert_eq!(lines.colors[9..], skeleton.color(1));
    }
}

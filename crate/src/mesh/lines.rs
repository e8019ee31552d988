//! Every segment of a skeleton as one straight line: what the studio draws in its Lines mode
//! (constant-width lines, as the book's two-dimensional figures are drawn) and the fallback of
//! models too large to mesh.

pub use crate::turtle::SegmentLines;
use crate::turtle::Skeleton;

/// The segments of `skeleton` as lines with their colours and modules.
pub fn segment_lines(skeleton: &Skeleton) -> SegmentLines {
    let count = skeleton.segments.len();
    let mut lines = SegmentLines {
        ends: Vec::with_capacity(6 * count),
        colors: Vec::with_capacity(6 * count),
        modules: Vec::with_capacity(count),
    };
    for s in &skeleton.segments {
        let color = skeleton.color(s.color);
        for p in [s.start, s.end] {
            lines.ends.extend([p.x as f32, p.y as f32, p.z as f32]);
            lines.colors.extend(color);
        }
        lines.modules.push(s.module);
    }
    lines
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

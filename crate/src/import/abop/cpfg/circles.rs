//! cpfg's circles (manual section 6.6; `blackbox.c`, `irisGL.c`): `@c(d)` a filled disc of
//! diameter `d` in the turtle's H–L plane, `@o(d)` a filled disc of diameter `d` facing the
//! viewer. Meristem has no disc, so `@c` becomes a regular polygon of [`SIDES`] sides traced
//! in the H–L plane inside a branch (`[f(r)+(…){f(s)+(…)…}]`: the turtle comes back where it
//! was), and `@o` a sphere of that diameter, which every view sees as that disc.

use super::super::Importer;
use crate::vocabulary::{name_of, Command, Meaning};

/// The sides of the polygon `@c` becomes.
pub(in crate::import::abop) const SIDES: usize = 12;

impl Importer {
    /// `@c(d)` or `@o(d)` (`name`) in Meristem's commands; without `d` (cpfg: the line width),
    /// a sphere as wide as the line.
    pub(in crate::import::abop) fn circle(
        &mut self,
        name: &str,
        params: &[String],
        n: usize,
    ) -> String {
        let sphere = name_of(Meaning::Turtle(Command::Sphere));
        let Some(d) = params.first().filter(|d| !d.trim().is_empty()) else {
            self.note_once(
                name,
                n,
                format!("cpfg's {name} without a diameter is as wide as the line: it becomes a sphere as wide as the line ({sphere}), which every view sees as a disc of that diameter"),
            );
            return sphere.to_string();
        };
        if name == "@o" {
            self.note_once(
                name,
                n,
                format!("cpfg's @o(d) draws a disc of diameter d facing the viewer; it becomes a sphere of that diameter ({sphere}((d)/2)), which every view sees as that disc"),
            );
            return format!("{sphere}(({d})/2)");
        }
        self.note_once(
            name,
            n,
            format!("cpfg's @c(d) draws a disc of diameter d in the turtle's H–L plane; it becomes a regular polygon of {SIDES} sides inscribed in that circle"),
        );
        disc(d)
    }
}

/// A polygon of [`SIDES`] sides inscribed in the circle of diameter `d` (an expression) around
/// the turtle, in its H–L plane: from the centre `f` to the first corner, turn towards the
/// next, then a side and a turn for each corner but the last (`}` closes the polygon).
fn disc(d: &str) -> String {
    let turn = 360.0 / SIDES as f64;
    // A side of the inscribed polygon is d · sin(180° / SIDES).
    let side = crate::maths::sin(std::f64::consts::PI / SIDES as f64);
    let first = 90.0 + turn / 2.0;
    let mut out = format!("[f(({d})/2)+({first}){{");
    for k in 0..SIDES - 1 {
        out.push_str(&format!("f(({d})*{side:.12})"));
        if k + 2 < SIDES {
            out.push_str(&format!("+({turn})"));
        }
    }
    out.push_str("}]");
    out
}

#[cfg(test)]
mod tests {
    use super::disc;

    #[test]
    fn a_disc_is_a_closed_polygon_of_twelve_corners_around_the_turtle() {
        let text = disc("2");
        assert!(text.starts_with("[f((2)/2)+(105){f((2)*0.258819045103)+(30)"));
        assert!(text.ends_with("f((2)*0.258819045103)}]"));
        // The start, then eleven moves: twelve corners.
        assert_eq!(text.matches("f((2)*").count(), 11);
        assert_eq!(text.matches("+(30)").count(), 10);
    }
}

//! L-Py's world axes. Its turtle starts with H = +Z, L = −Y, U = +X (PlantGL's `TurtleParam`);
//! Meristem's with H = +Y, L = −X, U = +Z. The cyclic change (x, y, z) → (y, z, x) carries the
//! one frame onto the other exactly (a rotation), so the commands that take points or vectors
//! in world coordinates (`MoveTo`, `LineTo`, `SetHead`, …) read them through it and draw the
//! plant L-Py draws, turned so that it grows up Meristem's +Y.

use crate::import::abop::Importer;
use crate::vocabulary::{name_of, Command, Meaning};

/// L-Py's commands whose first parameters are world coordinates, by their long L-Py names, with
/// the Meristem command each becomes (L-Py's short names of the first and last, `@M` and `@R`,
/// are Meristem's).
const PLACED: &[(&str, Command)] = &[
    ("MoveTo", Command::MoveTo),
    ("LineTo", Command::LineTo),
    ("LineRel", Command::LineRel),
    ("OLineTo", Command::OrientedLineTo),
    ("OLineRel", Command::OrientedLineRel),
    ("SetHead", Command::SetHeading),
];

impl Importer {
    /// The Meristem text of an L-Py module that reads or writes world coordinates (`?P`, the
    /// [`placed`] commands) or draws the frame; `None` for any other.
    pub(in crate::import::abop) fn lpy_world_module(
        &mut self,
        name: &str,
        params: &[String],
        n: usize,
    ) -> Option<String> {
        if let Some(text) = placed(name, params) {
            return Some(text);
        }
        let frame = name_of(Meaning::Turtle(Command::Frame));
        if name == "Frame" {
            // Its other parameters shape the arrows' cones, which Meristem does not draw.
            return Some(match params.first() {
                Some(size) => format!("{frame}({size})"),
                None => frame.to_string(),
            });
        }
        let query = name_of(Meaning::Turtle(Command::QueryPosition));
        if name != query || params.len() != 3 {
            return None;
        }
        self.note_once(
            query,
            n,
            "L-Py's turtle grows along +Z and turns towards Y, Meristem's grows along +Y and turns towards X: ?P(x,y,z) becomes ?P(y,z,x), so that each name reads the same axis of the plant; signs along the horizontal axes may differ",
        );
        Some(format!(
            "{query}({},{},{})",
            params[1], params[2], params[0]
        ))
    }
}

/// L-Py's default up vector for `SetHead` given a heading alone (its helpcard: 1, 0, 0).
const SET_HEAD_UP: [&str; 3] = ["1", "0", "0"];

/// The Meristem text of an L-Py module whose parameters are world coordinates, each triple read
/// in Meristem's axes; `None` for any other module, or when the parameters are not three
/// numbers per vector (a PlantGL vector written as one parameter stays as L-Py wrote it).
fn placed(name: &str, params: &[String]) -> Option<String> {
    let command = PLACED
        .iter()
        .find(|(n, _)| *n == name)
        .map(|&(_, c)| c)
        .or_else(|| {
            [Command::MoveTo, Command::SetHeading]
                .into_iter()
                .find(|&c| name_of(Meaning::Turtle(c)) == name)
        })?;
    let vectors = match (command, params.len()) {
        (Command::SetHeading, 3) => [&params[..3], &SET_HEAD_UP.map(String::from)[..]].concat(),
        (Command::SetHeading, 6) => params.to_vec(),
        (Command::MoveTo, 3) => params.to_vec(),
        (Command::MoveTo, _) | (Command::SetHeading, _) => return None,
        (_, 3 | 4) => params.to_vec(),
        _ => return None,
    };
    let mut out: Vec<String> = Vec::with_capacity(vectors.len());
    for triple in vectors.chunks(3) {
        match triple {
            [x, y, z] => out.extend([y.clone(), z.clone(), x.clone()]),
            rest => out.extend(rest.iter().cloned()),
        }
    }
    Some(format!(
        "{}({})",
        name_of(Meaning::Turtle(command)),
        out.join(",")
    ))
}

#[cfg(test)]
mod tests {
    use super::placed;

    fn of(name: &str, params: &[&str]) -> Option<String> {
        placed(
            name,
            &params.iter().map(|p| p.to_string()).collect::<Vec<_>>(),
        )
    }

    #[test]
    fn points_and_vectors_are_read_in_meristem_s_axes() {
        assert_eq!(
            of("LineTo", &["0", "1", "4"]).as_deref(),
            Some("@LineTo(1,4,0)")
        );
        assert_eq!(
            of("OLineRel", &["a", "b", "c", "0.2"]).as_deref(),
            Some("@OLineRel(b,c,a,0.2)")
        );
        assert_eq!(of("@M", &["1", "2", "3"]).as_deref(), Some("@M(2,3,1)"));
        // L-Py's heading +Z and up +X are Meristem's +Y and +Z.
        assert_eq!(
            of("SetHead", &["0", "0", "1", "1", "0", "0"]).as_deref(),
            Some("@R(0,1,0,0,0,1)")
        );
        assert_eq!(
            of("@R", &["1", "1", "1"]).as_deref(),
            Some("@R(1,1,1,0,0,1)")
        );
        // A vector written as one parameter, or a module without coordinates: not these.
        assert_eq!(of("LineTo", &["v"]), None);
        assert_eq!(of("@M", &[]), None);
        assert_eq!(of("F", &["1", "2", "3"]), None);
    }
}

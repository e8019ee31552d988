//! L-Py's world axes. Its turtle starts with H = +Z, L = −Y, U = +X (PlantGL's `TurtleParam`);
//! Meristem's with H = +Y, L = −X, U = +Z. The cyclic change (x, y, z) → (y, z, x) carries the
//! one frame onto the other exactly (a rotation), so the commands that take points or vectors
//! in world coordinates (`MoveTo`, `LineTo`, `SetHead`, …) read them through it and draw the
//! plant L-Py draws, turned so that it grows up Meristem's +Y.

use crate::vocabulary::{name_of, Command, Meaning};

/// L-Py's commands whose first parameters are world coordinates, by their L-Py names (long and
/// short), with the Meristem command each becomes.
const PLACED: &[(&str, Command)] = &[
    ("MoveTo", Command::MoveTo),
    ("@M", Command::MoveTo),
    ("LineTo", Command::LineTo),
    ("LineRel", Command::LineRel),
    ("OLineTo", Command::OrientedLineTo),
    ("OLineRel", Command::OrientedLineRel),
    ("SetHead", Command::SetHeading),
    ("@R", Command::SetHeading),
];

/// L-Py's default up vector for `SetHead` given a heading alone (its helpcard: 1, 0, 0).
const SET_HEAD_UP: [&str; 3] = ["1", "0", "0"];

/// The Meristem text of an L-Py module whose parameters are world coordinates, each triple read
/// in Meristem's axes; `None` for any other module, or when the parameters are not three
/// numbers per vector (a PlantGL vector written as one parameter stays as L-Py wrote it).
pub(in crate::import::abop) fn placed(name: &str, params: &[String]) -> Option<String> {
    let &(_, command) = PLACED.iter().find(|(n, _)| *n == name)?;
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

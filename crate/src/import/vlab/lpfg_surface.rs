//! lpfg's surfaces: a view file's `surface: file.s [scale [s t [texture]]]` lines (lpfg
//! `drawparam.cpp`, `surfarr.cpp`, `surface.cpp`). lpfg numbers them from 0 in the order it loads
//! them, a line it has loaded already (the same text) or a file it cannot load taking no number;
//! `Surface(id, s)` and `Surface3(id, sx, sy, sz)` draw surface `id`. Each becomes a `#surface`
//! with a letter of its own ([`super::surface_file::read_lpfg`]), which the L+C translation draws
//! by `~X` ([`crate::import::abop`]).

use super::{base, surface_file, Files, LpfgSurface, View};

/// Reads one `surface:` line of lpfg's form: `file`, then `rest` (scale, precisions s and t, a
/// texture).
pub(super) fn read(file: &str, rest: &[&str], all: &Files, view: &mut View) {
    let line = std::iter::once(file)
        .chain(rest.iter().copied())
        .collect::<Vec<_>>()
        .join(" ");
    if view.lpfg_surfaces.iter().any(|s| s.line == line) {
        return;
    }
    let (scale, precision, numbers) = super::surface_numbers(rest);
    if numbers > 3 {
        view.notes.push(format!(
            "the view file's surface {file} is given a texture: Meristem draws it in the turtle's colour"
        ));
    }
    let Some(text) = all.text(file) else {
        view.lpfg_surface_missing = true;
        view.notes.push(format!(
            "the view file's surface file {file} was not opened with the object: lpfg leaves a file it cannot load out of its surface ids, and Surface(id, …) draws Meristem's own leaf where no surface has that id"
        ));
        return;
    };
    let letter = free_letter(file, &view.surface_letters);
    let wanted = surface_file::Wanted {
        file: base(file),
        letter: &letter,
        scale,
        precision,
        colours: false,
    };
    match surface_file::read_lpfg(&text, &wanted) {
        Ok(lines) => {
            view.surfaces.extend(lines.lines);
            view.notes.extend(lines.note);
            view.surface_letters.push(letter.clone());
            view.lpfg_surfaces.push(LpfgSurface { line, letter });
        }
        Err(why) => view.notes.push(format!(
            "the view file's surface file {file} cannot be read ({why}): it takes no surface id, as lpfg leaves out a file it cannot load"
        )),
    }
}

/// The letter a surface file is declared by: the first letter of its name (`leaf.s`: `l`), else
/// the first letter not taken.
fn free_letter(file: &str, taken: &[String]) -> String {
    let first = base(file)
        .chars()
        .next()
        .filter(char::is_ascii_alphabetic)
        .map(|c| c.to_ascii_lowercase());
    first
        .into_iter()
        .chain('a'..='z')
        .chain('A'..='Z')
        .map(String::from)
        .find(|l| !taken.contains(l))
        .unwrap_or_else(|| "z".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::import::ObjectFile;

    /// A one-patch file: the header's up is −Z, as vlab's Bézier editor writes most leaves.
    const LEAF: &str = "-1 1 0 2 0 0\nCONTACT POINT  X: 0.5 Y: -1 Z: 0\nEND POINT  X: 0 Y: 0 Z: 0\nHEADING  X: 0 Y: 1 Z: 0\nUP  X: 0 Y: 0 Z: -1\nSIZE: 2\npatch\nTOP COLOR: 7 DIFFUSE: 0.00 BOTTOM COLOR: 7 DIFFUSE: 0.00\nAL: ~ A: ~ AR: ~\nL: ~ R: ~\nBL: ~ B: ~ BR: ~\n0 0 1 1 0 0 2 0 0 3 0 0\n0 1 0 1 1 0 2 1 0 3 1 0\n0 2 0 1 2 0 2 2 0 3 2 0\n0 3 0 1 3 0 2 3 0 3 3 0\n";

    fn view_of(lines: &[&str], files: &[(&str, &str)]) -> View {
        let files: Vec<ObjectFile> = files
            .iter()
            .map(|(n, t)| ObjectFile {
                name: n.to_string(),
                bytes: t.as_bytes().to_vec(),
            })
            .collect();
        let all = Files::new(&files);
        let mut view = View::default();
        for l in lines {
            let words: Vec<&str> = l.split_whitespace().collect();
            read(words[0], &words[1..], &all, &mut view);
        }
        view
    }

    #[test]
    fn surfaces_are_numbered_in_order_with_letters_of_their_own() {
        let view = view_of(
            &[
                "petal.s 1 4 6",
                "leaf.s 2",
                "petal.s 1 4 6",
                "lost.s",
                "leaf2.s",
            ],
            &[("petal.s", LEAF), ("leaf.s", LEAF), ("leaf2.s", LEAF)],
        );
        let ids: Vec<&str> = view
            .lpfg_surfaces
            .iter()
            .map(|s| s.letter.as_str())
            .collect();
        // The repeated line is loaded once; the missing file takes no id.
        assert_eq!(ids, ["p", "l", "a"]);
        assert!(view.lpfg_surface_missing);
        assert_eq!(
            view.surfaces[0],
            "#surface p contact 0.5 -1 0 size 2 scale 1 precision 4 6"
        );
        assert!(view.surfaces[2]
            .starts_with("#surface l contact 0.5 -1 0 size 2 scale 2 precision 10 10"));
    }

    #[test]
    fn lpfg_places_points_by_its_own_frame_and_drops_colours() {
        let view = view_of(&["leaf.s"], &[("leaf.s", LEAF)]);
        // lpfg: left = up × heading = (0,0,−1) × (0,1,0) = (1,0,0); a point p goes to
        // −p.x·left + p.y·heading + p.z·up = (−x, y, −z), drawn along −L, H, U: Meristem's
        // x along L is then x, y along H is y, z along U is −z.
        assert_eq!(
            view.surfaces[1],
            "#patch l 0 0 -1, 1 0 0, 2 0 0, 3 0 0, 0 1 0, 1 1 0, 2 1 0, 3 1 0, 0 2 0, 1 2 0, 2 2 0, 3 2 0, 0 3 0, 1 3 0, 2 3 0, 3 3 0"
        );
    }
}

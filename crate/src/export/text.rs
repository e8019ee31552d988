//! Coordinate triples in the text formats: the one writer of `x y z` (VRML, Inventor) and
//! `<x, y, -z>` (POV-Ray), a vector at a time or a line per vector of a flat `f32` × 3 array.

use super::scene::number;

/// The three numbers of `v`, each with at most `decimals` decimals ([`number`]), `separator`
/// between them.
pub fn triple(out: &mut String, v: [f64; 3], decimals: usize, separator: &str) {
    for (k, c) in v.iter().enumerate() {
        if k > 0 {
            out.push_str(separator);
        }
        number(out, *c, decimals);
    }
}

/// One line per vector of a flat `f32` × 3 array: `indent`, the vector as `write` writes it, `,`.
pub fn triple_lines(
    out: &mut String,
    flat: &[f32],
    indent: &str,
    write: impl Fn(&mut String, [f64; 3]),
) {
    for v in flat.chunks_exact(3) {
        out.push_str(indent);
        write(out, [v[0] as f64, v[1] as f64, v[2] as f64]);
        out.push_str(",\n");
    }
}

/// `x y z`: a vector as VRML and Inventor write it.
pub fn xyz(out: &mut String, v: [f64; 3], decimals: usize) {
    triple(out, v, decimals, " ");
}

/// One `x y z,` line per vector of a flat `f32` × 3 array: VRML's and Inventor's point and normal
/// lists.
pub fn xyz_lines(out: &mut String, flat: &[f32], decimals: usize) {
    triple_lines(out, flat, "      ", |out, v| xyz(out, v, decimals));
}

//! The surfaces a grammar declares (`#surface`, `#patch`), as a surface editor reads them: each
//! letter's patches and, for `#patch` lines, every control point with the text of its numbers.

use crate::model::Model;
use serde::Serialize;

/// One declared surface.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DeclaredSurface {
    /// The letter X of `~X`.
    pub letter: char,
    /// The library shape it is (`petal`), or `None` for `#patch` lines.
    pub organ: Option<&'static str>,
    /// Quads per patch along s and t.
    pub precision: [u32; 2],
    /// How many patches it has.
    pub patches: usize,
    /// The `#patch` points as written, in order (16 per patch).
    pub points: Vec<DeclaredPoint>,
}

/// A control point as written in a `#patch` line.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct DeclaredPoint {
    /// Its patch (the surface's `#patch` lines in order) and its place in the 4 × 4 grid, row by
    /// row.
    pub patch: u32,
    pub index: u32,
    /// x y z as written.
    pub value: [f64; 3],
    /// The byte range of its three numbers in the grammar's text (`from` the x to the end of the
    /// z): what an editor replaces to move the point.
    pub from: usize,
    pub to: usize,
}

/// The surfaces `model` declares, in the order their letters first appear.
pub fn declared_surfaces(model: &Model) -> Vec<DeclaredSurface> {
    model
        .settings
        .surfaces
        .iter()
        .map(|s| DeclaredSurface {
            letter: s.letter,
            organ: s.organ.map(|o| o.name()),
            precision: s.precision,
            patches: s.patches.len(),
            points: s
                .written
                .iter()
                .map(|p| DeclaredPoint {
                    patch: p.patch,
                    index: p.index,
                    value: p.value,
                    from: p.span.start,
                    to: p.span.end,
                })
                .collect(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::{build, BuildOptions};

    #[test]
    fn each_point_names_the_text_of_its_numbers() {
        let points: Vec<String> = (0..16).map(|k| format!("{k} 0 -{k}")).collect();
        let text = format!(
            "#surface a petal\n#patch b {}\naxiom: ~a~b",
            points.join(", ")
        );
        let b = build(&text, &BuildOptions::default());
        let surfaces = declared_surfaces(b.model.as_ref().expect("model"));
        assert_eq!(surfaces.len(), 2);
        assert_eq!((surfaces[0].organ, surfaces[0].patches), (Some("petal"), 2));
        assert!(surfaces[0].points.is_empty());
        let p = &surfaces[1].points[11];
        assert_eq!((p.patch, p.index, p.value), (0, 11, [11.0, 0.0, -11.0]));
        assert_eq!(&text[p.from..p.to], "11 0 -11");
        let json = serde_json::to_string(&surfaces).expect("json");
        assert!(
            json.starts_with(
                r#"[{"letter":"a","organ":"petal","precision":[8,8],"patches":2,"points":[]}"#
            ),
            "{json}"
        );
    }
}

//! What the importers' tests check of every translation: that Meristem reads it without errors;
//! and how they read its notes.

use super::Import;
use crate::diagnostics::has_errors;

/// Panics, with the text and the diagnostics, unless the text of `import` parses and resolves
/// without errors.
pub(super) fn assert_resolves(import: &Import) {
    let (file, d) = crate::syntax::parse(&import.text);
    let (_, r) = crate::model::resolve(&file);
    assert!(
        !has_errors(&d) && !has_errors(&r),
        "{}\n{d:?}\n{r:?}",
        import.text
    );
}

/// The check on the import of odd input `source`: when its translation has an axiom, it
/// resolves without errors (a translation without one is reported as such).
fn assert_resolves_if_it_has_an_axiom(source: &str, import: &Import) {
    let (file, _) = crate::syntax::parse(&import.text);
    if file.axiom.is_some() {
        let (_, r) = crate::model::resolve(&file);
        assert!(!has_errors(&r), "{source:?}\n{}\n{r:?}", import.text);
    }
}

/// The check on an importer's odd inputs: `import` does not panic on any of `sources`, and each
/// translation that has an axiom resolves without errors.
pub(super) fn assert_odd_inputs_resolve(sources: &[&str], import: impl Fn(&str) -> Import) {
    for source in sources {
        assert_resolves_if_it_has_an_axiom(source, &import(source));
    }
}

/// The notes of `import` as (line, message) pairs, to compare or to search.
pub(super) fn noted(import: &Import) -> Vec<(usize, &str)> {
    import
        .notes
        .iter()
        .map(|n| (n.line, n.message.as_str()))
        .collect()
}

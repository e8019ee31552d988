//! Cut (`%`, `@Prune`): after each step, a cut module and the rest of its branch leave the string.

use crate::model::{LString, Model, SuccessorModule};

/// True when the axiom or a successor writes a cut module.
pub(super) fn contains_cut(model: &Model) -> bool {
    let is_cut = |s: &SuccessorModule| model.cut.contains(&s.id);
    let in_axiom = |id: &crate::model::ModuleId| model.in_axiom.get(id.index()) == Some(&true);
    model.cut.iter().any(in_axiom)
        || [&model.productions, &model.decomposition]
            .iter()
            .any(|set| {
                set.productions
                    .iter()
                    .any(|p| p.successor.iter().any(is_cut))
            })
}

/// Removes each cut module and the rest of its branch (up to, not including, the `]` that closes
/// the branch, or to the end of the string on the main axis).
/// Returns the indices of the kept modules in the old string, when anything was cut.
pub(super) fn cut(model: &Model, s: &mut LString) -> Option<Vec<u32>> {
    if !s.ids.iter().any(|id| model.cut.contains(id)) {
        return None;
    }
    let old = std::mem::take(s);
    s.clear(old.is_parametric());
    let mut kept = Vec::new();
    let mut i = 0;
    while i < old.len() {
        let id = old.ids[i];
        if model.cut.contains(&id) {
            let mut depth = 0usize;
            i += 1;
            while i < old.len() {
                let id = old.ids[i];
                if id == model.open {
                    depth += 1;
                } else if id == model.close || model.groups.is_marker(id) && id != model.groups.open
                {
                    if depth == 0 {
                        break;
                    }
                    depth -= 1;
                } else if id == model.groups.open {
                    depth += 1;
                }
                i += 1;
            }
            continue;
        }
        s.push(id, old.params_of(i));
        kept.push(i as u32);
        i += 1;
    }
    Some(kept)
}

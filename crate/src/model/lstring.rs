//! The derived string: the plain data that flows from `derive` to `turtle`.

use super::{Alphabet, ModuleId};

/// A string of modules, stored as a flat array of module ids (no allocation per module).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LString {
    pub ids: Vec<ModuleId>,
}

impl LString {
    pub fn len(&self) -> usize {
        self.ids.len()
    }

    pub fn is_empty(&self) -> bool {
        self.ids.is_empty()
    }

    /// The canonical text form: module names as written, no spaces (`F[+X]F`).
    pub fn to_text(&self, alphabet: &Alphabet) -> String {
        let mut out = String::with_capacity(self.ids.len());
        for &id in &self.ids {
            out.push_str(alphabet.name(id));
        }
        out
    }

    /// Like [`LString::to_text`] but stops after about `max_chars` characters, appending `…` when
    /// the string is longer.
    pub fn to_text_truncated(&self, alphabet: &Alphabet, max_chars: usize) -> String {
        let mut out = String::new();
        let mut chars = 0;
        for &id in &self.ids {
            let name = alphabet.name(id);
            if chars + name.chars().count() > max_chars {
                out.push('…');
                return out;
            }
            chars += name.chars().count();
            out.push_str(name);
        }
        out
    }
}

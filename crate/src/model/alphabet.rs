//! Module names interned as small integer ids.

use std::collections::HashMap;

/// The id of a module name in an [`Alphabet`]; ids are dense, starting at 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ModuleId(pub u32);

impl ModuleId {
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// The interned module names of one grammar.
#[derive(Clone, Debug, PartialEq)]
pub struct Alphabet {
    names: Vec<String>,
    /// 1 + the id of each one-byte name (0: not interned). Most names are one byte (`F`, `+`,
    /// `[`), and every build interns or looks up each module it reads: these need no hashing.
    single: [u32; 128],
    /// The ids of the longer names.
    ids: HashMap<String, ModuleId>,
}

impl Default for Alphabet {
    fn default() -> Self {
        Alphabet {
            names: Vec::new(),
            single: [0; 128],
            ids: HashMap::new(),
        }
    }
}

impl Alphabet {
    /// The id of `name`, adding it when new.
    pub fn intern(&mut self, name: &str) -> ModuleId {
        if let Some(id) = self.get(name) {
            return id;
        }
        let id = ModuleId(self.names.len() as u32);
        self.names.push(name.to_string());
        match single_byte(name) {
            Some(byte) => self.single[byte] = id.0 + 1,
            None => {
                self.ids.insert(name.to_string(), id);
            }
        }
        id
    }

    pub fn get(&self, name: &str) -> Option<ModuleId> {
        match single_byte(name) {
            Some(byte) => self.single[byte].checked_sub(1).map(ModuleId),
            None => self.ids.get(name).copied(),
        }
    }

    pub fn name(&self, id: ModuleId) -> &str {
        &self.names[id.index()]
    }

    pub fn len(&self) -> usize {
        self.names.len()
    }

    pub fn is_empty(&self) -> bool {
        self.names.is_empty()
    }
}

/// The byte of a one-byte (ASCII) name, as an index into [`Alphabet::single`].
fn single_byte(name: &str) -> Option<usize> {
    match *name.as_bytes() {
        [byte] if byte.is_ascii() => Some(usize::from(byte)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_byte_and_longer_names_get_dense_ids_once() {
        let mut a = Alphabet::default();
        let names = ["F", "A_1", "+", "@Gc", "F", "\u{7f}", "A_1", "\0", "é"];
        let ids: Vec<u32> = names.iter().map(|n| a.intern(n).0).collect();
        assert_eq!(ids, [0, 1, 2, 3, 0, 4, 1, 5, 6]);
        assert_eq!(a.len(), 7);
        for (name, id) in names.iter().zip(ids) {
            assert_eq!(a.get(name), Some(ModuleId(id)));
            assert_eq!(a.name(ModuleId(id)), *name);
        }
        assert_eq!(a.get("X"), None);
        assert_eq!(a.get("FF"), None);
    }
}

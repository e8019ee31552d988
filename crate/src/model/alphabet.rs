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
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Alphabet {
    names: Vec<String>,
    ids: HashMap<String, ModuleId>,
}

impl Alphabet {
    /// The id of `name`, adding it when new.
    pub fn intern(&mut self, name: &str) -> ModuleId {
        if let Some(&id) = self.ids.get(name) {
            return id;
        }
        let id = ModuleId(self.names.len() as u32);
        self.names.push(name.to_string());
        self.ids.insert(name.to_string(), id);
        id
    }

    pub fn get(&self, name: &str) -> Option<ModuleId> {
        self.ids.get(name).copied()
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

//! Imports at the boundary: another dialect's grammar, or a vlab object's files, translated.

use wasm_bindgen::prelude::*;

/// Imports files opened together, a vlab object (its `.l`, view file, functions and colours, as a
/// folder, several files or a `.zip`) or an L-Py model: `names[k]` is the k-th file's name (a path
/// inside the folder), its bytes are the next `lengths[k]` bytes of `bytes`. Returns the JSON of
/// [`import_grammar`] (`dialect` is null when nothing could be imported).
#[wasm_bindgen(js_name = importObject)]
pub fn import_object(names: Vec<String>, bytes: &[u8], lengths: &[u32]) -> String {
    use crate::import::{self, Dialect, Import, ObjectFile};
    #[derive(serde::Serialize)]
    struct Imported {
        #[serde(flatten)]
        import: Import,
        dialect: Option<Dialect>,
    }
    let mut files = Vec::new();
    let mut at = 0usize;
    for (name, &len) in names.into_iter().zip(lengths) {
        let end = at.saturating_add(len as usize).min(bytes.len());
        files.push(ObjectFile {
            name,
            bytes: bytes[at.min(end)..end].to_vec(),
        });
        at = end;
    }
    let (import, dialect) = import::import_files(&files);
    serde_json::to_string(&Imported { import, dialect }).unwrap_or_else(|_| "{}".into())
}

/// Translates `text`, written in another L-system dialect, into Meristem's language.
/// `dialect_or_file_name` is a dialect name (`green`, `lparser`, `cpfg`, `lpy`) or the file's
/// name, whose extension or content then tells the dialect. Returns JSON
/// `{text, notes: [{line, message}], dialect}`: `line` is 1-based in `text` (0 for the whole
/// file); when the dialect cannot be told, `text` is empty, `dialect` null and one note says why.
#[wasm_bindgen(js_name = importGrammar)]
pub fn import_grammar(text: &str, dialect_or_file_name: &str) -> String {
    use crate::import::{self, Dialect, Import, ImportNote};
    #[derive(serde::Serialize)]
    struct Imported {
        #[serde(flatten)]
        import: Import,
        dialect: Option<Dialect>,
    }
    let dialect = Dialect::from_name(dialect_or_file_name)
        .or_else(|| import::detect(text, dialect_or_file_name));
    let result = match dialect {
        Some(d) => Imported {
            import: import::import(text, d),
            dialect: Some(d),
        },
        None => Imported {
            import: Import {
                text: String::new(),
                notes: vec![ImportNote {
                    line: 0,
                    message: format!(
                        "cannot tell which dialect '{dialect_or_file_name}' is written in (green, lparser, cpfg or lpy)"
                    ),
                }],
            },
            dialect: None,
        },
    };
    serde_json::to_string(&result).unwrap_or_else(|_| "{}".into())
}

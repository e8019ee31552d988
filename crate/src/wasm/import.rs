//! Imports at the boundary: another dialect's grammar, or a vlab object's files, translated.

use wasm_bindgen::prelude::*;

/// Imports files opened together, a vlab object (its `.l`, view file, functions and colours, as a
/// folder, several files or a `.zip`) or an L-Py model: `names[k]` is the k-th file's name (a path
/// inside the folder), its bytes are the next `lengths[k]` bytes of `bytes`. Returns the JSON of
/// [`import_grammar`] (`dialect` is null when nothing could be imported, and when the names,
/// bytes and lengths disagree: a note says how).
#[wasm_bindgen(js_name = importObject)]
pub fn import_object(names: Vec<String>, bytes: &[u8], lengths: &[u32]) -> String {
    let (import, dialect) = match object_files(names, bytes, lengths) {
        Ok(files) => crate::import::import_files(&files),
        Err(why) => (not_imported(why), None),
    };
    imported_json(import, dialect)
}

/// Translates `text`, written in another L-system dialect, into Meristem's language.
/// `dialect_or_file_name` is a dialect name (`green`, `lparser`, `cpfg`, `lpy`) or the file's
/// name, whose extension or content then tells the dialect. Returns JSON
/// `{text, notes: [{line, message}], dialect}`: `line` is 1-based in `text` (0 for the whole
/// file); when the dialect cannot be told, `text` is empty, `dialect` null and one note says why.
#[wasm_bindgen(js_name = importGrammar)]
pub fn import_grammar(text: &str, dialect_or_file_name: &str) -> String {
    use crate::import::{self, Dialect};
    let dialect = Dialect::from_name(dialect_or_file_name)
        .or_else(|| import::detect(text, dialect_or_file_name));
    match dialect {
        Some(d) => imported_json(import::import(text, d), Some(d)),
        None => imported_json(
            not_imported(format!(
                "cannot tell which dialect '{dialect_or_file_name}' is written in (green, lparser, cpfg or lpy)"
            )),
            None,
        ),
    }
}

/// The files of [`import_object`]'s arguments: `names[k]` with the next `lengths[k]` bytes; or
/// why not, when there are not as many names as lengths or the lengths do not add up to the
/// bytes (a file cut short or dropped without a word would be imported wrong).
fn object_files(
    names: Vec<String>,
    bytes: &[u8],
    lengths: &[u32],
) -> Result<Vec<crate::import::ObjectFile>, String> {
    if names.len() != lengths.len() {
        return Err(format!(
            "the files opened together do not agree: {} names but {} lengths",
            names.len(),
            lengths.len()
        ));
    }
    let total: u64 = lengths.iter().map(|&len| u64::from(len)).sum();
    if total != bytes.len() as u64 {
        return Err(format!(
            "the files opened together do not agree: their lengths add up to {total} bytes, but \
             {} bytes were given",
            bytes.len()
        ));
    }
    let mut files = Vec::with_capacity(names.len());
    let mut rest = bytes;
    for (name, &len) in names.into_iter().zip(lengths) {
        let (file, after) = rest.split_at(len as usize);
        files.push(crate::import::ObjectFile {
            name,
            bytes: file.to_vec(),
        });
        rest = after;
    }
    Ok(files)
}

/// The JSON the importers' doors return: the import's `text` and `notes`, and its `dialect`
/// (null when nothing could be imported).
fn imported_json(import: crate::import::Import, dialect: Option<crate::import::Dialect>) -> String {
    #[derive(serde::Serialize)]
    struct Imported {
        #[serde(flatten)]
        import: crate::import::Import,
        dialect: Option<crate::import::Dialect>,
    }
    serde_json::to_string(&Imported { import, dialect }).unwrap_or_else(|_| "{}".into())
}

/// An import of nothing, with the note that says why.
fn not_imported(why: String) -> crate::import::Import {
    crate::import::Import {
        text: String::new(),
        notes: vec![crate::import::ImportNote {
            line: 0,
            message: why,
        }],
    }
}

/// Which of the files opened together (as [`import_object`] takes them) Python would run:
/// JSON `{"main": name, "dialect": "lpy" | "lpfg"}` (the runtime's `main` and
/// `options.dialect`), or `null` when none can be (cpfg, Lparser, Green: the hand translation is
/// all there is). Throws when the names, bytes and lengths disagree.
#[wasm_bindgen(js_name = pythonMain)]
pub fn python_main(names: Vec<String>, bytes: &[u8], lengths: &[u32]) -> Result<String, JsError> {
    let files = object_files(names, bytes, lengths).map_err(|why| JsError::new(&why))?;
    Ok(
        serde_json::to_string(&crate::import::python_main(&files))
            .unwrap_or_else(|_| "null".into()),
    )
}

/// The rule that chooses the Python route: `importJson` is what [`import_object`] or
/// [`import_grammar`] returned for a model [`python_main`] can run. True when that hand
/// translation has no axiom, carries a note (something dropped or approximated) or draws
/// nothing: then run the model by Python and call [`import_derived`]. False (and for JSON that
/// cannot be read): keep the translation, an editable grammar with its rules.
#[wasm_bindgen(js_name = needsPython)]
pub fn needs_python(import_json: &str) -> bool {
    serde_json::from_str::<crate::import::Import>(import_json)
        .map(|import| crate::import::needs_python(&import))
        .unwrap_or(false)
}

/// A Python run turned into Meristem text: `resultJson` is the JSON `meristem_lsystem.run`
/// returned for the file `mainName` (from [`python_main`]) of the files given as to
/// [`import_object`], run with `seed`. Returns JSON `{text, notes, dialect}` as
/// [`import_object`]; a run that stopped gives an empty `text` and a note at the error's line
/// (then call [`prefer_derived`] with the hand translation). TypeScript:
/// `importDerived(resultJson: string, mainName: string, names: string[], bytes: Uint8Array,
/// lengths: Uint32Array, seed: number): string`.
#[wasm_bindgen(js_name = importDerived)]
pub fn import_derived(
    result_json: &str,
    main_name: &str,
    names: Vec<String>,
    bytes: &[u8],
    lengths: &[u32],
    seed: f64,
) -> String {
    use crate::import::{self, Dialect};
    let files = match object_files(names, bytes, lengths) {
        Ok(files) => files,
        Err(why) => return imported_json(not_imported(why), None),
    };
    let seed = if seed.is_finite() && seed >= 0.0 {
        seed as u64
    } else {
        0
    };
    let import = import::import_derived(result_json, main_name, &files, seed);
    let lpy = main_name.to_ascii_lowercase().ends_with(".lpy");
    let dialect = (!import.is_empty()).then_some(if lpy { Dialect::Lpy } else { Dialect::Cpfg });
    imported_json(import, dialect)
}

/// The import to open: the derived one (`derivedJson`, from [`import_derived`]) when it has a
/// plant, else the hand translation (`translationJson`) with the derived one's notes saying why
/// Python gave none. Both as JSON `{text, notes, dialect}`; returns the same.
#[wasm_bindgen(js_name = preferDerived)]
pub fn prefer_derived(translation_json: &str, derived_json: &str) -> String {
    use crate::import::{self, Dialect, Import};
    #[derive(serde::Serialize, serde::Deserialize)]
    struct Imported {
        #[serde(flatten)]
        import: Import,
        dialect: Option<Dialect>,
    }
    let read = |json: &str| serde_json::from_str::<Imported>(json).ok();
    let (Some(translation), Some(derived)) = (read(translation_json), read(derived_json)) else {
        return translation_json.to_string();
    };
    let dialect = if derived.import.is_empty() {
        translation.dialect
    } else {
        derived.dialect
    };
    let import = import::prefer_derived(translation.import, derived.import);
    serde_json::to_string(&Imported { import, dialect }).unwrap_or_else(|_| "{}".into())
}

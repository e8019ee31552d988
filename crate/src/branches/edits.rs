//! Branch edits as data, and their JSON document: what `meristem … --edits FILE` reads and what
//! the studio keeps in share links, undo history and downloads.
//!
//! ```json
//! {"version": 1, "edits": [{"path": [0, 2, 1], "handles": [[0, 0.1, 0], [0, 0, 0], [0.05, 0.3, 0]]}]}
//! ```
//!
//! `path` names a branch (see [`super`]); `handles` are the offsets of its Bézier handles P1, P2
//! and P3 from their fitted places, each as (heading, left, up) components in the branch's
//! unedited start frame (the turtle's H, L, U on its first segment, carried along when an
//! ancestor moves) and in units of the branch's length (the sum of its segments' lengths). So
//! an edit keeps its meaning when its ancestors are edited, and scales with the branch when a
//! re-derivation makes it longer or shorter.

use glam::DVec3;
use serde::Serialize;

/// The version of the edits document this core writes and reads.
pub const EDITS_VERSION: u32 = 1;
/// Most edits one document may hold.
pub const MAX_EDITS: usize = 100_000;
/// Longest path accepted.
pub const MAX_PATH: usize = 10_000;
/// Largest offset accepted, in branch lengths.
pub const MAX_OFFSET: f64 = 1_000.0;

/// An override of one branch's Bézier handles (see the module documentation).
#[derive(Clone, Debug, PartialEq)]
pub struct BranchEdit {
    /// The branch: its root's index, then child indices.
    pub path: Vec<u32>,
    /// Offsets of P1, P2, P3: (heading, left, up) in the branch's start frame, in branch lengths.
    pub handles: [DVec3; 3],
}

/// An edit that was not applied, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NotApplied {
    pub path: Vec<u32>,
    pub reason: String,
}

/// What applying a list of edits did: never an error, every edit is either applied or reported.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct EditReport {
    /// Paths of the edits applied, in the order given.
    pub applied: Vec<Vec<u32>>,
    #[serde(rename = "notApplied")]
    pub not_applied: Vec<NotApplied>,
}

impl EditReport {
    /// One JSON object: `{"applied": [[0,2]], "notApplied": [{"path": [0,9], "reason": "…"}]}`.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|_| "{}".into())
    }
}

#[derive(Serialize)]
struct Document {
    version: u32,
    edits: Vec<EditJson>,
}

#[derive(Serialize)]
struct EditJson {
    path: Vec<u32>,
    handles: [[f64; 3]; 3],
}

/// Checks one edit against the document's limits: what [`parse_edits`] refuses, and what the
/// branch editor checks before a drag makes an edit (so every document it writes reads back).
pub fn check_edit(path_len: usize, handles: &[DVec3; 3]) -> Result<(), String> {
    if path_len == 0 || path_len > MAX_PATH {
        return Err(format!(
            "a path has 1 to {MAX_PATH} indices, not {path_len}"
        ));
    }
    if handles
        .iter()
        .any(|h| !h.is_finite() || h.abs().max_element() > MAX_OFFSET)
    {
        return Err(format!(
            "handle offsets must be finite numbers of at most {MAX_OFFSET} branch lengths"
        ));
    }
    Ok(())
}

/// What a JSON value is, in words.
fn kind(value: &serde_json::Value) -> &'static str {
    match value {
        serde_json::Value::Null => "null",
        serde_json::Value::Bool(_) => "true or false",
        serde_json::Value::Number(_) => "a number",
        serde_json::Value::String(_) => "a string",
        serde_json::Value::Array(_) => "a list",
        serde_json::Value::Object(_) => "an object",
    }
}

/// The one field of `object` not in `known`, if any.
fn unknown_field<'a>(
    object: &'a serde_json::Map<String, serde_json::Value>,
    known: &[&str],
) -> Option<&'a str> {
    object
        .keys()
        .map(String::as_str)
        .find(|k| !known.contains(k))
}

/// The list in the field `field` of `object`; else an error saying it must be a list of `what`,
/// or `missing` when there is no such field.
fn list<'a>(
    object: &'a serde_json::Map<String, serde_json::Value>,
    field: &str,
    what: &str,
    missing: &str,
) -> Result<&'a Vec<serde_json::Value>, String> {
    match object.get(field) {
        Some(serde_json::Value::Array(list)) => Ok(list),
        Some(other) => Err(format!(
            "\"{field}\" must be a list of {what}, not {}",
            kind(other)
        )),
        None => Err(missing.into()),
    }
}

/// Reads an edits document. Errors say what is wrong in words, naming the edit and the field
/// (the text may come from a link or a file written by hand); a leading byte order mark, as some
/// editors write, is ignored.
pub fn parse_edits(json: &str) -> Result<Vec<BranchEdit>, String> {
    let json = json.strip_prefix('\u{feff}').unwrap_or(json);
    let value: serde_json::Value =
        serde_json::from_str(json).map_err(|e| format!("the edits are not valid JSON: {e}"))?;
    let Some(document) = value.as_object() else {
        return Err(format!(
            "the edits are not a JSON object (the document is {})",
            kind(&value)
        ));
    };
    // The version first, so a newer document says so instead of failing on a new field.
    match document.get("version") {
        Some(serde_json::Value::Number(n)) if n.as_u64() == Some(EDITS_VERSION as u64) => {}
        Some(serde_json::Value::Number(n)) if n.as_u64().is_some_and(|v| v > 1) => {
            return Err(format!(
                "the edits were written by a newer Meristem (version {n}); this one reads version {EDITS_VERSION}"
            ))
        }
        _ => return Err(format!("the edits have no \"version\": {EDITS_VERSION}")),
    }
    if let Some(field) = unknown_field(document, &["version", "edits"]) {
        return Err(format!(
            "the edits document has an unknown field \"{field}\" (it holds only \"version\" and \"edits\")"
        ));
    }
    let edits = list(
        document,
        "edits",
        "edits",
        "the edits document has no \"edits\" list",
    )?;
    if edits.len() > MAX_EDITS {
        return Err(format!("more than {MAX_EDITS} edits"));
    }
    edits
        .iter()
        .enumerate()
        .map(|(k, edit)| read_edit(edit).map_err(|e| format!("edit {k}: {e}")))
        .collect()
}

/// One edit of the document: `{"path": [...], "handles": [[h, l, u], [h, l, u], [h, l, u]]}`.
/// Long because each field it checks has its own message in words (what is wrong, where).
fn read_edit(edit: &serde_json::Value) -> Result<BranchEdit, String> {
    let Some(edit) = edit.as_object() else {
        return Err(format!(
            "an edit is an object with \"path\" and \"handles\", not {}",
            kind(edit)
        ));
    };
    if let Some(field) = unknown_field(edit, &["path", "handles"]) {
        return Err(format!(
            "unknown field \"{field}\" (an edit holds only \"path\" and \"handles\")"
        ));
    }
    let path = list(edit, "path", "branch indices", "no \"path\"")?;
    let path = path
        .iter()
        .enumerate()
        .map(|(i, index)| {
            index
                .as_u64()
                .and_then(|index| u32::try_from(index).ok())
                .ok_or_else(|| {
                    format!(
                        "index {i} of \"path\" must be a whole number from 0 to {}, not {index}",
                        u32::MAX
                    )
                })
        })
        .collect::<Result<Vec<u32>, String>>()?;
    let handles = list(edit, "handles", "3 points (P1, P2, P3)", "no \"handles\"")?;
    if handles.len() != 3 {
        return Err(format!(
            "\"handles\" must hold 3 points (P1, P2, P3), not {}",
            handles.len()
        ));
    }
    let mut points = [DVec3::ZERO; 3];
    for (n, handle) in handles.iter().enumerate() {
        let numbers = handle.as_array().filter(|h| h.len() == 3).ok_or_else(|| {
            let what = match handle.as_array() {
                Some(h) => format!("{} numbers", h.len()),
                None => kind(handle).to_string(),
            };
            format!(
                "handle P{} must be 3 numbers (heading, left, up), not {what}",
                n + 1
            )
        })?;
        for (c, number) in numbers.iter().enumerate() {
            points[n][c] = number.as_f64().ok_or_else(|| {
                format!(
                    "handle P{} must be 3 numbers (heading, left, up), but its number {} is {}",
                    n + 1,
                    c + 1,
                    kind(number)
                )
            })?;
        }
    }
    check_edit(path.len(), &points)?;
    Ok(BranchEdit {
        path,
        handles: points,
    })
}

/// Writes an edits document (numbers in shortest round-trip form).
pub fn write_edits(edits: &[BranchEdit]) -> String {
    let document = Document {
        version: EDITS_VERSION,
        edits: edits
            .iter()
            .map(|e| EditJson {
                path: e.path.clone(),
                handles: e.handles.map(|h| h.to_array()),
            })
            .collect(),
    };
    serde_json::to_string(&document).unwrap_or_else(|_| "{}".into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_document_round_trips() {
        let edits = vec![
            BranchEdit {
                path: vec![0, 2, 1],
                handles: [
                    DVec3::new(0.0, 0.1, 0.0),
                    DVec3::ZERO,
                    DVec3::new(0.05, 0.3, -1.5),
                ],
            },
            BranchEdit {
                path: vec![1],
                handles: [DVec3::ZERO; 3],
            },
        ];
        let json = write_edits(&edits);
        assert_eq!(
            json,
            r#"{"version":1,"edits":[{"path":[0,2,1],"handles":[[0.0,0.1,0.0],[0.0,0.0,0.0],[0.05,0.3,-1.5]]},{"path":[1],"handles":[[0.0,0.0,0.0],[0.0,0.0,0.0],[0.0,0.0,0.0]]}]}"#
        );
        assert_eq!(parse_edits(&json), Ok(edits));
    }

    #[test]
    fn bad_documents_say_what_is_wrong() {
        let cases = [
            ("[]", "not a JSON object (the document is a list)"),
            ("{\"version\": 1,", "not valid JSON"),
            ("{\"edits\": []}", "no \"version\""),
            ("{\"version\": 2, \"edits\": []}", "newer Meristem"),
            ("{\"version\": 1}", "no \"edits\" list"),
            ("{\"version\": 1, \"edits\": {}}", "\"edits\" must be a list of edits, not an object"),
            ("{\"version\": 1, \"edits\": [], \"x\": 1}", "unknown field \"x\""),
            ("{\"version\": 1, \"edits\": [3]}", "edit 0: an edit is an object"),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [], \"handles\": [[0,0,0],[0,0,0],[0,0,0]]}]}",
                "edit 0: a path",
            ),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [-1], \"handles\": [[0,0,0],[0,0,0],[0,0,0]]}]}",
                "edit 0: index 0 of \"path\" must be a whole number from 0 to 4294967295, not -1",
            ),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [0, 1.5], \"handles\": [[0,0,0],[0,0,0],[0,0,0]]}]}",
                "edit 0: index 1 of \"path\"",
            ),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [0], \"handles\": [[0,0,0],[0,0]]}]}",
                "edit 0: \"handles\" must hold 3 points (P1, P2, P3), not 2",
            ),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [0], \"handles\": [[0,0,0],[0,0,0],[0,0,0],[0,0,0]]}]}",
                "edit 0: \"handles\" must hold 3 points (P1, P2, P3), not 4",
            ),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [0], \"handles\": [[0,0,0],[0,0],[0,0,0]]}]}",
                "edit 0: handle P2 must be 3 numbers (heading, left, up), not 2 numbers",
            ),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [0], \"handles\": [[0,0,0],[0,0,0],[0,\"1\",0]]}]}",
                "edit 0: handle P3 must be 3 numbers (heading, left, up), but its number 2 is a string",
            ),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [0], \"handles\": [[0,0,0],[0,0,0],[0,0,0]], \"x\": 1}]}",
                "edit 0: unknown field \"x\"",
            ),
            (
                "{\"version\": 1, \"edits\": [{\"handles\": [[0,0,0],[0,0,0],[0,0,0]]}]}",
                "edit 0: no \"path\"",
            ),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [0], \"handles\": [[0,0,0],[0,0,0],[0,0,1e9]]}]}",
                "edit 0: handle offsets",
            ),
        ];
        for (json, expected) in cases {
            let error = parse_edits(json).expect_err(json);
            assert!(error.contains(expected), "{json}: {error}");
        }
        assert_eq!(parse_edits("{\"version\": 1, \"edits\": []}"), Ok(vec![]));
    }

    #[test]
    fn a_byte_order_mark_is_ignored() {
        let edits = vec![BranchEdit {
            path: vec![0, 1],
            handles: [
                DVec3::new(0.0, 0.25, 0.0),
                DVec3::ZERO,
                DVec3::new(-1.0, 0.0, 2.0),
            ],
        }];
        let json = write_edits(&edits);
        assert_eq!(parse_edits(&format!("\u{feff}{json}")), Ok(edits.clone()));
        assert_eq!(parse_edits(&format!("\u{feff}  {json}\r\n")), Ok(edits));
        // Only at the start: a mark inside is not JSON.
        assert!(parse_edits(&format!("{json}\u{feff}")).is_err());
    }
}

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
use serde::{Deserialize, Serialize};

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

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Document {
    version: u32,
    edits: Vec<EditJson>,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct EditJson {
    path: Vec<u32>,
    handles: [[f64; 3]; 3],
}

/// Reads an edits document. Errors say what is wrong in words (the text may come from a link).
pub fn parse_edits(json: &str) -> Result<Vec<BranchEdit>, String> {
    #[derive(Deserialize)]
    struct Version {
        version: Option<serde_json::Value>,
    }
    // The version first, so a newer document says so instead of failing on a new field.
    let version: Version =
        serde_json::from_str(json).map_err(|e| format!("the edits are not a JSON object: {e}"))?;
    match version.version {
        Some(serde_json::Value::Number(n)) if n.as_u64() == Some(EDITS_VERSION as u64) => {}
        Some(serde_json::Value::Number(n)) if n.as_u64().is_some_and(|v| v > 1) => {
            return Err(format!(
                "the edits were written by a newer Meristem (version {n}); this one reads version {EDITS_VERSION}"
            ))
        }
        _ => return Err(format!("the edits have no \"version\": {EDITS_VERSION}")),
    }
    let document: Document =
        serde_json::from_str(json).map_err(|e| format!("the edits are malformed: {e}"))?;
    if document.edits.len() > MAX_EDITS {
        return Err(format!("more than {MAX_EDITS} edits"));
    }
    document
        .edits
        .into_iter()
        .enumerate()
        .map(|(k, e)| {
            if e.path.is_empty() || e.path.len() > MAX_PATH {
                return Err(format!(
                    "edit {k}: a path has 1 to {MAX_PATH} indices, not {}",
                    e.path.len()
                ));
            }
            let handles = e.handles.map(DVec3::from_array);
            if handles
                .iter()
                .any(|h| !h.is_finite() || h.abs().max_element() > MAX_OFFSET)
            {
                return Err(format!(
                    "edit {k}: handle offsets must be finite numbers of at most {MAX_OFFSET} branch lengths"
                ));
            }
            Ok(BranchEdit {
                path: e.path,
                handles,
            })
        })
        .collect()
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
            ("[]", "not a JSON object"),
            ("{\"edits\": []}", "no \"version\""),
            ("{\"version\": 2, \"edits\": []}", "newer Meristem"),
            ("{\"version\": 1}", "malformed"),
            ("{\"version\": 1, \"edits\": [], \"x\": 1}", "malformed"),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [], \"handles\": [[0,0,0],[0,0,0],[0,0,0]]}]}",
                "edit 0: a path",
            ),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [-1], \"handles\": [[0,0,0],[0,0,0],[0,0,0]]}]}",
                "malformed",
            ),
            (
                "{\"version\": 1, \"edits\": [{\"path\": [0], \"handles\": [[0,0,0],[0,0]]}]}",
                "malformed",
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
}

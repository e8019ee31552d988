//! The language's vocabulary: every name a grammar can use with a meaning, declared once.
//!
//! - [`MODULES`]: the modules with a meaning (turtle commands, cut, Green's control modules), each
//!   with its typed parameters ([`Param`]: name, kind, default, range, unit, doc), a doc line and a
//!   category;
//! - [`DIRECTIVES`]: every `#directive`, with the forms its arguments may take;
//! - [`KEYWORDS`]: the words that open a line (`axiom:`, `homomorphism:`, …);
//! - [`FUNCTIONS`] and [`VALUES`]: what expressions may call and read.
//!
//! Everything that needs one of these names reads it here: the tokenizer (`@` names, control
//! modules), the resolver (what each module means, directive arguments and their defaults), the
//! turtle (through the model: commands and parameter defaults), the command line's help, and the
//! studio through the wasm boundary ([`vocabulary_json`]: highlighting, completion, hover docs and
//! the Growth panel's fields). Adding a turtle command is one row of [`MODULES`] plus its behaviour
//! in `turtle`. Nothing here depends on any other part of the crate.

mod directives;
mod environment;
mod expressions;
mod keywords;
mod modules;
mod params;
mod surfaces;

pub use directives::{
    directive, directive_named, DirectiveInfo, DirectiveKind, Season, DIRECTIVES,
};
pub use environment::{
    environment_program_named, environment_shape_named, stand_layout_named, EnvironmentProgram,
    EnvironmentProgramInfo, EnvironmentSetting, EnvironmentShape, EnvironmentShapeInfo,
    StandLayout, StandLayoutInfo, ENVIRONMENT_PROGRAMS, ENVIRONMENT_SHAPES, STAND_LAYOUTS,
};
pub use expressions::{
    function_named, value_named, Function, FunctionInfo, Value, ValueInfo, FUNCTIONS, VALUES,
};
pub use keywords::{keyword_named, KeywordInfo, KeywordKind, KEYWORDS};
pub use modules::{
    module_named, name_of, names_of, Category, Command, GroupKind, Meaning, ModuleInfo, MODULES,
    PLACING,
};
pub use params::{Param, ParamDefault, ParamKind};
pub use surfaces::{
    frame_word_named, organ_named, FrameWord, FrameWordInfo, Organ, OrganInfo, FRAME_WORDS,
    PATCH_COLOR, SURFACE_SHAPES,
};

use serde::Serialize;

/// The whole vocabulary as one JSON object for the studio:
/// `{modules, directives, keywords, functions, values}` (see each table's row type).
pub fn vocabulary_json() -> String {
    #[derive(Serialize)]
    struct Vocabulary {
        modules: &'static [ModuleInfo],
        directives: &'static [DirectiveInfo],
        keywords: &'static [KeywordInfo],
        functions: &'static [FunctionInfo],
        values: &'static [ValueInfo],
    }
    serde_json::to_string(&Vocabulary {
        modules: MODULES,
        directives: DIRECTIVES,
        keywords: KEYWORDS,
        functions: FUNCTIONS,
        values: VALUES,
    })
    .unwrap_or_else(|_| "{}".into())
}

/// Every name of the vocabulary as it is written in a grammar: module names, `#directive`s,
/// keywords with their colon, functions and values. What the tests check other layers against.
pub fn written_names() -> Vec<String> {
    let mut names: Vec<String> = MODULES.iter().map(|m| m.name.to_string()).collect();
    names.extend(DIRECTIVES.iter().map(|d| format!("#{}", d.name)));
    names.extend(
        KEYWORDS
            .iter()
            .flat_map(|k| k.spellings().map(str::to_string)),
    );
    names.extend(FUNCTIONS.iter().map(|f| f.name.to_string()));
    names.extend(VALUES.iter().map(|v| v.name.to_string()));
    names.extend(SURFACE_SHAPES.iter().map(|o| o.name.to_string()));
    names.extend(FRAME_WORDS.iter().map(|w| w.name.to_string()));
    names.push(PATCH_COLOR.to_string());
    names.extend(ENVIRONMENT_PROGRAMS.iter().map(|p| p.name.to_string()));
    names.extend(ENVIRONMENT_SHAPES.iter().map(|s| s.name.to_string()));
    names.extend(STAND_LAYOUTS.iter().map(|l| l.name.to_string()));
    names
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_name_is_declared_twice() {
        let mut names = written_names();
        let before = names.len();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), before, "a name is declared twice");
    }

    #[test]
    fn every_row_has_a_doc_and_every_parameter_a_kind_and_doc() {
        for m in MODULES {
            assert!(!m.doc.is_empty(), "{}", m.name);
            for p in m.params {
                assert!(!p.doc.is_empty(), "{} {}", m.name, p.name);
            }
        }
        for d in DIRECTIVES {
            assert!(!d.doc.is_empty() && !d.label.is_empty(), "#{}", d.name);
            for p in d.forms.iter().flat_map(|f| f.iter()) {
                assert!(!p.doc.is_empty(), "#{} {}", d.name, p.name);
            }
        }
    }

    #[test]
    fn the_json_holds_every_table() {
        let json: serde_json::Value = serde_json::from_str(&vocabulary_json()).expect("json");
        for (table, len) in [
            ("modules", MODULES.len()),
            ("directives", DIRECTIVES.len()),
            ("keywords", KEYWORDS.len()),
            ("functions", FUNCTIONS.len()),
        ] {
            assert_eq!(json[table].as_array().map(Vec::len), Some(len), "{table}");
        }
        // A default that is another directive's value is written as that directive.
        assert_eq!(json["modules"][0]["params"][0]["default"], "#step");
        assert_eq!(json["directives"][0]["forms"][0][0]["default"], 90.0);
    }
}

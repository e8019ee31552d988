//! The words that open a line of their own: the axiom, the sections, and cpfg's spellings of
//! directives.

use super::params::text;
use serde::Serialize;

/// What a keyword line says (serialized as the variant's identifier, `Axiom`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum KeywordKind {
    Axiom,
    /// `derivation length: N`, the same as `#iterations N`.
    DerivationLength,
    /// `maximum depth: N` after `homomorphism:` or `decomposition:`.
    MaximumDepth,
    Productions,
    Homomorphism,
    Decomposition,
    /// `endlsystem`: back to the productions section (cpfg's end of the L-system).
    EndLSystem,
}

impl KeywordKind {
    /// As written in a grammar, with its colon: `maximum depth:` (`endlsystem` has none).
    pub fn written(self) -> String {
        let row = KEYWORDS.iter().find(|k| k.kind == self);
        row.map_or_else(String::new, |k| {
            format!("{}{}", k.name, if k.colon { ":" } else { "" })
        })
    }
}

/// One row of the keyword table.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct KeywordInfo {
    /// The word(s) before the colon, in lower case (`derivation length`).
    pub name: &'static str,
    pub kind: KeywordKind,
    /// Other spellings (`ω` for the axiom).
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    pub aliases: &'static [&'static str],
    /// False for `endlsystem`, which stands alone.
    pub colon: bool,
    pub doc: &'static str,
}

impl KeywordInfo {
    /// The keyword as written, and its aliases: `axiom:`, `ω:`.
    pub fn spellings(&self) -> impl Iterator<Item = &'static str> {
        std::iter::once(self.name).chain(self.aliases.iter().copied())
    }
}

const fn kw(name: &'static str, kind: KeywordKind, doc: &'static str) -> KeywordInfo {
    KeywordInfo {
        name,
        kind,
        aliases: &[],
        colon: true,
        doc: text(doc),
    }
}

/// Every keyword, in the order the completion lists them.
pub const KEYWORDS: &[KeywordInfo] = &[
    KeywordInfo {
        aliases: &["ω"],
        ..kw(
            "axiom",
            KeywordKind::Axiom,
            "The initial string ω (also written ω:).",
        )
    },
    kw(
        "homomorphism",
        KeywordKind::Homomorphism,
        "Start the rules that rewrite the string for the turtle only.",
    ),
    kw(
        "decomposition",
        KeywordKind::Decomposition,
        "Start the rules applied after each step until nothing changes.",
    ),
    kw(
        "maximum depth",
        KeywordKind::MaximumDepth,
        "The depth limit of the homomorphism or decomposition section above.",
    ),
    kw(
        "derivation length",
        KeywordKind::DerivationLength,
        "The number of derivation steps (as #iterations).",
    ),
    kw(
        "productions",
        KeywordKind::Productions,
        "Start the productions (after a homomorphism or decomposition section).",
    ),
    KeywordInfo {
        colon: false,
        ..kw(
            "endlsystem",
            KeywordKind::EndLSystem,
            "End of the grammar's sections: later productions are productions again.",
        )
    },
];

/// The keyword of a line's first word(s) before a colon (any case), or of a whole line
/// (`endlsystem`).
pub fn keyword_named(word: &str, with_colon: bool) -> Option<&'static KeywordInfo> {
    let word = word.trim();
    KEYWORDS
        .iter()
        .find(|k| k.colon == with_colon && k.spellings().any(|s| s.eq_ignore_ascii_case(word)))
}

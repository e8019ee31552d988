//! The syntax tree: what the text says, with byte spans, before any validation.

use std::ops::Range;

/// A UTF-8 byte range in the source text.
pub type Span = Range<usize>;

/// A whole grammar file as written.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SourceFile {
    pub directives: Vec<Directive>,
    /// The axiom, with the span of the `axiom:` line (`None` when the file has none).
    pub axiom: Option<(Vec<ModuleSyntax>, Span)>,
    pub productions: Vec<ProductionSyntax>,
}

/// A `#name args` line (also `derivation length: N`, which is stored as `iterations`).
#[derive(Clone, Debug, PartialEq)]
pub struct Directive {
    pub name: String,
    pub name_span: Span,
    /// The text after the name, trimmed.
    pub args: String,
    pub args_span: Span,
}

/// One module occurrence: a name such as `F`, `F_a`, `@O`, `?P`.
#[derive(Clone, Debug, PartialEq)]
pub struct ModuleSyntax {
    pub name: String,
    pub span: Span,
}

/// `label: predecessor -> successor`.
#[derive(Clone, Debug, PartialEq)]
pub struct ProductionSyntax {
    pub label: Option<String>,
    pub predecessor: ModuleSyntax,
    /// Empty for `A -> ε` and `A ->`.
    pub successor: Vec<ModuleSyntax>,
    /// The whole production line.
    pub span: Span,
}

//! The syntax tree: what the text says, with byte spans, before any validation.

use crate::vocabulary::DirectiveKind;
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
    /// Where each line starts (`diagnostics::line_starts`), for messages that name another line
    /// than their own ("replaces the one on line 2"): messages never carry byte offsets.
    pub line_starts: Vec<usize>,
}

impl SourceFile {
    /// The 1-based line of byte `offset`.
    pub fn line(&self, offset: usize) -> usize {
        crate::diagnostics::line_of(&self.line_starts, offset)
    }
}

/// A `#name args` line. `derivation length: N` is stored as `iterations`, and `maximum depth: N`
/// as `homomorphism_depth` or `decomposition_depth` after the section it stands in.
#[derive(Clone, Debug, PartialEq)]
pub struct Directive {
    /// The name as written, without `#` (`derivation length:` is `iterations`).
    pub name: String,
    /// What the vocabulary says the name is; `None` for an unknown directive.
    pub kind: Option<DirectiveKind>,
    /// The directive as the user wrote it, for messages: `#angle`, `derivation length:`.
    pub written: String,
    pub name_span: Span,
    /// The text after the name, trimmed.
    pub args: String,
    pub args_span: Span,
    /// For `#define NAME expr` and `#random NAME = expr`: the name being defined.
    pub target: Option<(String, Span)>,
    /// For `#define` and `#random`: the expression.
    pub expr: Option<ExprSyntax>,
    /// For `#ignore`, `#consider`, `#draw`, `#apex`: the modules listed.
    pub modules: Vec<ModuleSyntax>,
    /// For `#curve` and `#table`: the numbers after the name (pairs x y); for `#patch`, triples
    /// x y z.
    pub points: Vec<f64>,
    /// Where each of `points` is written.
    pub point_spans: Vec<Span>,
}

/// One module occurrence: a name such as `F`, `F_a`, `@O`, `?P`, with its parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct ModuleSyntax {
    pub name: String,
    /// The name and its parameter list.
    pub span: Span,
    pub params: Vec<ExprSyntax>,
    /// For Green's control modules `@Switch(A B C)`, `@Pendulum(A B C)` and `@Repeat(k, A B)`:
    /// the members (each a module string). `@Repeat` has one member and its count in `params`.
    pub group: Option<Vec<Vec<ModuleSyntax>>>,
}

/// Which rule set a production belongs to (LANGUAGE.md section 3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Section {
    Productions,
    Homomorphism,
    Decomposition,
}

/// `label: left < predecessor > right : condition -> (weight) successor`.
#[derive(Clone, Debug, PartialEq)]
pub struct ProductionSyntax {
    pub label: Option<String>,
    pub section: Section,
    /// Left context, in written order; empty when absent or `*`.
    pub left: Vec<ModuleSyntax>,
    pub predecessor: ModuleSyntax,
    /// Right context, in written order, possibly with `[` `]`; empty when absent or `*`.
    pub right: Vec<ModuleSyntax>,
    pub condition: Option<ExprSyntax>,
    pub weight: Option<ExprSyntax>,
    /// Empty for `A -> ε`, `A -> *` and `A ->`.
    pub successor: Vec<ModuleSyntax>,
    /// The whole production line.
    pub span: Span,
}

/// Unary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    Neg,
    Not,
}

/// Binary operators, lowest precedence last.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    Pow,
    Mul,
    Div,
    Rem,
    Add,
    Sub,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
}

/// An arithmetic expression (LANGUAGE.md section 4).
///
/// Left-associative operators of one precedence level form a [`ExprSyntax::Chain`], not a tower of
/// nested binary nodes, so the tree's depth follows the nesting the text writes (parentheses,
/// operators of other levels), never the length of a sum: `1+1+…+1` with 100,000 terms is one
/// node with a long list, and nothing that walks the tree recurses 100,000 deep.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprSyntax {
    Number(f64, Span),
    Name(String, Span),
    Unary(UnaryOp, Box<ExprSyntax>, Span),
    /// `a ^ b` (right-associative, so its depth is bounded by the parser's nesting limit).
    Binary(BinaryOp, Box<ExprSyntax>, Box<ExprSyntax>, Span),
    /// `first op₁ x₁ op₂ x₂ …`, evaluated left to right: `((first op₁ x₁) op₂ x₂) …`. Each link's
    /// span runs from the start of `first` to the end of its operand (what a binary node's span
    /// would be).
    Chain(Box<ExprSyntax>, Vec<(BinaryOp, ExprSyntax, Span)>),
    /// `c ? a : b`
    Conditional(Box<ExprSyntax>, Box<ExprSyntax>, Box<ExprSyntax>, Span),
    /// `name(args)`: the name's span, then the whole call's span.
    Call(String, Span, Vec<ExprSyntax>, Span),
}

impl ExprSyntax {
    pub fn span(&self) -> Span {
        match self {
            ExprSyntax::Number(_, s)
            | ExprSyntax::Name(_, s)
            | ExprSyntax::Unary(_, _, s)
            | ExprSyntax::Binary(_, _, _, s)
            | ExprSyntax::Conditional(_, _, _, s)
            | ExprSyntax::Call(_, _, _, s) => s.clone(),
            ExprSyntax::Chain(first, links) => {
                links.last().map_or_else(|| first.span(), |l| l.2.clone())
            }
        }
    }
}

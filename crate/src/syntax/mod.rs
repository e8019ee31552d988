//! Stage 1, `syntax`: grammar text to a syntax tree with spans, plus diagnostics.
//!
//! The parser never gives up: it reads the file line by line, reports what it cannot read and goes
//! on at the next line, so the editor always gets every problem at once. Nothing here knows what a
//! module *means*; that is the resolve step's job (`model`).

mod ast;
mod brackets;
mod comments;
mod directive;
mod expr;
mod parse;
mod production;
mod scanner;

pub use ast::{
    BinaryOp, Directive, ExprSyntax, ModuleSyntax, ProductionSyntax, Section, SourceFile, Span,
    UnaryOp,
};
pub use brackets::{Brackets, ALL_BRACKETS, BRACES, PARENTHESES, PARENTHESES_AND_BRACES};
pub use comments::blank_comments;
pub use expr::{parse_expression, MAX_EXPRESSION_DEPTH};
pub use parse::parse;
pub use scanner::{MAX_GROUP_DEPTH, MAX_SCANNED_MODULES};

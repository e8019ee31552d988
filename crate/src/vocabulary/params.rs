//! Typed parameters: of modules (`F(l)`) and of directives (`#lifetime MB VB`).

use super::DirectiveKind;
use serde::{Serialize, Serializer};

/// What a parameter holds, and so how it is read and checked.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub enum ParamKind {
    /// A number, or a constant expression over `#define`d names (`360 / n`).
    Number,
    /// A whole number within the parameter's range.
    Whole,
    /// A number or an expression that may change from step to step (over `NumIt`, `MaxIt` and
    /// `#define`d names), drawing no random number.
    StepExpression,
    /// Any expression (a `#define`'s value, a `#random` distribution).
    Expression,
    /// One of the season names ([`super::Season`]).
    Season,
    /// A name being defined (`#define NAME …`).
    Name,
    /// A list of module names, without parameters.
    Modules,
    /// Numbers in pairs `x y` (the points of `#curve` and `#table`).
    Points,
    /// A module name and a number, in pairs (`#terminal_age a 2 b 1`).
    Ages,
    /// A surface's library shape and frame words with their numbers
    /// (`#surface p petal precision 8 8`; [`super::SURFACE_SHAPES`], [`super::FRAME_WORDS`]).
    Surface,
    /// Words with their numbers that the resolver reads by a table of its own: `#environment`'s
    /// program, shape and settings ([`super::ENVIRONMENT_PROGRAMS`]), `#stand`'s layout and
    /// settings ([`super::STAND_LAYOUTS`]).
    Words,
}

/// The value a parameter takes when it is not written.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParamDefault {
    Value(f64),
    /// The value of a directive (`F`'s length is `#step`).
    Directive(DirectiveKind),
}

impl Serialize for ParamDefault {
    /// A number, or the directive as written (`"#step"`).
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            ParamDefault::Value(v) => serializer.serialize_f64(*v),
            ParamDefault::Directive(d) => serializer.serialize_str(&format!("#{}", d.name())),
        }
    }
}

/// One parameter of a module or a directive.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Param {
    /// Its name in docs and in the studio's fields (`l`, `MB`, `latitude`).
    pub name: &'static str,
    pub kind: ParamKind,
    /// The value when it is not written; `None` when leaving it out means something else (the
    /// doc says what) or when it must be written.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub default: Option<ParamDefault>,
    /// The values it may take, inclusive.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub range: Option<(f64, f64)>,
    /// `degrees`, `steps`, … (empty for plain numbers).
    #[serde(skip_serializing_if = "str::is_empty")]
    pub unit: &'static str,
    /// A few plain words for the studio's field (`at least` for `MB`); empty: the name says it.
    #[serde(skip_serializing_if = "str::is_empty")]
    pub label: &'static str,
    /// What it is or does, in plain words (hover docs, the studio's field tooltips).
    pub doc: &'static str,
    /// For [`ParamKind::Season`]: the names it accepts.
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    pub choices: &'static [&'static str],
}

/// The vocabulary's texts for people (docs and labels), as the rows give them; empty in
/// `crate/pkg-core` (wasm32 without `studio-extras`), where nothing reads them: the studio reads
/// them from `vocabulary.json`, written from `crate/pkg` at build time (issue 22, the first load:
/// 11 KB of text). The row still compiles its text, which a build without it leaves out.
pub(crate) const fn text(text: &'static str) -> &'static str {
    if cfg!(any(feature = "studio-extras", not(target_arch = "wasm32"))) {
        text
    } else {
        ""
    }
}

impl Param {
    /// A parameter of `kind` with nothing else said.
    pub const fn new(name: &'static str, kind: ParamKind, doc: &'static str) -> Param {
        Param {
            name,
            kind,
            default: None,
            range: None,
            unit: "",
            label: "",
            doc: text(doc),
            choices: &[],
        }
    }

    /// A number (or constant expression).
    pub const fn number(name: &'static str, doc: &'static str) -> Param {
        Param::new(name, ParamKind::Number, doc)
    }

    /// A whole number from `min` to `max`.
    pub const fn whole(name: &'static str, min: f64, max: f64, doc: &'static str) -> Param {
        Param::new(name, ParamKind::Whole, doc).range(min, max)
    }

    pub const fn default(mut self, value: f64) -> Param {
        self.default = Some(ParamDefault::Value(value));
        self
    }

    /// Defaults to the value of `directive`.
    pub const fn default_from(mut self, directive: DirectiveKind) -> Param {
        self.default = Some(ParamDefault::Directive(directive));
        self
    }

    pub const fn range(mut self, min: f64, max: f64) -> Param {
        self.range = Some((min, max));
        self
    }

    pub const fn unit(mut self, unit: &'static str) -> Param {
        self.unit = unit;
        self
    }

    pub const fn label(mut self, label: &'static str) -> Param {
        self.label = text(label);
        self
    }

    pub const fn choices(mut self, choices: &'static [&'static str]) -> Param {
        self.choices = choices;
        self
    }

    /// The default as a number, reading a directive's value through `setting`.
    pub fn default_value(&self, setting: impl Fn(DirectiveKind) -> f64) -> Option<f64> {
        match self.default? {
            ParamDefault::Value(v) => Some(v),
            ParamDefault::Directive(d) => Some(setting(d)),
        }
    }
}

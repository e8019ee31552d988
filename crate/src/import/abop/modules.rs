//! Module strings (axioms, successors, patterns) in Meristem's notation: each module's name as
//! the dialect reads it, its parameters, and its meaning renamed where Meristem writes it with
//! another symbol.

use super::cpfg::cpfg_symbol;
use super::lpy::LPY_NAMES;
use super::{split_top, Env, Flavour, Importer};
use crate::syntax::PARENTHESES;
use crate::vocabulary::{module_named, name_of};

/// The module name at `chars[start]`, which is `@`, `~` or `?`: `@` and the letters after it
/// (or cpfg's one symbol, `@!`, `@#`), or `~` or `?` and one letter. Returns it and the index
/// after it.
pub(in crate::import::abop) fn symbol_name(chars: &[char], start: usize) -> (String, usize) {
    let mut i = start + 1;
    if chars[start] == '@' {
        while i < chars.len() && chars[i].is_ascii_alphabetic() {
            i += 1;
        }
        // cpfg's `@!`, `@#`: one symbol after the '@'.
        if i == start + 1 && i < chars.len() && !chars[i].is_whitespace() && chars[i] != '(' {
            i += 1;
        }
    } else if chars.get(i).is_some_and(char::is_ascii_alphabetic) {
        i += 1;
    }
    (chars[start..i].iter().collect(), i)
}

impl Importer {
    /// Translates a module string; modules are written without spaces. Long because it is one
    /// scanner over the successor's characters, each kind of character an arm of it.
    pub(in crate::import::abop) fn modules(
        &mut self,
        text: &str,
        env: &Env,
        n: usize,
    ) -> Result<String, String> {
        let chars: Vec<char> = text.chars().collect();
        let mut out = String::new();
        let mut i = 0;
        // cpfg draws a generalized cylinder through the points where the turtle puts its
        // control points (@Gc, @Ge), moved there by f as well as F: an f before them in the
        // same successor moves along the cylinder, which Meristem's smooth axis draws only
        // along segments.
        let cylinder_end = (self.flavour == Flavour::Cpfg)
            .then(|| {
                // dialect: cpfg's control point and end of a generalized cylinder.
                ["@Gc", "@Ge"]
                    .iter()
                    .filter_map(|g| text.rfind(g))
                    .max()
                    .map(|b| text[..b].chars().count())
            })
            .flatten();
        while i < chars.len() {
            let c = chars[i];
            if c.is_whitespace() {
                i += 1;
                continue;
            }
            // cpfg's `=` in a right context skips the rest of the branch up to its `]`
            // (`[I(b)=]`): what Meristem's `]` in a pattern does.
            if c == '='
                && self.flavour == Flavour::Cpfg
                && chars[i + 1..].iter().find(|c| !c.is_whitespace()) == Some(&']')
            {
                i += 1;
                continue;
            }
            let (name, after) =
                if (c == '@' || c == '~' || c == '?') && self.flavour == Flavour::Cpfg {
                    cpfg_symbol(&chars, i)
                } else if (c == '@' || c == '~' || c == '?') && self.flavour == Flavour::Lpy {
                    super::lpy::lpy_symbol_name(&chars, i)
                } else if c == '@' || c == '~' || c == '?' {
                    symbol_name(&chars, i)
                } else if c.is_ascii_alphabetic() && self.flavour == Flavour::Lpy {
                    self.lpy_name(&chars, i, n)
                } else if let Some((word, name)) = self
                    .cpfg
                    .words
                    .iter()
                    .find(|(w, _)| chars[i..].iter().take(w.len()).copied().eq(w.chars()))
                {
                    (name.clone(), i + word.len())
                } else {
                    (c.to_string(), i + 1)
                };
            let name = if name == "f" && cylinder_end.is_some_and(|end| i < end) {
                self.note_once(
                    "f@G",
                    n,
                    "cpfg's f before a control point of a generalized cylinder moves along the cylinder cpfg draws; Meristem's smooth axis follows segments only, so it becomes F",
                );
                "F".to_string()
            } else {
                name
            };
            i = after;
            // Parameters.
            let mut j = i;
            while j < chars.len() && chars[j] == ' ' {
                j += 1;
            }
            let mut params = Vec::new();
            let mut has_params = false;
            if chars.get(j) == Some(&'(') {
                let close = PARENTHESES
                    .closing_char(&chars, j)
                    .ok_or("a '(' is never closed")?;
                let inner: String = chars[j + 1..close].iter().collect();
                if name == "@L" {
                    // A text label (`@L("%.f", c)`): Meristem draws no text.
                    let tool = self.flavour.tool();
                    self.note_once(
                        "@L",
                        n,
                        format!("{tool}'s @L draws a text label; Meristem draws no text, so the label is dropped"),
                    );
                    i = close + 1;
                    continue;
                }
                has_params = true;
                for arg in split_top(&inner, ',') {
                    params.push(self.expression(arg, env)?);
                }
                i = close + 1;
            }
            self.cpfg_module_notes(&name, n);
            out.push_str(&self.module(&name, params, has_params, n));
        }
        Ok(out)
    }

    /// One module with its parameters, renamed where the dialect's meaning is Meristem's other
    /// symbol.
    pub(in crate::import::abop) fn module(
        &mut self,
        name: &str,
        params: Vec<String>,
        has_params: bool,
        n: usize,
    ) -> String {
        let with = |m: &str, p: &[String]| {
            if p.is_empty() {
                m.to_string()
            } else {
                format!("{m}({})", p.join(","))
            }
        };
        let tool = self.flavour.tool();
        let width = match self.flavour {
            Flavour::Cpfg => "#",
            Flavour::Lpy => "_",
        };
        if name == width {
            if has_params {
                return with("!", &params);
            }
            self.note_once(
                "width+",
                n,
                format!("{tool}'s '{width}' without a value widens by the width increment; Meristem has no such command; dropped"),
            );
            return String::new();
        }
        if let Some(text) = self.view_module(name, &params, has_params, n) {
            return text;
        }
        if self.flavour == Flavour::Lpy {
            if let Some(text) = self.lpy_world_module(name, &params, n) {
                return text;
            }
        }
        if name == "," {
            return if has_params {
                with(";", &params)
            } else {
                "'(-1)".into()
            };
        }
        if let Some(&(_, meaning)) = LPY_NAMES.iter().find(|(l, _)| *l == name) {
            return with(name_of(meaning), &params);
        }
        if name.starts_with('@') && module_named(name).is_none() {
            if !name[1..].chars().all(|c| c.is_ascii_alphabetic()) || name.len() == 1 {
                self.note_once(
                    name,
                    n,
                    format!("{tool}'s {name} is not a Meristem command; dropped"),
                );
                return String::new();
            }
            self.note_once(
                name,
                n,
                format!("{tool}'s {name} is not a Meristem command; kept as a module the turtle ignores"),
            );
        }
        if name.starts_with('~') && module_named(name).is_none() && !self.view_declares(name) {
            self.note_once(
                name,
                n,
                format!("{name} names a surface the object's view file does not give (or whose file was not read): kept, and it draws nothing"),
            );
        }
        if name.chars().count() > 1
            && name.chars().all(|c| c.is_ascii_alphanumeric())
            && !self.declared.iter().any(|d| d == name)
        {
            self.declared.push(name.to_string());
        }
        with(name, &params)
    }
}

impl Importer {
    /// True when the object's view file declares the surface `~X` that `name` draws (its
    /// `surface: X file.s` line was read).
    fn view_declares(&self, name: &str) -> bool {
        self.cpfg.view.as_ref().is_some_and(|v| {
            v.surface_letters
                .iter()
                .any(|letter| name.strip_prefix('~') == Some(letter.as_str()))
        })
    }
}

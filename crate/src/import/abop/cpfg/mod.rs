//! What only cpfg writes: the C preprocessor ([`cpp`]), its lines joined ([`joins`]), statement
//! blocks ([`blocks`]), global variables and `Start:` blocks ([`globals`]), the vlab object's
//! view ([`view`]) and functions ([`functions`]: `func`, lpfg's `tfunc` and `val`), predecessors of several modules ([`predecessors`]), `#define` lines and its
//! `@`/`~`/`?` names.

pub(super) mod blocks;
mod circles;
pub(super) mod cpp;
pub(super) mod draws;
mod functions;
pub(super) mod globals;
pub(super) mod joins;
pub(super) mod loops;
mod predecessors;
#[cfg(test)]
mod tests;
mod view;

use super::modules::symbol_name;
use super::{is_identifier, Env, Flavour, Importer, Line};
use crate::vocabulary::DirectiveKind;

/// The functions a cpfg `#define` value may call and stay a number expression: Meristem's and
/// cpfg's own.
pub(in crate::import::abop) fn cpp_functions() -> Vec<String> {
    crate::vocabulary::FUNCTIONS
        .iter()
        .map(|f| f.name.to_string())
        .chain(
            [
                "func", "tfunc", "val", "ran", "nran", "bran", "biran", "trunc", "fabs", "curveX",
                "curveY", "curveZ", "curveGAL", "pow",
            ]
            .iter()
            .map(|s| s.to_string()),
        )
        .collect()
}

/// cpfg's `@`, `~` or `?` name at `chars[start]`, as [`symbol_name`] reads it, except that
/// cpfg's names of the generalized cylinder and texture (`@Gs`, `@Ge`, `@Gc`, `@Gt`, `@Gr`,
/// `@Tx`, `@Tf`) end after their two letters (`@GsF` is `@Gs` then `F`).
pub(in crate::import::abop) fn cpfg_symbol(chars: &[char], start: usize) -> (String, usize) {
    let (name, end) = symbol_name(chars, start);
    // dialect: cpfg's names
    for short in ["@Gs", "@Ge", "@Gc", "@Gt", "@Gr", "@Tx", "@Tf"] {
        if name.len() > short.len() && name.starts_with(short) {
            return (short.to_string(), start + short.len());
        }
    }
    (name, end)
}

impl Importer {
    /// cpfg's preprocessor lines: `#define NAME value` becomes Meristem's `#define`.
    pub(in crate::import::abop) fn preprocessor(&mut self, line: &Line) {
        let code = line.code.trim_start_matches('#').trim_start();
        if let Some(rest) = code.strip_prefix("define") {
            let rest = rest.trim();
            let name_end = rest
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(rest.len());
            let (name, value) = (&rest[..name_end], rest[name_end..].trim());
            if value.starts_with('(') && rest[name_end..].starts_with('(') {
                self.note(
                    line.n,
                    format!("#define {name}(…): macros with arguments are not translated"),
                );
                return;
            }
            if !is_identifier(name) || value.is_empty() {
                self.note(line.n, format!("'#{code}' defines no value; skipped"));
                return;
            }
            match self.expression(value, &Env::new()) {
                Ok(e) => self.out.line(
                    format!("{} {name} {e}", DirectiveKind::Define.written()),
                    line.n,
                ),
                Err(why) => self.note(line.n, format!("#define {name}: {why}")),
            }
            return;
        }
        let word = code.split_whitespace().next().unwrap_or("");
        self.note(
            line.n,
            format!("the C preprocessor's #{word} is not translated; the line is skipped"),
        );
    }

    /// The notes for cpfg's `?E` and `_`, which are kept as modules the turtle ignores.
    pub(in crate::import::abop) fn cpfg_module_notes(&mut self, name: &str, n: usize) {
        use crate::vocabulary::{name_of, Command, Meaning};
        let communication = name_of(Meaning::Turtle(Command::QueryEnvironment));
        if name == communication && self.flavour == Flavour::Cpfg {
            if let Some(note) = self.communication_note() {
                self.note_once(name, n, note);
            }
        }
        if name == "_" && self.flavour == Flavour::Cpfg {
            self.note_once(
                name,
                n,
                "cpfg's _ is not a Meristem command; kept as a module the turtle ignores",
            );
        }
    }
}

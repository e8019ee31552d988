//! The file read as lines: comments split off (cpfg's `/* … */` and `//`, L-Py's `#`), then
//! each dialect's preparation (cpfg's preprocessor and joined lines, L-Py's declarations).

use super::cpfg::{cpp, cpp_functions, globals, joins::*};
use super::lpfg::is_lpfg;
use super::lpy::{flags, globals::write_only_globals, python_string_line};
use super::{is_identifier, Flavour, Importer, Line};

/// Splits the text into lines without comments: cpfg's `/* … */` and `//`, L-Py's `#`.
pub(in crate::import::abop) fn lines(text: &str, flavour: Flavour) -> Vec<Line> {
    let mut result = Vec::new();
    let mut in_block = false;
    // L-Py: the triple quote of a Python string that runs over several lines.
    let mut in_string: Option<&str> = None;
    for (index, raw) in text.lines().enumerate() {
        if flavour == Flavour::Lpy {
            if let Some(line) = python_string_line(raw, &mut in_string) {
                result.push(Line {
                    n: index + 1,
                    ..line
                });
                continue;
            }
        }
        let mut code = String::new();
        let mut comment = String::new();
        let chars: Vec<char> = raw.chars().collect();
        let mut i = 0;
        let mut quote: Option<char> = None;
        while i < chars.len() {
            let c = chars[i];
            if in_block {
                if c == '*' && chars.get(i + 1) == Some(&'/') {
                    in_block = false;
                    i += 2;
                    comment.push(' ');
                    continue;
                }
                comment.push(c);
                i += 1;
                continue;
            }
            if let Some(q) = quote {
                code.push(c);
                if c == q {
                    quote = None;
                }
                i += 1;
                continue;
            }
            match flavour {
                Flavour::Cpfg => {
                    if c == '/' && chars.get(i + 1) == Some(&'*') {
                        in_block = true;
                        i += 2;
                        continue;
                    }
                    if c == '/' && chars.get(i + 1) == Some(&'/') {
                        comment.extend(&chars[i + 2..]);
                        break;
                    }
                }
                Flavour::Lpy => {
                    if c == '\'' || c == '"' {
                        quote = Some(c);
                    } else if c == '#' {
                        comment.extend(&chars[i + 1..]);
                        break;
                    }
                }
            }
            code.push(c);
            i += 1;
        }
        let indent = code.chars().take_while(|c| c.is_whitespace()).count();
        result.push(Line {
            n: index + 1,
            code: code.trim().to_string(),
            comment: comment.trim().to_string(),
            indent,
        });
    }
    result
}

impl Importer {
    /// The file's lines ready to translate: comments split off, cpfg's preprocessor run, blocks
    /// and productions over several lines joined, globals and L-Py's module declarations read.
    pub(in crate::import::abop) fn prepare(
        &mut self,
        text: &str,
        include: &dyn Fn(&str) -> Option<String>,
    ) -> Vec<Line> {
        let mut all = lines(text, self.flavour);
        if self.flavour == Flavour::Cpfg {
            let functions = cpp_functions();
            let names: Vec<&str> = functions.iter().map(String::as_str).collect();
            let mut pre = cpp::Preprocessor::new(include, &names);
            all = pre.run(all, 0);
            self.lpfg.constants = pre.constants();
            for (n, message) in pre.notes {
                self.note(n, message);
            }
            all = join_blocks(all, self.flavour);
            if is_lpfg(&all) {
                all = self.lpfg_lines(all);
            }
            all = join_axiom_lines(join_two_line_productions(all));
            if !self.lpfg.active {
                self.cpfg.default_depth = sections_without_depth(&all);
            }
            self.cpfg.globals = globals::Globals::scan(&all);
            self.cpfg.has_decomposition = all.iter().any(|l| {
                super::statements::section(&l.code.to_lowercase()).as_deref()
                    == Some(
                        crate::vocabulary::KeywordKind::Decomposition
                            .written()
                            .as_str(),
                    )
            });
            self.words(&all);
        }
        // L-Py's `module` declarations change how strings split into modules: read them first.
        if self.flavour == Flavour::Lpy {
            self.lpy.write_only = write_only_globals(&all);
            self.lpy.flags = flags::candidates(&all);
            for line in &all {
                if let Some(rest) = line.code.strip_prefix("module ") {
                    for item in rest.split(',') {
                        let name = item.split('(').next().unwrap_or("").trim();
                        if is_identifier(name) && name.len() > 1 {
                            self.declared.push(name.to_string());
                        }
                    }
                }
            }
        }
        all
    }
}

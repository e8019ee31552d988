//! cpfg's predecessors of several modules, which Meristem writes as one: several letters
//! (`AXIOM`) become one declared module, several modules (`F(v,n)#(w)`) one production each
//! with the others as context.

use super::super::{arrow, top_level, Flavour, Importer, Line};
use super::cpfg_symbol;
use crate::syntax::PARENTHESES;

/// Most modules of a cpfg predecessor translated as contexts (each module becomes a production
/// with the others as its context, so k modules give k productions of k modules each).
const MAX_PREDECESSOR_MODULES: usize = 64;

impl Importer {
    /// The tool whose predecessor a note speaks of: lpfg's files are read as cpfg's.
    fn predecessor_tool(&self) -> &'static str {
        if self.lpfg.active {
            "lpfg"
        } else {
            "cpfg"
        }
    }

    /// cpfg's predecessors made of several modules that are letters without parameters
    /// (`AXIOM : c --> …`, five modules A X I O M): Meristem's predecessor is one module, so the
    /// letters written together become one declared module, with a note at the first
    /// production.
    pub(in crate::import::abop) fn words(&mut self, all: &[Line]) {
        for line in all {
            let Some((arrow_at, _)) = arrow(&line.code) else {
                continue;
            };
            let left = &line.code[..arrow_at];
            let left = top_level(left, ":").map_or(left, |i| &left[..i]);
            if top_level(left, "<").is_some() || top_level(left, ">").is_some() {
                self.cpfg.other_contexts = true;
            }
            let strict = top_level(left, "<").map_or(left, |i| &left[i + 1..]);
            let strict = top_level(strict, ">")
                .map_or(strict, |i| &strict[..i])
                .trim();
            if strict.len() < 2
                || strict.len() > 32
                || !strict.chars().all(|c| c.is_ascii_alphabetic())
                || self.cpfg.words.iter().any(|(w, _)| w == strict)
            {
                continue;
            }
            // Meristem reads a line that starts with `axiom :` as its axiom.
            let name = if strict.eq_ignore_ascii_case("axiom") {
                format!("{strict}_")
            } else {
                strict.to_string()
            };
            let letters: Vec<String> = strict.chars().map(String::from).collect();
            let tool = self.predecessor_tool();
            self.note(
                line.n,
                format!(
                    "{tool}'s predecessor {strict} is {} modules ({}); Meristem's predecessor is one module, so {strict} written together (here, in the axiom and in successors) becomes one module {name} (#module): where no production for it applies, cpfg would rewrite the letters one by one, Meristem keeps it whole",
                    letters.len(),
                    letters.join(" ")
                ),
            );
            self.declared.push(name.clone());
            self.cpfg.words.push((strict.to_string(), name));
        }
        self.cpfg
            .words
            .sort_by_key(|w| std::cmp::Reverse(w.0.len()));
    }

    /// cpfg's predecessor of several modules (`F(v,n)#(w) --> F(v)#(w)@O`): Meristem's
    /// predecessor is one module, so it becomes one production per module, each with the others
    /// as context: the first gives the successor, the others erase their module (`F(v,n) >
    /// #(w) -> F(v)#(w)@O` and `F(v,n) < #(w) -> ε`), with a note. `None` when the predecessor
    /// is one module, or when the production draws a random number (its probability or a random
    /// condition would be drawn apart for each module).
    pub(in crate::import::abop) fn several_modules(
        &mut self,
        left: &str,
        right: &str,
        n: usize,
    ) -> Option<Vec<(String, String)>> {
        if self.flavour != Flavour::Cpfg {
            return None;
        }
        let (pattern, guard) = match top_level(left, ":") {
            Some(i) => (left[..i].trim(), Some(left[i + 1..].trim())),
            None => (left, None),
        };
        // The new contexts `<<`, `>>` are read with the pattern (see `new_contexts`).
        if pattern.contains("<<") || pattern.contains(">>") {
            return None;
        }
        let (before, rest) = match top_level(pattern, "<") {
            Some(i) => (pattern[..i].trim(), &pattern[i + 1..]),
            None => ("", pattern),
        };
        let (strict, after) = match top_level(rest, ">") {
            Some(i) => (rest[..i].trim(), rest[i + 1..].trim()),
            None => (rest.trim(), ""),
        };
        let modules = self.source_modules(strict)?;
        if modules.len() < 2
            || top_level(right, ":").is_some()
            || ["ran(", "nran("].iter().any(|r| left.contains(r))
        {
            return None;
        }
        if modules.len() > MAX_PREDECESSOR_MODULES {
            // Each module would become a production with all the others as its context: k
            // productions of k modules each (issue 50, 4: a macro bomb's 6,000-module
            // predecessor made 36 MB of text).
            let tool = self.predecessor_tool();
            self.note(
                n,
                format!(
                    "{tool}'s predecessor here is {} modules, more than the {MAX_PREDECESSOR_MODULES} \
                     Meristem translates (each becomes a production with all the others as its \
                     context); the production is left out",
                    modules.len()
                ),
            );
            return Some(Vec::new());
        }
        let before = if before == "*" { "" } else { before };
        let after = if after == "*" { "" } else { after };
        let tool = self.predecessor_tool();
        self.note(
            n,
            format!(
                "{tool}'s predecessor {strict} is {} modules; Meristem's predecessor is one module, so it becomes a production for {} with the others as its context and one for each other module that erases it there: the same unless two matches overlap or modules cpfg ignores stand between them",
                modules.len(),
                modules[0]
            ),
        );
        self.match_predecessor_modules(&modules, n);
        let parts = (0..modules.len())
            .map(|i| {
                let lc = format!("{before}{}", modules[..i].concat());
                let rc = format!("{}{after}", modules[i + 1..].concat());
                let mut head = String::new();
                if !lc.trim().is_empty() {
                    head.push_str(&format!("{lc} < "));
                }
                head.push_str(&modules[i]);
                if !rc.trim().is_empty() {
                    head.push_str(&format!(" > {rc}"));
                }
                if let Some(g) = guard {
                    head.push_str(&format!(" : {g}"));
                }
                let successor = if i == 0 {
                    right.to_string()
                } else {
                    "*".to_string()
                };
                (head, successor)
            })
            .collect();
        Some(parts)
    }

    /// A predecessor of several modules becomes contexts, which `consider:` and `ignore:` act
    /// on while cpfg's predecessor is matched whole: its modules are added to the `#consider`
    /// line (taken off the `#ignore` line), with a note, when no production has contexts of its
    /// own.
    fn match_predecessor_modules(&mut self, modules: &[String], n: usize) {
        let Some((index, directive, mut names)) = self.cpfg.context_list.clone() else {
            return;
        };
        // Another production's contexts would see the modules added too (the pipe model of
        // 02-Borchert-Slade would no longer find its `!`): then the list stays as it is.
        if self.cpfg.other_contexts {
            return;
        }
        let consider = directive == crate::vocabulary::DirectiveKind::Consider.written();
        let mut changed = Vec::new();
        for m in modules {
            let name = m.split('(').next().unwrap_or("").trim().to_string();
            let listed = names.contains(&name);
            if consider && !listed {
                names.push(name.clone());
                changed.push(name);
            } else if !consider && listed {
                names.retain(|x| *x != name);
                changed.push(name);
            }
        }
        if changed.is_empty() {
            return;
        }
        let line = if names.is_empty() {
            String::new()
        } else {
            format!("{directive} {}", names.join(" "))
        };
        self.out.replace(index, line);
        self.cpfg.context_list = Some((index, directive.clone(), names));
        let how = if consider { "added to" } else { "taken off" };
        self.note(
            n,
            format!(
                "the modules of this predecessor ({}) are {how} {directive}, so that the contexts it becomes match them as cpfg matches its predecessor; other productions' contexts see them too",
                changed.join(" ")
            ),
        );
    }

    /// The modules of a cpfg module string as written (`F(v,n)#(w)` → `F(v,n)`, `#(w)`); `None`
    /// when it holds a bracket or a parenthesis that is never closed.
    pub(in crate::import::abop) fn source_modules(&self, text: &str) -> Option<Vec<String>> {
        let chars: Vec<char> = text.chars().collect();
        let mut out = Vec::new();
        let mut i = 0;
        while i < chars.len() {
            let c = chars[i];
            if c.is_whitespace() {
                i += 1;
                continue;
            }
            if "[]{}<>".contains(c) {
                return None;
            }
            let start = i;
            i = if c == '@' || c == '~' || c == '?' {
                cpfg_symbol(&chars, i).1
            } else if let Some((word, _)) = self
                .cpfg
                .words
                .iter()
                .find(|(w, _)| chars[i..].iter().take(w.len()).copied().eq(w.chars()))
            {
                i + word.chars().count()
            } else {
                i + 1
            };
            let mut j = i;
            while chars.get(j) == Some(&' ') {
                j += 1;
            }
            if chars.get(j) == Some(&'(') {
                i = PARENTHESES.closing_char(&chars, j)? + 1;
            }
            out.push(
                chars[start..i]
                    .iter()
                    .collect::<String>()
                    .trim()
                    .to_string(),
            );
        }
        Some(out)
    }
}

//! The statements of an L-system, one at a time: the keywords (`Axiom:`, `derivation length:`,
//! `ignore:`, sections, `endlsystem`), productions over one or several lines, and what each
//! dialect adds (cpfg's preprocessor lines, lpfg's C blocks, L-Py's Python).

use super::lpfg::lpfg_production_parts;
use super::{arrow, module_names, separate, Env, Flavour, Importer, Line};
use crate::vocabulary::{DirectiveKind, KeywordKind};

/// `derivation length: 5` -> `Some(" 5")` (case-insensitive keyword).
pub(in crate::import::abop) fn keyword<'a>(
    lower: &str,
    code: &'a str,
    keyword: &str,
) -> Option<&'a str> {
    let compact: String = lower.chars().filter(|c| !c.is_whitespace()).collect();
    let key: String = keyword.chars().filter(|c| !c.is_whitespace()).collect();
    if !compact.starts_with(&key) {
        return None;
    }
    let colon = code.find(':')?;
    Some(&code[colon + 1..])
}

/// The section a line starts, in Meristem's words.
pub(in crate::import::abop) fn section(lower: &str) -> Option<String> {
    let word = lower.split(':').next().unwrap_or("").trim();
    let rest_ok = |w: &str| {
        let after = lower[w.len()..].trim_start_matches(':').trim();
        after.is_empty() || after == "no warnings"
    };
    match word {
        // cpfg's and L-Py's section words, and Meristem's section each starts.
        "homomorphism" if rest_ok("homomorphism") => Some(KeywordKind::Homomorphism),
        "interpretation" if rest_ok("interpretation") => Some(KeywordKind::Homomorphism),
        "decomposition" if rest_ok("decomposition") => Some(KeywordKind::Decomposition),
        "production" if rest_ok("production") => Some(KeywordKind::Productions),
        "productions" if rest_ok("productions") => Some(KeywordKind::Productions),
        _ => None,
    }
    .map(KeywordKind::written)
}

impl Importer {
    pub(in crate::import::abop) fn run(
        &mut self,
        text: &str,
        include: &dyn Fn(&str) -> Option<String>,
    ) {
        let all = self.prepare(text, include);
        self.out.comment(
            &format!("Imported from {} by meristem import.", self.flavour.tool()),
            0,
        );
        let module_line = self.out.len();
        self.out.line("", 0);
        self.view_lines();
        let mut ended = false;
        let mut i = 0;
        while i < all.len() {
            let line = all[i].clone();
            i += 1;
            if line.code.is_empty() {
                if !line.comment.is_empty() {
                    self.out.comment(&line.comment, line.n);
                }
                continue;
            }
            // The lines of a block: those indented more than its header.
            let block_end = {
                let mut j = i;
                while j < all.len() && (all[j].code.is_empty() || all[j].indent > line.indent) {
                    j += 1;
                }
                j
            };
            let before = self.out.len();
            i = self.statement(&line, &all, i, block_end, &mut ended);
            // A comment after code stays after its translation.
            if !line.comment.is_empty() {
                if self.out.len() > before && !self.out.last().starts_with("//") {
                    let last = self.out.len() - 1;
                    let text = format!(
                        "{} // {}",
                        self.out.last(),
                        crate::import::defuse_comment(&line.comment)
                    );
                    self.out.replace(last, text);
                } else {
                    self.out.comment(&line.comment, line.n);
                }
            }
        }
        if !ended {
            let last = all.last().map_or(0, |l| l.n);
            self.staged_lines(last);
        }
        if !self.declared.is_empty() {
            self.out.replace(
                module_line,
                format!(
                    "{} {}",
                    DirectiveKind::Module.written(),
                    self.declared.join(" ")
                ),
            );
        }
        if !self.axiom {
            self.note(0, "no Axiom: line");
        }
        self.unknown_view();
        // Last: the lines move those after them down.
        self.function_lines();
    }

    /// Translates one statement (a line, or a production with the lines it takes); returns the
    /// index of the next line to read.
    pub(in crate::import::abop) fn statement(
        &mut self,
        line: &Line,
        all: &[Line],
        i: usize,
        block_end: usize,
        ended: &mut bool,
    ) -> usize {
        let code = line.code.as_str();
        if *ended {
            if self.flavour == Flavour::Lpy {
                return self.python(line, &all[i..block_end], block_end, i);
            }
            self.note_once(
                "after",
                line.n,
                "text after endlsystem (another L-system of the file) is not translated",
            );
            return i;
        }
        if self.flavour == Flavour::Cpfg && code.starts_with('#') {
            self.preprocessor(line);
            return i;
        }
        if self.keyword_statement(line, ended) {
            return i;
        }
        if self.lpfg.active {
            if let Some((pattern, body)) = lpfg_production_parts(code) {
                self.lpfg_production(pattern, body, line.n);
                return i;
            }
        }
        if arrow(code).is_some() {
            return self.production_lines(line, all, i);
        }
        if self.flavour == Flavour::Lpy {
            return self.python_statement(line, all, i, block_end);
        }
        self.note(
            line.n,
            format!("'{code}' is not part of the notation Meristem imports; skipped"),
        );
        i
    }

    /// Translates a line that starts with a keyword of the notation (`Axiom:`, `derivation
    /// length:`, `ignore:`, a section's name, `endlsystem` …) or that means nothing to Meristem
    /// (`lsystem:`, production groups, L-Py's `module` declarations, read before). Returns
    /// whether the line was one; sets `ended` at `endlsystem`.
    pub(in crate::import::abop) fn keyword_statement(
        &mut self,
        line: &Line,
        ended: &mut bool,
    ) -> bool {
        let code = line.code.as_str();
        let lower = code.to_ascii_lowercase();
        if keyword(&lower, code, "lsystem:").is_some() {
            return true;
        }
        if self.flavour == Flavour::Cpfg && self.global_block(code, line.n) {
            return true;
        }
        // dialect: cpfg's keyword
        if let Some(rest) = keyword(&lower, code, "derivation length:") {
            match self.expression(rest, &Env::new()) {
                Ok(e) => self.out.line(
                    format!("{} {e}", KeywordKind::DerivationLength.written()),
                    line.n,
                ),
                Err(why) => self.note(line.n, format!("derivation length: {why}")),
            }
            return true;
        }
        // dialect: cpfg's keyword (the random generator's seed)
        if let Some(rest) = keyword(&lower, code, "seed:") {
            match self.expression(rest, &Env::new()) {
                Ok(e) => self
                    .out
                    .line(format!("{} {e}", DirectiveKind::Seed.written()), line.n),
                Err(why) => self.note(line.n, format!("seed: {why}")),
            }
            return true;
        }
        // dialect: cpfg's keyword
        // dialect: cpfg's keyword (`AXIOM : c --> …` is a production for a module AXIOM)
        if let Some(rest) = keyword(&lower, code, "axiom:").filter(|_| arrow(code).is_none()) {
            self.axiom(rest, line.n);
            return true;
        }
        let lists = [
            ("ignore:", DirectiveKind::Ignore.written()),
            ("consider:", DirectiveKind::Consider.written()),
        ];
        if let Some((kw, directive)) = lists.iter().find(|(k, _)| lower.starts_with(k)) {
            self.module_list(kw, directive, &code[kw.len()..], line.n);
            return true;
        }
        // dialect: cpfg's keyword
        if let Some(rest) = keyword(&lower, code, "maximum depth:") {
            self.maximum_depth(rest.trim(), line.n);
            return true;
        }
        if let Some(section) = section(&lower) {
            self.in_productions = section == KeywordKind::Productions.written();
            self.cpfg.depth_line = None;
            self.out.line(section.clone(), line.n);
            // cpfg rewrites its homomorphism and decomposition to depth 1 unless the section
            // says `maximum depth:` (its parser's default); Meristem's default is deeper.
            if self.cpfg.default_depth.contains(&line.n) {
                self.out
                    .line(format!("{} 1", KeywordKind::MaximumDepth.written()), line.n);
            }
            return true;
        }
        let end = KeywordKind::EndLSystem.written();
        if lower == end {
            self.staged_lines(line.n);
            self.out.line(end, line.n);
            *ended = true;
            return true;
        }
        if lower.starts_with("group") || lower == "endgroup" {
            self.note_once(
                "group",
                line.n,
                "L-Py's production groups are not translated: every group's productions are imported as one set",
            );
            return true;
        }
        self.flavour == Flavour::Lpy && code.starts_with("module ")
    }

    /// `maximum depth: n` of the section being read (a loop may raise it: `cpfg/loops.rs`).
    fn maximum_depth(&mut self, value: &str, n: usize) {
        self.cpfg.depth_line = Some((self.out.len(), value.to_string()));
        self.out.line(
            format!("{} {value}", KeywordKind::MaximumDepth.written()),
            n,
        );
    }

    /// `Axiom: modules` (the text after the colon is `rest`).
    pub(in crate::import::abop) fn axiom(&mut self, rest: &str, n: usize) {
        let lpfg;
        let rest = if self.lpfg.active {
            match self.lpfg_symbols(rest, n) {
                Ok(text) => {
                    lpfg = text;
                    lpfg.as_str()
                }
                Err(why) => {
                    self.note(n, format!("the axiom: {why}"));
                    return;
                }
            }
        } else {
            rest
        };
        match self.modules(rest, &Env::new(), n) {
            Ok(m) => {
                self.axiom = true;
                let m = format!("{}{m}", self.initial_colour());
                self.out.line(
                    format!("{} {}", KeywordKind::Axiom.written(), separate(&m)),
                    n,
                );
            }
            Err(why) => self.note(n, format!("the axiom: {why}")),
        }
    }

    /// `ignore: modules` or `consider: modules` (the keyword `kw`, then `rest`) as Meristem's
    /// `directive` with the modules' names.
    pub(in crate::import::abop) fn module_list(
        &mut self,
        kw: &str,
        directive: &str,
        rest: &str,
        n: usize,
    ) {
        // The names listed draw nothing: a `+` here is no turn by the view's angle.
        let (bare_turn, colour) = (self.cpfg.bare_turn, self.cpfg.colour);
        let modules = self.modules(rest, &Env::new(), n);
        (self.cpfg.bare_turn, self.cpfg.colour) = (bare_turn, colour);
        match modules {
            Ok(m) => {
                let names = module_names(&m);
                if !names.is_empty() {
                    self.cpfg.context_list =
                        Some((self.out.len(), directive.to_string(), names.clone()));
                    self.out.line(format!("{directive} {}", names.join(" ")), n);
                }
            }
            Err(why) => self.note(n, format!("{kw} {why}")),
        }
    }

    /// A production starting at `line`, which may go on on the lines after it from `i` (cpfg
    /// writes long successors so: lines indented more that have no arrow). Returns the index of
    /// the next line to read.
    pub(in crate::import::abop) fn production_lines(
        &mut self,
        line: &Line,
        all: &[Line],
        mut i: usize,
    ) -> usize {
        let mut text = line.code.clone();
        while i < all.len()
            && !all[i].code.is_empty()
            && all[i].indent > line.indent
            && arrow(&all[i].code).is_none()
        {
            text.push(' ');
            text.push_str(&all[i].code);
            i += 1;
        }
        self.production(&text, line.n);
        i
    }
}

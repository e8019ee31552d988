//! One production `lc < pred > rc : {pre} cond {post} --> succ : probability` in Meristem's
//! notation: its guard (statement blocks and condition), its pattern (contexts, new contexts) and
//! its successor.

use super::lpy::literal_parameters;
use super::{arrow, separate, top_level, Env, Flavour, Importer};
use crate::syntax::PARENTHESES_AND_BRACES;

impl Importer {
    /// `pred : {pre} cond {post} --> succ : probability` in Meristem's notation.
    pub(in crate::import::abop) fn production(&mut self, code: &str, n: usize) {
        let Some((start, end)) = arrow(code) else {
            return;
        };
        let (left, right) = (code[..start].trim(), code[end..].trim());
        if let Some(parts) = self.several_modules(left, right, n) {
            let mut texts = Vec::new();
            for (left, right) in parts {
                match self.production_text(&left, &right, n) {
                    Ok(text) => texts.push(text),
                    Err(why) => {
                        self.note(n, format!("{why}; the production is skipped"));
                        return;
                    }
                }
            }
            for text in texts {
                self.out.line(text, n);
            }
            return;
        }
        match self.production_text(left, right, n) {
            Ok(text) => {
                self.out.line(text, n);
                for line in std::mem::take(&mut self.cpfg.after) {
                    self.out.line(line, n);
                }
            }
            Err(why) => {
                self.cpfg.after.clear();
                self.note(n, format!("{why}; the production is skipped"))
            }
        }
    }

    /// The Meristem production of `left --> right`, or why it has none.
    pub(in crate::import::abop) fn production_text(
        &mut self,
        left: &str,
        right: &str,
        n: usize,
    ) -> Result<String, String> {
        let (pattern, guard) = match top_level(left, ":") {
            Some(i) => (left[..i].trim(), left[i + 1..].trim()),
            None => (left, ""),
        };
        let (pattern, literals) = match self.flavour {
            Flavour::Lpy => literal_parameters(pattern),
            Flavour::Cpfg => (pattern.to_string(), Vec::new()),
        };
        let pattern = pattern.as_str();
        // cpfg's loops (see `cpfg/loops.rs`).
        if let Some(text) = self.loop_production(pattern, guard, right, n)? {
            return Ok(text);
        }
        // cpfg's block variables that draw random numbers (see `cpfg/draws.rs`).
        if self.may_stage_draws() {
            self.cpfg.draws = Some(Default::default());
            let guarded = self.guard(guard, n);
            let draws = self.cpfg.draws.take().unwrap_or_default();
            if !draws.values.is_empty() && !draws.tangled {
                let (env, condition) = guarded?;
                let (right, weight) = self.weight(right, &env)?;
                let successor = if right.is_empty() || right == "*" {
                    String::new()
                } else {
                    self.modules(right, &env, n)?
                };
                let staged = self.staged(
                    pattern,
                    condition.as_deref(),
                    weight.as_deref(),
                    &successor,
                    &draws,
                )?;
                if let Some(text) = staged {
                    return Ok(text);
                }
            }
        }
        let (env, condition) = self.guard(guard, n)?;
        // L-Py's `D(20, k)` matches a D whose first parameter is 20: a condition.
        let condition = if literals.is_empty() {
            condition
        } else {
            literals
                .into_iter()
                .chain(condition.map(|c| format!("({c})")))
                .reduce(|a, b| format!("{a} && {b}"))
        };
        let (right, weight) = self.weight(right, &env)?;
        let mut text = self.pattern(pattern, n)?;
        let successor = if right.is_empty() || right == "*" {
            String::new()
        } else {
            self.modules(right, &env, n)?
        };
        if let Some(c) = condition {
            text.push_str(&format!(" : {c}"));
        }
        text.push_str(" ->");
        if let Some(w) = weight {
            text.push_str(&format!(" ({w})"));
        }
        if successor.is_empty() {
            text.push_str(" ε");
        } else {
            text.push(' ');
            text.push_str(&separate(&successor));
        }
        Ok(text)
    }

    /// The production whose blocks hold a loop (see `cpfg/loops.rs`); `None` when they hold
    /// none, or the dialect has none.
    fn loop_production(
        &mut self,
        pattern: &str,
        guard: &str,
        right: &str,
        n: usize,
    ) -> Result<Option<String>, String> {
        let may = self.flavour == Flavour::Cpfg
            && !self.lpfg.active
            && (!self.in_productions || !self.cpfg.has_decomposition)
            && (guard.contains("while") || guard.contains("do"));
        if !may {
            return Ok(None);
        }
        self.cpfg.loops = Some(None);
        let guarded = self.guard(guard, n);
        let found = self.cpfg.loops.take().flatten();
        let (env, condition) = guarded?;
        let Some(l) = found else {
            return Ok(None);
        };
        let (right, weight) = self.weight(right, &env)?;
        if weight.is_some() {
            return Err("a production with a loop and a probability is not translated".into());
        }
        let successor = if right.is_empty() || right == "*" {
            String::new()
        } else {
            self.modules(right, &env, n)?
        };
        let mut head = self.pattern(pattern, n)?;
        if let Some(c) = condition {
            head.push_str(&format!(" : {c}"));
        }
        let letter = super::cpfg::draws::aux_letter(pattern);
        let params = super::cpfg::draws::formal_parameters(pattern);
        self.looped(&letter, &head, &params, &successor, &l, n)
            .map(Some)
    }

    /// cpfg's probability after the successor (`--> succ : 0.3`): the successor and the weight.
    fn weight<'r>(
        &mut self,
        right: &'r str,
        env: &Env,
    ) -> Result<(&'r str, Option<String>), String> {
        Ok(match top_level(right, ":") {
            Some(i) => {
                let weight = self
                    .expression(right[i + 1..].trim(), env)
                    .map_err(|why| format!("the probability: {why}"))?;
                (right[..i].trim(), Some(weight))
            }
            None => (right, None),
        })
    }

    /// A production's guard (what stands between `:` and the arrow): statement blocks `{…}`
    /// before and after a condition. Returns the names the blocks bind and the condition in
    /// Meristem's terms (`None` when there is none or it is `*`).
    pub(in crate::import::abop) fn guard(
        &mut self,
        guard: &str,
        n: usize,
    ) -> Result<(Env, Option<String>), String> {
        let mut env = Env::new();
        let mut condition = String::new();
        let mut rest = guard;
        let mut post = None;
        while !rest.is_empty() {
            if let Some(inner) = rest.strip_prefix('{') {
                let close = PARENTHESES_AND_BRACES
                    .closing(rest, 0)
                    .ok_or("a '{' block is never closed")?
                    - 1;
                let block = &inner[..close];
                if condition.trim().is_empty() {
                    self.block(block, &mut env, n)?;
                } else {
                    post = Some(block.to_string());
                }
                rest = inner[close + 1..].trim_start();
            } else {
                let stop = rest.find('{').unwrap_or(rest.len());
                condition.push_str(&rest[..stop]);
                rest = &rest[stop..];
            }
        }
        let condition = condition.trim();
        let looped = self.cpfg.loops.as_ref().is_some_and(Option::is_some);
        if looped && !(condition.is_empty() || condition == "*") {
            return Err("a loop before the production's condition is not translated (Meristem tests the condition before the auxiliary module that runs the loop)".into());
        }
        let condition = if condition.is_empty() || condition == "*" {
            None
        } else {
            let translated = self
                .expression(condition, &env)
                .map_err(|why| format!("the condition {condition}: {why}"))?;
            Some(translated)
        };
        if let Some(block) = post {
            self.block(&block, &mut env, n)?;
        }
        Ok((env, condition))
    }

    /// A production's left side: contexts and predecessor (formal parameters are names).
    pub(in crate::import::abop) fn pattern(
        &mut self,
        pattern: &str,
        n: usize,
    ) -> Result<String, String> {
        let new_contexts = self.new_contexts(pattern, n);
        let pattern = new_contexts.as_str();
        let strict = {
            let after = top_level(pattern, "<").map_or(pattern, |i| &pattern[i + 1..]);
            top_level(after, ">").map_or(after, |i| &after[..i]).trim()
        };
        let (width, target) = match self.flavour {
            Flavour::Cpfg => ('#', "!"),
            Flavour::Lpy => ('_', "!"),
        };
        for (symbol, meristem) in [(width, target), (',', ";")] {
            if strict.starts_with(symbol) {
                self.note(
                    n,
                    format!(
                        "a production for {}'s '{symbol}' becomes one for Meristem's '{meristem}', which also stands for the dialect's own '{meristem}': it rewrites those modules too",
                        self.flavour.tool()
                    ),
                );
            }
        }
        let mut parts = Vec::new();
        let mut rest = pattern;
        if let Some(i) = top_level(rest, "<") {
            parts.push(self.modules(&rest[..i], &Env::new(), n)?);
            parts.push("<".into());
            rest = &rest[i + 1..];
        }
        if let Some(i) = top_level(rest, ">") {
            parts.push(self.modules(&rest[..i], &Env::new(), n)?);
            parts.push(">".into());
            parts.push(self.modules(&rest[i + 1..], &Env::new(), n)?);
        } else {
            parts.push(self.modules(rest, &Env::new(), n)?);
        }
        Ok(parts
            .into_iter()
            .map(|p| if p.is_empty() { "*".to_string() } else { p })
            .collect::<Vec<_>>()
            .join(" "))
    }

    /// The pattern with the new contexts `<<` and `>>` read as the ordinary `<` and `>`, with a
    /// note on what changes: the tool matches a new context on the string being produced (the
    /// neighbour already rewritten in this step, so a signal can cross the whole plant in one
    /// step); Meristem matches on the string of the step before, so a signal moves one module a
    /// step.
    pub(in crate::import::abop) fn new_contexts(&mut self, pattern: &str, n: usize) -> String {
        let mut out = pattern.to_string();
        for (new, old, side) in [("<<", "<", "left"), (">>", ">", "right")] {
            if top_level(&out, new).is_some() {
                self.note(
                    n,
                    format!(
                        "{}'s new {side} context '{new}' (matched on the string being produced in this step) becomes an ordinary {side} context '{old}' (matched on the string of the step before): a signal it carries moves one module a step instead of along the whole axis in one step, so the plant may differ",
                        self.flavour.tool()
                    ),
                );
                while let Some(i) = top_level(&out, new) {
                    out.replace_range(i..i + 2, old);
                }
            }
        }
        out
    }
}

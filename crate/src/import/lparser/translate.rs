//! The translation of Lparser's strings: which values each rewritten symbol needs, the net
//! factors of their expansions, and each symbol as a Meristem module with explicit values.

use super::values::{classify, factor, net_expr, reads, Net, Prod};
use super::{
    Format, LsFile, Rule, Tok, Translator, Uses, A, L, NET_SAMPLES, NOT_REWRITABLE, PARAM_NAMES,
    POSITIONAL_LENGTH_UNIT, SELF_RULES, T, TILDE_DEFAULT_DEGREES, TROPISM_DEFAULT, VALUE_COMMANDS,
};
use crate::import::{number, Output};
use std::collections::HashMap;

impl<'f, 'o> Translator<'f, 'o> {
    pub(super) fn new(file: &'f LsFile, out: &'o mut Output) -> Self {
        let mut rule_of = HashMap::new();
        for (i, rule) in file.rules.iter().enumerate() {
            if NOT_REWRITABLE.contains(rule.pred) {
                out.note(
                    rule.line,
                    format!(
                        "a rule for '{}' would rewrite the string's structure; not translated",
                        rule.pred
                    ),
                );
                continue;
            }
            if let Some(&first) = rule_of.get(&rule.pred) {
                let first: &Rule = &file.rules[first];
                out.note(
                    rule.line,
                    format!(
                        "a second rule for '{}': Lparser uses the first one (line {}); this one is skipped",
                        rule.pred, first.line
                    ),
                );
                continue;
            }
            rule_of.insert(rule.pred, i);
        }
        // Lparser rewrites every character, the digits of a value too.
        let digits: Vec<char> = rule_of
            .keys()
            .copied()
            .filter(char::is_ascii_digit)
            .collect();
        let strings = std::iter::once((file.axiom_line, &file.axiom))
            .chain(file.rules.iter().map(|r| (r.line, &r.succ)));
        for (line, toks) in strings {
            if let Some(t) = toks
                .iter()
                .find(|t| t.written.chars().any(|c| digits.contains(&c)))
            {
                out.note(
                    line,
                    format!(
                        "'{}({})': Lparser's rules for digits rewrite the digits of values too; Meristem keeps the value",
                        t.ch, t.written
                    ),
                );
            }
        }
        let mut used = [false; 3];
        let all = file
            .rules
            .iter()
            .flat_map(|r| r.succ.iter())
            .chain(file.axiom.iter());
        for tok in all {
            if let Some((comp, _)) = factor(tok) {
                used[comp] = true;
            }
        }
        let mut t = Translator {
            file,
            out,
            rule_of,
            used,
            start: [1.0, file.angle, file.thickness / 100.0],
            needs: HashMap::new(),
            nets: HashMap::new(),
            uses: Uses::default(),
            noted: Vec::new(),
            width_line: None,
        };
        t.compute_needs();
        t.compute_nets();
        t
    }

    pub(super) fn rule(&self, ch: char) -> Option<&'f Rule> {
        let file: &'f LsFile = self.file;
        self.rule_of.get(&ch).map(|&i| &file.rules[i])
    }

    pub(super) fn ruled(&self, ch: char) -> bool {
        self.rule_of.contains_key(&ch)
    }

    pub(super) fn mask(&self, r: [bool; 3]) -> [bool; 3] {
        [
            r[0] && self.used[0],
            r[1] && self.used[1],
            r[2] && self.used[2],
        ]
    }

    /// The components each rewritten symbol must carry: those its expansion reads (fixpoint).
    pub(super) fn compute_needs(&mut self) {
        let preds: Vec<char> = self.rule_of.keys().copied().collect();
        for &p in &preds {
            // Left in the final string, a rewritten command acts as that command.
            let own = self.mask(reads(p, false));
            self.needs.insert(p, own);
        }
        loop {
            let mut changed = false;
            for &p in &preds {
                let Some(rule) = self.rule(p) else { continue };
                let mut need = self.needs[&p];
                for tok in &rule.succ {
                    let r = match self.needs.get(&tok.ch) {
                        Some(n) => *n,
                        None => self.mask(reads(tok.ch, tok.value.is_some())),
                    };
                    for c in 0..3 {
                        need[c] |= r[c];
                    }
                }
                if need != self.needs[&p] {
                    self.needs.insert(p, need);
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
    }

    /// The net scaling of each rewritten symbol's expansion, per component, as a law of the
    /// steps left (computed for [`NET_SAMPLES`] steps, then classified).
    pub(super) fn compute_nets(&mut self) {
        let preds: Vec<char> = self.rule_of.keys().copied().collect();
        let own = |p: char| -> [f64; 3] {
            let mut v = [1.0; 3];
            if let Some((c, f)) = factor(&Tok {
                ch: p,
                value: None,
                written: String::new(),
            }) {
                v[c] = f;
            }
            v
        };
        let mut samples: HashMap<char, Vec<[f64; 3]>> =
            preds.iter().map(|&p| (p, vec![own(p)])).collect();
        for r in 1..NET_SAMPLES {
            let mut next = HashMap::new();
            for &p in &preds {
                let mut v = [1.0; 3];
                let mut depth = 0i32;
                for tok in &self.rule(p).map_or(&[][..], |rule| &rule.succ[..]).to_vec() {
                    match tok.ch {
                        '[' => depth += 1,
                        ']' => depth = (depth - 1).max(0),
                        _ if depth > 0 => {}
                        ch if samples.contains_key(&ch) => {
                            let s = samples[&ch][r - 1];
                            for c in 0..3 {
                                v[c] *= s[c];
                            }
                        }
                        _ => {
                            if let Some((c, f)) = factor(tok) {
                                v[c] *= f;
                            }
                        }
                    }
                }
                next.insert(p, v);
            }
            for (p, v) in next {
                if let Some(s) = samples.get_mut(&p) {
                    s.push(v);
                }
            }
        }
        for &p in &preds {
            let s = &samples[&p];
            let nets = [0, 1, 2].map(|c| {
                if !self.used[c] {
                    return Net::Neutral;
                }
                let series: Vec<f64> = s.iter().map(|v| v[c]).collect();
                classify(&series)
            });
            self.nets.insert(p, nets);
        }
    }

    /// The Meristem name of a rewritten symbol.
    pub(super) fn name_of(ch: char) -> String {
        if ch.is_ascii_alphabetic() {
            if "FfZzgctG".contains(ch) {
                format!("{ch}_r")
            } else {
                ch.to_string()
            }
        } else if ch.is_ascii_digit() {
            format!("D_{ch}")
        } else {
            format!("Q_{}", ch as u32)
        }
    }

    /// True when something after a symbol, before the end of its branch, reads the turtle's
    /// state (inert characters do not).
    pub(super) fn has_followers(&self, rest: &[Tok]) -> bool {
        for t in rest {
            if t.ch == ']' {
                return false;
            }
            let command = VALUE_COMMANDS.contains(t.ch) || "[{}.|%$".contains(t.ch);
            if self.ruled(t.ch) || command {
                return true;
            }
        }
        false
    }

    pub(super) fn note_once(&mut self, key: &str, line: usize, message: String) {
        if !self.noted.iter().any(|k| k == key) {
            self.noted.push(key.to_string());
            self.out.note(line, message);
        }
    }

    /// A rewritten symbol's pattern or occurrence: its name and the components it carries.
    pub(super) fn module(&self, ch: char, state: &[Prod; 3]) -> String {
        let need = self.needs.get(&ch).copied().unwrap_or([false; 3]);
        let params: Vec<String> = (0..3)
            .filter(|&c| need[c])
            .map(|c| state[c].render())
            .collect();
        let name = Self::name_of(ch);
        if params.is_empty() {
            name
        } else {
            format!("{name}({})", params.join(","))
        }
    }

    /// Translates an Lparser string whose state starts as `state`.
    pub(super) fn string(&mut self, toks: &[Tok], mut state: [Prod; 3], line: usize) -> String {
        let mut s = String::new();
        let mut stack: Vec<[Prod; 3]> = Vec::new();
        let mut polygon = 0usize;
        for (index, tok) in toks.iter().enumerate() {
            if self.ruled(tok.ch) {
                let module = self.ruled_symbol(toks, index, &mut state, line);
                s.push_str(&module);
                continue;
            }
            match tok.ch {
                '[' => {
                    stack.push(state.clone());
                    s.push('[');
                }
                ']' => {
                    if let Some(saved) = stack.pop() {
                        state = saved;
                    }
                    s.push(']');
                }
                '{' => {
                    polygon += 1;
                    s.push('{');
                }
                '}' => {
                    polygon = polygon.saturating_sub(1);
                    s.push('}');
                }
                'F' | 'Z' if polygon > 0 => {
                    self.note_once(
                        &format!("polygon {line}"),
                        line,
                        format!(
                            "'{}' inside '{{…}}': Lparser draws a segment there and records no vertex; Meristem records a vertex and draws nothing",
                            tok.ch
                        ),
                    );
                    s.push_str(&self.terminal(tok, &state, line));
                }
                _ => {
                    if let Some((c, f)) = factor(tok) {
                        state[c] = state[c].times(f);
                    } else {
                        s.push_str(&self.terminal(tok, &state, line));
                    }
                }
            }
        }
        s
    }

    /// A symbol with a rule at `toks[index]`: its module with the values it needs from
    /// `state`, which then takes the net factors its expansion applies to the symbols after it.
    fn ruled_symbol(
        &mut self,
        toks: &[Tok],
        index: usize,
        state: &mut [Prod; 3],
        line: usize,
    ) -> String {
        let tok = &toks[index];
        if let Some(v) = tok.value {
            self.note_once(
                &format!("value {line} {}", tok.ch),
                line,
                format!(
                    "'{}({})': '{}' has a rule, and Lparser keeps '({})' as plain characters after its expansion; the value is dropped",
                    tok.ch,
                    number(v),
                    tok.ch,
                    number(v)
                ),
            );
        }
        let module = self.module(tok.ch, state);
        let nets = self.nets.get(&tok.ch).cloned();
        let irregular = nets.iter().flatten().position(|n| *n == Net::Irregular);
        if let Some(c) = irregular.filter(|_| self.has_followers(&toks[index + 1..])) {
            let what = ["lengths", "angles", "thicknesses"][c];
            let p = tok.ch;
            let rule_line = self.rule(p).map_or(line, |r| r.line);
            self.note_once(
                &format!("irregular {p}"),
                rule_line,
                format!(
                    "the expansion of '{p}' scales the {what} of the symbols after it by a factor that follows no simple law of the step; the translation does not carry it (symbols after '{p}', as on line {line}, keep the {what} before it)"
                ),
            );
        }
        for (c, net) in nets.iter().flatten().enumerate() {
            if let Some(e) = net_expr(net) {
                state[c].times_expr(e);
            }
        }
        module
    }

    /// One symbol without a rule (or a rewritten command left in the final string).
    pub(super) fn terminal(&mut self, tok: &Tok, state: &[Prod; 3], line: usize) -> String {
        let turn = |m: char, this: &Self| match tok.value {
            Some(v) => format!("{m}({})", number(v)),
            None if !this.used[A] => m.to_string(),
            None => format!("{m}({})", state[A].render()),
        };
        match tok.ch {
            'F' | 'Z' | 'f' | 'z' | 'g' => self.segment(tok, state),
            '+' | '-' | '&' | '^' => turn(tok.ch, self),
            '<' => turn('\\', self),
            '>' => turn('/', self),
            '|' => "|".into(),
            '.' => ".".into(),
            '%' => "/(180)".into(),
            '$' => {
                self.note_once(
                    "$",
                    line,
                    "'$' is translated as Meristem's '$' (roll so that the left vector is horizontal); after Lparser's '$' its frame is mirrored and its left and up vectors are not unit vectors, so its later '+' and '-' turn the other way and by distorted angles unless the heading is horizontal".into(),
                );
                "$".into()
            }
            '~' => self.tilde(tok, line),
            't' => self.tropism(tok, line),
            'c' => match tok.value {
                Some(v) => format!(";({})", number(v.trunc())),
                None => ";".into(),
            },
            ch if ch.is_ascii_alphabetic() && !SELF_RULES.contains(ch) => {
                // Any other letter without a rule becomes '_' after one step and never draws.
                String::new()
            }
            ch if !ch.is_ascii() => {
                self.note_once(
                    &format!("char {ch}"),
                    line,
                    format!("'{ch}' is not an Lparser symbol; dropped"),
                );
                String::new()
            }
            _ => String::new(),
        }
    }

    /// A move: `F` and `Z` (half) draw, `f`, `z` (half) and `g` move without drawing; their
    /// length is their value (in the positional format's units) or the current length.
    fn segment(&mut self, tok: &Tok, state: &[Prod; 3]) -> String {
        let unit = match self.file.format {
            Format::Positional => POSITIONAL_LENGTH_UNIT,
            Format::Keyword => 1.0,
        };
        let length = |half: bool| match tok.value {
            Some(v) => Prod::constant(v * unit),
            None if half => state[L].times(0.5),
            None => state[L].clone(),
        };
        match tok.ch {
            'F' | 'Z' => {
                if tok.ch == 'F' {
                    self.uses.forward = true;
                } else {
                    self.uses.half = true;
                }
                format!(
                    "{}({},{})",
                    tok.ch,
                    length(tok.ch == 'Z').render(),
                    state[T].render()
                )
            }
            'f' | 'z' | 'g' => {
                let len = length(tok.ch == 'z');
                let m = if tok.ch == 'g' { 'g' } else { 'f' };
                if len.is_constant(1.0) && tok.value.is_none() {
                    m.to_string()
                } else {
                    format!("{m}({})", len.render())
                }
            }
            _ => String::new(),
        }
    }

    /// `~`: a random turn about each axis, by up to its value in degrees.
    fn tilde(&mut self, tok: &Tok, line: usize) -> String {
        self.uses.tilde = true;
        let r = match tok.value {
            Some(v) => v,
            None => {
                self.note_once(
                    "~",
                    line,
                    format!(
                        "'~' without a value: Lparser's source turns by up to 6 radians ({}°, surely meant as 6°) about each axis; translated as written, '~({})'",
                        number(TILDE_DEFAULT_DEGREES),
                        number(TILDE_DEFAULT_DEGREES)
                    ),
                );
                TILDE_DEFAULT_DEGREES
            }
        };
        format!("~({})", number(r))
    }

    /// `t`: gravity, as Meristem's tropism.
    fn tropism(&mut self, tok: &Tok, line: usize) -> String {
        self.uses.tropism = true;
        self.note_once(
            "t",
            line,
            "'t' (gravity) bends the heading by tr·sin(angle to the vertical) as Lparser does, but towards the ground (Meristem's tropism, @Ts); Lparser bends about the turtle's left vector, which points that way only after '$'".into(),
        );
        format!("t({})", number(tok.value.unwrap_or(TROPISM_DEFAULT)))
    }

    pub(super) fn params(&self, ch: char) -> [Prod; 3] {
        let need = self.needs.get(&ch).copied().unwrap_or([false; 3]);
        [0, 1, 2].map(|c| {
            if need[c] {
                Prod::name(PARAM_NAMES[c])
            } else {
                Prod::constant(self.start[c])
            }
        })
    }
}

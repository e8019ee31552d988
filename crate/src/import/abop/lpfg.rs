//! L+C (lpfg) files read as cpfg: `module` declarations, the `;` that ends lpfg's lines, blocks
//! with `produce` (each path to a `produce` a conditional production) and lpfg's long turtle
//! names.

use super::{is_identifier, separate, split_top, Env, Importer, Line};
use crate::syntax::{PARENTHESES, PARENTHESES_AND_BRACES};
use crate::vocabulary::{name_of, Command, Meaning};

impl Importer {
    /// The lines of an L+C (lpfg) file in cpfg's terms: `module` declarations are read (a name
    /// of several letters is declared) and dropped, the `;` that ends lpfg's `Axiom:` and
    /// `derivation length:` lines is dropped, and a production's head `A(t):` joins the `{…}`
    /// block on the lines after it.
    pub(super) fn lpfg_lines(&mut self, all: Vec<Line>) -> Vec<Line> {
        self.lpfg.active = true;
        let mut out: Vec<Line> = Vec::new();
        for mut line in all {
            if let Some(rest) = line.code.strip_prefix("module ") {
                for item in rest.trim_end_matches(';').split(';') {
                    let name = item.split('(').next().unwrap_or("").trim();
                    if is_identifier(name)
                        && name.len() > 1
                        && !self.declared.iter().any(|d| d == name)
                    {
                        self.declared.push(name.to_string());
                        self.cpfg.words.push((name.to_string(), name.to_string()));
                    }
                }
                continue;
            }
            if !line.code.contains('{') {
                if let Some(code) = line.code.strip_suffix(';') {
                    line.code = code.trim_end().to_string();
                }
            }
            if line.code.starts_with('{') {
                if let Some(head) = out.last_mut().filter(|h| h.code.ends_with(':')) {
                    head.code = format!("{} {}", head.code, line.code);
                    continue;
                }
            }
            out.push(line);
        }
        self.cpfg
            .words
            .sort_by_key(|w| std::cmp::Reverse(w.0.len()));
        out
    }

    /// An lpfg production `pattern: { statements }`: the block is read as cpfg's statement
    /// blocks are, and each `produce` on its way gives a production whose condition is the path
    /// to it (lpfg leaves a module that produces nothing as it is, as Meristem does when no
    /// production applies).
    pub(super) fn lpfg_production(&mut self, pattern: &str, body: &str, n: usize) {
        self.lpfg.produced = Some(Vec::new());
        self.lpfg.path.clear();
        let mut env = Env::new();
        let result = self.statements(body, &mut env, n, 0);
        let produced = self.lpfg.produced.take().unwrap_or_default();
        self.lpfg.path.clear();
        if let Err(why) = result {
            self.note(n, format!("{why}; the production is skipped"));
            return;
        }
        let pattern = match self
            .lpfg_symbols(pattern, n)
            .and_then(|p| self.pattern(&p, n))
        {
            Ok(p) => p,
            Err(why) => {
                self.note(n, format!("{why}; the production is skipped"));
                return;
            }
        };
        // A predecessor of several modules (`f(l)E1(x)`): one production a module, the others
        // its context, as for cpfg; the first produces, the others erase their module.
        let heads: Vec<String> = match self.several_modules(&pattern, "", n) {
            Some(parts) => parts.into_iter().map(|(head, _)| head).collect(),
            None => vec![pattern],
        };
        for (condition, successor) in produced {
            for (i, head) in heads.iter().enumerate() {
                let mut text = head.clone();
                if let Some(c) = &condition {
                    text.push_str(&format!(" : {c}"));
                }
                text.push_str(" -> ");
                text.push_str(if successor.is_empty() || i > 0 {
                    "ε"
                } else {
                    &successor
                });
                self.out.line(text, n);
            }
        }
    }

    /// An lpfg module string (what `produce` and `Axiom:` write) in Meristem's notation: lpfg's
    /// long names (`SB()`, `Left(a)`, `SetWidth(w)`, …) become the symbols they stand for.
    pub(super) fn lpfg_modules(
        &mut self,
        text: &str,
        env: &Env,
        n: usize,
    ) -> Result<String, String> {
        let cpfg = self.lpfg_symbols(text, n)?;
        self.modules(&cpfg, env, n).map(|m| separate(&m))
    }

    /// lpfg's long names in `text` replaced by cpfg's symbols; a long name Meristem has no
    /// command for is dropped with a note.
    pub(super) fn lpfg_symbols(&mut self, text: &str, n: usize) -> Result<String, String> {
        let chars: Vec<char> = text.chars().collect();
        let mut out = String::new();
        let mut i = 0;
        while i < chars.len() {
            let c = chars[i];
            if !(c.is_ascii_alphabetic() || c == '_') {
                out.push(c);
                i += 1;
                continue;
            }
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            let mut j = i;
            while chars.get(j) == Some(&' ') {
                j += 1;
            }
            let (args, after) = if chars.get(j) == Some(&'(') {
                let close = PARENTHESES
                    .closing_char(&chars, j)
                    .ok_or("a '(' is never closed")?;
                (
                    Some(chars[j + 1..close].iter().collect::<String>()),
                    close + 1,
                )
            } else {
                (None, i)
            };
            i = after;
            if word.len() == 1 || self.cpfg.words.iter().any(|(w, _)| *w == word) {
                out.push_str(&word);
                // lpfg writes a module without parameters as `A()`; Meristem as `A`.
                if let Some(a) = args.as_ref().filter(|a| !a.trim().is_empty()) {
                    out.push_str(&format!("({a})"));
                }
                continue;
            }
            let symbol = self.lpfg_symbol(&word, &args.unwrap_or_default(), n);
            out.push_str(&symbol);
        }
        Ok(out)
    }

    /// The cpfg symbols of one lpfg long name `word` with its arguments `a`; empty (with a
    /// note) for a name Meristem has no command for.
    fn lpfg_symbol(&mut self, word: &str, a: &str, n: usize) -> String {
        let parts: Vec<&str> = split_top(a, ',');
        let sphere = name_of(Meaning::Turtle(Command::Sphere));
        match word {
            "SB" => "[".to_string(),
            "EB" => "]".to_string(),
            "Left" => format!("+({a})"),
            "Right" => format!("-({a})"),
            "Up" => format!("^({a})"),
            "Down" => format!("&({a})"),
            "RollL" => format!("\\({a})"),
            "RollR" => format!("/({a})"),
            "TurnAround" => "|".to_string(),
            "SetWidth" => format!("#({a})"),
            "SetColor" => format!(";({a})"),
            "Sphere" => format!("@O({a})"),
            "Sphere0" => sphere.to_string(),
            // lpfg's polygons (`stdmods.h`): start, vertex, end.
            "SP" => "{".to_string(),
            "PP" => ".".to_string(),
            "EP" => "}".to_string(),
            "IncColor" => "'".to_string(),
            "DecColor" => "'(-1)".to_string(),
            "MoveTo" | "MoveTo3f" | "MoveTo3d" => format!("@M({a})"),
            // lpfg's lines to a point or by a vector (`stdmods.h`), in cpfg's axes as Meristem's.
            "LineTo" | "LineTo3f" | "LineTo3d" => format!("@LineTo({a})"),
            "LineRel3f" | "LineRel3d" => format!("@LineRel({a})"),
            "SetHead" | "SetHead3f" => format!("@R({a})"),
            "RollToVert" => "$".to_string(),
            "Circle" | "Circle0" | "CircleFront" | "CircleFront0" | "CircleB" | "CircleFrontB" => {
                self.note_once(
                    "lpfg Circle",
                    n,
                    format!("lpfg's {word} draws a disc; Meristem has no disc and draws a sphere of its radius (@O) in its place"),
                );
                if a.trim().is_empty() {
                    sphere.to_string()
                } else {
                    format!("{sphere}({a})")
                }
            }
            // lpfg's communication modules, with one or two parameters: cpfg's ?E.
            "E1" | "E2" => format!("?E({a})"),
            "Surface3" if parts.len() == 4 => {
                let scales = parts[1..].iter().map(|p| p.trim()).collect::<Vec<_>>();
                self.lpfg_surface(word, parts[0], &scales.join(", "), n)
            }
            "Surface" if parts.len() == 2 => self.lpfg_surface(word, parts[0], parts[1].trim(), n),
            _ => {
                self.note_once(
                    &format!("lpfg {word}"),
                    n,
                    format!("lpfg's {word} is not a Meristem command; dropped"),
                );
                String::new()
            }
        }
    }
}

impl Importer {
    /// lpfg's `Surface(id, s)` or `Surface3(id, sx, sy, sz)` (`word`): `~X(scales)` of the
    /// surface the view file gives that id ([`crate::import::vlab`]), else Meristem's own leaf
    /// `~l` with a note; nothing (as lpfg) when the view file has surfaces but none with that id.
    fn lpfg_surface(&mut self, word: &str, id: &str, scales: &str, n: usize) -> String {
        let leaf = format!("~l({scales})");
        let Some(view) = self.cpfg.view.as_ref() else {
            self.note_once(word, n, format!("lpfg's {word}(id, …) draws the surface the object's view file gives that id; the .l was opened alone, so Meristem draws its own leaf ~l instead"));
            return leaf;
        };
        let (surfaces, missing) = (view.lpfg_surfaces.clone(), view.lpfg_surface_missing);
        let own = match surfaces.iter().find(|s| s.letter == "l") {
            Some(s) => format!("~l, the view file's {}", s.line),
            None => "its own leaf ~l".to_string(),
        };
        let id = id.trim();
        let value = id.parse::<f64>().ok().or_else(|| {
            let c = self.lpfg.constants.iter().find(|(name, _)| name == id);
            c.map(|(_, v)| *v)
        });
        let Some(value) = value.filter(|v| v.fract() == 0.0 && *v >= 0.0) else {
            self.note_once(&format!("{word} {id}"), n, format!("lpfg's {word}({id}, …): the surface id {id} is not a constant Meristem can work out, so Meristem draws {own} instead"));
            return leaf;
        };
        match surfaces.get(value as usize) {
            Some(s) => format!("~{}({scales})", s.letter),
            None if missing => {
                self.note_once(&format!("{word} {id}"), n, format!("lpfg's {word}({id}, …) draws the view file's surface {value}, which was not read (see the notes on the view file): Meristem draws {own} instead"));
                leaf
            }
            None => {
                let given = match surfaces.len() {
                    0 => "no surface".to_string(),
                    k => format!("surfaces with ids 0 to {}", k - 1),
                };
                self.note_once(&format!("{word} {id}"), n, format!("lpfg's {word}({id}, …): the view file gives {given}, none with id {value}; lpfg ignores the module, and so does Meristem"));
                String::new()
            }
        }
    }
}

/// Whether the lines are an L+C (lpfg) file: `module X(…);` declarations or `produce` in a block.
pub(super) fn is_lpfg(all: &[Line]) -> bool {
    all.iter().any(|l| {
        (l.code.starts_with("module ") && l.code.ends_with(';'))
            || (l.code.contains('{') && l.code.contains("produce "))
    })
}

/// An lpfg production `pattern: { … }` (or `pattern : { … }`): its pattern and the text inside
/// the braces.
pub(super) fn lpfg_production_parts(code: &str) -> Option<(&str, &str)> {
    let open = code.find('{')?;
    let head = code[..open].trim_end().strip_suffix(':')?.trim();
    let close = PARENTHESES_AND_BRACES.closing(code, open)?;
    if head.is_empty() || !code[close + 1..].trim().is_empty() {
        return None;
    }
    Some((head, &code[open + 1..close]))
}

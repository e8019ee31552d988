//! The Meristem text written from the translation: the header's defines, the axiom, the
//! productions, the homomorphism that draws what Meristem has no command for, the width scale
//! (measured on the derived plant) and the palette.

use super::read::keep_comment;
use super::values::Prod;
use super::{Format, Tok, Translator, MEASURE_MODULES, MEASURE_STEPS, VALUE_COMMANDS, WIDTH_SCALE};
use crate::import::number;
use crate::vocabulary::{DirectiveKind, KeywordKind};

/// Meristem's width unit is relative: 1/300 of the diagonal of the plant's bounding box (see
/// `mesh`). Lparser draws a segment `length × thickness` thick in model units, so the width in
/// Meristem's units is that times `300 / diagonal`: the importer derives the translated grammar
/// at its own depth (at most [`MEASURE_STEPS`] steps and [`MEASURE_MODULES`] modules) and measures the diagonal as the mesh
/// does. `None` when that fails.
pub(super) fn measure_width_scale(text: &str) -> Option<f64> {
    let (file, diagnostics) = crate::syntax::parse(text);
    if crate::diagnostics::has_errors(&diagnostics) {
        return None;
    }
    let (model, diagnostics) = crate::model::resolve(&file);
    let mut model = model.filter(|_| !crate::diagnostics::has_errors(&diagnostics))?;
    model.settings.max_modules = model.settings.max_modules.min(MEASURE_MODULES);
    if model.settings.iterations > MEASURE_STEPS {
        return None;
    }
    let options = crate::derive::DeriveOptions {
        steps: model.settings.iterations,
        ..Default::default()
    };
    let derivation = crate::derive::derive(&model, &options).ok()?;
    let skeleton = crate::turtle::interpret(&model, derivation.turtle_string());
    let diagonal = crate::mesh::skeleton_diagonal(&skeleton);
    let fraction = match crate::mesh::MeshOptions::default().width_unit {
        crate::mesh::WidthUnit::Relative(f) => f,
        crate::mesh::WidthUnit::Absolute(_) => return None,
    };
    (diagonal > 0.0 && diagonal.is_finite()).then(|| 1.0 / (fraction * diagonal))
}

/// `lhs -> rhs`, written so that a successor starting with `//` is not read as a comment.
pub(super) fn production(lhs: &str, rhs: &str) -> String {
    if rhs.is_empty() {
        format!("{lhs} -> ε")
    } else {
        format!("{lhs} -> {}", separate(rhs))
    }
}

/// The colours 2 to 13 of Lparser's table, the same in Lparser 2.1 (`Add_default_colors`) and in
/// the Lparser 4 code's VRML colours.
#[rustfmt::skip]
const SHARED_COLOURS: [(usize, [f64; 3]); 12] = [
    (2, [0.8, 0.4, 0.4]), (3, [0.8, 0.8, 0.4]), (4, [0.4, 0.8, 0.4]), (5, [0.4, 0.8, 0.8]),
    (6, [0.4, 0.4, 0.8]), (7, [0.8, 0.4, 0.8]), (8, [0.2, 0.5, 0.2]), (9, [0.2, 0.5, 0.5]),
    (10, [0.2, 0.2, 0.5]), (11, [0.5, 0.2, 0.5]), (12, [0.6, 0.2, 0.2]), (13, [0.5, 0.5, 0.5]),
];

/// Meristem reads `//` after a space as a comment unless it is part of a run of three or more
/// slashes, so a string that starts with exactly two rolls is written `/ /…` (whitespace between
/// modules is insignificant).
pub(super) fn separate(s: &str) -> String {
    let slashes = s.chars().take_while(|&c| c == '/').count();
    if slashes == 2 {
        format!("/ {}", &s[1..])
    } else {
        s.to_string()
    }
}

impl<'f, 'o> Translator<'f, 'o> {
    /// Writes the translation: the header, the `#width_scale` and palette, the axiom and the
    /// productions, the homomorphism that draws what Meristem's turtle does not, and finally the
    /// width scale measured on the plant.
    pub(super) fn write(mut self) {
        self.header();
        // The axiom and rules first (they decide what the homomorphism needs).
        let axiom = self.axiom();
        let productions = self.productions();
        let commands = self.command_productions();
        if self.uses.forward || self.uses.half {
            self.width_scale_placeholder();
        }
        self.palette();
        let file = self.file;
        self.out
            .line(format!("axiom: {}", separate(&axiom)), file.axiom_line);
        if !file.axiom_comment.is_empty() {
            self.out.comment(&file.axiom_comment, file.axiom_line);
        }
        for (text, line, comment) in productions {
            match keep_comment(&comment) {
                Some(c) => self.out.line(
                    format!("{text} // {}", crate::import::defuse_comment(&c)),
                    line,
                ),
                None => self.out.line(text, line),
            }
        }
        self.homomorphism(commands);
        if let Some(at) = self.width_line {
            self.measure_width(at);
        }
    }

    /// Where the translation comes from, the file's header comments, `#iterations` (a
    /// fractional recursion rounded up, with a note) and `#angle`.
    pub(super) fn header(&mut self) {
        let file = self.file;
        let format = match file.format {
            Format::Positional => "positional format",
            Format::Keyword => "keyword format of Lparser 2",
        };
        self.out.comment(
            &format!("Imported from Lparser ({format}) by meristem import."),
            0,
        );
        for c in &file.header {
            self.out.comment(c, 0);
        }
        let mut depth = file.recursion.max(0.0);
        if depth.fract() != 0.0 {
            self.out.note(
                file.recursion_line,
                format!(
                    "fractional recursion {}: Lparser grows the last step partly (its lengths, angles and thicknesses scaled by {}); Meristem derives {} whole steps",
                    number(depth),
                    number(depth.fract()),
                    number(depth.ceil())
                ),
            );
            depth = depth.ceil();
        }
        self.out.line(
            format!(
                "{} {}",
                DirectiveKind::Iterations.written(),
                number(depth.min(1e6))
            ),
            file.recursion_line,
        );
        self.out.line(
            format!("{} {}", DirectiveKind::Angle.written(), number(file.angle)),
            0,
        );
    }

    /// The axiom in Meristem's modules, starting with Lparser's first colour.
    pub(super) fn axiom(&mut self) -> String {
        let file = self.file;
        let start = self.start.map(Prod::constant);
        let axiom = self.string(&file.axiom, start, file.axiom_line);
        if file.axiom.first().map(|t| t.ch) != Some('c') {
            return format!(";(2){axiom}"); // Lparser starts with colour 2
        }
        axiom
    }

    /// Each rule as a production, in the file's order: (text, line, comment).
    pub(super) fn productions(&mut self) -> Vec<(String, usize, String)> {
        let file = self.file;
        let mut preds: Vec<(usize, char)> = self.rule_of.iter().map(|(&c, &i)| (i, c)).collect();
        preds.sort();
        let mut productions = Vec::new();
        for (i, ch) in preds {
            let rule = &file.rules[i];
            let params = self.params(ch);
            let lhs = self.module(ch, &params);
            let rhs = self.string(&rule.succ, params, rule.line);
            productions.push((production(&lhs, &rhs), rule.line, rule.comment.clone()));
        }
        productions
    }

    /// For each command that has a rule (and so stays a module of its own in the derived
    /// string), the homomorphism production that draws it: (text, line).
    pub(super) fn command_productions(&mut self) -> Vec<(String, usize)> {
        let file = self.file;
        let mut commands = Vec::new();
        for (ch, i) in self.sorted_rules() {
            let is_command = VALUE_COMMANDS.contains(ch) || "|%$".contains(ch);
            if !is_command {
                continue;
            }
            let params = self.params(ch);
            let lhs = self.module(ch, &params);
            let rhs = self.terminal(
                &Tok {
                    ch,
                    value: None,
                    written: String::new(),
                },
                &params,
                file.rules[i].line,
            );
            commands.push((production(&lhs, &rhs), file.rules[i].line));
        }
        commands
    }

    /// `#define width_scale` with a default value, replaced once the plant is measured
    /// ([`Translator::measure_width`]), and a note on what it means.
    pub(super) fn width_scale_placeholder(&mut self) {
        let thickness_line = self.file.thickness_line;
        self.out.note(
            thickness_line,
            "thickness: Lparser draws each segment as thick as its length times the thickness, in model units; Meristem's widths are in width units (1/300 of the plant's size), so the translation writes width_scale × length × thickness with width_scale measured on the plant at the file's depth: at other depths the plant's size changes and the widths with it",
        );
        self.width_line = Some(self.out.len());
        self.out.line(
            format!(
                "{} width_scale {}",
                DirectiveKind::Define.written(),
                number(WIDTH_SCALE)
            ),
            thickness_line,
        );
    }

    /// The `homomorphism:` section, when anything needs one: widths, `Z`, `~` and `t` as
    /// Meristem draws them, and the productions of `commands` that have rules.
    pub(super) fn homomorphism(&mut self, commands: Vec<(String, usize)>) {
        let width = if self.file.min_thickness > 0.0 {
            format!(
                "width_scale*max(x*t,{})",
                number(self.file.min_thickness / 100.0)
            )
        } else {
            "width_scale*x*t".to_string()
        };
        let mut homomorphism = Vec::new();
        if self.uses.forward {
            homomorphism.push(format!("F(x,t) -> !({width})F(x)"));
        }
        if self.uses.half {
            homomorphism.push(format!("Z(x,t) -> !({width})F(x)"));
        }
        if self.uses.tilde {
            homomorphism
                .push("~(r) -> +(uniform(-r,r))&(uniform(-r,r))/(uniform(-r,r))".to_string());
        }
        if self.uses.tropism {
            homomorphism.push("t(e) -> @Ts(e)G(0)@Ts(0)".to_string());
        }
        if homomorphism.is_empty() && commands.is_empty() {
            return;
        }
        self.out.line(KeywordKind::Homomorphism.written(), 0);
        self.out.comment(
            "How Lparser draws what Meristem's turtle does not: widths, Z (half length), ~ (random turn), t (gravity).",
            0,
        );
        for h in homomorphism {
            self.out.line(h, 0);
        }
        for (text, line) in commands {
            self.out.line(text, line);
        }
    }

    /// Replaces the `#define width_scale` line at `at` with the scale measured on the translated
    /// plant, or notes that it could not be measured.
    pub(super) fn measure_width(&mut self, at: usize) {
        match measure_width_scale(&self.out.text()) {
            Some(scale) => self.out.replace(
                at,
                format!(
                    "{} width_scale {} // width units per model unit: Lparser's thicknesses at the file's depth",
                    DirectiveKind::Define.written(),
                    number(scale)
                ),
            ),
            None => {
                self.out.note(
                    self.file.thickness_line,
                    format!("the plant could not be measured at its depth (too large to derive, or it draws nothing): width_scale is {}, tune it", number(WIDTH_SCALE)),
                );
            }
        }
    }

    pub(super) fn sorted_rules(&self) -> Vec<(char, usize)> {
        let mut v: Vec<(char, usize)> = self.rule_of.iter().map(|(&c, &i)| (c, i)).collect();
        v.sort_by_key(|&(_, i)| i);
        v
    }

    /// Lparser's colour table, with the file's `color` entries, as `#color` lines (runs of one
    /// colour as one flat ramp).
    pub(super) fn palette(&mut self) {
        let mut table = [[0.5; 3]; 100];
        let defaults: &[(usize, [f64; 3])] = match self.file.format {
            // Lparser 2.1, Add_default_colors: the shared ones and these.
            Format::Keyword => &[(14, [0.75, 0.75, 0.75]), (15, [1.0, 1.0, 1.0])],
            // The Lparser 4 code's VRML colours ("translate colors from lparser to RGB"): the
            // shared ones and these.
            Format::Positional => &[
                (1, [0.3, 0.3, 0.3]),
                (14, [0.7, 0.7, 0.7]),
                (15, [0.9, 0.9, 0.9]),
            ],
        };
        let defaults = SHARED_COLOURS.iter().chain(defaults);
        for &(i, c) in defaults.chain(self.file.colors.iter()) {
            table[i] = c;
        }
        let byte = |v: f64| (v.clamp(0.0, 1.0) * 255.0).round() as u8;
        let rgb = |c: [f64; 3]| format!("{} {} {}", byte(c[0]), byte(c[1]), byte(c[2]));
        self.out
            .comment("Lparser's colour table (indices 0 to 99).", 0);
        let mut i = 0;
        while i < table.len() {
            let mut j = i;
            while j + 1 < table.len() && rgb(table[j + 1]) == rgb(table[i]) {
                j += 1;
            }
            let c = rgb(table[i]);
            if j == i {
                self.out
                    .line(format!("{} {i} {c}", DirectiveKind::Color.written()), 0);
            } else {
                self.out.line(
                    format!("{} {i} {j} {c} {c}", DirectiveKind::Color.written()),
                    0,
                );
            }
            i = j + 1;
        }
    }
}

//! What a cpfg L-system takes from the rest of its vlab object: the view file's angle increment,
//! widths and colours, its functions (read by [`super::functions`]), its colour map; and the
//! notes a `.l` opened alone needs when it relies on them.

use super::super::{Flavour, Importer};
use crate::import::number;
use crate::vocabulary::{name_of, Command, DirectiveKind, Meaning};

impl Importer {
    /// The directives the view and colour files give, after the header.
    pub(in crate::import::abop) fn view_lines(&mut self) {
        let Some(view) = self.cpfg.view.clone() else {
            return;
        };
        self.out.comment(
            &format!("From the vlab object's {}.", view.sources.join(", ")),
            0,
        );
        let settings = [
            (DirectiveKind::Angle, view.angle),
            (DirectiveKind::Width, view.width),
            (DirectiveKind::WidthStep, view.width_step),
        ];
        // cpfg's cylinders and polygons are as wide as the width in the model's units.
        let unit = view.model_widths.then_some(1.0);
        for (kind, value) in settings
            .into_iter()
            .chain([(DirectiveKind::WidthUnit, unit)])
        {
            if let Some(v) = value {
                self.out
                    .line(format!("{} {}", kind.written(), number(v)), 0);
            }
        }
        if let (Some([x, y, z]), Some(e)) = (view.tropism, view.elasticity) {
            if e != 0.0 {
                let values = [x, y, z, e].map(number).join(" ");
                self.out
                    .line(format!("{} {values}", DirectiveKind::Tropism.written()), 0);
            }
        }
        for line in view.palette.iter().chain(&view.surfaces) {
            self.out.line(line.clone(), 0);
        }
        // The functions the L-system reads go here once it has been read
        // ([`Importer::function_lines`]).
        self.cpfg.functions_at = Some(self.out.len());
        for line in view.contours.iter().flatten().flat_map(|c| &c.lines) {
            match line.strip_prefix("// ") {
                Some(comment) => self.out.comment(comment, 0),
                None => self.out.line(line.clone(), 0),
            }
        }
        for note in &view.notes {
            self.note(0, note.clone());
        }
        if let Some(env) = &view.environment {
            for line in &env.lines {
                match line.strip_prefix("// ") {
                    Some(comment) => self.out.comment(comment, 0),
                    None => self.out.line(line.clone(), 0),
                }
            }
            for note in &env.notes {
                self.note(0, note.clone());
            }
        }
    }

    /// The note at the first `?E`: what answers it; `None` when the object's program became an
    /// `#environment` line that answers as it does (nothing differs, nothing to note).
    pub(in crate::import::abop) fn communication_note(&self) -> Option<String> {
        let environment = self.cpfg.view.as_ref().and_then(|v| v.environment.as_ref());
        Some(match environment {
            Some(env) if env.lines.iter().any(|l| !l.starts_with("//")) && env.notes.is_empty() => {
                return None
            }
            Some(env) if env.lines.iter().any(|l| !l.starts_with("//")) => format!(
                "?E(…) is answered between steps by the #environment line above, the object's {} translated (its note at the top says what differs)",
                env.program
            ),
            Some(env) => format!(
                "?E(…) asks the object's environmental program {}, which Meristem does not have: it is kept as a module whose parameters stay as the L-system writes them, and productions that read it see those values",
                env.program
            ),
            None => "cpfg's ?E(…) asks the environment program (a light or space model run beside cpfg) for values; the object's .e file, which names it, was not opened, so ?E is kept as a module whose parameters stay as the L-system writes them, unless an #environment line (light, obstacle, space, attractors or collision) is added to answer it".into(),
        })
    }

    /// The axiom's start: the view's initial colour.
    pub(in crate::import::abop) fn initial_colour(&self) -> String {
        match self.cpfg.view.as_ref().and_then(|v| v.color) {
            Some(c) => format!(
                "{}({})",
                name_of(Meaning::Turtle(Command::SetColor)),
                number(c)
            ),
            None => String::new(),
        }
    }

    /// Notes for a `.l` opened alone: what its view file would have said.
    pub(in crate::import::abop) fn unknown_view(&mut self) {
        if self.flavour != Flavour::Cpfg {
            return;
        }
        let no_angle = self.cpfg.view.as_ref().is_none_or(|v| v.angle.is_none());
        if self.cpfg.bare_turn && no_angle {
            let why = if self.cpfg.view.is_some() {
                "the view file gives no angle increment"
            } else {
                "the angle increment is in the object's view file (.v), which was not opened with this file"
            };
            self.note(0, format!("{why}: turns without an angle use Meristem's default of 90° (open the object's folder or .zip to use its own)"));
        }
        if self.cpfg.colour && self.cpfg.view.is_none() {
            self.note(0, "the colours are in the object's view file and colour map, which were not opened with this file: Meristem's palette is used (open the object's folder or .zip to use its own)");
        }
    }

    /// A module whose meaning depends on the view (turns without an angle, colours) or that cpfg
    /// spells differently (`@Gs`, `@Gc`, `@Ge`); `None` for the others.
    pub(in crate::import::abop) fn view_module(
        &mut self,
        name: &str,
        params: &[String],
        has_params: bool,
        n: usize,
    ) -> Option<String> {
        if ["+", "-", "&", "^", "/", "\\"].contains(&name) && !has_params {
            self.cpfg.bare_turn = true;
            return None;
        }
        if self.flavour != Flavour::Cpfg {
            return None;
        }
        // dialect: cpfg's module names
        match name {
            ";" | "," => {
                self.cpfg.colour = true;
                let step = self.cpfg.view.as_ref().and_then(|v| v.color_increment)?;
                if has_params || step == 1.0 {
                    return None;
                }
                let sign = if name == "," { -step } else { step };
                Some(format!("'({})", number(sign)))
            }
            "@c" | "@o" => Some(self.circle(name, params, n)),
            // dialect: cpfg's sphere takes its diameter, Meristem's its radius.
            "@O" if has_params && !self.lpfg.active => {
                let d = params.first().map_or("", String::as_str);
                Some(format!("{name}(({d})/2)"))
            }
            "@Gs" => Some(name_of(Meaning::Turtle(Command::StartSmooth)).to_string()),
            // dialect: cpfg's end of a generalized cylinder
            "@Ge" => Some(name_of(Meaning::Turtle(Command::EndSmooth)).to_string()),
            // dialect: cpfg's control point
            "@Gc" => {
                let _ = params;
                self.note_once(
                    "control point",
                    n,
                    // dialect: cpfg's @Gc, Meristem's smooth axis
                    "cpfg's @Gc marks a control point of a generalized cylinder; Meristem's smooth axis (@Gc … @Ge) passes through every point the turtle reaches, so it is dropped and the cylinder follows the segments rather than only the control points",
                );
                Some(String::new())
            }
            _ => None,
        }
    }
}

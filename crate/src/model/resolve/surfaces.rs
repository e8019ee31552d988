//! `#surface X …` and `#patch X …`: what `~X` draws (docs/LANGUAGE.md, "Surfaces"), read into
//! [`SurfaceShape`]s in the turtle's frame.

use super::{surface_index, Resolver};
use crate::diagnostics::Diagnostic;
use crate::model::surface::{Frame, DEFAULT_PRECISION, LIBRARY_PRECISION};
use crate::model::{
    organ_patches, ModuleId, Patch, RuleSet, SuccessorModule, SurfaceShape, WrittenPoint,
    MAX_PATCHES, MAX_PRECISION,
};
use crate::syntax::{Directive, SourceFile, Span};
use crate::vocabulary::{
    frame_word_named, organ_named, Command, DirectiveKind, FrameWord, ModuleInfo, Organ,
    FRAME_WORDS, PATCH_COLOR, SURFACE_SHAPES,
};
use glam::DVec3;
use std::sync::Arc;

/// Numbers in one `#patch` line: 16 points x y z.
const PATCH_NUMBERS: usize = 48;

/// One letter's declarations, gathered over the file.
struct Declaration {
    letter: char,
    /// The `#surface` line, if any (where messages about the whole surface point).
    line: Option<Span>,
    /// The first line that declares it.
    first: Span,
    organ: Option<Organ>,
    frame: Frame,
    end: Option<DVec3>,
    precision: Option<[f64; 2]>,
    patches: Vec<Patch>,
    written: Vec<WrittenPoint>,
    colors: Vec<[u16; 2]>,
}

impl Resolver {
    /// The surfaces the file declares, in the order their letters first appear.
    pub(super) fn surfaces(&mut self, file: &SourceFile) -> Vec<Arc<SurfaceShape>> {
        let mut declared: Vec<Declaration> = Vec::new();
        for d in &file.directives {
            let kind = d.kind;
            if !matches!(kind, Some(DirectiveKind::Surface | DirectiveKind::Patch)) {
                continue;
            }
            let Some(letter) = self.surface_letter(d) else {
                continue;
            };
            let k = match declared.iter().position(|x| x.letter == letter) {
                Some(k) => k,
                None => {
                    declared.push(Declaration::new(letter, d.name_span.start..d.args_span.end));
                    declared.len() - 1
                }
            };
            if kind == Some(DirectiveKind::Surface) {
                self.surface_line(d, &mut declared[k]);
            } else {
                self.patch_line(d, &mut declared[k]);
            }
        }
        declared
            .into_iter()
            .filter_map(|x| self.surface_shape(x).map(Arc::new))
            .collect()
    }

    /// The letter of a `#surface` / `#patch` line, or `None` (and E0221) when it is not one
    /// ASCII letter.
    fn surface_letter(&mut self, d: &Directive) -> Option<char> {
        let (name, span) = d.target.as_ref()?;
        let mut chars = name.chars();
        match (chars.next(), chars.next()) {
            (Some(c), None) if c.is_ascii_alphabetic() => Some(c),
            _ => {
                self.diagnostics.push(Diagnostic::error(
                    "E0221",
                    span.clone(),
                    format!(
                        "'{name}' is not a surface's letter: {} takes one letter X, and ~X draws it",
                        d.written
                    ),
                ));
                None
            }
        }
    }

    /// `#surface X [shape] [word numbers]…`.
    fn surface_line(&mut self, d: &Directive, x: &mut Declaration) {
        let line = d.name_span.start..d.args_span.end;
        if x.line.is_some() {
            let message = format!("{} {} is declared twice", d.written, x.letter);
            self.diagnostics
                .push(Diagnostic::error("E0221", line.clone(), message));
            return;
        }
        x.line = Some(line);
        let words = words_after_name(d);
        let mut k = 0;
        if let Some((word, _)) = words.first() {
            if let Some(o) = organ_named(word) {
                x.organ = Some(o.organ);
                k = 1;
            }
        }
        while k < words.len() {
            let (word, span) = &words[k];
            let Some(info) = frame_word_named(word) else {
                self.diagnostics
                    .push(Diagnostic::error("E0221", span.clone(), unknown_word(word)));
                return;
            };
            let numbers: Vec<f64> = words[k + 1..]
                .iter()
                .take(info.numbers)
                .map_while(|(w, _)| crate::number::parse_f64(w).filter(|v| v.is_finite()))
                .collect();
            if numbers.len() < info.numbers {
                let message = format!("'{word}' takes {} numbers", info.numbers);
                self.diagnostics
                    .push(Diagnostic::error("E0221", span.clone(), message));
                return;
            }
            if !self.frame_word(info.word, &numbers, span, x) {
                return;
            }
            k += 1 + info.numbers;
        }
    }

    /// Applies one frame word; false (with E0221) when its numbers cannot be used.
    fn frame_word(&mut self, word: FrameWord, n: &[f64], span: &Span, x: &mut Declaration) -> bool {
        let v = || DVec3::new(n[0], n[1], n[2]);
        match word {
            FrameWord::Contact => x.frame.contact = v(),
            FrameWord::Heading => x.frame.heading = v(),
            FrameWord::Up => x.frame.up = v(),
            FrameWord::End => x.end = Some(v()),
            FrameWord::Size | FrameWord::Scale if n[0] <= 0.0 => {
                let message = format!("'{}' must be above 0", word.name());
                self.diagnostics
                    .push(Diagnostic::error("E0221", span.clone(), message));
                return false;
            }
            FrameWord::Size => x.frame.size = n[0],
            FrameWord::Scale => x.frame.scale = n[0],
            FrameWord::Precision => x.precision = Some([n[0], n[1]]),
        }
        true
    }

    /// `#patch X` and 16 points.
    fn patch_line(&mut self, d: &Directive, x: &mut Declaration) {
        if d.points.len() != PATCH_NUMBERS {
            let message = format!(
                "{} {} needs 16 points x y z (48 numbers), found {} numbers",
                d.written,
                x.letter,
                d.points.len()
            );
            let span = d.name_span.start..d.args_span.end;
            self.diagnostics
                .push(Diagnostic::error("E0220", span, message));
            return;
        }
        if x.patches.len() >= MAX_PATCHES {
            let message = format!("~{} has more than {MAX_PATCHES} patches", x.letter);
            self.diagnostics
                .push(Diagnostic::error("E0221", d.name_span.clone(), message));
            return;
        }
        let patch = x.patches.len() as u32;
        let points = d.points.chunks_exact(3).zip(d.point_spans.chunks_exact(3));
        for (index, (p, spans)) in points.enumerate() {
            x.written.push(WrittenPoint {
                patch,
                index: index as u32,
                value: [p[0], p[1], p[2]],
                span: spans[0].start..spans[2].end,
            });
        }
        let written = &x.written[x.written.len() - 16..];
        x.patches
            .push(std::array::from_fn(|k| DVec3::from_array(written[k].value)));
        let colors = self.patch_colors(d);
        x.colors.push(colors);
    }

    /// The colours after a `#patch` line's points (`color top [bottom]`, the bottom the top's
    /// when not given), 0 for the turtle's; [0, 0] (with E0220 when they are not one or two
    /// colour indices) when there are none.
    fn patch_colors(&mut self, d: &Directive) -> [u16; 2] {
        let words = words_after_name(d);
        let Some(k) = words.iter().position(|(w, _)| w == PATCH_COLOR) else {
            return [0, 0];
        };
        let index = |w: &str| {
            crate::number::parse_f64(w)
                .filter(|v| v.fract() == 0.0 && (0.0..=u16::MAX as f64).contains(v))
                .map(|v| v as u16)
        };
        let values: Vec<Option<u16>> = words[k + 1..].iter().map(|(w, _)| index(w)).collect();
        match values[..] {
            [Some(top)] => [top, top],
            [Some(top), Some(bottom)] => [top, bottom],
            _ => {
                let end = words.last().map_or(words[k].1.end, |w| w.1.end);
                let message = format!(
                    "'{PATCH_COLOR}' takes one or two colour indices (whole numbers from 0 to {}), the top's then the bottom's; 0 is the turtle's colour",
                    u16::MAX
                );
                self.diagnostics
                    .push(Diagnostic::error("E0220", words[k].1.start..end, message));
                [0, 0]
            }
        }
    }

    /// The shape of one letter's declarations, placed in the turtle's frame; `None` (with a
    /// diagnostic) when it has none.
    fn surface_shape(&mut self, x: Declaration) -> Option<SurfaceShape> {
        let at = x.line.clone().unwrap_or(x.first.clone());
        let raw = match (x.organ, x.patches.is_empty()) {
            (Some(organ), true) => organ_patches(organ),
            (Some(organ), false) => {
                let message = format!(
                    "~{} is the library's {}: remove its #patch lines or the shape's name",
                    x.letter,
                    organ.name()
                );
                self.diagnostics
                    .push(Diagnostic::error("E0221", at, message));
                return None;
            }
            (None, false) => x.patches,
            (None, true) => {
                let message = format!(
                    "~{} has no shape: name one of the library ({}) or add #patch {} lines",
                    x.letter,
                    names(SURFACE_SHAPES.iter().map(|o| o.name)),
                    x.letter
                );
                self.diagnostics
                    .push(Diagnostic::error("E0221", at, message));
                return None;
            }
        };
        let axes = match x.frame.axes() {
            Some(axes) => axes,
            None => {
                let message = format!("the heading and up of ~{} are parallel or zero", x.letter);
                self.diagnostics
                    .push(Diagnostic::error("E0221", at, message));
                return None;
            }
        };
        let place = |p: DVec3| x.frame.place(p, &axes);
        let default = if x.organ.is_some() {
            LIBRARY_PRECISION
        } else {
            DEFAULT_PRECISION
        };
        let precision = x.precision.map_or([default; 2], |p| {
            p.map(|v| self.precision(v, &at, x.letter))
        });
        Some(SurfaceShape {
            letter: x.letter,
            patches: raw.iter().map(|p| p.map(place)).collect(),
            precision,
            end: x.end.map(place),
            organ: x.organ,
            frame: x.frame,
            written: x.written,
            colors: if x.colors.iter().all(|c| *c == [0, 0]) {
                Vec::new()
            } else {
                x.colors
            },
        })
    }

    /// A precision rounded and kept within 1 to [`MAX_PRECISION`] (warning E0223 when it was not).
    fn precision(&mut self, v: f64, at: &Span, letter: char) -> u32 {
        let kept = v.round().clamp(1.0, MAX_PRECISION as f64);
        if kept != v {
            // The kept value as a whole number: the first plant's core formats no float (issue 22).
            let kept = kept as u32;
            let message = format!(
                "the precision of ~{letter} is a whole number from 1 to {MAX_PRECISION}: one is read as {kept}"
            );
            self.diagnostics
                .push(Diagnostic::warning("E0223", at.clone(), message));
        }
        kept as u32
    }
}

impl Resolver {
    /// Warns (E0222) of every `~X` written but not declared, but `~l` and `~p`, which draw
    /// Meristem's own leaf and petal.
    pub(super) fn check_surfaces_drawn(
        &mut self,
        meanings: &[Option<&'static ModuleInfo>],
        surfaces: &[Arc<SurfaceShape>],
        axiom: &[SuccessorModule],
        sets: [&RuleSet; 3],
    ) {
        let declared: Vec<String> = surfaces.iter().map(|s| format!("~{}", s.letter)).collect();
        for (i, meaning) in meanings.iter().enumerate() {
            let id = ModuleId(i as u32);
            let name = self.alphabet.name(id);
            let built_in = meaning
                .and_then(ModuleInfo::command)
                .is_some_and(|c| c != Command::Surface);
            if built_in
                || super::surface_letter(name).is_none()
                || surface_index(name, surfaces).is_some()
            {
                continue;
            }
            let Some(span) = first_use(id, axiom, sets) else {
                continue;
            };
            let message = format!(
                "{name} draws nothing: no #surface or #patch declares it ({})",
                if declared.is_empty() {
                    "none is declared".to_string()
                } else {
                    format!("declared: {}", declared.join(", "))
                }
            );
            self.diagnostics
                .push(Diagnostic::warning("E0222", span, message));
        }
    }
}

/// Where module `id` is first written in the axiom or a successor.
fn first_use(id: ModuleId, axiom: &[SuccessorModule], sets: [&RuleSet; 3]) -> Option<Span> {
    fn find(id: ModuleId, modules: &[SuccessorModule]) -> Option<Span> {
        modules.iter().find_map(|m| {
            if m.id == id {
                return Some(m.span.clone());
            }
            m.group.iter().flatten().find_map(|member| find(id, member))
        })
    }
    find(id, axiom).or_else(|| {
        sets.iter()
            .flat_map(|set| &set.productions)
            .find_map(|p| find(id, &p.successor))
    })
}

impl Declaration {
    fn new(letter: char, first: Span) -> Self {
        Declaration {
            letter,
            line: None,
            first,
            organ: None,
            frame: Frame::default(),
            end: None,
            precision: None,
            patches: Vec::new(),
            written: Vec::new(),
            colors: Vec::new(),
        }
    }
}

/// The words after a directive's name, with their spans.
fn words_after_name(d: &Directive) -> Vec<(String, Span)> {
    let name_len = d.target.as_ref().map_or(0, |(n, _)| n.len());
    let args = d.args.as_str();
    args[name_len..]
        .split(|c: char| c.is_whitespace() || c == ',')
        .filter(|w| !w.is_empty())
        .map(|w| {
            let at = d.args_span.start + (w.as_ptr() as usize - args.as_ptr() as usize);
            (w.to_string(), at..at + w.len())
        })
        .collect()
}

fn unknown_word(word: &str) -> String {
    format!(
        "'{word}' is neither a shape of the library ({}) nor a frame word ({}), or the shape is not first",
        names(SURFACE_SHAPES.iter().map(|o| o.name)),
        names(FRAME_WORDS.iter().map(|w| w.name)),
    )
}

fn names<'a>(names: impl Iterator<Item = &'a str>) -> String {
    names.collect::<Vec<_>>().join(", ")
}

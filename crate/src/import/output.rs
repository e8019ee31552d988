//! What an importer writes: [`Output`], the translated text line by line with the line of the
//! imported text each came from, and its notes; [`Output::finish`] comments out what Meristem
//! rejects. The output and its notes are capped ([`MAX_OUTPUT`], [`MAX_NOTES`]): translations
//! expand (cpp's macros, L-Py's inlined functions, arrays read element by element), and a few
//! kilobytes of input must not become gigabytes (issue 50, 4-6).

use super::{Import, ImportNote};
use crate::diagnostics::{has_errors, LineIndex, Severity};

/// The text an importer writes, line by line, each line remembering the line of the imported
/// text it came from (for notes about it).
#[derive(Debug, Default)]
pub(crate) struct Output {
    lines: Vec<(String, usize)>,
    notes: Vec<ImportNote>,
    /// The bytes of `lines`, each with its line end.
    bytes: usize,
    /// The source line whose translation would have passed [`MAX_OUTPUT`]: nothing from it on
    /// is written.
    cut_at: Option<usize>,
    /// Notes past [`MAX_NOTES`], counted, not kept.
    notes_left_out: usize,
}

/// The most bytes of lines an importer writes (the check then marks the lines Meristem rejects
/// `// not imported:`, a few bytes more each). Real models translate to at most about a
/// megabyte (an L-Py model whose string is derived when imported); a 45 KB cpfg file of macros
/// 10,000 modules long translated to 20 MB, and 1.2 GB of memory, before this cap.
pub(crate) const MAX_OUTPUT: usize = 4 << 20;

/// The most notes an import lists; the rest are counted in one last note. Each rejected line has
/// a note quoting it, and 200,000 rejected lines made tens of megabytes of notes.
pub(crate) const MAX_NOTES: usize = 1_000;

/// How many times [`Output::finish`] re-checks after commenting out rejected lines.
const MAX_REPAIRS: usize = 64;

impl Output {
    /// Appends one line (which must not contain a line break) that came from source line
    /// `source` (0: from no particular line).
    pub fn line(&mut self, text: impl Into<String>, source: usize) {
        let text: String = text.into();
        // A line break would shift every later line, and [`Output::finish`] would comment out the
        // wrong one: keep any extra text as lines of their own. Meristem's parser ends a line at
        // `\n`, `\r\n` or a lone `\r` (a `\r` in a name of a mutated `.vset` made `#define SIM_END`
        // the line commented out in place of the one in error).
        for part in text.replace("\r\n", "\n").split(['\n', '\r']) {
            if self.cut_at.is_some() {
                return;
            }
            if self.bytes + part.len() + 1 > MAX_OUTPUT {
                self.cut_at = Some(source);
                return;
            }
            self.bytes += part.len() + 1;
            self.lines.push((part.to_string(), source));
        }
    }

    /// Appends a `// …` comment line (comment markers inside are defused).
    pub fn comment(&mut self, text: &str, source: usize) {
        self.line(format!("// {}", defuse_comment(text)), source);
    }

    /// Records a note at source line `line`.
    pub fn note(&mut self, line: usize, message: impl Into<String>) {
        let note = ImportNote {
            line,
            message: message.into(),
        };
        // One source line translated into several productions says each thing once (the notes
        // of one line are written together: the last few are enough to look at).
        if self.notes.iter().rev().take(16).any(|n| *n == note) {
            return;
        }
        if self.notes.len() < MAX_NOTES {
            self.notes.push(note);
        } else {
            self.notes_left_out += 1;
        }
    }

    /// Checks the text with Meristem's parser and resolver; every line holding an error is
    /// commented out (`// not imported: …`) with a note at its source line, and the check runs
    /// again, until the text resolves or only errors without a line are left. Notes are sorted
    /// by line (stable).
    pub fn finish(mut self) -> Import {
        for _ in 0..MAX_REPAIRS {
            let text = self.text();
            let (file, mut diagnostics) = crate::syntax::parse(&text);
            diagnostics.extend(crate::model::resolve(&file).1);
            if !has_errors(&diagnostics) {
                break;
            }
            let index = LineIndex::new(&text);
            let mut repaired = false;
            for d in diagnostics.iter().filter(|d| d.severity == Severity::Error) {
                if d.code == "E0300" {
                    let message = "nothing to derive: no axiom could be imported".to_string();
                    if !self.notes.iter().any(|n| n.message == message) {
                        self.note(0, message);
                    }
                    continue;
                }
                let (line, _) = index.line_column(d.span.start);
                let Some((content, source)) = self.lines.get(line - 1).cloned() else {
                    continue;
                };
                // A line commented out already (by an earlier error on it too) is left as it is.
                if content.trim_start().starts_with("//") {
                    continue;
                }
                self.lines[line - 1].0 = format!("// not imported: {}", defuse_comment(&content));
                self.note(
                    source,
                    format!(
                        "Meristem rejects the translation `{}`: {} (the line is commented out)",
                        excerpt(content.trim()),
                        d.message
                    ),
                );
                repaired = true;
            }
            if !repaired {
                break;
            }
        }
        self.note_the_caps();
        self.notes.sort_by_key(|n| n.line);
        Import {
            text: self.text(),
            notes: self.notes,
        }
    }

    /// The notes that say what the caps left out (kept whatever [`MAX_NOTES`] says).
    fn note_the_caps(&mut self) {
        if let Some(line) = self.cut_at {
            self.notes.push(ImportNote {
                line,
                message: format!(
                    "the translation passes {} MB here: the rest of the file is left out",
                    MAX_OUTPUT >> 20
                ),
            });
        }
        if self.notes_left_out > 0 {
            self.notes.push(ImportNote {
                line: 0,
                message: format!(
                    "{} more notes are not listed (only the first {MAX_NOTES} are)",
                    self.notes_left_out
                ),
            });
        }
    }

    /// How many lines have been written.
    pub fn len(&self) -> usize {
        self.lines.len()
    }

    /// The last line written ("" when none).
    pub fn last(&self) -> &str {
        self.lines.last().map_or("", |(text, _)| text.as_str())
    }

    /// Inserts `lines` (from no particular source line) before line `index` (0-based); the lines
    /// after them move down, so an index kept of a later line no longer holds.
    pub fn insert(&mut self, index: usize, lines: Vec<String>) {
        let mut inserted = Output::default();
        for line in lines {
            inserted.line(line, 0);
        }
        let index = index.min(self.lines.len());
        self.bytes += inserted.bytes;
        self.lines.splice(index..index, inserted.lines);
    }

    /// Replaces the text of line `index` (0-based), keeping its source line. A line break in
    /// `text` becomes a space: the line stays one line, so the lines after it keep their places.
    pub fn replace(&mut self, index: usize, text: String) {
        if let Some(line) = self.lines.get_mut(index) {
            let text = one_line(&text);
            self.bytes = self.bytes - line.0.len() + text.len();
            line.0 = text;
        }
    }

    /// The text written so far.
    pub fn text(&self) -> String {
        let mut text = String::new();
        for (line, _) in &self.lines {
            text.push_str(line);
            text.push('\n');
        }
        text
    }
}

/// The most bytes of a translated line a note quotes.
const MAX_QUOTED: usize = 300;

/// `text`, cut after [`MAX_QUOTED`] bytes (at a character's start) with `…`: a note about a long
/// line quotes its start, not the whole line (issue 50, 6: a 35 MB note).
fn excerpt(text: &str) -> String {
    if text.len() <= MAX_QUOTED {
        return text.to_string();
    }
    let mut end = MAX_QUOTED;
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    format!("{}…", &text[..end])
}

/// Makes text safe inside a `//` comment: no block-comment markers, and no line break, which
/// would end the comment (Meristem's parser ends a line at a lone `\r` too: an unclosed cpfg
/// comment `/*z\r]` was written as `// z\r]`, and its `]` became a line of its own).
pub(crate) fn defuse_comment(text: &str) -> String {
    one_line(&text.replace("/*", "/ *").replace("*/", "* /"))
}

/// `text` with each line break (`\n`, or a lone `\r`, which Meristem's parser also ends a line
/// at) made a space.
fn one_line(text: &str) -> String {
    text.replace(['\r', '\n'], " ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_text_stops_at_its_cap_with_a_note_at_the_line_that_passed_it() {
        let mut out = Output::default();
        // Comments, which the check leaves as they are.
        let line = format!("// {}", "F".repeat(996));
        for source in 1..=5000 {
            out.line(line.clone(), source);
        }
        let import = out.finish();
        assert!(import.text.len() <= MAX_OUTPUT, "{}", import.text.len());
        // 1,000 bytes a line with its end: line 4,195 is the first that does not fit.
        let cut = import
            .notes
            .iter()
            .find(|n| n.message.contains("passes 4 MB"));
        assert_eq!(
            cut.map(|n| n.line),
            Some(MAX_OUTPUT / 1000 + 1),
            "{:?}",
            import.notes
        );
    }

    #[test]
    fn notes_past_their_cap_are_counted_in_one_note() {
        let mut out = Output::default();
        out.line("axiom: F", 1);
        for line in 1..=1500 {
            out.note(line, format!("note {line}"));
        }
        let import = out.finish();
        assert_eq!(import.notes.len(), MAX_NOTES + 1);
        assert_eq!(import.notes[0].line, 0);
        assert_eq!(
            import.notes[0].message,
            "500 more notes are not listed (only the first 1000 are)"
        );
    }
}

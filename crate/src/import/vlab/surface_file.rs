//! A cpfg surface file (`.s`, written by vlab's Bézier editor) as Meristem's `#surface` and
//! `#patch` lines, read as cpfg reads it (vlab `cpfg/patches.c`: `determine_transform`,
//! `get_patch`): six numbers (the box, unused), an optional `PRECISION S: s T: t`, `CONTACT
//! POINT X: Y: Z:`, `END POINT`, `HEADING`, `UP`, `SIZE:`, then patches, each a name, a `TOP
//! COLOR` line, the neighbours `AL: A: AR:`, `L: R:`, `BL: B: BR:` and 16 points x y z.

use crate::import::number;
use crate::model::MAX_PATCHES;
use crate::vocabulary::{DirectiveKind, FrameWord};

/// A surface file read: the lines that declare `~letter`.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct SurfaceLines {
    pub lines: Vec<String>,
    /// A note for what was read but not kept (patches past the limit).
    pub note: Option<String>,
}

/// One line of the file: its number (from 1) and words.
#[derive(Clone)]
struct Line<'a> {
    number: usize,
    words: Vec<&'a str>,
}

impl Line<'_> {
    /// The number after each of `labels` (`X:`, `Y:`, `Z:`).
    fn labelled(&self, labels: &[&str]) -> Result<Vec<f64>, String> {
        labels
            .iter()
            .map(|label| {
                let k = self
                    .words
                    .iter()
                    .position(|w| w.eq_ignore_ascii_case(label));
                let word = k.and_then(|k| self.words.get(k + 1)).copied().unwrap_or("");
                parse(word).ok_or_else(|| format!("'{label} {word}' is not a number"))
            })
            .collect()
    }

    fn starts(&self, keyword: &str) -> bool {
        self.words
            .join(" ")
            .to_ascii_uppercase()
            .starts_with(keyword)
    }
}

fn parse(word: &str) -> Option<f64> {
    word.parse::<f64>().ok().filter(|v| v.is_finite())
}

/// The file's non-empty lines, read in order.
struct Reader<'a> {
    lines: Vec<Line<'a>>,
    next: usize,
    file: &'a str,
    /// The number of the file's last line (where "the file ends" points).
    last: usize,
}

impl<'a> Reader<'a> {
    /// An error at `line` (`None`: the end of the file).
    fn at(&self, line: Option<&Line>, why: impl std::fmt::Display) -> String {
        format!(
            "{}, line {}: {why}",
            self.file,
            line.map_or(self.last, |l| l.number)
        )
    }

    fn line(&mut self, what: &str) -> Result<Line<'a>, String> {
        let k = self.next;
        self.next += 1;
        match self.lines.get(k) {
            Some(line) => Ok(line.clone()),
            None => Err(self.at(None, format!("the file ends before its {what}"))),
        }
    }

    /// The box (six numbers, unused), `PRECISION` if there, and the frame: the frame words and
    /// the file's precision.
    fn header(&mut self) -> Result<(Vec<String>, f64, [u32; 2]), String> {
        let mut box_numbers = 0;
        while box_numbers < 6 {
            let line = self.line("box")?;
            if let Some(w) = line.words.iter().find(|w| parse(w).is_none()) {
                return Err(self.at(Some(&line), format!("'{w}' is not a number of the box")));
            }
            box_numbers += line.words.len();
        }
        let mut line = self.line("contact point")?;
        let mut precision = [5, 5];
        if line.starts("PRECISION") {
            let p = line
                .labelled(&["S:", "T:"])
                .map_err(|e| self.at(Some(&line), e))?;
            precision = [p[0], p[1]].map(|v| v.round().clamp(1.0, 1e6) as u32);
            line = self.line("contact point")?;
        }
        let mut frame = Vec::new();
        for (keyword, word) in [
            ("CONTACT POINT", FrameWord::Contact),
            ("END POINT", FrameWord::End),
            ("HEADING", FrameWord::Heading),
            ("UP", FrameWord::Up),
        ] {
            if !line.starts(keyword) {
                return Err(self.at(Some(&line), format!("expected {keyword}")));
            }
            let v = line
                .labelled(&["X:", "Y:", "Z:"])
                .map_err(|e| self.at(Some(&line), e))?;
            let v: Vec<String> = v.iter().map(|x| number(*x)).collect();
            frame.push(format!("{} {}", word.name(), v.join(" ")));
            line = self.line("size")?;
        }
        let size = line
            .words
            .iter()
            .position(|w| w.eq_ignore_ascii_case("SIZE:"))
            .and_then(|k| line.words.get(k + 1))
            .and_then(|w| parse(w))
            .filter(|s| *s > 0.0)
            .ok_or_else(|| self.at(Some(&line), "expected SIZE: and a size above 0"))?;
        Ok((frame, size, precision))
    }

    /// The next patch's 48 numbers: its name, colours and neighbours (four lines), then its
    /// points.
    fn patch(&mut self) -> Result<Vec<f64>, String> {
        self.next += 1;
        for keyword in ["TOP COLOR", "AL:", "L:", "BL:"] {
            match self.lines.get(self.next) {
                Some(l) if l.starts(keyword) => self.next += 1,
                l => return Err(self.at(l, format!("expected the patch's {keyword} line"))),
            }
        }
        let mut points = Vec::with_capacity(48);
        while points.len() < 48 {
            let line = self.line("patch's 16 points")?;
            for w in &line.words {
                match parse(w) {
                    Some(v) => points.push(v),
                    None => {
                        let why = format!("'{w}' is not a number of a control point");
                        return Err(self.at(Some(&line), why));
                    }
                }
            }
        }
        if points.len() > 48 {
            let line = self.lines.get(self.next - 1);
            return Err(self.at(line, "more than 16 points x y z in a patch"));
        }
        Ok(points)
    }
}

/// Reads `text` (the file `file`) for the letter `letter`, with the view file's `scale` and
/// precision (0 0: the file's). An error says which line and why.
pub(super) fn read(
    text: &str,
    file: &str,
    letter: &str,
    scale: f64,
    precision: [u32; 2],
) -> Result<SurfaceLines, String> {
    let mut reader = Reader {
        lines: text
            .lines()
            .enumerate()
            .map(|(k, l)| Line {
                number: k + 1,
                words: l.split_whitespace().collect(),
            })
            .filter(|l| !l.words.is_empty())
            .collect(),
        next: 0,
        file,
        last: text.lines().count(),
    };
    let (frame, size, own) = reader.header()?;
    let precision = [0, 1].map(|i| {
        if precision[i] > 0 {
            precision[i]
        } else {
            own[i]
        }
    });
    let mut lines = vec![format!(
        "{} {letter} {} {} {} {} {} {} {} {}",
        DirectiveKind::Surface.written(),
        frame.join(" "),
        FrameWord::Size.name(),
        number(size),
        FrameWord::Scale.name(),
        number(scale),
        FrameWord::Precision.name(),
        precision[0],
        precision[1],
    )];
    let mut patches = 0;
    while reader.next < reader.lines.len() {
        let points = reader.patch()?;
        patches += 1;
        if patches <= MAX_PATCHES {
            let triples: Vec<String> = points
                .chunks_exact(3)
                .map(|p| p.iter().map(|x| number(*x)).collect::<Vec<_>>().join(" "))
                .collect();
            let patch = DirectiveKind::Patch.written();
            lines.push(format!("{patch} {letter} {}", triples.join(", ")));
        }
    }
    if patches == 0 {
        return Err(reader.at(None, "no patch"));
    }
    let note = (patches > MAX_PATCHES).then(|| {
        format!("{file} has {patches} patches: those after the {MAX_PATCHES}th are left out")
    });
    Ok(SurfaceLines { lines, note })
}

#[cfg(test)]
mod tests {
    use super::*;

    const HEADER: &str = "-1 1 0 2 0 0\nPRECISION S: 4 T: 6\nCONTACT POINT  X: 0 Y: 0 Z: 0\nEND POINT  X: 0 Y: 2 Z: 0\nHEADING  X: 0 Y: 1 Z: 0\nUP  X: 0 Y: 0 Z: 1\nSIZE: 2\n";
    const PATCH: &str = "P1\nTOP COLOR: 1 DIFFUSE: 0.00 BOTTOM COLOR: 1 DIFFUSE: 0.00\nAL: ~ A: ~ AR: ~\nL: ~ R: ~\nBL: ~ B: ~ BR: ~\n0 0 0 1 0 0 2 0 0 3 0 0\n0 1 0 1 1 0 2 1 0 3 1 0\n0 2 0 1 2 0 2 2 0 3 2 0\n0 3 0 1 3 0 2 3 0 3 3 0\n";

    #[test]
    fn a_file_becomes_a_surface_line_and_a_patch_line() {
        let text = format!("{HEADER}{PATCH}{PATCH}");
        let s = read(&text, "a.s", "x", 3.0, [0, 0]).unwrap();
        assert_eq!(s.lines.len(), 3);
        assert_eq!(
            s.lines[0],
            "#surface x contact 0 0 0 end 0 2 0 heading 0 1 0 up 0 0 1 size 2 scale 3 precision 4 6"
        );
        assert!(s.lines[1].starts_with("#patch x 0 0 0, 1 0 0, 2 0 0, 3 0 0, 0 1 0,"));
        // The view file's precision wins over the file's.
        let s = read(&text, "a.s", "x", 1.0, [8, 9]).unwrap();
        assert!(s.lines[0].ends_with("precision 8 9"));
    }

    #[test]
    fn malformed_files_say_where() {
        let cut = format!("{HEADER}{}", &PATCH[..PATCH.len() - 20]);
        let e = read(&cut, "a.s", "x", 1.0, [0, 0]).unwrap_err();
        assert!(
            e.starts_with("a.s, line ") && e.contains("ends before its patch"),
            "{e}"
        );
        let bad = HEADER.replace("Y: 1 Z: 0\nUP", "Y: one Z: 0\nUP");
        let e = read(&format!("{bad}{PATCH}"), "a.s", "x", 1.0, [0, 0]).unwrap_err();
        assert_eq!(e, "a.s, line 5: 'Y: one' is not a number");
        let e = read(HEADER, "a.s", "x", 1.0, [0, 0]).unwrap_err();
        assert!(e.contains("no patch"), "{e}");
        assert!(read("", "a.s", "x", 1.0, [0, 0]).is_err());
        assert!(read("1 2 3 4 5 6\nSIZE: 1", "a.s", "x", 1.0, [0, 0]).is_err());
    }
}

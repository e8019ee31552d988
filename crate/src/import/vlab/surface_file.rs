//! A cpfg surface file (`.s`, written by vlab's Bézier editor) as Meristem's `#surface` and
//! `#patch` lines, read as cpfg reads it (vlab `cpfg/patches.c`: `determine_transform`,
//! `get_patch`): six numbers (the box, unused), an optional `PRECISION S: s T: t`, `CONTACT
//! POINT X: Y: Z:`, `END POINT`, `HEADING`, `UP`, `SIZE:`, then patches, each a name, a `TOP
//! COLOR` line, the neighbours `AL: A: AR:`, `L: R:`, `BL: B: BR:` and 16 points x y z. lpfg
//! reads the same files and places them its own way ([`read_lpfg`]).

use crate::import::number;
use crate::model::MAX_PATCHES;
use crate::vocabulary::{DirectiveKind, FrameWord, PATCH_COLOR};

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

    /// The box (six numbers, unused), `PRECISION` if there, and the frame.
    fn header(&mut self) -> Result<Header, String> {
        let mut box_numbers = 0;
        while box_numbers < 6 {
            let line = self.line("box")?;
            if let Some(w) = line.words.iter().find(|w| parse(w).is_none()) {
                return Err(self.at(Some(&line), format!("'{w}' is not a number of the box")));
            }
            box_numbers += line.words.len();
        }
        let mut line = self.line("contact point")?;
        let mut precision = None;
        if line.starts("PRECISION") {
            let p = line
                .labelled(&["S:", "T:"])
                .map_err(|e| self.at(Some(&line), e))?;
            precision = Some([p[0], p[1]].map(|v| v.round().clamp(1.0, 1e6) as u32));
            line = self.line("contact point")?;
        }
        let mut frame = [[0.0; 3]; 4];
        for (k, keyword) in ["CONTACT POINT", "END POINT", "HEADING", "UP"]
            .into_iter()
            .enumerate()
        {
            if !line.starts(keyword) {
                return Err(self.at(Some(&line), format!("expected {keyword}")));
            }
            let v = line
                .labelled(&["X:", "Y:", "Z:"])
                .map_err(|e| self.at(Some(&line), e))?;
            frame[k] = [v[0], v[1], v[2]];
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
        let [contact, end, heading, up] = frame;
        Ok(Header {
            precision,
            contact,
            end,
            heading,
            up,
            size,
        })
    }

    /// The next patch: its name, colours and neighbours (four lines), then its 16 points.
    fn patch(&mut self) -> Result<FilePatch, String> {
        self.next += 1;
        let colours = self.lines.get(self.next).cloned();
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
        let (colors, diffuse) = colours.map(|l| sides(&l)).unwrap_or_default();
        Ok(FilePatch {
            points,
            colors,
            diffuse,
        })
    }
}

/// The `TOP COLOR: c DIFFUSE: d BOTTOM COLOR: c DIFFUSE: d` line's colours and diffuse factors,
/// top then bottom (cpfg's `fscanf`: what is missing or not a number is 0).
fn sides(line: &Line) -> ([u32; 2], [f64; 2]) {
    let after = |label: &str| -> Vec<f64> {
        line.words
            .iter()
            .enumerate()
            .filter(|(_, w)| w.eq_ignore_ascii_case(label))
            .map(|(k, _)| line.words.get(k + 1).and_then(|w| parse(w)).unwrap_or(0.0))
            .collect()
    };
    let (colors, diffuse) = (after("COLOR:"), after("DIFFUSE:"));
    let at = |v: &[f64], k: usize| v.get(k).copied().unwrap_or(0.0);
    (
        [0, 1].map(|k| at(&colors, k).clamp(0.0, u16::MAX as f64) as u32),
        [0, 1].map(|k| at(&diffuse, k)),
    )
}

/// A `.s` file's header.
struct Header {
    /// `PRECISION S: T:`, if the file gives it.
    precision: Option<[u32; 2]>,
    contact: [f64; 3],
    end: [f64; 3],
    heading: [f64; 3],
    up: [f64; 3],
    size: f64,
}

/// One patch of a `.s` file: its 48 numbers, its top and bottom colours (0: the turtle's) and
/// diffuse factors.
struct FilePatch {
    points: Vec<f64>,
    colors: [u32; 2],
    diffuse: [f64; 2],
}

/// A `.s` file read whole: its header, and its patches up to [`MAX_PATCHES`] of `count`.
struct SurfaceFile {
    header: Header,
    patches: Vec<FilePatch>,
    count: usize,
}

/// Reads `text`, the file `file`. An error says which line and why.
fn parse_file(text: &str, file: &str) -> Result<SurfaceFile, String> {
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
    let header = reader.header()?;
    let mut patches = Vec::new();
    let mut count = 0;
    while reader.next < reader.lines.len() {
        let patch = reader.patch()?;
        count += 1;
        if count <= MAX_PATCHES {
            patches.push(patch);
        }
    }
    if count == 0 {
        return Err(reader.at(None, "no patch"));
    }
    Ok(SurfaceFile {
        header,
        patches,
        count,
    })
}

/// How a view file's surface line asks for a `.s` file.
pub(super) struct Wanted<'a> {
    /// The file's name (for messages).
    pub file: &'a str,
    /// The letter `~X` draws it by.
    pub letter: &'a str,
    /// The view file's scale.
    pub scale: f64,
    /// The view file's precision (0 0: the file's, or the tool's default).
    pub precision: [u32; 2],
    /// Whether the patches' colours are drawn (cpfg draws them with a colour map, not with
    /// materials).
    pub colours: bool,
}

/// Reads `text` for `wanted` as cpfg does: the file's frame as `#surface` frame words, its
/// patches as `#patch` lines with their colours. An error says which line and why.
pub(super) fn read(text: &str, wanted: &Wanted) -> Result<SurfaceLines, String> {
    let f = parse_file(text, wanted.file)?;
    let h = &f.header;
    let own = h.precision.unwrap_or([5, 5]);
    let precision = [0, 1].map(|i| {
        if wanted.precision[i] > 0 {
            wanted.precision[i]
        } else {
            own[i]
        }
    });
    let frame = [
        (FrameWord::Contact, h.contact),
        (FrameWord::End, h.end),
        (FrameWord::Heading, h.heading),
        (FrameWord::Up, h.up),
    ]
    .map(|(word, v)| format!("{} {}", word.name(), triple(v, number)));
    let first = format!(
        "{} {}",
        frame.join(" "),
        size_scale(h.size, wanted, precision)
    );
    Ok(lines(&f, wanted, first, (|p| p, number), wanted.colours))
}

/// Reads `text` for `wanted` as lpfg does (`lpfg/surface.cpp`, `Surface::_LoadSurface`, and the
/// turtle's `Surface`): the end point and the file's precision are not read (the view file's
/// precision or 10 × 10), nor the patches' colours (lpfg draws a surface in the turtle's
/// colour); a point p becomes R(p − contact) / size, R the matrix whose columns are −left,
/// heading and up (left = up × heading), drawn along −L, H and U of the turtle. Meristem draws x
/// along L: the points are written as lpfg places them with x negated, in the default frame.
pub(super) fn read_lpfg(text: &str, wanted: &Wanted) -> Result<SurfaceLines, String> {
    let f = parse_file(text, wanted.file)?;
    let h = &f.header;
    let unit = |v: [f64; 3]| {
        let d = glam::DVec3::from_array(v);
        (d.length() >= 0.001).then(|| d.normalize())
    };
    let (Some(heading), Some(up)) = (unit(h.heading), unit(h.up)) else {
        return Err(format!("{}: its heading or up is zero", wanted.file));
    };
    let right = heading.cross(up);
    let place = move |p: [f64; 3]| {
        let v = right * p[0] + heading * p[1] + up * p[2];
        [-v.x, v.y, v.z]
    };
    let precision = [0, 1].map(|i| match wanted.precision[i] {
        0 => 10,
        p => p,
    });
    let first = format!(
        "{} {} {}",
        FrameWord::Contact.name(),
        triple(place(h.contact), super::short),
        size_scale(h.size, wanted, precision)
    );
    Ok(lines(&f, wanted, first, (place, super::short), false))
}

/// `size s scale k precision s t`.
fn size_scale(size: f64, wanted: &Wanted, precision: [u32; 2]) -> String {
    format!(
        "{} {} {} {} {} {} {}",
        FrameWord::Size.name(),
        number(size),
        FrameWord::Scale.name(),
        number(wanted.scale),
        FrameWord::Precision.name(),
        precision[0],
        precision[1],
    )
}

fn triple(v: [f64; 3], write: fn(f64) -> String) -> String {
    v.map(write).join(" ")
}

/// The `#surface` line (its words after the letter: `words`) and a `#patch` line a patch, each
/// point through `place` and written by `write`, with its colours when `colours`; a note for
/// the patches left out and for diffuse factors.
fn lines(
    f: &SurfaceFile,
    wanted: &Wanted,
    words: String,
    (place, write): (impl Fn([f64; 3]) -> [f64; 3], fn(f64) -> String),
    colours: bool,
) -> SurfaceLines {
    let letter = wanted.letter;
    let mut lines = vec![format!(
        "{} {letter} {words}",
        DirectiveKind::Surface.written()
    )];
    let patch = DirectiveKind::Patch.written();
    for p in &f.patches {
        let triples: Vec<String> = p
            .points
            .chunks_exact(3)
            .map(|q| triple(place([q[0], q[1], q[2]]), write))
            .collect();
        let mut line = format!("{patch} {letter} {}", triples.join(", "));
        if colours {
            line.push_str(&patch_colours(p.colors));
        }
        lines.push(line);
    }
    let mut notes = Vec::new();
    if f.count > MAX_PATCHES {
        notes.push(format!(
            "{} has {} patches: those after the {MAX_PATCHES}th are left out",
            wanted.file, f.count
        ));
    }
    if colours && f.patches.iter().any(|p| p.diffuse != [0.0, 0.0]) {
        notes.push(format!(
            "{} gives its patches diffuse factors for cpfg's own lighting: Meristem lights every surface alike, so they are not kept",
            wanted.file
        ));
    }
    SurfaceLines {
        lines,
        note: (!notes.is_empty()).then(|| notes.join("; ")),
    }
}

/// ` color top [bottom]` for a patch's colours, empty when both are 0 (the turtle's).
fn patch_colours([top, bottom]: [u32; 2]) -> String {
    match (top, bottom) {
        (0, 0) => String::new(),
        (t, b) if t == b => format!(" {PATCH_COLOR} {t}"),
        (t, b) => format!(" {PATCH_COLOR} {t} {b}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wanted(scale: f64, precision: [u32; 2]) -> Wanted<'static> {
        Wanted {
            file: "a.s",
            letter: "x",
            scale,
            precision,
            colours: true,
        }
    }

    const HEADER: &str = "-1 1 0 2 0 0\nPRECISION S: 4 T: 6\nCONTACT POINT  X: 0 Y: 0 Z: 0\nEND POINT  X: 0 Y: 2 Z: 0\nHEADING  X: 0 Y: 1 Z: 0\nUP  X: 0 Y: 0 Z: 1\nSIZE: 2\n";
    const PATCH: &str = "P1\nTOP COLOR: 1 DIFFUSE: 0.00 BOTTOM COLOR: 1 DIFFUSE: 0.00\nAL: ~ A: ~ AR: ~\nL: ~ R: ~\nBL: ~ B: ~ BR: ~\n0 0 0 1 0 0 2 0 0 3 0 0\n0 1 0 1 1 0 2 1 0 3 1 0\n0 2 0 1 2 0 2 2 0 3 2 0\n0 3 0 1 3 0 2 3 0 3 3 0\n";

    #[test]
    fn a_file_becomes_a_surface_line_and_a_patch_line() {
        let text = format!("{HEADER}{PATCH}{PATCH}");
        let s = read(&text, &wanted(3.0, [0, 0])).unwrap();
        assert_eq!(s.lines.len(), 3);
        assert_eq!(
            s.lines[0],
            "#surface x contact 0 0 0 end 0 2 0 heading 0 1 0 up 0 0 1 size 2 scale 3 precision 4 6"
        );
        assert!(s.lines[1].starts_with("#patch x 0 0 0, 1 0 0, 2 0 0, 3 0 0, 0 1 0,"));
        // The view file's precision wins over the file's.
        let s = read(&text, &wanted(1.0, [8, 9])).unwrap();
        assert!(s.lines[0].ends_with("precision 8 9"));
    }

    #[test]
    fn patch_colours_are_kept_with_a_colour_map_and_diffuse_factors_are_noted() {
        let second = PATCH.replace(
            "TOP COLOR: 1 DIFFUSE: 0.00 BOTTOM COLOR: 1 DIFFUSE: 0.00",
            "TOP COLOR: 32 DIFFUSE: 0.5 BOTTOM COLOR: 40 DIFFUSE: 0.00",
        );
        let third = PATCH
            .replace("TOP COLOR: 1", "TOP COLOR: 0")
            .replace("BOTTOM COLOR: 1", "BOTTOM COLOR: 0");
        let text = format!("{HEADER}{PATCH}{second}{third}");
        let s = read(&text, &wanted(1.0, [0, 0])).unwrap();
        assert!(s.lines[1].ends_with(", 3 3 0 color 1"), "{}", s.lines[1]);
        assert!(
            s.lines[2].ends_with(", 3 3 0 color 32 40"),
            "{}",
            s.lines[2]
        );
        assert!(s.lines[3].ends_with(", 3 3 0"), "{}", s.lines[3]);
        assert!(s.note.unwrap().contains("diffuse factors"));
        // With materials cpfg draws the turtle's material: no colours.
        let plain = Wanted {
            colours: false,
            ..wanted(1.0, [0, 0])
        };
        let s = read(&text, &plain).unwrap();
        assert!(s.lines.iter().all(|l| !l.contains("color")));
        assert_eq!(s.note, None);
    }

    #[test]
    fn malformed_files_say_where() {
        let cut = format!("{HEADER}{}", &PATCH[..PATCH.len() - 20]);
        let e = read(&cut, &wanted(1.0, [0, 0])).unwrap_err();
        assert!(
            e.starts_with("a.s, line ") && e.contains("ends before its patch"),
            "{e}"
        );
        let bad = HEADER.replace("Y: 1 Z: 0\nUP", "Y: one Z: 0\nUP");
        let e = read(&format!("{bad}{PATCH}"), &wanted(1.0, [0, 0])).unwrap_err();
        assert_eq!(e, "a.s, line 5: 'Y: one' is not a number");
        let e = read(HEADER, &wanted(1.0, [0, 0])).unwrap_err();
        assert!(e.contains("no patch"), "{e}");
        assert!(read("", &wanted(1.0, [0, 0])).is_err());
        assert!(read("1 2 3 4 5 6\nSIZE: 1", &wanted(1.0, [0, 0])).is_err());
    }
}

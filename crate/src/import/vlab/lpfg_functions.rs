//! lpfg's list of functions: the function set (`.fset`), the timeline functions (`.tset`, written
//! by vlab's `timeline` tool), the values (`.vset`) and the function files (`.func`) its command
//! line names, read in the order lpfg numbers them (`LPFG::_NewModel`: the `.fset`, the `.tset`,
//! the `.vset`, then the `.func` files; one list, numbered from 1), so that `func(k, x)`,
//! `tfunc(k, t)` and `val(k)` find the same entry by number as by name (lpfg defines each name as
//! its number when it compiles the L-system). lpfg tells a file's format by its first line, not
//! its extension (`Functions::Load`): `funcgalleryver 1 1` is a function set, `timeEdit 1 2`
//! timeline functions, anything else a list of `#define NAME value` lines. Where lpfg would refuse
//! a file (and run no model), the entries before the fault are read and a note gives the file, the
//! line and what is wrong.

use super::{
    function, function_set, identifier, Body, CurveFunction, Files, FunctionKind, Reader, Span,
    View,
};
use crate::import::{leading_float, number};
use crate::vocabulary::DirectiveKind;

/// The function files lpfg is started with.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(in crate::import) struct LpfgFiles {
    function_set: Option<String>,
    timeline: Option<String>,
    values: Option<String>,
    functions: Vec<String>,
}

impl LpfgFiles {
    /// Takes a word of lpfg's command line that names one of its function files (lpfg keeps the
    /// last set of each kind named, and every `.func`).
    pub(super) fn name(&mut self, word: &str) {
        let word = word.to_string();
        if word.ends_with(".fset") {
            self.function_set = Some(word);
        } else if word.ends_with(".tset") {
            self.timeline = Some(word);
        } else if word.ends_with(".vset") {
            self.values = Some(word);
        } else if word.ends_with(".func") {
            self.functions.push(word);
        }
    }

    /// An object without a command line in its `specifications`: its first `.fset`, `.tset`
    /// and `.vset`, as lpfg would be started with them.
    pub(super) fn guessed(all: &Files) -> LpfgFiles {
        let first = |ext: &str| all.with(ext).first().map(|s| s.to_string());
        LpfgFiles {
            function_set: first(".fset"),
            timeline: first(".tset"),
            values: first(".vset"),
            functions: Vec::new(),
        }
    }
}

/// Reads the files into `view.functions`, in lpfg's order; a set the view file already read
/// (cpfg's `function set:`, named in `view_text`) is not read again.
pub(super) fn read(all: &Files, files: &LpfgFiles, view_text: &str, view: &mut View) {
    let sets = [
        (&files.function_set, "function set", "func"),
        (&files.timeline, "timeline functions", "tfunc"),
        (&files.values, "values", "val"),
    ];
    for (file, what, call) in sets {
        let Some(file) = file else { continue };
        if view_text.contains(file.as_str()) {
            continue;
        }
        match all.text(file) {
            Some(text) => load(&text, file, view),
            None => view.notes.push(format!(
                "{file} (lpfg's {what}) was not opened with the object: {call}(…) of what it holds is not translated"
            )),
        }
    }
    for file in &files.functions {
        let f = all
            .text(file)
            .and_then(|text| function(&text, None, file, Reader::Lpfg, view));
        if f.is_none() {
            view.notes.push(format!(
                "the function file {file} could not be read: func({}, …) is not translated",
                view.functions.len() + 1
            ));
        }
        view.functions.push(f);
    }
}

/// One file of functions, in the format its first line says.
fn load(text: &str, file: &str, view: &mut View) {
    let first = text.lines().next().unwrap_or("");
    let mut words = first.split_whitespace();
    let kind = words.next().unwrap_or("");
    if kind != "funcgalleryver" && kind != "timeEdit" {
        values(text, file, view);
        return;
    }
    let version: Option<Vec<u32>> = words.take(2).map(|w| w.parse().ok()).collect();
    match version.as_deref() {
        Some([1, 1]) => function_set(text, file, Reader::Lpfg, view),
        Some([1, 2]) => timeline(text, file, view),
        _ => note(
            view,
            file,
            1,
            format!("'{}' is not a version lpfg reads (1 1, a function set, or 1 2, timeline functions): the file is not read", first.trim()),
        ),
    }
}

/// A note about line `line` of `file`.
fn note(view: &mut View, file: &str, line: usize, message: String) {
    view.notes.push(format!("{file}, line {line}: {message}"));
}

/// The lines of a file after its first, numbered from 2, trimmed, blank ones skipped.
struct Lines<'a> {
    lines: Vec<(usize, &'a str)>,
    /// The index in `lines` of the next line to take.
    next: usize,
    /// The number of the last line taken (or of the last line of the file).
    at: usize,
}

impl<'a> Lines<'a> {
    fn new(text: &'a str) -> Lines<'a> {
        let lines: Vec<(usize, &str)> = text
            .lines()
            .enumerate()
            .skip(1)
            .map(|(i, l)| (i + 1, l.trim()))
            .filter(|(_, l)| !l.is_empty())
            .collect();
        Lines {
            lines,
            next: 0,
            at: text.lines().count().max(1),
        }
    }

    /// The next line and its number, without taking it.
    fn peek(&self) -> Option<(usize, &'a str)> {
        self.lines.get(self.next).copied()
    }

    /// Takes the next line and its number.
    fn take(&mut self) -> Option<(usize, &'a str)> {
        let line = self.peek()?;
        self.next += 1;
        self.at = line.0;
        Some(line)
    }

    /// The next line, which must start with `key` (`start:`…): what follows the key.
    fn field(&mut self, key: &str) -> Result<&'a str, (usize, String)> {
        match self.take() {
            Some((n, line)) => line
                .strip_prefix(key)
                .map(str::trim)
                .ok_or_else(|| (n, format!("lpfg expects '{key}' here, not '{line}'"))),
            None => Err((self.at, format!("the file ends where lpfg expects '{key}'"))),
        }
    }

    /// The next line's `key` and the number after it.
    fn number(&mut self, key: &str) -> Result<f64, (usize, String)> {
        let value = self.field(key)?;
        value
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| (self.at, format!("'{key} {value}' is not a number")))
    }
}

/// The most timeline functions a file may hold (vlab's timeline tool shows a few dozen).
const MAX_ITEMS: usize = 1000;

/// lpfg's timeline functions (`Functions::_Read0102`): `items: n`, then for each `start:`,
/// `end:`, `name:`, an optional `color:`, `startLabel:` and `endLabel:` (the values of the `.vset`
/// the timeline tool ties its ends to; lpfg reads the numbers), and a function file between
/// `timelineFunceditFileStart:` and `timelineFunceditFileEnd:`.
fn timeline(text: &str, file: &str, view: &mut View) {
    let mut lines = Lines::new(text);
    let items = match lines.field("items:") {
        Ok(v) => v.parse::<usize>().map_err(|_| {
            (
                lines.at,
                format!("'items: {v}' is not a count: no timeline function is read"),
            )
        }),
        Err(e) => Err(e),
    };
    let items = match items {
        Ok(n) if n > MAX_ITEMS => {
            let at = lines.at;
            note(view, file, at, format!("{n} timeline functions are more than the {MAX_ITEMS} read: the first {MAX_ITEMS} are"));
            MAX_ITEMS
        }
        Ok(n) => n,
        Err((line, why)) => return note(view, file, line, why),
    };
    for k in 1..=items {
        match item(&mut lines, file, view) {
            Ok(f) => view.functions.push(f),
            Err((line, why)) => {
                // The items not read keep their numbers: the values after them keep theirs.
                view.functions.extend((k..=items).map(|_| None));
                return note(
                    view,
                    file,
                    line,
                    format!("{why}: lpfg refuses the file (and runs no model); its timeline functions from the {} on are not translated", ordinal(k)),
                );
            }
        }
    }
    if let Some((n, _)) = lines.peek() {
        note(
            view,
            file,
            n,
            format!("the file goes on after the {items} timeline functions its 'items:' line counts: lpfg reads no more, nor does Meristem"),
        );
    }
}

/// `1st`, `2nd`, `3rd`, `4th`… for a note.
fn ordinal(k: usize) -> String {
    let suffix = match (k % 10, k % 100) {
        (1, n) if n != 11 => "st",
        (2, n) if n != 12 => "nd",
        (3, n) if n != 13 => "rd",
        _ => "th",
    };
    format!("{k}{suffix}")
}

/// One timeline function: `None` (with a note) when its function file cannot be read, an error
/// (its line and why) when the item itself is not as lpfg reads it.
fn item(
    lines: &mut Lines,
    file: &str,
    view: &mut View,
) -> Result<Option<CurveFunction>, (usize, String)> {
    let start = lines.number("start:")?;
    let end = lines.number("end:")?;
    lines.field("name:")?;
    if lines.peek().is_some_and(|(_, l)| l.starts_with("color:")) {
        lines.take();
    }
    let start_label = lines.field("startLabel:")?.to_string();
    let end_label = lines.field("endLabel:")?.to_string();
    lines.field("timelineFunceditFileStart:")?;
    let first = lines.at + 1;
    let mut body = String::new();
    loop {
        match lines.take() {
            Some((_, "timelineFunceditFileEnd:")) => break,
            Some((_, line)) => {
                body.push_str(line);
                body.push('\n');
            }
            None => {
                return Err((
                    first - 1,
                    "the function file this line starts has no 'timelineFunceditFileEnd:'".into(),
                ))
            }
        }
    }
    let fver = body.split_whitespace().take(3).collect::<Vec<_>>() == ["fver", "1", "1"];
    let named = body.lines().any(|l| l.starts_with("name:"));
    let f = if fver && named {
        function(&body, None, file, Reader::Lpfg, view)
    } else {
        None
    };
    let Some(mut f) = f else {
        note(view, file, first, format!("the timeline function here is not a function file lpfg reads ('fver 1 1', 'name:', 'samples:', 'points:' and at least 4 points): tfunc({}, …) is not translated", view.functions.len() + 1));
        return Ok(None);
    };
    if start == end {
        note(view, file, first - 1, format!("the timeline function {} starts and ends at {}: lpfg divides by their difference, 0; Meristem reads it at its start before that time and at its end from then on", f.source, number(start)));
    }
    f.about = format!(
        "the timeline function of {file}, from t = {} to t = {}",
        number(start),
        number(end)
    );
    f.kind = FunctionKind::Timeline(Span {
        start,
        end,
        start_label,
        end_label,
    });
    Ok(Some(f))
}

/// lpfg's values (`Functions::_Read0103`): lines `#define NAME value` (blank lines skipped),
/// each a `#define` that `val(NAME)` reads.
fn values(text: &str, file: &str, view: &mut View) {
    for (i, line) in text.lines().enumerate() {
        let words: Vec<&str> = line.split([' ', '\t']).filter(|w| !w.is_empty()).collect();
        let Some(&first) = words.first() else {
            continue;
        };
        let value = words.get(2).and_then(|w| leading_float(w));
        match (first, words.get(1), value) {
            // dialect: lpfg's value files are C's #define lines
            ("#define", Some(name), Some(value)) => {
                let id = identifier(name, view);
                let line = format!(
                    "{} {id} {} // val({name}) of {file}",
                    DirectiveKind::Define.written(),
                    number(value)
                );
                view.functions.push(Some(CurveFunction {
                    name: id,
                    source: name.to_string(),
                    about: format!("val({name}) of {file}"),
                    body: Body::Lines(vec![line]),
                    kind: FunctionKind::Value(value),
                }));
            }
            _ => note(
                view,
                file,
                i + 1,
                format!("'{}' is not '#define NAME value' with a number: lpfg refuses the file (and runs no model); Meristem skips the line", line.trim()),
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read_one(name: &str, text: &str) -> View {
        let mut view = View::default();
        load(text, name, &mut view);
        view
    }

    const TSET: &str = "timeEdit 1 2\nitems: 2\nstart: 2\nend: 8\nname: GROWTH\ncolor: 91,115,229\nstartLabel: \nendLabel: \ntimelineFunceditFileStart:\nfver 1 1\nname: GROWTH\nsamples: 21\nflip: off\npoints: 4\n0 0\n0.333333 0\n0.666667 0\n1 1\ntimelineFunceditFileEnd:\nstart: 0\nend: 1\nname: FLAT\nstartLabel: A\nendLabel: B\ntimelineFunceditFileStart:\nfver 1 1\nname: FLAT\nsamples: 3\nflip: off\npoints: 4\n0 1\n0.3 1\n0.6 1\n1 1\ntimelineFunceditFileEnd:\n";

    #[test]
    fn a_timeline_file_gives_its_functions_with_their_times() {
        let view = read_one("f.tset", TSET);
        assert!(view.notes.is_empty(), "{:?}", view.notes);
        let f: Vec<&CurveFunction> = view.functions.iter().flatten().collect();
        assert_eq!(f.len(), 2);
        assert_eq!(f[0].name, "GROWTH");
        let span = |start, end, start_label: &str, end_label: &str| {
            FunctionKind::Timeline(Span {
                start,
                end,
                start_label: start_label.into(),
                end_label: end_label.into(),
            })
        };
        assert_eq!(f[0].kind, span(2.0, 8.0, "", ""));
        assert_eq!(f[1].kind, span(0.0, 1.0, "A", "B"));
        assert!(f[0].lines()[0].contains("the timeline function of f.tset, from t = 2 to t = 8,"));
        // lpfg samples 21 times; FLAT's 3 samples are raised to lpfg's least, 10.
        assert!(f[0].lines()[1].starts_with("#table GROWTH 0 0 0.05 "));
        assert_eq!(f[1].lines()[1].split_whitespace().count(), 2 + 2 * 10);
    }

    #[test]
    fn a_value_file_gives_defines_and_says_which_lines_it_skips() {
        let view = read_one(
            "v.vset",
            "#define BR_END 15.4362\n\n#define\tSIM_END 23.2721 extra\nBR 3\n#define X abc\n",
        );
        let names: Vec<String> = view
            .functions
            .iter()
            .flatten()
            .map(|f| f.lines()[0].clone())
            .collect();
        assert_eq!(
            names,
            [
                "#define BR_END 15.4362 // val(BR_END) of v.vset",
                "#define SIM_END 23.2721 // val(SIM_END) of v.vset"
            ]
        );
        assert_eq!(view.notes.len(), 2, "{:?}", view.notes);
        assert!(view.notes[0].starts_with("v.vset, line 4: 'BR 3' is not"));
        assert!(view.notes[1].starts_with("v.vset, line 5: '#define X abc'"));
    }

    #[test]
    fn malformed_timelines_say_the_line_and_keep_what_came_before() {
        // Each: the file, how many entries it gives (the first read, the second not), the note.
        let cases: [(String, usize, &str); 6] = [
            (
                TSET.replacen("end: 1\n", "end: one\n", 1),
                2,
                "f.tset, line 21: 'end: one' is not a number",
            ),
            (
                TSET.replacen("0.6 1\n", "", 1),
                2,
                "f.tset, line 26: the timeline function here is not",
            ),
            (
                TSET[..TSET.len() - 60].to_string(),
                2,
                "f.tset, line 25: the function file this line starts has no 'timelineFunceditFileEnd:'",
            ),
            (
                format!("{TSET}start: 0\n"),
                2,
                "goes on after the 2 timeline functions",
            ),
            (
                "timeEdit 1 2\nitems: two\n".into(),
                0,
                "f.tset, line 2: 'items: two' is not a count",
            ),
            (
                "timeEdit 1 3\n".into(),
                0,
                "f.tset, line 1: 'timeEdit 1 3' is not a version",
            ),
        ];
        for (text, entries, piece) in cases {
            let view = read_one("f.tset", &text);
            assert_eq!(view.functions.len(), entries, "{piece}");
            if entries == 2 {
                assert!(view.functions[0].is_some(), "{piece}");
            }
            assert!(
                view.notes.len() == 1 && view.notes[0].contains(piece),
                "{piece}: {:?}",
                view.notes
            );
        }
    }

    #[test]
    fn lpfg_numbers_sets_timelines_values_then_function_files() {
        let mut files = LpfgFiles::default();
        for w in ["a.vset", "b.tset", "c.fset", "d.func", "e.fset"] {
            files.name(w);
        }
        assert_eq!(files.function_set.as_deref(), Some("e.fset"));
        assert_eq!(files.timeline.as_deref(), Some("b.tset"));
        assert_eq!(files.values.as_deref(), Some("a.vset"));
        assert_eq!(files.functions, ["d.func"]);
    }

    #[test]
    fn ordinals_read_as_english() {
        assert_eq!(ordinal(1), "1st");
        assert_eq!(ordinal(12), "12th");
        assert_eq!(ordinal(23), "23rd");
    }
}

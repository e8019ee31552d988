//! The importers on real files: every file under `tests/import/` (Lparser `.ls` files from the
//! Lparser distribution, cpfg `.l` files from the Virtual Laboratory, L-Py `.lpy` files from
//! L-Py's share/, Green's worked example) is imported; the output must parse and resolve without
//! errors and carry exactly the expected notes. Known files are then derived and compared with
//! what the other tool gives: Green's published step, and, for Lparser, an independent model of
//! Lparser 2.1's own rewriting and turtle (`L_system`, `L_draw`) that the translation must draw
//! segment for segment.

use meristem::import::{self, Dialect, Import};
use meristem::model::LString;
use meristem::pipeline::{build, Build, BuildOptions};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/import")
}

fn files(dir: &Path, found: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir)
        .expect("tests/import exists")
        .flatten()
    {
        let path = entry.path();
        if path.is_dir() {
            files(&path, found);
        } else if path.extension().is_none_or(|e| e != "md") {
            found.push(path);
        }
    }
}

fn read(relative: &str) -> String {
    std::fs::read_to_string(root().join(relative)).expect("test file")
}

fn import_file(relative: &str) -> Import {
    let text = read(relative);
    let dialect = import::detect(&text, relative).expect("dialect detected");
    import::import(&text, dialect)
}

/// Every file, its dialect, and the notes it must give: (line, a piece of the message). The notes
/// given must be exactly these (one note per entry).
type Notes = &'static [(usize, &'static str)];

const EXPECTED: &[(&str, Dialect, Notes)] = &[
    (
        "green/worked-example.txt",
        Dialect::Green,
        &[(0, "how many steps"), (8, "p<0.4 (line 7) and p>0.4")],
    ),
    (
        "green/random-variables.txt",
        Dialect::Green,
        &[
            (0, "how many steps"),
            (3, "standard deviation or a variance"),
        ],
    ),
    (
        "cpfg/snowflake.l",
        Dialect::Cpfg,
        &[(0, "angle increment is in the object's view file")],
    ),
    (
        "cpfg/compound-homo.l",
        Dialect::Cpfg,
        &[
            (0, "angle increment is in the object's view file"),
            (0, "colours are in the object's view file"),
        ],
    ),
    (
        "cpfg/recursive.l",
        Dialect::Cpfg,
        &[
            (0, "angle increment is in the object's view file"),
            (0, "colours are in the object's view file"),
        ],
    ),
    (
        "cpfg/alternating.l",
        Dialect::Cpfg,
        &[
            (0, "angle increment is in the object's view file"),
            (0, "colours are in the object's view file"),
        ],
    ),
    (
        "cpfg/basipetal.l",
        Dialect::Cpfg,
        &[
            (0, "angle increment is in the object's view file"),
            (0, "colours are in the object's view file"),
        ],
    ),
    (
        "cpfg/phyllotaxis.l",
        Dialect::Cpfg,
        &[
            (9, "@c(d) draws a disc of diameter d"),
            (0, "colours are in the object's view file"),
        ],
    ),
    (
        "cpfg/monopodial.l",
        Dialect::Cpfg,
        &[
            (0, "colours are in the object's view file"),
            (
                23,
                "func(1, …) reads function 1 of the object's view file (.v), which was not opened",
            ),
            (
                24,
                "func(2, …) reads function 2 of the object's view file (.v), which was not opened",
            ),
        ],
    ),
    (
        "cpfg/lychnis.l",
        Dialect::Cpfg,
        &[
            (0, "colours are in the object's view file"),
            (50, "of the object's view file (.v), which was not opened"),
            (52, "of the object's view file (.v), which was not opened"),
            (53, "of the object's view file (.v), which was not opened"),
            (58, "of the object's view file (.v), which was not opened"),
            (66, "of the object's view file (.v), which was not opened"),
            (71, "of the object's view file (.v), which was not opened"),
            (
                71,
                "cpfg's f before a control point of a generalized cylinder",
            ),
            (76, "of the object's view file (.v), which was not opened"),
            (83, "of the object's view file (.v), which was not opened"),
        ],
    ),
    ("lpy/lsystem1.9.lpy", Dialect::Lpy, &[]),
    ("lpy/lsystem1.4.lpy", Dialect::Lpy, &[]),
    ("lpy/lsystem-fig1.37.lpy", Dialect::Lpy, &[]),
    ("lpy/lsystem-fig1.37b.lpy", Dialect::Lpy, &[]),
    (
        "lpy/06a-simple-differentiation.lpy",
        Dialect::Lpy,
        &[(23, "@c is not a Meristem command")],
    ),
    (
        "lpy/ex_vonkoch.lpy",
        Dialect::Lpy,
        &[(8, "function '__initialiseContext__'")],
    ),
    (
        "lpy/ex_lsystem1.lpy",
        Dialect::Lpy,
        &[
            (17, "function 'Start'"),
            (21, "function 'End'"),
            (25, "function 'StartEach'"),
            (28, "function 'EndEach'"),
            (73, "L-Py's '_' becomes one for Meristem's '!'"),
        ],
    ),
    (
        "lparser/abop-bush.ls",
        Dialect::Lparser,
        &[(4, "thickness:")],
    ),
    (
        "lparser/abop-monopodial-tree.ls",
        Dialect::Lparser,
        &[
            (15, "thickness:"),
            (20, "'$' is translated"),
            (23, "6 radians"),
        ],
    ),
    (
        "lparser/abop-ternary-tree.ls",
        Dialect::Lparser,
        &[
            (7, "thickness:"),
            (11, "'t' (gravity)"),
            (12, "'$' is translated"),
        ],
    ),
    ("lparser/axis.ls", Dialect::Lparser, &[(31, "thickness:")]),
    (
        "lparser/cello_plant.ls",
        Dialect::Lparser,
        &[(5, "thickness:"), (6, "'switch_yz'"), (7, "'shape'")],
    ),
    (
        "lparser/conifer-type-tree.ls",
        Dialect::Lparser,
        &[
            (4, "thickness:"),
            (10, "'t' (gravity)"),
            (11, "'$' is translated"),
            (14, "6 radians"),
        ],
    ),
    (
        "lparser/fern-plant.ls",
        Dialect::Lparser,
        &[
            (5, "thickness:"),
            (17, "'$' is translated"),
            (17, "'t' (gravity)"),
        ],
    ),
    (
        "lparser/spiral_plant.ls",
        Dialect::Lparser,
        &[(6, "thickness:"), (8, "'shape'"), (9, "'switch_yz'")],
    ),
    (
        "lparser/tree5.ls",
        Dialect::Lparser,
        &[
            (5, "thickness:"),
            (6, "'shape'"),
            (7, "'switch_yz'"),
            (14, "'$' is translated"),
            (14, "'t' (gravity)"),
        ],
    ),
];

fn resolve_errors(text: &str) -> Vec<String> {
    let (file, mut diagnostics) = meristem::syntax::parse(text);
    diagnostics.extend(meristem::model::resolve(&file).1);
    diagnostics
        .iter()
        .filter(|d| d.severity == meristem::diagnostics::Severity::Error)
        .map(|d| format!("{} {}", d.code, d.message))
        .collect()
}

#[test]
fn every_test_file_imports_resolves_and_gives_exactly_its_notes() {
    let mut found = Vec::new();
    files(&root(), &mut found);
    found.sort();
    assert!(found.len() >= EXPECTED.len());
    for path in found {
        let relative = path
            .strip_prefix(root())
            .expect("under the root")
            .to_string_lossy()
            .replace('\\', "/");
        let Some((_, dialect, notes)) = EXPECTED.iter().find(|(p, _, _)| *p == relative) else {
            panic!("{relative}: add it to EXPECTED with its notes");
        };
        let text = std::fs::read_to_string(&path).expect("UTF-8 test file");
        assert_eq!(
            import::detect(&text, &relative),
            Some(*dialect),
            "{relative}"
        );
        let result = import::import(&text, *dialect);
        assert!(!result.is_empty(), "{relative}: nothing imported");
        let errors = resolve_errors(&result.text);
        assert!(errors.is_empty(), "{relative}: {errors:?}\n{}", result.text);
        let mut unmatched: Vec<&(usize, &str)> = notes.iter().collect();
        for note in &result.notes {
            let at = unmatched
                .iter()
                .position(|(line, piece)| *line == note.line && note.message.contains(piece));
            match at {
                Some(i) => {
                    unmatched.remove(i);
                }
                None => panic!("{relative}: unexpected note {note:?}"),
            }
        }
        assert!(
            unmatched.is_empty(),
            "{relative}: missing notes {unmatched:?}"
        );
    }
}

// ------------------------------------------------------------------------------------------------
// Lparser: an independent model of Lparser 2.1 (`L_system` and `L_draw` of Lparser2.c).

/// An Lparser file reduced to what `L_system` and `L_draw` use.
struct Lparser {
    axiom: &'static str,
    rules: &'static [&'static str],
    angle: f64,
    thickness: f64,
    min_thickness: f64,
    /// `dis`: 100 for the positional format's Lparser, 1 for Lparser 2.
    dis: f64,
}

/// `L_system`: every character rewritten in parallel by its first rule, by the default rules of
/// the turtle characters (themselves), or by `_` for any other character.
fn lparser_expand(l: &Lparser, depth: usize) -> String {
    let mut table: HashMap<char, &str> = HashMap::new();
    for rule in l.rules.iter().rev() {
        let mut chars = rule.chars();
        let pred = chars.next().expect("rule");
        table.insert(pred, &rule[pred.len_utf8() + 1..]);
    }
    let mut s = l.axiom.to_string();
    for _ in 0..depth {
        let mut next = String::new();
        for c in s.chars() {
            match table.get(&c) {
                Some(succ) => next.push_str(succ),
                None if "+-&^<>%|!?:;'\"c[]{}FftgZz*$~.0123456789()_".contains(c) => next.push(c),
                None => next.push('_'),
            }
        }
        s = next;
    }
    s
}

/// What the turtle does that the translation must reproduce exactly: segments (length and
/// diameter) and turns (their angle in degrees; `None` for `~`'s random ones).
#[derive(Debug, PartialEq)]
enum Act {
    Segment(f64, f64),
    Turn(Option<f64>),
}

/// `L_draw`'s state machine for lengths, angles and thicknesses.
fn lparser_draw(l: &Lparser, s: &str) -> Vec<Act> {
    let chars: Vec<char> = s.chars().collect();
    let (mut dis, mut dis2, mut ang, mut thick) =
        (l.dis, l.dis / 2.0, l.angle, l.thickness / 100.0);
    let min = l.min_thickness / 100.0;
    let mut stack = Vec::new();
    let mut acts = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let mut value = None;
        if "+-~t&^<>!?:;'\"ZFfgzc".contains(c) && chars.get(i + 1) == Some(&'(') {
            let close = chars[i..].iter().position(|&x| x == ')').expect(")") + i;
            let text: String = chars[i + 2..close].iter().collect();
            value = Some(text.parse::<f64>().expect("value"));
            i = close;
        }
        match c {
            '+' | '-' | '&' | '^' | '<' | '>' => acts.push(Act::Turn(Some(value.unwrap_or(ang)))),
            '%' => acts.push(Act::Turn(Some(180.0))),
            '~' => acts.extend([Act::Turn(None), Act::Turn(None), Act::Turn(None)]),
            '!' => thick *= value.unwrap_or(0.7),
            '?' => thick *= value.map_or(1.0 / 0.7, |v| v),
            ':' => ang *= value.unwrap_or(0.9),
            ';' => ang *= value.map_or(1.0 / 0.9, |v| v),
            '\'' => {
                let r = value.unwrap_or(0.9);
                dis *= r;
                dis2 *= r;
            }
            '"' => {
                let r = value.unwrap_or(1.0 / 0.9);
                dis *= r;
                dis2 *= r;
            }
            'F' | 'Z' => {
                let d = value.unwrap_or(if c == 'F' { dis } else { dis2 });
                acts.push(Act::Segment(d, (d * thick).max(min)));
            }
            '[' => stack.push((dis, dis2, ang, thick)),
            ']' => (dis, dis2, ang, thick) = stack.pop().expect("balanced"),
            _ => {}
        }
        i += 1;
    }
    acts
}

/// The same from Meristem's build of the translation: the string the turtle reads.
fn meristem_draw(b: &Build, width_scale: f64, dis: f64) -> Vec<Act> {
    let model = b.model.as_ref().expect("model");
    let s: &LString = b
        .derivation
        .interpreted
        .as_ref()
        .unwrap_or(&b.derivation.string);
    let mut width = 0.0;
    let mut acts = Vec::new();
    for i in 0..s.len() {
        let text = s.module_text(&model.alphabet, i);
        let name = text.split('(').next().unwrap_or("").to_string();
        let first = s.params_of(i).first().copied();
        match name.as_str() {
            "!" => width = first.expect("!(w)"),
            // Meristem's lengths are Lparser's over `dis`.
            "F" => acts.push(Act::Segment(
                first.expect("F(x)") * dis,
                width / width_scale * dis,
            )),
            "+" | "-" | "&" | "^" | "/" | "\\" => {
                acts.push(Act::Turn(Some(first.unwrap_or(model.settings.angle))))
            }
            _ => {}
        }
    }
    acts
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1e-12)
}

fn width_scale_of(text: &str) -> f64 {
    let line = text
        .lines()
        .find(|l| l.starts_with("#define width_scale "))
        .expect("width_scale");
    line["#define width_scale ".len()..]
        .split_whitespace()
        .next()
        .and_then(|v| v.parse().ok())
        .expect("a number")
}

/// Imports `file`, builds it at `depth`, and checks it draws what Lparser draws.
fn same_drawing(file: &str, l: &Lparser, depth: u32, random_turns: bool) {
    let result = import_file(file);
    let b = build(
        &result.text,
        &BuildOptions {
            iterations: Some(depth),
            ..BuildOptions::default()
        },
    );
    assert!(b.ok(), "{file}: {:?}", b.diagnostics);
    let expected = lparser_draw(l, &lparser_expand(l, depth as usize));
    let actual = meristem_draw(&b, width_scale_of(&result.text), l.dis);
    assert_eq!(expected.len(), actual.len(), "{file} at depth {depth}");
    let segments = expected
        .iter()
        .filter(|a| matches!(a, Act::Segment(..)))
        .count();
    assert!(segments > 0 || depth <= 1, "{file}: draws nothing");
    for (k, (e, a)) in expected.iter().zip(&actual).enumerate() {
        let same = match (e, a) {
            (Act::Segment(l1, w1), Act::Segment(l2, w2)) => close(*l1, *l2) && close(*w1, *w2),
            (Act::Turn(None), Act::Turn(_)) => random_turns,
            (Act::Turn(Some(x)), Act::Turn(Some(y))) => close(*x, *y),
            _ => false,
        };
        assert!(
            same,
            "{file} at depth {depth}, act {k}: Lparser {e:?}, Meristem {a:?}"
        );
    }
}

const ABOP_BUSH: Lparser = Lparser {
    axiom: "c(12)A",
    rules: &[
        "A=[&FL!A]>>>>>[&FL!A]>>>>>>>[&FL!A]",
        "F=S>>>>>F",
        "S=FL",
        "L=[c(8)^^{-f+f+f-|-f+f+f}]",
    ],
    angle: 22.5,
    thickness: 80.0,
    min_thickness: 0.0,
    dis: 100.0,
};

const MONOPODIAL: Lparser = Lparser {
    axiom: "c(12)FFAL",
    rules: &[
        "A=F[&'(.8)!BL]>(137)'!(.9)A",
        "B=F[-'(.8)!(.9)$CL]'!(.9)C",
        "C=F[+'(.8)!(.9)$BL]'!(.9)B",
        "L=~c(8){+(30)f(20)-(120)f(20)-(120)f(20)}",
    ],
    angle: 45.0,
    thickness: 15.0,
    min_thickness: 0.0,
    dis: 100.0,
};

/// Growth rule `F='(1.25)F'(.8)` (net factor 1) and tropism.
const TERNARY: Lparser = Lparser {
    axiom: "c(12)FA",
    rules: &[
        "A=!(.9)t(.4)FB>(94)B>(132)B",
        "B=[&t(.4)F$A]",
        "F='(1.25)F'(.8)",
    ],
    angle: 30.0,
    thickness: 20.0,
    min_thickness: 0.0,
    dis: 100.0,
};

/// A scaling macro `S='(.8)!(.9)` (its effect comes one step after it is written).
const CONIFER: Lparser = Lparser {
    axiom: "c(12)A",
    rules: &[
        "A=aaSaaSA",
        "S='(.8)!(.9)",
        "a=tF[&'(.8)!LBL]>(137)[z&'(.7)!LBL]>(137)",
        "B=tF[-'(.8)!(.9)$LCL]'!(.9)C",
        "C=tF[+'(.8)!(.9)$LBL]'!(.9)B",
        "L=[~c(8){+(30)f(20)-(120)f(20)-(120)f(20)}]",
    ],
    angle: 30.0,
    thickness: 40.0,
    min_thickness: 0.0,
    dis: 100.0,
};

/// Growth rules whose net factor 1.3 × 0.77 compounds every step (`1.001^(MaxIt-NumIt)`).
const FERN: Lparser = Lparser {
    axiom: "c(12)b>(60)b>(60)b>(60)b>(60)b>(60)b",
    rules: &[
        "b=[&(30)A]",
        "A=~(7)$t(.1)F[+(40)C][-(40)C]!(.95)~(7)t(.1)FA",
        "C=~(10)$tF[+(60)L][-(60)L]C",
        "L=[~(15)c(4){-f+f+f-|-f+f}]",
        "F='(1.3)F'(.77)",
        "f='(1.3)f'(.77)",
    ],
    angle: 20.0,
    thickness: 15.0,
    min_thickness: 0.0,
    dis: 100.0,
};

/// The keyword format: angle scaling `;` `:` inside a rewritten `i=;i`, digit rules, a minimum
/// thickness, length scaling through `D` (net 0.9 per step).
const SPIRAL: Lparser = Lparser {
    axiom: "[|ffff|?FFFF]&&&^D",
    rules: &[
        "D=AB!'DcZO",
        "B=[---'''!:D]",
        "A=&+^FLA",
        "O=[!iw>>w>>w>>w>>w>>w]",
        "w=[c(6)&{-f+f|-f+f}]",
        "i=;i",
        "L=[--->c!!!!!!!1cl[a][b]]",
        "a=[+a{.].C.}",
        "b=[-b{.].C.}",
        "C=gC",
        "l='l",
        "1=2",
        "2=3",
        "3=F",
    ],
    angle: 30.0,
    thickness: 100.0,
    min_thickness: 5.0,
    dis: 1.0,
};

/// Elongation `F='(1.25)F'(.8)` and turning rules `B=&B`.
const TREE5: Lparser = Lparser {
    axiom: "c(4)FFS",
    rules: &[
        "S=FFR>(60)R>(60)R>(60)R>(60)R>(60)R>(30)S",
        "R=[Ba]",
        "a=$tF[Cx]Fb",
        "b=$tF[Dy]Fa",
        "B=&B",
        "C=+C",
        "D=-D",
        "x=a",
        "y=b",
        "F='(1.25)F'(.8)",
    ],
    angle: 5.0,
    thickness: 30.0,
    min_thickness: 0.0,
    dis: 1.0,
};

#[test]
fn lparser_translations_draw_every_segment_and_turn_as_lparser_does() {
    for depth in [0, 1, 2, 4, 7] {
        same_drawing("lparser/abop-bush.ls", &ABOP_BUSH, depth, false);
    }
    for depth in [0, 1, 3, 6, 10] {
        same_drawing("lparser/abop-monopodial-tree.ls", &MONOPODIAL, depth, true);
        same_drawing("lparser/conifer-type-tree.ls", &CONIFER, depth, true);
    }
    for depth in [1, 3, 8] {
        same_drawing("lparser/abop-ternary-tree.ls", &TERNARY, depth, false);
        same_drawing("lparser/fern-plant.ls", &FERN, depth, true);
        same_drawing("lparser/spiral_plant.ls", &SPIRAL, depth, false);
        same_drawing("lparser/tree5.ls", &TREE5, depth, false);
    }
    // At the files' own depths.
    same_drawing("lparser/fern-plant.ls", &FERN, 20, true);
    same_drawing("lparser/spiral_plant.ls", &SPIRAL, 12, false);
    same_drawing("lparser/tree5.ls", &TREE5, 12, false);
}

/// One Meristem module per Lparser symbol that means something: the derived string of the
/// translation, module names only, against Lparser's string read through the symbol table of
/// docs/LANGUAGE.md ("Importing other dialects").
fn lparser_names(l: &Lparser, depth: usize, rewritten: &str) -> Vec<String> {
    let s = lparser_expand(l, depth);
    let chars: Vec<char> = s.chars().collect();
    let mut names = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if "+-~t&^<>!?:;'\"ZFfgzc".contains(c) && chars.get(i + 1) == Some(&'(') {
            i += chars[i..].iter().position(|&x| x == ')').expect(")");
        }
        let name = if rewritten.contains(c) {
            match c {
                'F' | 'f' | 'Z' | 'z' | 'g' | 'c' | 't' | 'G' => format!("{c}_r"),
                d if d.is_ascii_digit() => format!("D_{d}"),
                _ => c.to_string(),
            }
        } else {
            match c {
                '<' => "\\".into(),
                '>' | '%' => "/".into(),
                'c' => ";".into(),
                'z' => "f".into(),
                '!' | '?' | ':' | ';' | '\'' | '"' => String::new(),
                c if "+-&^|$~t[]{}.FfgZ".contains(c) => c.to_string(),
                _ => String::new(),
            }
        };
        if !name.is_empty() {
            names.push(name);
        }
        i += 1;
    }
    names
}

fn derived_names(b: &Build) -> Vec<String> {
    let model = b.model.as_ref().expect("model");
    (0..b.derivation.string.len())
        .map(|i| {
            let t = b.derivation.string.module_text(&model.alphabet, i);
            t.split('(').next().unwrap_or("").to_string()
        })
        .collect()
}

#[test]
fn lparser_translations_keep_lparsers_string_symbol_for_symbol() {
    let cases: [(&str, &Lparser, &str, u32, bool); 4] = [
        ("lparser/abop-bush.ls", &ABOP_BUSH, "AFSL", 7, false),
        (
            "lparser/spiral_plant.ls",
            &SPIRAL,
            "DBAOwiLabCl123",
            12,
            true,
        ),
        ("lparser/tree5.ls", &TREE5, "SRabBCDxyF", 12, false),
        ("lparser/fern-plant.ls", &FERN, "bACLFf", 20, false),
    ];
    for (file, l, rewritten, depth, colour_prefix) in cases {
        let result = import_file(file);
        let b = build(&result.text, &BuildOptions::default());
        assert!(b.ok(), "{file}: {:?}", b.diagnostics);
        assert_eq!(b.derived_with.steps, depth);
        let mut expected = lparser_names(l, depth as usize, rewritten);
        if colour_prefix {
            expected.insert(0, ";".into()); // Lparser starts with colour 2: `;(2)`
        }
        let actual = derived_names(&b);
        assert_eq!(
            actual.len(),
            expected.len(),
            "{file}: module count at depth {depth}"
        );
        assert_eq!(actual, expected, "{file}");
        assert_eq!(b.plant.stats.modules, expected.len());
    }
    // The count at the file's depth, as `meristem derive --stats` reports it.
    let b = build(
        &import_file("lparser/abop-bush.ls").text,
        &BuildOptions::default(),
    );
    assert_eq!(b.plant.stats.modules, 69_367);
}

// ------------------------------------------------------------------------------------------------
// Green, cpfg and L-Py: derived results that can be counted by hand.

fn derive(result: &Import, iterations: Option<u32>, seed: Option<u64>) -> Build {
    let b = build(
        &result.text,
        &BuildOptions {
            iterations,
            seed,
            ..BuildOptions::default()
        },
    );
    assert!(b.ok(), "{:?}\n{}", b.diagnostics, result.text);
    b
}

#[test]
fn greens_worked_example_derives_to_the_published_step() {
    // Lluch et al.: "A(1)B(3)A(5) => A(2)B(6)[A(3)]B(4)" when the first rule is drawn for A(1)
    // and the second for A(5); seed 3 (as public/examples/green-context.lsys) draws exactly so.
    let result = import_file("green/worked-example.txt");
    let b = derive(&result, None, Some(3));
    assert_eq!(b.derived_with.steps, 1);
    assert_eq!(b.derived_text(), "A(2)B(6)[A(3)]B(4)");
    // Other seeds give Green's other outcomes: each A becomes A(x+1) or B(x-1), and B(3) always
    // becomes B(6)[A(3)] when both its neighbours are still A.
    let mut outcomes = std::collections::BTreeSet::new();
    for seed in 0..64 {
        outcomes.insert(derive(&result, None, Some(seed)).derived_text());
    }
    assert!(outcomes.len() >= 3, "{outcomes:?}");
    for o in &outcomes {
        assert!(o.starts_with("A(2)") || o.starts_with("B(0)"), "{o}");
        assert!(o.contains("B(6)[A(3)]"), "{o}");
    }
}

#[test]
fn cpfg_and_lpy_translations_derive_the_strings_their_rules_give() {
    // Koch curve: F -> F+F--F+F, 4 steps: 4^4 F, and 4 turns for each of the 1 + 4 + 16 + 64
    // rewritings.
    let b = derive(&import_file("cpfg/snowflake.l"), None, None);
    assert_eq!(b.derived_with.steps, 4);
    assert_eq!(b.plant.stats.modules, 1 + 256 + 4 * 85);
    assert_eq!(b.plant.stats.segments, 256);
    // A compound leaf drawn through its homomorphism: the derived string keeps A and I.
    let b = derive(&import_file("cpfg/compound-homo.l"), None, None);
    let text = b.derived_text();
    assert!(
        text.starts_with("IIIIIIII[+IIII[+II[+I[+A][-A]IA]"),
        "{text}"
    );
    assert!(b.derivation.interpreted.is_some() && !text.contains('F'));
    // ABOP Fig 1.9's H-tree in L-Py: A(s) -> F(s)[+(a)A(s/R)][-(a)A(s/R)], 11 steps: 2^11 apices,
    // 2^11 - 1 rewritings of 7 more modules each, and the width `_(0.01)` first.
    let b = derive(&import_file("lpy/lsystem1.9.lpy"), None, None);
    assert_eq!(b.plant.stats.modules, 1 + 2048 + 2047 * 7);
    assert_eq!(b.plant.stats.segments, 2047);
    assert!(b
        .derived_text()
        .starts_with("!(0.01)F(1)[+(85)F(0.6868131868131868)"));
    // ABOP Fig 1.4's alternating branches: 20 branches B(20,i) of 20 internodes each, and A(20);
    // the Python `if` bodies became conditions, the interpretation's `,(2 if i % 2 else 3)` a
    // conditional expression.
    let b = derive(&import_file("lpy/lsystem1.4.lpy"), None, None);
    assert_eq!(b.plant.stats.modules, 20 * 21 + 1);
    assert_eq!(b.plant.stats.segments, 400);
    assert!(b.derived_text().ends_with("B(20,19)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)F(0.01)A(20)"));
    // Fig 1.37's L-Py file with delays: `G(x,t):` then `if t == 0: produce …` and
    // `else: produce G(x,t-1)` became two conditional productions, so only the segments whose
    // delay has run out are divided.
    let delayed = import_file("lpy/lsystem-fig1.37b.lpy");
    assert_eq!(
        derive(&delayed, Some(1), None).derived_text(),
        "!(0.002)-(90)G(0.3,2)+(86)G(0.458257569495584,1)-(172)G(0.458257569495584,1)+(86)G(0.7,0)"
    );
    assert_eq!(
        derive(&delayed, Some(2), None).derived_text(),
        "!(0.002)-(90)G(0.3,1)+(86)G(0.458257569495584,0)-(172)G(0.458257569495584,0)+(86)G(0.21,2)+(86)G(0.32078029864690877,1)-(172)G(0.32078029864690877,1)+(86)G(0.48999999999999994,0)"
    );
    let plain = derive(&import_file("lpy/lsystem-fig1.37.lpy"), None, None);
    assert_eq!(plain.plant.stats.segments, 4usize.pow(5));
}

// ------------------------------------------------------------------------------------------------
// No input makes an importer panic, and what it gives either resolves or has nothing to derive.

// Native only: proptest is not a wasm32 dependency (tests/wasm_boundary.rs has the wasm32 tests).
#[cfg(not(target_arch = "wasm32"))]
use proptest::prelude::*;

/// L-Py's inlining bomb (issue 50, 5): `f` doubles its argument and is nested 28 deep, so the
/// inlined call would be 2^28 copies of `s`; the production is left open for the body to finish.
#[cfg(not(target_arch = "wasm32"))]
const BOMB_LPY: &str = "def f(x):\n    return x+x\n\nAxiom: A(1)\nderivation length: 2\nproduction:\n\
    A(s) --> F(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(f(s))))))))))))))))))))))))))))";

/// What an import of the fuzzer's few hundred bytes may write, text and notes together. The
/// importers' caps (cpp's expansions and line, the inlining's 20,000 characters, the predecessor's
/// 64 modules, …) keep the bombs above to tens of kilobytes; before them, one gave 36 MB.
#[cfg(not(target_arch = "wasm32"))]
const MAX_IMPORTED_BYTES: usize = 1 << 20;

#[cfg(not(target_arch = "wasm32"))]
proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    #[test]
    fn importers_never_panic_and_their_text_resolves(
        prefix in prop::sample::select(vec![
            "",
            "SYSTEM\nDECLARATIONS\nCONTINUOUS p UNIFORM(0,1)\nAXIOM\nA(1)\nRULES\n",
            "3\n30\n10\nA\n",
            "recursion 3\nangle 20\naxiom A\nrule A = ",
            "#define N 3\nLsystem: 1\nderivation length: 2\nAxiom: A(1)\n",
            "k = 2\nAxiom: A(1)\nproduction:\nA(t) :\n    if ",
            // cpfg statement blocks with if/else and loops, arrays of two dimensions, a
            // predecessor of several modules, L+C's produce blocks, L-Py globals and
            // assignments in if branches (issue 21).
            "Lsystem: 1\nderivation length: 1\nAxiom: A(1)\nA(t) : {if (t>1) {t = t/2;} else ",
            "Define: { array a[2][2] = {1,2,3,4}; }\nAxiom: A(1)\nA(t) --> F(a[1][",
            "Axiom: F(1,0)#(1)\n\tAXIOM\nAXIOM : 1 --> B\nF(v,n)#(w) : ",
            "#include <lpfgall.h>\nmodule A(float);\nAxiom: A(1);\nA(t):{ ",
            "g = 0\nAxiom: A(1)\nproduction:\nA(t) :\n    global g\n    g += 1\n    if t > 1:\n        x = ",
            "m = 0\nderivation length: 9\nAxiom: P(0)G\nproduction:\nP(t) :\n    if t < 3: produce P(t+1)\n    else:\n        global m\n        m = 1\n        produce ",
            // Issue 50, 6: lines continued by `\` among blank lines, a production over two
            // lines after them (the joins), an #include the file alone cannot give.
            "#include \"a.h\"\nLsystem: 1\nderivation length: 2\nAxiom: F\\\n\n\n  F\\\nF\n\n\nA :\n\n",
            // Issue 50, 4 and 5: the macro bombs (each macro twice the other; one ten times
            // itself) and L-Py's inlining bomb (a function doubling its argument, nested 28 deep),
            // each left open for the body to finish.
            "#define A B B\n#define B A A\nLsystem: 1\nderivation length: 3\nAxiom: A\nA --> ",
            "#define A A A A A A A A A A A\nLsystem: 1\nderivation length: 3\nAxiom: A B\nB --> A",
            BOMB_LPY,
        ]),
        // `\r` too: Meristem's parser ends a line there (issue 50's flaky timeline case).
        body in "[-+&^<>|%$~!?:;'\"cFfgZzt\\[\\]{}.()0-9ABCabpxiewhlrodu=@#*/, \n\r]{0,80}",
    ) {
        let text = format!("{prefix}{body}");
        for dialect in Dialect::ALL {
            let result = import::import(&text, dialect);
            let notes: usize = result.notes.iter().map(|n| n.message.len()).sum();
            prop_assert!(
                result.text.len() + notes <= MAX_IMPORTED_BYTES,
                "{dialect:?} {text:?}: {} bytes of text, {notes} of notes",
                result.text.len()
            );
            if !result.is_empty() {
                let errors = resolve_errors(&result.text);
                prop_assert!(errors.is_empty(), "{dialect:?} {text:?}: {errors:?}\n{}", result.text);
            }
        }
    }
}

// ------------------------------------------------------------------------------------------------
// The gallery's imported examples are the importer's output under a written header.

#[test]
fn the_gallerys_lparser_examples_are_exactly_what_the_importer_writes() {
    let body = |text: &str| -> String {
        text.lines()
            .skip_while(|l| l.starts_with("//"))
            .map(|l| format!("{l}\n"))
            .collect()
    };
    for (example, original) in [
        ("lparser-fern.lsys", "lparser/fern-plant.ls"),
        ("lparser-conifer.lsys", "lparser/conifer-type-tree.ls"),
        ("lparser-spiral-plant.lsys", "lparser/spiral_plant.ls"),
    ] {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../public/examples")
            .join(example);
        let gallery = std::fs::read_to_string(&path).expect("gallery example");
        assert!(gallery
            .lines()
            .nth(1)
            .is_some_and(|l| l.starts_with("// Source:")));
        assert!(gallery.contains(original), "{example} names its original");
        assert_eq!(
            body(&gallery),
            body(&import_file(original).text),
            "{example}: regenerate it with meristem import crate/tests/import/{original}"
        );
    }
}

#[test]
fn a_cpfg_macro_bomb_imports_small_and_says_what_it_left_out() {
    // Issue 50, finding 4 (93 bytes): A and B each expand to the other twice, so the predecessor
    // `A` becomes some 6,000 modules after cpp's caps. Each module became a production with all
    // the others as its context: 36 MB of text and 31 MB of notes in 9 s.
    let text = "#define A B B\n#define B A A\nLsystem: 1\nderivation length: 3\nAxiom: A\n\
                A --> F[+A]A\nendlsystem\n";
    let imported = import::import(text, Dialect::Cpfg);
    assert!(
        imported.text.len() < 20_000,
        "{} bytes",
        imported.text.len()
    );
    let notes: usize = imported.notes.iter().map(|n| n.message.len()).sum();
    assert!(notes < 20_000, "{notes} bytes of notes");
    assert!(
        imported
            .notes
            .iter()
            .any(|n| n.message.contains("more than the 64 Meristem translates")),
        "{:?}",
        imported.notes
    );
    // (b) a macro expanding to ten copies of itself: cpp expands a macro once inside itself.
    let text = "#define A A A A A A A A A A A\nLsystem: 1\nderivation length: 3\nAxiom: A\n\
                A --> F[+A]A\nendlsystem\n";
    let imported = import::import(text, Dialect::Cpfg);
    assert!(
        imported.text.len() < 40_000,
        "{} bytes",
        imported.text.len()
    );
}

#[test]
fn a_carriage_return_in_a_comment_after_code_stays_in_the_comment() {
    // Found by the fuzzer below: an unclosed cpfg comment after a production's code was written
    // as `B -> A // z\r]`, and Meristem's parser, which ends a line at a lone `\r`, read `]` as a
    // line of its own (E0105).
    let text = "Lsystem: 1\nderivation length: 3\nAxiom: A B\nB --> A/*z\r]";
    let imported = import::import(text, Dialect::Cpfg);
    assert_eq!(resolve_errors(&imported.text), Vec::<String>::new());
    assert!(imported.text.contains("B -> A // z ]"), "{}", imported.text);
}

#[test]
fn an_l_py_function_nested_in_itself_is_not_inlined_without_end() {
    // Issue 50, finding 5: `f(x) = x+x` nested 28 deep doubles with each call (2^28 copies of
    // `s`): the importer asked for 4 GB. Now the inlining stops past 20,000 characters with a note.
    let mut call = "s".to_string();
    for _ in 0..28 {
        call = format!("f({call})");
    }
    let text = format!(
        "def f(x):\n    return x+x\n\nAxiom: A(1)\nderivation length: 2\nproduction:\n\
         A(s) --> F({call})A(s)\nendlsystem\n"
    );
    let imported = import::import(&text, Dialect::Lpy);
    assert!(
        imported.text.len() < 20_000,
        "{} bytes",
        imported.text.len()
    );
    assert!(
        imported
            .notes
            .iter()
            .any(|n| n.message.contains("grows longer than 20000 characters")),
        "{:?}",
        imported.notes
    );
}

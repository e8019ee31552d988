//! The ABOP reader on each dialect: what it translates and what it reports.

use super::cpfg::{cpp, cpp_functions};
use super::prepare::lines;
use super::*;
use crate::import::test_support::{assert_odd_inputs_resolve, assert_resolves, noted};

/// 200 chained `#define`s, each using the one before twice (through a macro with an
/// argument, which is expanded), an `#if` on the last, and an axiom drawing it.
fn define_chain(links: usize) -> String {
    let mut text = String::from("#define HALF(x) (x)/2\n#define C0 1\n");
    for i in 1..=links {
        text += &format!("#define C{i} HALF(C{} + C{})\n", i - 1, i - 1);
    }
    text += &format!(
        "Lsystem: 1\nderivation length: 1\nAxiom: A\n#if C{links} > 0.5\nA --> F(C{links})\n#else\nA --> F(7)\n#endif\nendlsystem\n"
    );
    text
}

#[test]
fn chained_defines_are_expanded_once_each_not_as_doubling_text() {
    let links = 200;
    let text = define_chain(links);
    // The preprocessor alone: one expansion a link (HALF), none of a kept macro.
    let functions = cpp_functions();
    let names: Vec<&str> = functions.iter().map(String::as_str).collect();
    let none = |_: &str| None;
    let mut pre = cpp::Preprocessor::new(&none, &names);
    let out = pre.run(lines(&text, Flavour::Cpfg), 0);
    assert_eq!(pre.expansions, links, "{:?}", pre.notes);
    assert!(pre.notes.is_empty(), "{:?}", pre.notes);
    let kept: Vec<&str> = out
        .iter()
        .map(|l| l.code.as_str())
        .filter(|c| c.starts_with("#define"))
        .collect();
    assert_eq!(kept.len(), links + 1);
    assert_eq!(
        kept[links],
        format!("#define C{links} (C{} + C{})/2", links - 1, links - 1)
    );
    // The `#if` read C200's number (1), so the first production is the one kept.
    assert!(out
        .iter()
        .any(|l| l.code.trim() == format!("A --> F(C{links})")));
    assert!(!out.iter().any(|l| l.code.contains("F(7)")));

    // The whole import: linear in size, and the plant it gives draws F(1).
    let import = import(&text, Flavour::Cpfg);
    assert!(import.notes.is_empty(), "{:?}", import.notes);
    assert!(
        import.text.len() < 60 * links,
        "{} bytes for {links} links",
        import.text.len()
    );
    let built = crate::pipeline::build(&import.text, &crate::BuildOptions::default());
    let segments = &built.plant.skeleton.segments;
    assert_eq!(segments.len(), 1, "{}", import.text);
    let length = (segments[0].end - segments[0].start).length();
    assert!((length - 1.0).abs() < 1e-9, "{length}");
}

/// The translation of `text` in `flavour`, which Meristem must read without errors.
fn resolved(text: &str, flavour: Flavour) -> Import {
    let import = import(text, flavour);
    assert_resolves(&import);
    import
}

/// The plant Meristem builds from the translation of `import`, which must build without errors.
fn built(import: &Import) -> crate::pipeline::Build {
    let b = crate::pipeline::build(&import.text, &crate::pipeline::BuildOptions::default());
    assert!(b.ok(), "{:?}", b.diagnostics);
    b
}

/// Panics unless `import` has exactly one note, and it contains `words`.
fn assert_one_note(import: &Import, words: &str) {
    assert_eq!(import.notes.len(), 1, "{:?}", import.notes);
    assert!(
        import.notes[0].message.contains(words),
        "{:?}",
        import.notes
    );
}

fn body(import: &Import) -> Vec<&str> {
    import
        .text
        .lines()
        .filter(|l| !l.starts_with("//") && !l.is_empty())
        .collect()
}

#[test]
fn lpy_reads_its_at_names_longest_first() {
    // L-Py reads `@gSetColor(3)` as `@g` then `SetColor(3)`, and `@GcF` as `@Gc F`.
    let import = super::import("Axiom: @gSetColor(3)@GcF(2)@Ge@Foo\n", Flavour::Lpy);
    let axiom = body(&import)[0].to_string();
    assert_eq!(axiom, "axiom: @g;(3)@GcF(2)@Ge@Foo", "{:?}", import.notes);
    assert!(import.notes.iter().any(|n| n.message.contains("@g ")));
    assert!(
        import.notes.iter().any(|n| n.message.contains("@Foo")),
        "an unknown @ name stays one name"
    );
}

#[test]
fn lpy_reads_undeclared_words_letter_by_letter_and_nests_its_ifs_and_locals() {
    let import = resolved(
        "Axiom: A(1)\nderivation length: 2\nproduction:\nA(x) :\n    p = min(1, x**2)\n    r = random()\n    if r <= p:\n        produce IB(1-x)\n    else:\n        produce A(x+p)\nB(x) :\n    if x >= 1:\n        if x < 3:\n            produce F(x)\n        else:\n            produce F(1)\n    else:\n        produce B(x+1)\nendlsystem\n",
        Flavour::Lpy,
    );
    assert_eq!(
        body(&import)[3..],
        [
            // IB is I then B: Meristem reads undeclared letters one by one too.
            "A(x) : (uniform(0,1)) <= (min(1,x^2)) -> IB(1-x)",
            "A(x) -> A(x+(min(1,x^2)))",
            "B(x) : (x >= 1) && (x < 3) -> F(x)",
            "B(x) : x >= 1 -> F(1)",
            "B(x) -> B(x+1)",
            "endlsystem",
        ]
    );
    // It draws random numbers: one note says that the same seed gives another plant.
    assert_eq!(import.notes.len(), 1, "{:?}", import.notes);
    assert!(
        import.notes[0].line == 0
            && import.notes[0]
                .message
                .starts_with("L-Py draws its random numbers with another generator")
    );
    // A random draw used twice would be drawn again in each place: not translated.
    let twice = super::import(
        "Axiom: A\nderivation length: 2\nproduction:\nA :\n    r = random()\n    if r < 0.3: produce B\n    elif r < 0.6: produce C\nendlsystem\n",
        Flavour::Lpy,
    );
    assert!(twice.notes[0]
        .message
        .contains("'r = random()' is not translated"));
}

#[test]
fn a_cpfg_define_continues_over_any_number_of_lines() {
    let import = resolved(
        "#define BOX [F(1) \\\n\t+(90)F(2) \\\n\t+(90)F(3)]\nLsystem: 1\nderivation length: 1\nAxiom: BOX A\nA --> FA\nendlsystem\n",
        Flavour::Cpfg,
    );
    assert!(import.notes.is_empty(), "{:?}", import.notes);
    assert!(
        import.text.contains("axiom: [F(1)+(90)F(2)+(90)F(3)]A"),
        "{}",
        import.text
    );
}

#[test]
fn cpfg_heads_over_several_lines_whole_branch_contexts_and_labels() {
    let import = resolved(
        "Lsystem: 1\nderivation length: 2\nAxiom: N(1)I(0)[I(2)A]I(3)\nN(k) < I(b) : b==0\n\t{f=k*2;} -->\n\tI(f)\nI(b) > [I(c)=]I(d) : b==0 --> I(c+d)@L(\" %.f\", b)\nendlsystem\n",
        Flavour::Cpfg,
    );
    assert_eq!(
        body(&import)[2..],
        [
            "N(k) < I(b) : b==0 -> I((k*2))",
            "I(b) > [I(c)]I(d) : b==0 -> I(c+d)",
            "endlsystem"
        ]
    );
    assert_one_note(&import, "@L draws a text label");
}

#[test]
fn new_contexts_become_ordinary_contexts_with_a_note_that_says_what_changes() {
    for flavour in [Flavour::Lpy, Flavour::Cpfg] {
        let import = resolved(
            "Axiom: A B B\nderivation length: 2\nproduction:\nA << B --> A\nB >> A --> C\nA < B --> B\nendlsystem\n",
            flavour,
        );
        let body = body(&import);
        assert!(body.contains(&"A < B -> A"), "{body:?}");
        assert!(body.contains(&"B > A -> C"), "{body:?}");
        let notes: Vec<&str> = import.notes.iter().map(|n| n.message.as_str()).collect();
        let new_context = |side: &str| {
            notes
                .iter()
                .filter(|m| {
                    m.contains(&format!("new {side} context")) && m.contains("one module a step")
                })
                .count()
        };
        assert_eq!(
            (new_context("left"), new_context("right")),
            (1, 1),
            "{notes:?}"
        );
    }
}

#[test]
fn cpfg_blocks_are_substituted_and_probabilities_become_weights() {
    let import = resolved(
        "#define STEPS 4 /* steps */\n#define R 1.3\nLsystem: 1\nderivation length: STEPS\nignore: +-/\nAxiom: #(0.05)A(0)\nA(t) : {t=t-1;} t>0 --> \n\tI(t)[+(45)A(t)]\nM(t) : 1 {x=0.5*R^t; x+=1;} --> I(x)M(t)\nF --> F[+F]F : 0.3\nB --> *\ndecomposition\nmaximum depth: 2\nhomomorphism: no warnings\nI(x) --> F(x)\nendlsystem\n",
        Flavour::Cpfg,
    );
    assert_eq!(
        body(&import),
        [
            "#define STEPS 4 // steps",
            "#define R 1.3",
            "derivation length: STEPS",
            "#ignore + - /",
            "axiom: !(0.05)A(0)",
            "A(t) : (t-1)>0 -> I((t-1))[+(45)A((t-1))]",
            "M(t) : 1 -> I(((0.5*R^t)+(1)))M(t)",
            "F -> (0.3) F[+F]F",
            "B -> ε",
            "decomposition:",
            "maximum depth: 2",
            "homomorphism:",
            // cpfg's default depth, which the section does not change.
            "maximum depth: 1",
            "I(x) -> F(x)",
            "endlsystem",
        ]
    );
    // `F[+F]F` turns by the view file's angle, which a `.l` alone does not give; its
    // probability draws random numbers, with another generator than cpfg's.
    assert_eq!(import.notes.len(), 2, "{:?}", import.notes);
    assert!(import.notes[0].line == 0 && import.notes[0].message.contains("angle increment"));
    assert_eq!(
        import.notes[1].message,
        "cpfg draws its random numbers with another generator than Meristem's: the same seed gives a different plant than in cpfg (the distribution of plants is the same)"
    );
}

#[test]
fn cpfg_if_blocks_become_conditional_values_and_printf_is_noted() {
    let import = resolved(
        "#define REL 1\nderivation length: 2\nAxiom: A(1,4)\nE : 1 {srand(1);} --> *\nA(x,w) : x<3\n\t{t = 2*x;\n\tif (REL) {t = t/2; w = 0;} else t = t+1;\n\tif (w<t) {w = t;}\n\tprintf(\"%f\", t);\n\tt - 1;\n\t} --> F(t)A(x+1,w)\nendlsystem\n",
        Flavour::Cpfg,
    );
    assert!(
        import.text.contains(
            "A(x,w) : x<3 -> F(((REL)?((2*x)/2):((2*x)+1)))A(x+1,((((REL)?(0):w)<((REL)?((2*x)/2):((2*x)+1)))?(((REL)?((2*x)/2):((2*x)+1))):((REL)?(0):w)))"
        ),
        "{}",
        import.text
    );
    let said = noted(&import);
    assert!(
        said.iter()
            .any(|(l, m)| *l == 4 && m.contains("'srand(1)' restarts")),
        "{said:?}"
    );
    assert!(
        said.iter()
            .any(|(l, m)| *l == 5 && m.starts_with("cpfg's printf")),
        "{said:?}"
    );
    assert!(
        said.iter()
            .any(|(l, m)| *l == 5 && m.contains("'t - 1' assigns nothing")),
        "{said:?}"
    );
    let b = built(&import);
    // A(1,4) → F(1)A(2,0) → F(1)F(2)A(3,0): two segments.
    assert_eq!(b.plant.stats.segments, 2);
    // A loop runs as an auxiliary module rewritten until its condition fails (cpfg/loops.rs):
    // A(1) counts x up to 3 within the one step.
    let looped = super::import(
        "derivation length: 1\nAxiom: A(1)\nA(x) : {while (x < 3) {x = x + 1;}} --> F(x)\n",
        Flavour::Cpfg,
    );
    assert!(looped.notes.is_empty(), "{:?}", looped.notes);
    let b = built(&looped);
    assert_eq!(b.plant.stats.segments, 1, "{}", looped.text);
    let end = b.plant.skeleton.segments[0].end;
    assert!((end.y - 3.0).abs() < 1e-9, "{end:?}\n{}", looped.text);
    // A second loop in the block is not translated: the production is skipped with a note.
    let twice = super::import(
        "Axiom: A(1)\nA(x) : {while (x < 3) {x = x + 1;} while (x < 5) {x = x + 1;}} --> F(x)\n",
        Flavour::Cpfg,
    );
    assert!(
        twice
            .notes
            .iter()
            .any(|n| n.line == 2 && n.message.contains("second loop")),
        "{:?}",
        twice.notes
    );
}

#[test]
fn cpfg_arrays_of_two_dimensions_and_predecessors_of_several_letters() {
    let import = resolved(
        "#define N 3\nLsystem: 1\nDefine: { array len[2][N] = {1, 2, 3, 4, 5, 6}; }\nderivation length: 1\nAxiom: AXIOM\nAXIOM : 1 --> F(len[0][2])F(len[1][0])F(len[1][ 2 ])F(len[5][5])\nendlsystem\n",
        Flavour::Cpfg,
    );
    assert!(import.text.contains("#module AXIOM_"), "{}", import.text);
    assert!(import.text.contains("axiom: AXIOM_"), "{}", import.text);
    assert_one_note(&import, "becomes one module AXIOM_");
    let b = built(&import);
    // len[0][2] = 3, len[1][0] = 4, len[1][2] = 6, and past the end the last value, 6.
    assert_eq!(b.derived_text(), "F(3)F(4)F(6)F(6)", "{}", import.text);
}

#[test]
fn cpfg_predecessors_of_several_modules_become_contexts_and_axioms_continue() {
    let import = resolved(
        "derivation length: 1\nAxiom: [F(2,0)#(1)]\n\t[F(3,1)#(2)]\nF(v,n)#(w) : n == 0 --> F(v)#(w)@O\n",
        Flavour::Cpfg,
    );
    let body = body(&import);
    assert!(
        body.contains(&"axiom: [F(2,0)!(1)][F(3,1)!(2)]"),
        "{body:?}"
    );
    assert!(
        body.contains(&"F(v,n) > !(w) : n == 0 -> F(v)!(w)@O"),
        "{body:?}"
    );
    assert!(body.contains(&"F(v,n) < !(w) : n == 0 -> ε"), "{body:?}");
    assert!(
        import
            .notes
            .iter()
            .any(|n| n.line == 4 && n.message.contains("is 2 modules")),
        "{:?}",
        import.notes
    );
    let b = built(&import);
    assert_eq!(b.derived_text(), "[F(2)!(1)@O][F(3,1)!(2)]");
}

#[test]
fn cpfg_sections_without_a_depth_get_cpfgs_default_depth_one() {
    let import = resolved(
        "derivation length: 0\nAxiom: h\nhomomorphism\nh --> [F]f\nf --> [F]f\nendlsystem\n",
        Flavour::Cpfg,
    );
    assert_eq!(
        body(&import),
        [
            "derivation length: 0",
            "axiom: h",
            "homomorphism:",
            "maximum depth: 1",
            "h -> [F]f",
            "f -> [F]f",
            "endlsystem"
        ]
    );
    let b = crate::pipeline::build(&import.text, &crate::pipeline::BuildOptions::default());
    // h is drawn once: its f is not rewritten again, as in cpfg.
    assert_eq!(b.plant.stats.segments, 1);
    let deeper = super::import(
        "Axiom: h\nhomomorphism\nmaximum depth: 3\nh --> [F]f\nendlsystem\n",
        Flavour::Cpfg,
    );
    assert!(!deeper.text.contains("maximum depth: 1"), "{}", deeper.text);
}

#[test]
fn lpy_flags_set_by_a_production_become_defines_over_the_step() {
    let text = "m = 0\nAxiom: P(0)G\nderivation length: 6\nproduction:\nP(t) :\n    if t < 3: produce P(t+1)\n    else:\n        global m\n        m = 1\n        produce *\nG :\n    if m == 1: produce FG\nendlsystem\n";
    let import = resolved(text, Flavour::Lpy);
    // P(0) → P(1) → P(2) → P(3) in three steps; the fourth erases it and sets m: from the
    // fifth step on, G grows an F a step (steps 5 and 6).
    assert!(
        import.text.contains("#define m (NumIt > 4 ? 1 : 0)"),
        "{}",
        import.text
    );
    assert!(!import.text.contains("ProbeMark"), "{}", import.text);
    assert_one_note(&import, "first applies in step 4");
    let b = crate::pipeline::build(&import.text, &crate::pipeline::BuildOptions::default());
    assert_eq!(b.derived_text(), "FFG");
    // A flag set to two different values is not one: the body is skipped as before.
    let two = text.replace("    if m == 1", "    global m\n    m = 2\n    if m == 1");
    let import = super::import(&two, Flavour::Lpy);
    assert!(!import.text.contains("NumIt >"), "{}", import.text);
    assert!(
        import
            .notes
            .iter()
            .any(|n| n.message.contains("'global m' is not translated")),
        "{:?}",
        import.notes
    );
}

#[test]
fn many_lpy_flags_are_found_by_one_probe_derivation_per_seed() {
    // Twelve flags, flag k set by its own module once that module counted to k + 2 (and read by
    // a production of its own): each flag's
    // step is its own (flags 1 and 10, 11 tell their markers apart), and the probe is derived
    // once per seed for all of them (it was twice per flag: 24 derivations of up to a million
    // modules each here, about 50 ms apiece in the studio).
    let names: Vec<String> = (0..12).map(|k| format!("Pa{k}")).collect();
    let readers: Vec<String> = (0..12).map(|k| format!("Qa{k}")).collect();
    let mut text = format!("module {}, {}\n", names.join(", "), readers.join(", "));
    for k in 0..12 {
        text += &format!("m{k} = 0\n");
    }
    text += &format!(
        "derivation length: 20\nAxiom: {}\nproduction:\n",
        names.join("")
    );
    let axiom: String = names.iter().map(|n| format!("{n}(0)")).collect();
    text = text.replace(
        &format!("Axiom: {}", names.join("")),
        &format!("Axiom: {axiom}G"),
    );
    for (k, name) in names.iter().enumerate() {
        let last = k + 2;
        text += &format!(
            "{name}(t) :\n    if t < {last}: produce {name}(t+1)\n    else:\n        global m{k}\n        m{k} = 1\n        produce *\n"
        );
    }
    for (k, reader) in readers.iter().enumerate() {
        text += &format!("{reader} :\n    if m{k} == 1: produce F\n");
    }
    text += "G :\n    if m11 == 1: produce FG\nendlsystem\n";
    super::lpy::flags::PROBE_DERIVATIONS.with(|n| n.set(0));
    let import = resolved(&text, Flavour::Lpy);
    assert_eq!(
        super::lpy::flags::PROBE_DERIVATIONS.with(|n| n.get()),
        2,
        "one derivation per seed"
    );
    for k in 0..12 {
        let define = format!("#define m{k} (NumIt > {} ? 1 : 0)", k + 3);
        assert!(import.text.contains(&define), "{define}\n{}", import.text);
    }
    // m11 is set in step 14: G grows an F in each of steps 15 to 20.
    let b = crate::pipeline::build(&import.text, &crate::pipeline::BuildOptions::default());
    assert_eq!(b.derived_text(), "FFFFFFG");
}

#[test]
fn lpfg_blocks_produce_conditional_productions() {
    let import = resolved(
        "#include <lpfgall.h>\n#define PL 0.5\nderivation length: 3;\nmodule A(float);\nmodule Apex(float);\nAxiom: Right(5) SetWidth(0.15) A(1.2) Apex(0);\nproduction:\nApex(t):{ produce Apex(t+1); }\ndecomposition:\nA(t):\n{\n\tt = t - PL;\n\tif(t>0)\n\t\tproduce F(t) SB() Left(30) F(1) EB() A(t);\n\tfloat w = 2*t;\n\tproduce Sphere(w) Frobnicate(1);\n}\n",
        Flavour::Cpfg,
    );
    let body = body(&import);
    assert!(body.contains(&"#module Apex"), "{body:?}");
    assert!(
        body.contains(&"axiom: -(5)!(0.15)A(1.2)Apex(0)"),
        "{body:?}"
    );
    assert!(body.contains(&"Apex(t) -> Apex(t+1)"), "{body:?}");
    assert!(
        body.contains(&"A(t) : (t - PL)>0 -> F((t - PL))[+(30)F(1)]A((t - PL))"),
        "{body:?}"
    );
    assert!(
        body.contains(&"A(t) : !((t - PL)>0) -> @O((2*(t - PL)))"),
        "{body:?}"
    );
    assert_one_note(&import, "Frobnicate is not a Meristem command");
    let b = built(&import);
    // A(1.2) → F(0.7)[+F]A(0.7) → F(0.7)[+F]F(0.2)[+F]A(0.2) → … @O(-0.6): four segments.
    assert_eq!(b.plant.stats.segments, 4, "{}", b.derived_text());
}

#[test]
fn lpy_python_becomes_defines_and_conditional_productions() {
    let import = resolved(
        "import math\nR = 1.456\nh = (0.3*0.7) ** 0.5\n__authors__ = 'C. Godin'\n\nAxiom: _(0.01) ,(2) A(1)\nderivation length: 3\nproduction:\nA(s) --> F(s)[+(85)A(s/R)][-(85)A(s/R)]\nB(t) :\n    if t < 2 and not t == 1: produce B(t+1)\n    elif t == 2:\n        produce C(t if t > 1 else 0)\n    else: produce *\nF(x) : produce F(x/3.)+(60)F(x/3.)\ninterpretation:\nC(t) --> F(sin(t))\nendlsystem\ndef End():\n    print('x')\n",
        Flavour::Lpy,
    );
    assert_eq!(
        body(&import),
        [
            "#define R 1.456",
            "#define h (0.3*0.7) ^ 0.5",
            "axiom: !(0.01);(2)A(1)",
            "derivation length: 3",
            "productions:",
            "A(s) -> F(s)[+(85)A(s/R)][-(85)A(s/R)]",
            "B(t) : t < 2 && ! t == 1 -> B(t+1)",
            "B(t) : t == 2 -> C((t > 1?t:0))",
            "B(t) -> ε",
            "F(x) -> F(x/3.)+(60)F(x/3.)",
            "homomorphism:",
            "C(t) -> F(sin((t)*57.2957795131))",
            "endlsystem",
        ]
    );
    let notes = noted(&import);
    // `import math` loses nothing (its names are translated where used).
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert!(notes[0].0 == 19 && notes[0].1.contains("'End'"));
    assert!(import.text.contains("// authors: C. Godin"));
}

#[test]
fn what_cannot_be_translated_is_reported_at_its_line() {
    let import = resolved(
        "#include \"x.h\"\n#define f(x) x\nAxiom: A(1)\nA(t) : {while (t>1) t=t-1;} t>0 --> B\nA(t) --> @c(1)~k(2)F(frob(1,t))\nendlsystem\nLsystem: 2\n",
        Flavour::Cpfg,
    );
    let lines: Vec<usize> = import.notes.iter().map(|n| n.line).collect();
    // `#define f(x) x` is expanded where it is used (line 2 needs no note).
    assert_eq!(lines, [1, 4, 5, 5, 5, 7], "{:?}", import.notes);
    // `@c(1)` is a disc (a polygon of 12 sides); `frob` stops the production.
    assert!(import
        .text
        .contains("// not imported: A(t) -> [f((1)/2)+(105){f((1)*0.258819045103)"));
    assert!(import.text.contains("}]~k(2)F(frob(1,t))"));
}

#[test]
fn lpy_helpers_tuples_and_the_iteration_number_are_translated() {
    let import = resolved(
        "def long(x):\n  return 2*x\ndef alpha(x): return 30\nTOP, dr = 10, 0.02\nAxiom: A(1)\nderivation length: 3\nproduction:\nA(n) :\n  if(n < TOP): produce F(long(n))+(alpha(n))A(n+dr)\nB(n) --> B(getIterationNb())\nendlsystem\n",
        Flavour::Lpy,
    );
    assert_eq!(
        body(&import),
        [
            "#define TOP 10",
            "#define dr 0.02",
            "axiom: A(1)",
            "derivation length: 3",
            "productions:",
            "A(n) : (n < TOP) -> F((2*(n)))+((30))A(n+dr)",
            "B(n) -> B((NumIt-1))",
            "endlsystem",
        ]
    );
    assert!(import.notes.is_empty(), "{:?}", import.notes);
    assert!(import
        .text
        .contains("// L-Py's function long(x) = 2*x, inlined where it is called"));
    let literal = resolved(
        "Axiom: D(20,1)\nderivation length: 2\nproduction:\nD(20,k) : k > 0 --> D(20,k+1)F\nD(x,k) --> D(x,k)\nendlsystem\n",
        Flavour::Lpy,
    );
    assert!(
        literal
            .text
            .contains("D(v_lit1,k) : v_lit1 == 20 && (k > 0) -> D(20,k+1)F"),
        "{}",
        literal.text
    );
}

#[test]
fn lpy_bodies_with_other_code_are_skipped_whole() {
    let import = resolved(
        "Axiom: A(0)\nA(t) :\n    x = t + 1\n    produce A(x)\nA(t) :\n    nproduce B\n",
        Flavour::Lpy,
    );
    // A local assignment before `produce` is put where it is used; `nproduce` is skipped.
    assert_eq!(body(&import), ["axiom: A(0)", "A(t) -> A((t + 1))"]);
    assert_one_note(&import, "nproduce B");
}

#[test]
fn odd_input_never_panics() {
    let texts = [
        "",
        "Axiom:",
        "-->",
        "A --> B(",
        "A(t) : {x= --> B",
        "Axiom: A\nA :\n",
        "if",
        "x = 'a'\nAxiom: F(\"a\")",
        "Axiom: A\nA --> B : \n",
    ];
    for flavour in [Flavour::Cpfg, Flavour::Lpy] {
        assert_odd_inputs_resolve(&texts, |text| import(text, flavour));
    }
}

//! Green (Lluch, Vicent, Vivó, Quirós: "Green: a tool for modelling natural elements") -> Meristem.
//!
//! A Green system is written `SYSTEM` (optionally a name), `DECLARATIONS` with one random variable
//! per line (`CONTINUOUS p UNIFORM(0,1)`, `DISCRETE n POISSON(3)`), `AXIOM` and its string,
//! `RULES` with one production per line (`lc < pred > rc : cond → succ`, the arrow also `->`,
//! `-->`, or `$\rightarrow$` as the paper's text prints it), and `END.`. Productions are already
//! Meristem's notation; the importer rewrites the arrow, the declarations into `#random`, `A()`
//! into `A`, and the names of Green's control modules (`Switch`, `Pendulum`, `Repetition`,
//! `Prune`) into Meristem's `@Switch`, `@Pendulum`, `@Repeat`, `@Prune`.

use super::{Import, Output};
use crate::syntax::PARENTHESES;
use crate::vocabulary::{name_of, names_of, DirectiveKind, Function, GroupKind, Meaning};

#[derive(Clone, Copy, PartialEq)]
enum Section {
    Before,
    System,
    Declarations,
    Axiom,
    Rules,
}

/// Green's control modules, by the paper's names and Meristem's, and what Meristem calls them.
const CONTROL_MODULES: &[(&str, Meaning)] = &[
    ("switch", Meaning::Group(GroupKind::Switch)),
    ("pendulum", Meaning::Group(GroupKind::Pendulum)),
    ("repetition", Meaning::Group(GroupKind::Repeat)),
    ("repeat", Meaning::Group(GroupKind::Repeat)),
    ("prune", Meaning::Cut),
];

/// The `@` spelling of a meaning: Green's control modules and pruning are written as `@` names.
fn at_name(meaning: Meaning) -> &'static str {
    names_of(meaning)
        .find(|n| n.starts_with('@'))
        .unwrap_or_else(|| name_of(meaning))
}

pub(super) fn import(text: &str) -> Import {
    let mut out = Output::default();
    out.comment("Imported from Green (an RL-system) by meristem import.", 0);
    let system = System::read(text, &mut out);
    out.line(format!("{} 1", DirectiveKind::Iterations.written()), 0);
    out.note(
        0,
        "Green's syntax does not say how many steps to derive (the number is given when the system is derived): #iterations 1 is written, one step as in the paper's worked example",
    );
    let mut variables = Vec::new();
    for (declaration, n) in &system.declarations {
        if let Some((name, line)) = random_variable(declaration, *n, &mut out) {
            variables.push(name);
            out.line(line, *n);
        }
    }
    if let Some(&(_, first)) = system.axiom.first() {
        let joined: Vec<&str> = system.axiom.iter().map(|(t, _)| t.as_str()).collect();
        out.line(format!("axiom: {}", modules(&joined.join(""))), first);
    }
    let mut translated = Vec::new();
    for (rule, n) in &system.rules {
        match production(rule) {
            Some(p) => {
                translated.push((p.clone(), *n));
                out.line(p.text, *n);
            }
            None => out.note(
                *n,
                format!("'{rule}' is not a production 'pred → succ'; skipped"),
            ),
        }
    }
    note_gaps(&translated, &variables, &mut out);
    out.finish()
}

/// The text of a Green system by section, each piece with its line number.
#[derive(Default)]
struct System {
    /// One random variable each (a line may declare several, separated by `;`).
    declarations: Vec<(String, usize)>,
    /// The axiom's pieces, to be joined (it may span lines).
    axiom: Vec<(String, usize)>,
    /// One production each.
    rules: Vec<(String, usize)>,
}

impl System {
    /// Splits `text` into its sections, noting in `out` what stands outside them (before the
    /// first section, after `END.`) and a missing `END.`.
    fn read(text: &str, out: &mut Output) -> System {
        let mut system = System::default();
        let mut section = Section::Before;
        let mut ended = false;
        for (index, raw) in text.lines().enumerate() {
            let n = index + 1;
            let line = raw.trim();
            if line.is_empty() {
                continue;
            }
            if ended {
                out.note(n, "text after END. is not part of the system; ignored");
                break;
            }
            let (word, rest) = match line.find(char::is_whitespace) {
                Some(i) => (&line[..i], line[i..].trim()),
                None => (line, ""),
            };
            let keyword = word.to_ascii_uppercase();
            let rest = match keyword.as_str() {
                "SYSTEM" => {
                    section = Section::System;
                    if !rest.is_empty() {
                        out.comment(&format!("System: {rest}"), n);
                    }
                    continue;
                }
                "DECLARATIONS" => {
                    section = Section::Declarations;
                    rest
                }
                "AXIOM" => {
                    section = Section::Axiom;
                    rest
                }
                "RULES" => {
                    section = Section::Rules;
                    rest
                }
                "END." | "END" => {
                    ended = true;
                    continue;
                }
                _ => line,
            };
            if !rest.is_empty() {
                system.add(section, rest, n, out);
            }
        }
        if !ended {
            out.note(0, "no END. closes the system; read to the end of the text");
        }
        system
    }

    /// Adds the text `rest` of line `n` to `section`.
    fn add(&mut self, section: Section, rest: &str, n: usize, out: &mut Output) {
        match section {
            Section::Before | Section::System => {
                out.note(n, "a line outside DECLARATIONS, AXIOM and RULES; ignored")
            }
            Section::Declarations => {
                for part in rest.split(';').map(str::trim).filter(|p| !p.is_empty()) {
                    self.declarations.push((part.to_string(), n));
                }
            }
            Section::Axiom => self.axiom.push((rest.to_string(), n)),
            Section::Rules => self.rules.push((rest.to_string(), n)),
        }
    }
}

/// `CONTINUOUS p UNIFORM(0,1)` -> `#random p = uniform(0,1)`, with notes on what the paper does
/// not define.
fn random_variable(text: &str, n: usize, out: &mut Output) -> Option<(String, String)> {
    let mut words = text.splitn(3, char::is_whitespace);
    let kind = words.next().unwrap_or("").to_ascii_uppercase();
    let name = words.next().unwrap_or("").trim();
    let distribution = words.next().unwrap_or("").trim();
    let continuous = match kind.as_str() {
        "CONTINUOUS" => true,
        "DISCRETE" => false,
        _ => {
            out.note(
                n,
                format!("'{text}': a declaration is CONTINUOUS or DISCRETE, a name and a distribution; skipped"),
            );
            return None;
        }
    };
    let valid_name = name.starts_with(|c: char| c.is_ascii_alphabetic())
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    let open = distribution.find('(');
    let (Some(open), true) = (open, valid_name) else {
        out.note(
            n,
            format!("'{text}': expected a name and a distribution such as UNIFORM(0,1); skipped"),
        );
        return None;
    };
    let function = distribution[..open].trim().to_ascii_lowercase();
    let arguments = &distribution[open..];
    let (meristem, fits) = match (function.as_str(), continuous) {
        // Green's distribution names (in lower case) and the function of Meristem's each becomes.
        ("constant", _) => (Function::Constant, true),
        ("uniform", true) => (Function::Uniform, true),
        ("uniform", false) => (Function::UniformInt, true),
        ("exponential", c) => (Function::Exponential, c),
        ("normal" | "gaussian", c) => (Function::Normal, c),
        ("binomial", c) => (Function::Binomial, !c),
        ("poisson", c) => (Function::Poisson, !c),
        _ => {
            out.note(
                n,
                format!("'{function}' is not one of Green's distributions (constant, uniform, exponential, normal or gaussian, binomial, poisson); skipped"),
            );
            return None;
        }
    };
    let translated = meristem.info().name;
    if !fits {
        out.note(
            n,
            format!(
                "Green lists {} as a {} distribution; declared {} here, translated as {translated}",
                function.to_ascii_uppercase(),
                if continuous { "discrete" } else { "continuous" },
                kind
            ),
        );
    }
    match meristem {
        Function::Exponential => out.note(
            n,
            "the paper does not say whether EXPONENTIAL takes a rate or a mean: Meristem's exponential takes the rate",
        ),
        Function::Normal => out.note(
            n,
            "the paper does not say whether NORMAL takes a standard deviation or a variance: Meristem's normal takes (mean, standard deviation)",
        ),
        _ => {}
    }
    Some((
        name.to_string(),
        format!(
            "{} {name} = {translated}{arguments}",
            DirectiveKind::Random.written()
        ),
    ))
}

/// A production in Meristem's notation, and what the note about condition gaps needs.
#[derive(Clone)]
struct Production {
    text: String,
    predecessor: String,
    condition: String,
}

fn production(rule: &str) -> Option<Production> {
    let rule = rule
        .replace("$\\rightarrow$", "->")
        .replace("\\rightarrow", "->")
        .replace('→', "->");
    let arrow = rule.find("->")?;
    // `-->`: the first '-' belongs to the arrow when something stands before it.
    let start = if arrow > 0 && rule[..arrow].ends_with('-') && !rule[..arrow - 1].trim().is_empty()
    {
        arrow - 1
    } else {
        arrow
    };
    let left = rule[..start].trim();
    let right = rule[arrow + 2..].trim();
    let (pattern, condition) = match PARENTHESES.find_char(left, ':') {
        Some(i) => (left[..i].trim(), left[i + 1..].trim()),
        None => (left, ""),
    };
    let predecessor = {
        let after_left = PARENTHESES
            .find_char(pattern, '<')
            .map_or(pattern, |i| &pattern[i + 1..]);
        let strict = PARENTHESES
            .find_char(after_left, '>')
            .map_or(after_left, |i| &after_left[..i]);
        modules(strict.trim())
    };
    let pattern = modules(pattern);
    let text = if condition.is_empty() {
        format!("{pattern} -> {}", modules(right))
    } else {
        format!("{pattern} : {condition} -> {}", modules(right))
    };
    Some(Production {
        text,
        predecessor,
        condition: condition.chars().filter(|c| !c.is_whitespace()).collect(),
    })
}

/// A module string: `A()` -> `A`, Green's control modules -> Meristem's `@` names; everything
/// inside parameter lists is left as written.
fn modules(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let mut depth = 0usize;
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if depth == 0 && c.is_ascii_alphabetic() {
            // `@Switch` is Meristem's spelling already: take the `@` back and write it once.
            let had_at = out.ends_with('@');
            if had_at {
                out.pop();
            }
            let mut j = i;
            while j < chars.len() && chars[j].is_ascii_alphabetic() {
                j += 1;
            }
            let word: String = chars[i..j].iter().collect();
            match CONTROL_MODULES
                .iter()
                .find(|(green, _)| word.eq_ignore_ascii_case(green))
            {
                Some(&(_, meaning)) => out.push_str(at_name(meaning)),
                None => {
                    if had_at {
                        out.push('@');
                    }
                    out.push_str(&word);
                }
            }
            i = j;
            continue;
        }
        match c {
            '(' => {
                // `A()`: no parameters.
                let mut j = i + 1;
                while j < chars.len() && chars[j].is_whitespace() {
                    j += 1;
                }
                if depth == 0 && chars.get(j) == Some(&')') {
                    i = j + 1;
                    continue;
                }
                depth += 1;
            }
            ')' => depth = depth.saturating_sub(1),
            _ => {}
        }
        out.push(c);
        i += 1;
    }
    out
}

/// Notes conditions such as `p<0.4` and `p>0.4` on a random variable for one predecessor: the
/// value between them satisfies neither, and the module is then copied unchanged.
fn note_gaps(productions: &[(Production, usize)], variables: &[String], out: &mut Output) {
    let parse = |c: &str| -> Option<(String, &'static str, String)> {
        for op in ["<=", ">=", "<", ">"] {
            let op: &'static str = op;
            if let Some((v, k)) = c.split_once(op) {
                if !k.starts_with('=') && variables.iter().any(|x| x == v) {
                    return Some((v.to_string(), op, k.to_string()));
                }
            }
        }
        None
    };
    for (p, line) in productions {
        let Some((var, op, value)) = parse(&p.condition) else {
            continue;
        };
        if op != ">" {
            continue;
        }
        let same = |q: &Production, wanted: &str| {
            q.predecessor == p.predecessor
                && parse(&q.condition)
                    .is_some_and(|(v, o, k)| v == var && o == wanted && k == value)
        };
        let below = productions.iter().find(|(q, _)| same(q, "<"));
        let closed = productions
            .iter()
            .any(|(q, _)| same(q, "<=") || same(q, ">="));
        if let (Some((_, below_line)), false) = (below, closed) {
            out.note(
                *line,
                format!(
                    "{var}<{value} (line {below_line}) and {var}>{value} leave {var} = {value} to neither production: Meristem then copies {} unchanged, as Green would (for a continuous {var} that draw has a probability of about 2^-53); kept as written",
                    p.predecessor
                ),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::import::test_support::{assert_odd_inputs_resolve, noted};

    /// The worked example, as the paper's text prints it.
    const WORKED: &str = "SYSTEM\nDECLARATIONS\n  CONTINUOUS p UNIFORM(0,1)\nAXIOM\n  A(1)B(3)A(5)\nRULES\n  A(x): p<0.4  $\\rightarrow$  A(x+1)\n  A(x): p>0.4  $\\rightarrow$  B(x-1)\n  A(x) < B(y) > A(z) : y<4  $\\rightarrow$  B(x+z)[A(y)]\nEND.\n";

    #[test]
    fn the_worked_example_translates_line_for_line() {
        let import = import(WORKED);
        let body: Vec<&str> = import
            .text
            .lines()
            .filter(|l| !l.starts_with("//"))
            .collect();
        assert_eq!(
            body,
            [
                "#iterations 1",
                "#random p = uniform(0,1)",
                "axiom: A(1)B(3)A(5)",
                "A(x) : p<0.4 -> A(x+1)",
                "A(x) : p>0.4 -> B(x-1)",
                "A(x) < B(y) > A(z) : y<4 -> B(x+z)[A(y)]",
            ]
        );
        let lines: Vec<usize> = import.notes.iter().map(|n| n.line).collect();
        assert_eq!(lines, [0, 8], "{:?}", import.notes);
        assert!(import.notes[1].message.contains("p<0.4 (line 7) and p>0.4"));
    }

    #[test]
    fn declarations_map_every_distribution_of_table_1() {
        let import = import("SYSTEM plant\nDECLARATIONS\nCONTINUOUS a CONSTANT(2)\nCONTINUOUS b Uniform(0, 1)\nCONTINUOUS c EXPONENTIAL(2)\nCONTINUOUS d NORMAL(0,1); CONTINUOUS e GAUSSIAN(1,2)\nDISCRETE f CONSTANT(3)\nDISCRETE g UNIFORM(1,6)\nDISCRETE h BINOMIAL(10,0.5)\nDISCRETE i POISSON(3)\nDISCRETE j NORMAL(0,1)\nDISCRETE k ZIPF(2)\nAXIOM A()\nRULES\nA() : NumIt = MaxIt -> Switch(B C)Prune\nEND.\n");
        let text = &import.text;
        for expected in [
            "// System: plant",
            "#random a = constant(2)",
            "#random b = uniform(0, 1)",
            "#random c = exponential(2)",
            "#random d = normal(0,1)",
            "#random e = normal(1,2)",
            "#random f = constant(3)",
            "#random g = uniform_int(1,6)",
            "#random h = binomial(10,0.5)",
            "#random i = poisson(3)",
            "#random j = normal(0,1)",
            "axiom: A\n",
            "A : NumIt = MaxIt -> @Switch(B C)@Prune",
        ] {
            assert!(text.contains(expected), "{expected} missing from\n{text}");
        }
        assert!(!text.contains("zipf"));
        let messages = noted(&import);
        assert!(messages.iter().any(|(l, m)| *l == 5 && m.contains("rate")));
        assert!(messages
            .iter()
            .any(|(l, m)| *l == 6 && m.contains("standard deviation")));
        assert!(messages
            .iter()
            .any(|(l, m)| *l == 11 && m.contains("continuous distribution")));
        assert!(messages.iter().any(|(l, m)| *l == 12 && m.contains("zipf")));
        let (file, d) = crate::syntax::parse(text);
        assert!(d.is_empty(), "{d:?}");
        assert!(crate::model::resolve(&file).1.is_empty());
    }

    #[test]
    fn every_arrow_is_read() {
        for arrow in ["->", "-->", "→", "\\rightarrow"] {
            let import = import(&format!("SYSTEM\nAXIOM\nA\nRULES\nA {arrow} B\nEND."));
            assert!(import.text.contains("A -> B\n"), "{arrow}: {}", import.text);
        }
        let import = import("SYSTEM\nAXIOM\nA\nRULES\n- --> +\nEND.");
        assert!(import.text.contains("- -> +\n"), "{}", import.text);
    }

    #[test]
    fn odd_input_never_panics_and_rejected_lines_are_reported() {
        assert_odd_inputs_resolve(
            &[
                "",
                "END.",
                "RULES\nA",
                "SYSTEM\nAXIOM\nA(\nRULES\nA -> B(\nEND.",
                "DECLARATIONS\nCONTINUOUS\nDISCRETE 1 x(",
                "AXIOM A\nRULES\nA -> frob(1)\nEND.\nmore",
            ],
            import,
        );
        let import = import("AXIOM A\nRULES\nA -> B(frob(1))\nEND.");
        assert!(import
            .notes
            .iter()
            .any(|n| n.line == 3 && n.message.contains("frob")));
    }
}

//! Lparser's formats read, its values threaded through parameters, its laws of net factors.

use super::read::tokenize;
use super::values::{classify, net_expr};
use super::*;
use crate::import::leading_float;
use crate::import::test_support::{assert_odd_inputs_resolve, assert_resolves};

fn run(text: &str) -> Import {
    import(text)
}

fn body(import: &Import) -> Vec<String> {
    import
        .text
        .lines()
        .filter(|l| !l.starts_with("//") && !l.starts_with("#color"))
        .map(str::to_string)
        .collect()
}

#[test]
fn leading_float_reads_like_sscanf() {
    assert_eq!(leading_float(".8)"), Some(0.8));
    assert_eq!(leading_float("  -12.5e1x"), Some(-125.0));
    assert_eq!(leading_float("1e"), Some(1.0));
    assert_eq!(leading_float("abc"), None);
    assert_eq!(leading_float("."), None);
}

#[test]
fn values_belong_to_commands_only() {
    let mut out = Output::default();
    let toks = tokenize("F(2)A(3)c(12)", 1, &mut out);
    let chars: Vec<char> = toks.iter().map(|t| t.ch).collect();
    assert_eq!(chars, ['F', 'A', '(', '3', ')', 'c']);
    assert_eq!(toks[0].value, Some(2.0));
    assert_eq!(toks[5].value, Some(12.0));
}

#[test]
fn the_laws_of_net_factors() {
    assert_eq!(classify(&[1.0; 20]), Net::Neutral);
    let mut macro_ = vec![1.0];
    macro_.extend([0.72; 19]);
    assert_eq!(
        classify(&macro_),
        Net::Law {
            prefix: vec![1.0],
            base: 0.72,
            ratio: 1.0
        }
    );
    assert_eq!(
        net_expr(&classify(&macro_)).unwrap(),
        "(NumIt<MaxIt?0.72:1)"
    );
    let geometric: Vec<f64> = (0..20).map(|r| 1.001f64.powi(r)).collect();
    assert_eq!(
        net_expr(&classify(&geometric)).unwrap(),
        "1.001^(MaxIt-NumIt)"
    );
    let odd: Vec<f64> = (0..20).map(|r| 1.0 + (r % 3) as f64).collect();
    assert_eq!(classify(&odd), Net::Irregular);
}

#[test]
fn a_positional_file_becomes_a_parametric_l_system() {
    // ABOP p. 56's monopodial tree as Lparser writes it.
    let import = run("# tree\n10\n45\n15\n#\nc(12)FFAL\n#\nA=F[&'(.8)!BL]>(137)'!(.9)A\nB=F[-'(.8)!(.9)$CL]'!(.9)C\nC=F[+'(.8)!(.9)$BL]'!(.9)B\nL=~c(8){+(30)f(20)-(120)f(20)-(120)f(20)}\n@\n");
    assert_resolves(&import);
    let body = body(&import);
    assert!(body.contains(&"#iterations 10".to_string()), "{body:?}");
    assert!(
        body.contains(&"axiom: ;(12)F(1,0.15)F(1,0.15)A(1,0.15)L".to_string()),
        "{body:?}"
    );
    assert!(
        body.contains(
            &"A(len,wid) -> F(len,wid)[&B(len*0.8,wid*0.7)L]/(137)A(len*0.9,wid*0.9)".to_string()
        ),
        "{body:?}"
    );
    // The positional format's lengths are in units of 100 (its F).
    assert!(
        body.contains(
            &"L -> ~(343.774677078);(8){+(30)f(0.2)-(120)f(0.2)-(120)f(0.2)}".to_string()
        ),
        "{body:?}"
    );
    assert!(body.contains(&"F(x,t) -> !(width_scale*x*t)F(x)".to_string()));
    let messages: Vec<&str> = import.notes.iter().map(|n| n.message.as_str()).collect();
    assert!(messages.iter().any(|m| m.contains("6 radians")));
    assert!(messages.iter().any(|m| m.starts_with("'$'")));
}

#[test]
fn macros_and_growth_rules_scale_what_follows() {
    let import = run("3\n30\n40\nA\nA=FSFA\nS='(.8)!(.9)\nF='(1.3)F'(.77)\n@\n");
    assert_resolves(&import);
    let body = body(&import);
    // S's effect comes one step after it is written; F's compounds 1.3 × 0.77 every step.
    for line in [
        "S -> ε",
        "A(len,wid) -> F_r(len,wid)SF_r(len*1.001^(MaxIt-NumIt)*(NumIt<MaxIt?0.8:1),wid*(NumIt<MaxIt?0.9:1))A(len*(1.001^(MaxIt-NumIt))^2*(NumIt<MaxIt?0.8:1),wid*(NumIt<MaxIt?0.9:1))",
        "F_r(len,wid) -> F_r(len*1.3,wid)",
        "F_r(len,wid) -> F(len,wid)",
    ] {
        assert!(body.iter().any(|l| l == line), "{line} not in {body:#?}");
    }
}

#[test]
fn the_keyword_format_reads_its_keywords() {
    let import = run("recursion 2\nangle 20\nthickness 50\nmin_thickness 5\nshape 1\ncolor 3 255 0 0\naxiom F\nrule F = F[+F]  # branch\nmutation 3\nfoo 1\n");
    assert_resolves(&import);
    let text = &import.text;
    assert!(text.contains("#iterations 2\n#angle 20\n"), "{text}");
    assert!(text.contains("#color 3 255 0 0"), "{text}");
    assert!(text.contains("\nF_r -> F_r[+F_r] // branch\n"), "{text}");
    assert!(text.contains("max(x*t,0.05)"), "{text}");
    let lines: Vec<usize> = import.notes.iter().map(|n| n.line).collect();
    assert!(
        lines.contains(&5) && lines.contains(&9) && lines.contains(&10),
        "{:?}",
        import.notes
    );
}

#[test]
fn successors_starting_with_two_rolls_are_not_comments() {
    let import = run("1\n30\n10\nA\nA=>>F\n@\n");
    assert_resolves(&import);
    assert!(import.text.contains("A -> / /F(1,0.1)"), "{}", import.text);
}

#[test]
fn nothing_panics_on_odd_input() {
    assert_odd_inputs_resolve(
        &[
            "",
            "@",
            "x\ny\nz\n",
            "1\n2\n3\nF(\n@",
            "1\n2\n3\nF\n[=]\n(=F\nF=F)\nF=G\n=\nF\n",
            "recursion\nrule\naxiom\ncolor 200 1 2 3\n",
            "3\n3\n3\nA\nA=]]A[[\n@\n",
            "99999999999\n1e308\n-5\nFé\n@\n",
        ],
        run,
    );
}

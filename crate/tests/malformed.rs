//! Malformed grammars: every case must give (among its diagnostics) an error with the expected code
//! at the expected 1-based line and column (columns count characters, not bytes), must not panic,
//! and must not build. Codes and positions were read off `meristem check` and checked by hand.

use meristem::diagnostics::Severity;
use meristem::pipeline::{build, BuildOptions};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// (name, source, code, line, column)
type Case = (&'static str, &'static str, &'static str, usize, usize);

// One line per case, so the table reads as a table.
#[rustfmt::skip]
const CASES: &[Case] = &[
    ("axiom_bracket_never_closed", "axiom: F[+F", "E0109", 1, 9),
    ("axiom_bracket_without_open", "axiom: F]+F", "E0108", 1, 9),
    ("successor_bracket_never_closed", "axiom: F\nF -> F[+F", "E0109", 2, 7),
    ("successor_bracket_without_open", "axiom: F\nF -> F+F]F", "E0108", 2, 9),
    ("right_context_bracket_never_closed", "axiom: AB\nA > [B -> C", "E0109", 2, 5),
    ("right_context_bracket_without_open", "axiom: AB\nA > B] -> C", "E0108", 2, 6),
    ("left_context_with_a_bracket", "axiom: AB\nA] < B -> C", "E0115", 2, 2),
    ("angle_is_a_word", "#angle twenty\naxiom: F", "E0203", 1, 8),
    ("iterations_negative", "#iterations -1\naxiom: F", "E0204", 1, 13),
    ("iterations_fraction", "#iterations 1.5\naxiom: F", "E0204", 1, 13),
    ("iterations_beyond_u32", "#iterations 99999999999\naxiom: F", "E0204", 1, 13),
    ("seed_negative", "#seed -1\naxiom: F", "E0204", 1, 7),
    ("number_too_large_in_axiom", "axiom: A(1e999)", "E0126", 1, 10),
    ("number_too_large_in_expression", "axiom: A(1)\nA(x) -> A(x*1e999)", "E0126", 2, 13),
    ("unknown_directive", "#colours 3\naxiom: F", "E0200", 1, 1),
    ("hash_alone", "#\naxiom: F", "E0103", 1, 1),
    ("define_without_expression", "#define R\naxiom: F", "E0113", 1, 9),
    ("tropism_needs_four_numbers", "#tropism 0 -1 0\naxiom: F", "E0207", 1, 10),
    ("color_needs_four_or_eight_numbers", "#color 1 2 3\naxiom: F", "E0208", 1, 8),
    ("color_component_out_of_range", "#color 1 0 300 0\naxiom: F", "E0208", 1, 8),
    ("color_ramp_backwards", "#color 5 2 0 0 0 9 9 9\naxiom: F", "E0208", 1, 8),
    ("lifetime_needs_two_or_five_values", "#lifetime 34\naxiom: F", "E0209", 1, 11),
    ("lifetime_draws_its_own_random_numbers", "#lifetime 34 uniform(0,32)\naxiom: F", "E0209", 1, 14),
    ("lifetime_shares_all_zero", "#lifetime 34 32 0 0 0\naxiom: F", "E0209", 1, 11),
    ("speed_needs_two_or_five_values", "#speed 0 1 2\naxiom: F", "E0209", 1, 8),
    ("shape_growth_rate_of_one", "#shape 1 3\naxiom: F", "E0209", 1, 8),
    ("shape_maturity_not_whole", "#shape 1.5 2.5\naxiom: F", "E0204", 1, 12),
    ("shape_width_two_values", "#shape_width 1 2\naxiom: F", "E0209", 1, 14),
    ("sun_unknown_season", "#sun 38 monsoon 2\naxiom: F", "E0209", 1, 9),
    ("sun_latitude_beyond_the_pole", "#sun 95 summer 2\naxiom: F", "E0209", 1, 6),
    ("wind_without_direction", "#wind 0 0 5\naxiom: F", "E0209", 1, 7),
    ("gravity_is_a_word", "#gravity strong\naxiom: F", "E0203", 1, 10),
    ("width_unit_zero", "#width_unit 0\naxiom: F", "E0215", 1, 13),
    ("width_unit_negative", "#width_unit -2\naxiom: F", "E0215", 1, 13),
    ("width_unit_beyond_the_largest_coordinate", "#width_unit 1e31\naxiom: F", "E0215", 1, 13),
    ("width_unit_is_a_word", "#width_unit model\naxiom: F", "E0203", 1, 13),
    ("apex_lists_no_modules", "#apex\naxiom: F", "E0133", 1, 1),
    ("predecessor_arity_differs_from_axiom", "axiom: A(1)\nA(x,y) -> B", "E0511", 2, 1),
    ("context_arity_differs_from_axiom", "axiom: A(1)B\nA < B -> C", "E0511", 2, 1),
    ("missing_arrow", "axiom: F\nF F[+F]F", "E0105", 2, 1),
    ("wrong_arrow", "axiom: F\nF => FF", "E0105", 2, 1),
    ("empty_predecessor", "axiom: F\n -> F", "E0106", 2, 2),
    ("two_module_predecessor", "axiom: F\nFF -> F", "E0107", 2, 1),
    ("unterminated_block_comment", "axiom: F\n/* never closed\nF -> FF", "E0102", 2, 1),
    ("unterminated_block_comment_after_a_production", "axiom: F\nF -> F /* oops", "E0102", 2, 8),
    ("parameters_never_closed", "axiom: A(1", "E0116", 1, 9),
    ("close_paren_without_open", "axiom: A)", "E0110", 1, 9),
    ("empty_parameter", "axiom: A(1,)", "E0119", 1, 12),
    ("empty_formal_parameter", "axiom: A(1)\nA(x,) -> B", "E0119", 2, 5),
    ("weight_never_closed", "axiom: F\nF -> (0.5 F", "E0116", 2, 6),
    ("two_operators_in_a_row", "axiom: A(1)\nA(x) -> A(x + * 2)", "E0120", 2, 15),
    ("call_never_closed_in_condition", "axiom: A(1)\nA(x) : sin(x > 0 -> B", "E0124", 2, 18),
    ("module_parameters_never_closed_after_call", "axiom: A(1)\nA(x) -> B(sin(x)", "E0116", 2, 10),
    ("condition_missing", "axiom: A(1)\nA(x) : -> B", "E0114", 2, 6),
    ("condition_ends_after_operator", "axiom: A(1)\nA(x) : x > -> B", "E0123", 2, 12),
    ("conditional_without_colon", "axiom: A(1)\nA(x) -> A(x > 1 ? 2)", "E0122", 2, 20),
    ("unknown_function", "axiom: A(1)\nA(x) -> A(foo(x))", "E0501", 2, 11),
    ("unknown_distribution_in_random", "#random p = foo(0, 1)\naxiom: F", "E0501", 1, 13),
    ("function_with_wrong_arity", "axiom: A(1)\nA(x) -> A(sin(x, 2))", "E0502", 2, 11),
    ("random_function_with_wrong_arity", "axiom: A(1)\nA(x) -> A(uniform(1))", "E0502", 2, 11),
    ("unknown_name_in_condition", "axiom: A(1)\nA(x) : y > 1 -> B", "E0505", 2, 8),
    ("unknown_name_in_successor", "axiom: A(1)\nA(x) -> B(y)", "E0505", 2, 11),
    ("function_name_without_call", "axiom: A(1)\nA(x) -> A(sin)", "E0504", 2, 11),
    ("hundred_nested_parentheses", concat!("axiom: A(", "((((((((((((((((((((((((((((((((((((((((((((((((((", "((((((((((((((((((((((((((((((((((((((((((((((((((", "1", "))))))))))))))))))))))))))))))))))))))))))))))))))", "))))))))))))))))))))))))))))))))))))))))))))))))))", ")"), "E0121", 1, 74),
    ("formal_parameter_not_a_name", "axiom: A(1)\nA(1) -> B", "E0510", 2, 3),
    ("duplicate_formal_parameter", "axiom: A(1,2)\nA(x,x) -> B", "E0512", 2, 5),
    ("define_refers_to_itself", "#define R R+1\naxiom: A(R)", "E0503", 1, 11),
    ("negative_constant_weight", "axiom: F\nF -> (-1) FF\nF -> (2) F", "E0513", 2, 7),
    ("empty_file", "", "E0300", 1, 1),
    ("comments_only", "// nothing here\n/* still nothing */\n", "E0300", 1, 1),
    ("division_by_zero_at_run_time", "#iterations 1\naxiom: A(0)\nA(x) -> A(1/x)", "E0500", 3, 11),
    ("remainder_by_zero_at_run_time", "#iterations 1\naxiom: A(3)\nA(x) -> A(x % 0)", "E0500", 3, 11),
    ("division_by_zero_in_a_weight", "#iterations 1\naxiom: F\nF -> (1/0) FF\nF -> (1) F", "E0500", 3, 7),
    ("square_root_of_negative_is_nan", "#iterations 1\naxiom: A(1)\nA(x) -> A(sqrt(-1))", "E0500", 3, 11),
    ("overflow_to_infinity", "#iterations 3\naxiom: A(1e300)\nA(x) -> A(x*1e300)", "E0500", 3, 11),
    ("module_limit", "#max_modules 1000\naxiom: F\nF -> FF\n#iterations 10", "E0400", 4, 1),
    ("maximum_depth_outside_a_section", "maximum depth: 3\naxiom: F", "E0111", 1, 1),
    ("decomposition_never_terminates", "axiom: A\ndecomposition:\nA -> AA", "E0402", 3, 1),
    ("ignore_together_with_consider", "#ignore +\n#consider A\naxiom: A", "E0206", 2, 1),
    ("successor_arity_differs_from_axiom", "axiom: A(1)\nA(x) -> A(x,2)", "E0514", 2, 9),
    ("successor_drops_parameters", "axiom: A(1)\nA(x) -> A", "E0514", 2, 9),
    ("axiom_mixes_arities", "axiom: A(1)A(1,2)", "E0514", 1, 12),
    ("two_arrows", "axiom: F\nF -> F -> FF", "E0136", 2, 8),
    ("draw_lists_nothing", "#draw\naxiom: F", "E0133", 1, 1),
    ("ignore_lists_nothing", "#ignore\naxiom: F", "E0133", 1, 1),
    ("module_name_starts_with_a_digit", "#module 1x\naxiom: F", "E0134", 1, 9),
    ("ignore_with_parameters", "#ignore A(1)\naxiom: F", "E0135", 1, 9),
    ("axiom_over_the_module_limit", "#max_modules 3\naxiom: FFFFF", "E0400", 2, 1),
    ("num_it_called_as_a_function", "axiom: A\nA -> B(NumIt(3))", "E0506", 2, 8),
    ("formal_parameter_called_as_a_function", "axiom: A(1)\nA(x) -> B(x(2))", "E0506", 2, 11),
    ("maximum_depth_is_negative", "axiom: F\nhomomorphism:\nmaximum depth: -1", "E0204", 3, 16),
    ("iterations_beyond_max_steps", "#iterations 20000\naxiom: F", "E0202", 1, 1),
    ("multibyte_comment_before_error", "/* ωωω */ axiom: F]", "E0108", 1, 19),
    ("multibyte_comment_before_error_in_a_production", "axiom: F\n/*ωωω*/ F -> F + ]", "E0108", 2, 18),
    ("multibyte_comment_before_run_time_error", "#iterations 1\naxiom: A(0)\n/*ωω*/ A(x) -> A(1/x)", "E0500", 3, 18),
    ("multibyte_module_before_error", "axiom: ωF]", "E0108", 1, 10),
    ("repeat_writes_itself", "#iterations 2\naxiom: A\nA -> @Repeat(2, A)", "E0404", 3, 6),
    ("pendulum_nests_at_every_step", "#iterations 100\naxiom: A\nA -> @Pendulum(A)", "E0404", 3, 6),
    ("repeat_count_above_the_step_limit", "axiom: @Repeat(1e9, A)", "E0405", 1, 16),
    ("repeat_count_above_a_lowered_step_limit", "#max_steps 10\naxiom: @Repeat(11, A)", "E0405", 2, 16),
    ("nested_repeats_over_the_budget", "#iterations 1\naxiom: @Repeat(10000, @Repeat(10000, @Repeat(10000, A)))\nA -> A", "E0405", 2, 8),
    ("module_limit_beyond_memory", "#max_modules 4000000000\n#iterations 40\naxiom: F\nF -> FFFFFFFFFFFFFFFF", "E0401", 2, 1),
    ("random_reads_itself", "#random p = uniform(0, p)\naxiom: F(p)", "E0507", 1, 24),
    ("random_variables_read_each_other", "#random p = uniform(0, q)\n#random q = normal(p, 1)\naxiom: F(p)", "E0507", 2, 20),
    ("random_cycle_through_a_define", "#define d q\n#random p = uniform(0, d)\n#random q = normal(p, 1)\naxiom: F(p)", "E0507", 3, 20),
    ("normal_with_a_negative_deviation", "#iterations 1\naxiom: A(0)\nA(x) -> A(normal(0, -1))", "E0500", 3, 11),
    ("error_after_lone_carriage_returns", "#iterations 1\raxiom: F\rF F[+F]F", "E0105", 3, 1),
    ("error_after_a_byte_order_mark", "\u{feff}axiom: F]", "E0108", 1, 9),
    ("curve_named_after_a_function", "#curve sin 0 0, 1 1\naxiom: F", "E0205", 1, 8),
    ("curve_defined_twice", "#curve c 0 0, 0.3 0.1, 0.7 0.9, 1 1\n#curve c 0 0, 0.3 0.1, 0.7 0.9, 1 1\naxiom: F(c(0))", "E0205", 2, 8),
    ("curve_named_after_a_define", "#define c 5\n#curve c 0 0, 0.3 0.1, 0.7 0.9, 1 1\naxiom: F(c)", "E0205", 2, 8),
    ("table_named_after_a_curve", "#curve c 0 0, 0.3 0.1, 0.7 0.9, 1 1\n#table c 0 0, 1 1\naxiom: F(c(0))", "E0205", 2, 8),
    ("curve_named_numit_without_points", "#curve NumIt\naxiom: F", "E0205", 1, 8),
    ("homomorphism_past_the_module_limit", "#iterations 0\n#max_modules 1000\naxiom: F\nhomomorphism:\nF -> FFFFFFFFFF", "E0400", 5, 1),
    ("decomposition_past_the_module_limit", "#iterations 1\n#max_modules 1000\naxiom: F\ndecomposition:\nF -> FFFFFFFFFF", "E0400", 5, 1),
    ("seed_above_u64", "#seed 18446744073709551616\naxiom: F", "E0204", 1, 7),
    ("angle_reads_numit", "#angle 10 * NumIt\naxiom: F", "E0203", 1, 8),
    ("iterations_read_maxit", "#iterations MaxIt\naxiom: F", "E0204", 1, 13),
    ("define_reading_numit_in_a_directive", "#define n NumIt + 1\n#step n\naxiom: F", "E0203", 2, 7),
    ("define_chain_too_large_once_expanded", "#define d0 x\n#define d1 d0+d0\n#define d2 d1+d1\n#define d3 d2+d2\n#define d4 d3+d3\n#define d5 d4+d4\n#define d6 d5+d5\n#define d7 d6+d6\n#define d8 d7+d7\n#define d9 d8+d8\n#define d10 d9+d9\n#define d11 d10+d10\n#define d12 d11+d11\n#define d13 d12+d12\naxiom: A(1)\nA(x) -> F(d13)", "E0128", 16, 11),
];

/// Builds one case; returns a description of what went wrong, if anything.
fn check(case: &Case) -> Option<String> {
    let &(name, source, code, line, column) = case;
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        let result = build(source, &BuildOptions::default());
        (result.ok(), result.located_diagnostics(source))
    }));
    let Ok((ok, diagnostics)) = outcome else {
        return Some(format!("{name}: building panicked"));
    };
    let listing: Vec<String> = diagnostics
        .iter()
        .map(|d| {
            format!(
                "{}:{} {:?} {} {}",
                d.line, d.column, d.severity, d.code, d.message
            )
        })
        .collect();
    if ok {
        return Some(format!(
            "{name}: built without errors; diagnostics: {listing:?}"
        ));
    }
    let found = diagnostics.iter().any(|d| {
        d.severity == Severity::Error && d.code == code && d.line == line && d.column == column
    });
    if found {
        None
    } else {
        Some(format!(
            "{name}: expected error {code} at {line}:{column}; got {listing:?}"
        ))
    }
}

#[test]
fn every_malformed_grammar_gives_its_error_at_its_place() {
    assert!(CASES.len() >= 45, "only {} cases", CASES.len());
    let failures: Vec<String> = CASES.iter().filter_map(check).collect();
    assert!(
        failures.is_empty(),
        "{} of {} cases failed:\n{}",
        failures.len(),
        CASES.len(),
        failures.join("\n")
    );
}

#[test]
fn a_broken_line_causes_no_further_errors() {
    // The unclosed '(' is the only problem: the half-read production must not also be checked
    // (it would say 'A' is matched with the wrong number of parameters).
    let source = "axiom: A(1)\nA(x -> B";
    let result = build(source, &BuildOptions::default());
    let codes: Vec<_> = result
        .located_diagnostics(source)
        .iter()
        .map(|d| d.code)
        .collect();
    assert_eq!(codes, ["E0116"]);
}

#[test]
fn messages_name_what_the_user_wrote() {
    for (source, written) in [
        (
            "axiom: F\nhomomorphism:\nmaximum depth: deep",
            "maximum depth:",
        ),
        ("derivation length: x\naxiom: F", "derivation length:"),
        ("#angle twenty\naxiom: F", "#angle"),
    ] {
        let result = build(source, &BuildOptions::default());
        let messages: Vec<_> = result
            .located_diagnostics(source)
            .into_iter()
            .map(|d| d.message)
            .collect();
        assert!(
            messages.iter().any(|m| m.starts_with(written)),
            "{source:?}: {messages:?}"
        );
    }
}

/// The located diagnostics of `source`: (line, column, code, message).
fn located(source: &str) -> Vec<(usize, usize, &'static str, String)> {
    build(source, &BuildOptions::default())
        .located_diagnostics(source)
        .into_iter()
        .map(|d| (d.line, d.column, d.code, d.message))
        .collect()
}

#[test]
fn messages_name_the_other_place_by_its_line_not_a_byte() {
    // issue 50, 11: E0201, E0104 and E0301 said "at byte N".
    for (source, code, line, column, other) in [
        ("#angle 10\n#angle 20\naxiom: F", "E0201", 2, 1, "line 1"),
        ("axiom: F\n\naxiom: G", "E0104", 3, 1, "line 1"),
        ("axiom: F\nF -> FF\n\nF -> G", "E0301", 4, 1, "line 2"),
        (
            "\u{feff}#angle 1\r#angle 2\raxiom: F",
            "E0201",
            2,
            1,
            "line 1",
        ),
    ] {
        let all = located(source);
        let found = all.iter().find(|d| d.2 == code);
        let Some((l, c, _, message)) = found else {
            panic!("{source:?}: no {code} in {all:?}");
        };
        assert_eq!((*l, *c), (line, column), "{source:?}: {message}");
        assert!(message.contains(other), "{source:?}: {message}");
        assert!(!message.contains("byte"), "{source:?}: {message}");
    }
}

#[test]
fn a_deeply_nested_directive_argument_is_quoted_short() {
    // issue 50, 11: 70 nested parentheses around a 200 KB argument were quoted whole.
    let argument = format!(
        "{}1{}{}",
        "(".repeat(70),
        " ".repeat(200_000),
        ")".repeat(70)
    );
    let source = format!("#angle {argument}\naxiom: F");
    let all = located(&source);
    let (line, column, code, message) = &all[0];
    assert_eq!((*line, *column, *code), (1, 8, "E0203"), "{message}");
    assert!(
        message.chars().count() < 200,
        "{} characters",
        message.len()
    );
    assert!(
        message.contains(&format!("{}…", "(".repeat(40))),
        "{message}"
    );
    assert!(message.contains("nested more than"), "{message}");
}

#[test]
fn seeds_up_to_u64_max_are_read_exactly() {
    let all = located("#seed 18446744073709551615\naxiom: F");
    assert!(all.is_empty(), "{all:?}");
    let all = located("#seed 18446744073709551616\naxiom: F");
    assert!(all[0].3.contains("found 18446744073709551616"), "{all:?}");
}

#[test]
fn a_homomorphism_overflow_names_the_production() {
    let all = located("#iterations 0\n#max_modules 1000\naxiom: F\nhomomorphism:\nF -> FFFFFFFFFF");
    let message = &all[0].3;
    assert!(
        message.starts_with("this homomorphism production makes a string of"),
        "{message}"
    );
    assert!(!message.contains("axiom"), "{message}");
}

#[test]
fn a_define_cycle_names_the_cycle() {
    let source = "#define R S\n#define S R\naxiom: A(R)";
    let result = build(source, &BuildOptions::default());
    let messages: Vec<_> = result
        .located_diagnostics(source)
        .into_iter()
        .map(|d| d.message)
        .collect();
    assert!(
        messages.iter().any(|m| m.contains("R -> S -> R")),
        "{messages:?}"
    );
}

#[test]
fn case_names_are_unique() {
    let mut names: Vec<&str> = CASES.iter().map(|c| c.0).collect();
    names.sort_unstable();
    let before = names.len();
    names.dedup();
    assert_eq!(before, names.len(), "two cases share a name");
}

//! A module's lineage (the studio's debugger, issue 48): the module of the derived string, the
//! module it came from at each earlier step back to the axiom, and the production that made it
//! at each step. It derives again with every step recorded (the derivation view's sequence,
//! [`derive::derive_traced`], within [`derive::MAX_TRACE_BYTES`]), so a stochastic grammar gives
//! the same plant with the same seed, and the environment answers between steps as it did.
//!
//! How the other rule kinds appear: decomposition finishes its step, so a module it wrote shows
//! that step's production (the one that rewrote its ancestor) with its own text; homomorphism
//! happens after the last step and is not part of the lineage (a module the turtle drew through
//! it is picked as the module of the derived string it comes from); a timed grammar's steps are
//! its rounds of replacements, each at its growth time, and a last step that only ages every
//! module, with no production.

use super::observer;
use crate::derive::{DeriveOptions, NOT_REWRITTEN};
use crate::diagnostics::{Diagnostic, LineIndex};
use crate::model::Model;

/// One step of a lineage: the ancestor at that step, and what made it.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
#[serde(rename_all = "camelCase")]
pub struct LineageRow {
    /// The step (0: the axiom).
    pub step: u32,
    /// The ancestor's index in that step's string.
    pub module: u32,
    /// The ancestor as written (`A(1.5)`).
    pub text: String,
    /// The production (an index into the model's productions) that wrote it in that step; `None`
    /// when it was copied, or is the axiom's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub production: Option<u32>,
    /// A timed grammar's growth time of that step's string, in steps.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time: Option<f64>,
    /// The modules of the derived string that descend from it: `first ..= last` (rewriting keeps
    /// the order of the modules, so every module between them descends from it too).
    pub first: u32,
    pub last: u32,
}

/// The lineage of module `module` of the string derived with `options`: one row per step, the
/// last step first, back to the axiom. `E0411` when there is no such module.
pub fn lineage(
    model: &Model,
    options: &DeriveOptions,
    module: usize,
) -> Result<Vec<LineageRow>, Diagnostic> {
    let steps = observer::trace(model, options)?;
    let last = steps.last().map_or(0, |s| s.string.len());
    if module >= last {
        return Err(Diagnostic::error(
            "E0411",
            model.axiom_span.clone(),
            format!(
                "no module {module} in the derived string: it has {last} modules, numbered from 0"
            ),
        ));
    }
    let mut rows = Vec::with_capacity(steps.len());
    let mut at = module;
    // Each module of the derived string's ancestor at the step of the row being written.
    let mut ancestors: Vec<u32> = (0..last as u32).collect();
    for (k, s) in steps.iter().enumerate().rev() {
        let production = s.origin.get(at).copied().filter(|&p| p != NOT_REWRITTEN);
        let (first, last) = descendants(&ancestors, at as u32);
        rows.push(LineageRow {
            step: k as u32,
            module: at as u32,
            text: s.string.module_text(&model.alphabet, at),
            production,
            time: s.time,
            first,
            last,
        });
        match s.parent.get(at) {
            Some(&p) => at = p as usize,
            None if k == 0 => {}
            // A step without provenance (never expected): the lineage stops there, said as is.
            None => break,
        }
        for a in &mut ancestors {
            *a = s.parent.get(*a as usize).copied().unwrap_or(u32::MAX);
        }
    }
    Ok(rows)
}

/// The first and last index of `ancestors` equal to `module` (it is one of them).
fn descendants(ancestors: &[u32], module: u32) -> (u32, u32) {
    let first = ancestors.iter().position(|&a| a == module).unwrap_or(0);
    let last = ancestors
        .iter()
        .rposition(|&a| a == module)
        .unwrap_or(first);
    (first as u32, last as u32)
}

/// Production `index` of `model` as the lineage names it: its line and column (from 1) in
/// `source`, and its text (with its condition and contexts, as written).
pub fn production_place(source: &str, model: &Model, index: u32) -> Option<(usize, usize, String)> {
    let span = model
        .productions
        .productions
        .get(index as usize)?
        .span
        .clone();
    let (line, column) = LineIndex::new(source).line_column(span.start);
    let text = source.get(span)?.trim().to_string();
    Some((line, column, text))
}

/// A lineage as the CLI prints it (and the studio's tests compare): one line per step, the last
/// first: `step 2: F [3] <- 1:1 F -> F[+F]F` (`copied`, `axiom`).
pub fn lineage_text(source: &str, model: &Model, rows: &[LineageRow]) -> String {
    let mut out = String::new();
    for row in rows {
        let when = row.time.map(|t| format!(" (t = {t})")).unwrap_or_default();
        let how = match row
            .production
            .and_then(|p| production_place(source, model, p))
        {
            Some((line, column, text)) => format!("{line}:{column} {text}"),
            None if row.step == 0 => "axiom".to_string(),
            None => "copied".to_string(),
        };
        out.push_str(&format!(
            "step {}{when}: {} [{}] <- {how}\n",
            row.step, row.text, row.module
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::{build, BuildOptions};

    fn lineage_of(source: &str, n: u32, module: usize) -> Result<String, Diagnostic> {
        let b = build(source, &BuildOptions::with_iterations(n));
        let model = b.model.as_ref().expect("a model");
        let rows = lineage(model, &b.derived_with, module)?;
        Ok(lineage_text(source, model, &rows))
    }

    #[test]
    fn a_twig_of_f_to_f_bracket_f_traced_back_by_hand() {
        // F -> F[+F]F: step 1 is F[+F]F (0..6); step 2 writes each F as F[+F]F:
        // F[+F]F [ + F[+F]F ] F[+F]F, modules 0-5, 6, 7, 8-13, 14, 15-20.
        // Module 11 (the second F of step 1's F at 3, written as its "F" at 8 + 3): the F inside
        // that copy's brackets. Step 1's module 3 is the F inside F[+F]F's brackets.
        let source = "axiom: F\nF -> F[+F]F\n";
        let got = lineage_of(source, 2, 11).unwrap();
        assert_eq!(
            got,
            "step 2: F [11] <- 2:1 F -> F[+F]F\n\
             step 1: F [3] <- 2:1 F -> F[+F]F\n\
             step 0: F [0] <- axiom\n"
        );
        // A bracket copied at step 2 from step 1's `[` (module 1), and the `+` module 7 of step 2,
        // copied from step 1's `+` at 2.
        let b = build(source, &BuildOptions::with_iterations(2));
        let rows = lineage(b.model.as_ref().unwrap(), &b.derived_with, 11).unwrap();
        let spans: Vec<_> = rows.iter().map(|r| (r.first, r.last)).collect();
        // Step 1's F at 3 became modules 8-13; the axiom, the whole string.
        assert_eq!(spans, [(11, 11), (8, 13), (0, 20)]);
        let got = lineage_of(source, 2, 7).unwrap();
        assert_eq!(
            got,
            "step 2: + [7] <- copied\nstep 1: + [2] <- 2:1 F -> F[+F]F\nstep 0: F [0] <- axiom\n"
        );
    }

    #[test]
    fn an_unknown_module_is_an_error_that_says_how_many_there_are() {
        let e = lineage_of("axiom: F\nF -> FF\n", 2, 4).unwrap_err();
        assert_eq!(e.code, "E0411");
        assert!(e.message.contains("it has 4 modules"), "{}", e.message);
    }

    #[test]
    fn parametric_context_sensitive_rows_name_the_production_with_its_condition_and_context() {
        let source = "axiom: B(0) A(1)\nB(x) < A(y) : y < 5 -> A(y + 1)\nA(y) -> A(y) B(y)\n";
        let got = lineage_of(source, 2, 1).unwrap();
        assert_eq!(
            got,
            "step 2: A(3) [1] <- 2:1 B(x) < A(y) : y < 5 -> A(y + 1)\n\
             step 1: A(2) [1] <- 2:1 B(x) < A(y) : y < 5 -> A(y + 1)\n\
             step 0: A(1) [1] <- axiom\n"
        );
    }

    #[test]
    fn a_stochastic_lineage_follows_the_plant_of_the_same_seed() {
        let source = "axiom: F\n#seed 7\nF -> (0.5) F[+F]\nF -> (0.5) FF\n";
        let b = build(source, &BuildOptions::with_iterations(4));
        let model = b.model.as_ref().unwrap();
        let s = &b.derivation.string;
        let last_f = (0..s.len())
            .rev()
            .find(|&i| s.module_text(&model.alphabet, i) == "F")
            .unwrap();
        let rows = lineage(model, &b.derived_with, last_f).unwrap();
        assert_eq!(rows.len(), 5);
        assert_eq!(rows[0].module as usize, last_f);
        // An F is rewritten at every step: each row names the production the generator chose.
        assert!(rows[..4].iter().all(|r| r.production.is_some()));
        assert!(rows.iter().all(|r| r.text == "F"));
        // The same seed, the same lineage.
        assert_eq!(lineage(model, &b.derived_with, last_f).unwrap(), rows);
    }

    #[test]
    fn a_timed_lineage_has_the_growth_time_of_each_round_and_the_ageing_step_last() {
        let source = include_str!("../../../public/examples/abop-6.1-timed-anabaena.lsys");
        let options = BuildOptions {
            time: Some(3.5),
            ..BuildOptions::default()
        };
        let b = build(source, &options);
        let rows = lineage(b.model.as_ref().unwrap(), &b.derived_with, 3).unwrap();
        let times: Vec<_> = rows.iter().map(|r| r.time).collect();
        let expected = [3.5, 3.0, 2.0, 1.0, 0.0].map(Some);
        assert_eq!(times, expected);
        // The ageing step rewrites nothing; each round before it wrote the ancestor.
        assert_eq!(rows[0].production, None);
        assert!(rows[1..4].iter().all(|r| r.production.is_some()));
    }

    #[test]
    fn decomposition_rows_show_the_step_that_rewrote_the_ancestor() {
        let source = "axiom: A\nA -> B\ndecomposition:\nB -> C D\n";
        let got = lineage_of(source, 1, 1).unwrap();
        assert_eq!(got, "step 1: D [1] <- 2:1 A -> B\nstep 0: A [0] <- axiom\n");
    }
}

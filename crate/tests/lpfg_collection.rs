//! lpfg objects of vlab's course collection (`tests/collections/lpfg/`, issue 49) opened as the
//! command line opens them (`meristem derive FOLDER --stats`: the hand translation when it
//! suffices, else the machine's Python running the L+C), each checked against a count of
//! segments and the height of its main axis derived by hand from its `lsystem.l`. The checks of
//! 01-quadratic-Koch, 03-snowflake, 05-compound-interp, 10-recursive, 01-hormone-up and
//! 03-signal-down live in `python/tests/test_lpfg_models.py`; these are other objects.
#![cfg(not(target_arch = "wasm32"))]

use std::path::PathBuf;
use std::process::Command;

/// The stats of the object `name` as `meristem derive FOLDER --stats` prints them.
fn stats(name: &str) -> serde_json::Value {
    let python = Command::new("python3").arg("--version").output();
    assert!(
        python.is_ok_and(|o| o.status.success()),
        "these tests need python3 (3.11 or later)"
    );
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/collections/lpfg")
        .join(name);
    let out = Command::new(env!("CARGO_BIN_EXE_meristem"))
        .args(["derive", &dir.display().to_string(), "--stats"])
        .output()
        .expect("run meristem");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{name}: {stderr}");
    let line = stdout.lines().last().unwrap_or("");
    serde_json::from_str(line).unwrap_or_else(|e| panic!("{name}: {e}: {stdout}\n{stderr}"))
}

/// The top of the plant: the largest y of its mesh (lpfg's turtle starts heading up +y).
fn top(stats: &serde_json::Value) -> f64 {
    stats["bounds"][1][1].as_f64().expect("bounds")
}

#[test]
fn compound_leaf_draws_130_internodes_after_4_steps() {
    // 04-compound: `A(v) → F(v) [Right A(v)] [Left A(v)] F(v) A(v)`, `F(v) → F(v) F(v)`, axiom
    // A(1.0), 4 steps; A has no interpretation, so only F draws. With a apices and f internodes:
    // a' = 3a, f' = 2f + 2a. Step 0: a 1, f 0; 1: 3, 2; 2: 9, 10; 3: 27, 38; 4: 81, 130.
    // Main axis: the pair of F laid at step k has doubled 4 − k times: 2·(8 + 4 + 2 + 1) = 30.
    let s = stats("04-compound");
    assert_eq!(s["segments"].as_u64(), Some(130), "{s}");
    assert!((top(&s) - 30.0).abs() < 0.01, "{s}");
}

#[test]
fn compound_leaf_with_parameters_draws_its_80_internodes_and_81_apices() {
    // 06-compound-param: `A(v) → I(1) [Right A(v)] [Left A(v)] I(1) A(v)`, `I(x) → I(2x)`,
    // interpretation A(v) → F(v), I(x) → F(x); 4 steps. a' = 3a, i' = i + 2a:
    // a 1, 3, 9, 27, 81; i 0, 2, 8, 26, 80. Segments: 80 + 81 = 161.
    // Main axis: I pairs of steps 1..4 have lengths 8, 4, 2, 1, then A(1): 2·15 + 1 = 31.
    let s = stats("06-compound-param");
    assert_eq!(s["segments"].as_u64(), Some(161), "{s}");
    assert!((top(&s) - 31.0).abs() < 0.01, "{s}");
}

#[test]
fn planation_branches_three_times_in_its_1000_steps() {
    // 01-planation: n = 1 at Start, n + 1 at StartEach, so step k runs with n = k + 1 (2..1001).
    // A and I rewrite only when n % 60 == 2 and 50 < n < 230: n = 62, 122, 182, three times.
    // Then `A → I [Left Roll A] [Right Roll A] I A` and `I → I I` (Roll only rolls):
    // a 1, 3, 9, 27; i 0, 2, 10, 38. Interpretation A → F(1), I → F(1): 38 + 27 = 65.
    // Main axis: pairs laid at the three events, doubled 2, 1, 0 times, and the apex:
    // 2·(4 + 2 + 1) + 1 = 15.
    let s = stats("01-planation");
    assert_eq!(s["segments"].as_u64(), Some(65), "{s}");
    assert!((top(&s) - 15.0).abs() < 0.01, "{s}");
}

#[test]
fn florigen_stops_the_apex_after_16_internodes() {
    // 04-florigen: axiom D(0) I() A(0); `I < A(t)`: A(0) → A(1), A(1) → I A(0): one internode
    // every second step, so 1 + ⌊s/2⌋ internodes after step s. D(t) → D(t+1) and `D(t) < I`
    // with t == 15 → J: the first internode turns J at step 16; `J < I → J` moves the signal up
    // one internode a step: internodes 1..s−15 are J after step s. After step 31 all 16
    // (1 + 15) are J; at step 32 `J < A → K`, and nothing rewrites after that (J and K have
    // no rules). Interpretation J → F(1), K → Sphere(0.85): 16 segments, top 16 + 0.85.
    let s = stats("04-florigen");
    assert_eq!(s["segments"].as_u64(), Some(16), "{s}");
    assert!((top(&s) - 16.85).abs() < 0.01, "{s}");
}

#[test]
fn hormone_down_lays_its_predefined_eleven_internodes() {
    // 02-hormone-down: derivation length 1; the axiom X() becomes 5 × (A [turn A]) then B, so
    // 10 A and 1 B, each F(1) by interpretation: 11 segments. The main axis holds 5 A and B:
    // top 6. (`A > B → B` would need a second step.)
    let s = stats("02-hormone-down");
    assert_eq!(s["segments"].as_u64(), Some(11), "{s}");
    assert!((top(&s) - 6.0).abs() < 0.01, "{s}");
}

#[test]
fn fractal_fern_grows_its_apices_through_three_delays() {
    // 07-fractal-ferns, STEPS 18, D 3, R 1.28: `A(v) → A(v+1)` while v < 3; A(3) →
    // I(1) [Right A(0)] [Left A(0)] I(1) A(3); `I(x) → I(1.28x)`; interpretation A(v) → F(v),
    // I(x) → F(x). Counting apices by state (a0, a1, a2, a3) and internodes i, per step:
    // a0' = 2·a3, a1' = a0, a2' = a1, a3' = a3 + a2, i' = i + 2·a3. From A(1):
    //  step:  1  2  3  4  5  6   7   8   9  10  11  12  13  14  15  16   17   18
    //  a0:    0  0  2  2  2  2   6  10  14  18  30  50  78 114 174 274  430  658
    //  a1:    0  0  0  2  2  2   2   6  10  14  18  30  50  78 114 174  274  430
    //  a2:    1  0  0  0  2  2   2   2   6  10  14  18  30  50  78 114  174  274
    //  a3:    0  1  1  1  1  3   5   7   9  15  25  39  57  87 137 215  329  503
    //  i:     0  0  2  4  6  8  14  24  38  56  86 136 214 328 502 776 1206 1864
    // After 18 steps: 1864 internodes and 430 + 274 + 503 apices of non-zero length (the 658
    // A(0) draw F(0), nothing): 1864 + 1207 = 3071 segments.
    // Main axis: the I pair of step k (3..18) is 1.28^(18−k) long, then A(3):
    // 2·(1.28^16 − 1)/0.28 + 3 = 366.74.
    let s = stats("07-fractal-ferns");
    assert_eq!(s["segments"].as_u64(), Some(3071), "{s}");
    let expected = 2.0 * (1.28f64.powi(16) - 1.0) / 0.28 + 3.0;
    assert!(
        (top(&s) - expected).abs() < 0.05,
        "{} vs {expected}",
        top(&s)
    );
}

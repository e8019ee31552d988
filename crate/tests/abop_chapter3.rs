//! ABOP chapter 3 (herbaceous plants and inflorescences) in the gallery, checked against the book:
//! the flowers of each developmental sequence counted at each step by hand from the grammar, and
//! the order in which they open (acropetal or basipetal) read from the derived strings.

mod shared;

use meristem::pipeline::{build, Build, BuildOptions};
use shared::{example, modules};

fn at(text: &str, n: u32) -> Build {
    let result = build(
        text,
        &BuildOptions {
            iterations: Some(n),
            ..BuildOptions::default()
        },
    );
    assert!(result.diagnostics.is_empty(), "{:?}", result.diagnostics);
    result
}

/// The laterals of the main axis, base first: for each top-level branch `[…]`, the modules in it.
fn laterals(derived: &str) -> Vec<Vec<(String, Vec<f64>)>> {
    let mut branches = Vec::new();
    let mut depth = 0;
    for m in modules(derived) {
        match m.0.as_str() {
            "[" => {
                if depth == 0 {
                    branches.push(Vec::new());
                }
                depth += 1;
            }
            "]" => depth -= 1,
            _ if depth > 0 => branches.last_mut().expect("open branch").push(m),
            _ => {}
        }
    }
    branches
}

/// The count of modules named `name` in `ms`.
fn count(ms: &[(String, Vec<f64>)], name: &str) -> usize {
    ms.iter().filter(|m| m.0 == name).count()
}

#[test]
fn the_raceme_opens_its_flowers_from_the_base_up_by_lineage() {
    // V = 3 vegetative nodes, then one bud a step; a bud made at step s is B(n - s) at step n and
    // open from age T = 3: n - V buds and flowers, max(0, n - V - T) of them open.
    let text = example("abop-sec-3.3.1-raceme.lsys");
    for n in 1..=14u32 {
        let derived = at(&text, n).derived_text();
        let ages: Vec<f64> = modules(&derived)
            .into_iter()
            .filter(|m| m.0 == "B")
            .map(|m| m.1[0])
            .collect();
        assert_eq!(ages.len(), n.saturating_sub(3) as usize, "buds at n = {n}");
        let open = ages.iter().filter(|&&t| t >= 3.0).count();
        assert_eq!(
            open,
            n.saturating_sub(6) as usize,
            "open flowers at n = {n}"
        );
        // Base first: the ages fall along the axis, so the open ones are the lowest.
        assert!(ages.windows(2).all(|w| w[0] > w[1]), "n = {n}: {ages:?}");
    }
    let leaves = count(&modules(&at(&text, 14).derived_text()), "L");
    assert_eq!(leaves, 3, "the three vegetative nodes");
}

/// The laterals' states along the main axis, base first: 'K' a flower, 'B' a bud.
fn states(derived: &str) -> String {
    laterals(derived)
        .iter()
        .map(|b| if count(b, "K") > 0 { 'K' } else { 'B' })
        .collect()
}

#[test]
fn the_acropetal_signal_opens_the_flowers_from_the_base_up() {
    // D(6) waits 6 steps; the signal enters the first internode at step 7 and climbs one a step;
    // a bud flowers the step after its internode: min(8, n - 7) flowers from step 8, the lowest
    // ones; the apex, above the 8th internode (signalled at step 14), flowers at step 15.
    let text = example("abop-sec-3.1.2-acropetal-flowering.lsys");
    for n in 0..=20u32 {
        let derived = at(&text, n).derived_text();
        let s = states(&derived);
        let flowers = (n.saturating_sub(7) as usize).min(8);
        let buds = (n as usize).min(8) - flowers;
        assert_eq!(s, "K".repeat(flowers) + &"B".repeat(buds), "n = {n}");
        assert_eq!(
            derived.ends_with('K'),
            n >= 15,
            "terminal flower at n = {n}"
        );
    }
}

#[test]
fn the_basipetal_signal_opens_the_flowers_from_the_top_down() {
    // The apex makes 8 nodes (steps 1 to 8), flowers at step 9 and signals the top internode at
    // step 10; the signal goes down one internode a step and a bud flowers the step after its
    // internode: clamp(n - 10, 0, 8) flowers, the highest ones.
    let text = example("abop-sec-3.1.2-basipetal-flowering.lsys");
    for n in 0..=18u32 {
        let derived = at(&text, n).derived_text();
        let buds = (n as usize).min(8);
        let flowers = (n.saturating_sub(10) as usize).min(8);
        assert_eq!(
            states(&derived),
            "B".repeat(buds - flowers) + &"K".repeat(flowers),
            "n = {n}"
        );
        assert_eq!(derived.ends_with('K'), n >= 9, "terminal flower at n = {n}");
    }
}

/// The step at which each lateral of the main axis (base first) first holds a flower.
fn first_flowering(text: &str, steps: u32) -> Vec<Option<u32>> {
    let mut first: Vec<Option<u32>> = Vec::new();
    for n in 1..=steps {
        let branches = laterals(&at(text, n).derived_text());
        first.resize(branches.len(), None);
        for (i, b) in branches.iter().enumerate() {
            if first[i].is_none() && count(b, "K") > 0 {
                first[i] = Some(n);
            }
        }
    }
    first
}

#[test]
fn mycelis_flowers_from_the_top_down() {
    let text = example("abop-ls-3.2-mycelis-muralis.lsys");
    // By hand: the apex makes a branch every third step (steps 1, 4, 7, …), so after step t the
    // main axis has 1 + floor((t + 2) / 3) internodes; the florigen leaves I(20) at step 21 and
    // climbs one internode a step, reaching the apex's side at step 33: the apex flowers at 34.
    assert!(!at(&text, 33).derived_text().ends_with('K'));
    assert!(at(&text, 34).derived_text().ends_with("T(0)K"));
    // Every lateral of the main axis flowers by step 78, and no lower one before a higher one:
    // the flowering sequence is basipetal.
    let first = first_flowering(&text, 78);
    assert_eq!(first.len(), 11, "11 laterals, made at steps 1, 4, …, 31");
    let steps: Vec<u32> = first.iter().map(|s| s.expect("flowered")).collect();
    assert!(steps.windows(2).all(|w| w[0] >= w[1]), "{steps:?}");
    assert!(steps[0] > steps[10], "{steps:?}");
    assert!(steps[10] > 34, "the laterals after the apex");
}

#[test]
fn lychnis_branches_as_a_dichasium_with_a_flower_ending_every_axis() {
    // A(7) fires at once and every new apex after 7 (A(0)) or 3 (A(4)) more steps; each firing
    // makes one flower K, two leaves L and two apices. Hand count of firings: step 1 (1 apex),
    // then A(4) fires at 1 + 4 = 5 and A(0) at 1 + 8 = 9, … (the recurrence below).
    let text = example("abop-3.14-lychnis-coronaria.lsys");
    // f(n): flowers after n steps. An apex born at step s as A(a) fires at step s + 8 - a.
    let mut births = vec![(0u32, 7.0f64)]; // the axiom's A(7), "born" at step 0
    let mut fired = Vec::new();
    while let Some((s, a)) = births.pop() {
        let step = s + (8.0 - a) as u32;
        if step <= 30 {
            fired.push(step);
            births.push((step, 0.0));
            births.push((step, 4.0));
        }
    }
    for n in [1u32, 5, 9, 13, 20, 30] {
        let ms = modules(&at(&text, n).derived_text());
        let expected = fired.iter().filter(|&&s| s <= n).count();
        assert_eq!(count(&ms, "K"), expected, "flowers at n = {n}");
        assert_eq!(count(&ms, "L"), 2 * expected, "leaves at n = {n}");
        assert_eq!(count(&ms, "A"), expected + 1, "apices at n = {n}");
    }
}

#[test]
fn the_panicle_carries_more_flowers_on_its_lower_branches() {
    // Lateral i (0 at the base) is made at step i + 1 and makes one bud a step for M = 5 steps,
    // then a terminal flower; a bud opens T = 2 steps after it is made.
    let text = example("abop-sec-3.3.1-panicle.lsys");
    for n in [4u32, 7, 10, 14] {
        let branches = laterals(&at(&text, n).derived_text());
        assert_eq!(branches.len(), (n as usize).min(6), "laterals at n = {n}");
        for (i, b) in branches.iter().enumerate() {
            let age = n as usize - (i + 1); // steps the lateral apex has worked
            assert_eq!(count(b, "B"), age.min(5), "buds of lateral {i} at n = {n}");
            let open = b.iter().filter(|m| m.0 == "B" && m.1[0] >= 2.0).count();
            assert_eq!(
                open,
                age.min(5).min(age.saturating_sub(2)),
                "lateral {i}, n = {n}"
            );
            assert_eq!(
                count(b, "K"),
                usize::from(age > 5),
                "lateral {i}'s flower, n = {n}"
            );
        }
        let flowers: Vec<usize> = branches.iter().map(|b| count(b, "B")).collect();
        assert!(flowers.windows(2).all(|w| w[0] >= w[1]), "{flowers:?}");
    }
}

#[test]
fn the_monochasium_makes_one_flower_every_d_plus_one_steps() {
    let text = example("abop-sec-3.3.2-monochasium.lsys");
    for n in 1..=24u32 {
        let ms = modules(&at(&text, n).derived_text());
        assert_eq!(
            count(&ms, "K"),
            n.div_ceil(3) as usize, // floor((n + D) / (D + 1)) with D = 2
            "flowers at n = {n}"
        );
        assert_eq!(count(&ms, "A"), 1, "one apex goes on at n = {n}");
    }
}

#[test]
fn the_partial_raceme_has_leaves_below_and_flowers_above() {
    let text = example("abop-sec-3.1.1-partial-raceme.lsys");
    for seed in 1..=12u64 {
        let result = build(
            &text,
            &BuildOptions {
                seed: Some(seed),
                ..BuildOptions::default()
            },
        );
        let ms = modules(&result.derived_text());
        let organs: String = laterals(&result.derived_text())
            .iter()
            .map(|b| if count(b, "K") > 0 { 'K' } else { 'L' })
            .collect();
        // Whatever the choices: the leaves come first, then the flowers (never a leaf above a flower).
        assert!(!organs.contains("KL"), "seed {seed}: {organs}");
        assert!(count(&ms, "I") >= organs.len());
    }
}

#[test]
fn capsella_makes_fourteen_leaves_then_a_raceme_of_flowers_turning_to_fruits() {
    // By hand from the grammar: a(13) makes one leaf L a step for 14 steps (t = 13 … 0), and A one
    // pedicel a step from step 15 on. A pedicel made at step s has its four petals K drawn from
    // step s + 1 (each K two polygons) and, at step s + 6, X(5) has counted down and becomes the
    // fruit (one polygon) while % cuts the petals behind it. An L becomes its two halves the step
    // after it is made.
    let text = example("abop-3.05-capsella-bursa-pastoris.lsys");
    for n in [1u32, 10, 14, 15, 16, 20, 21, 26, 30] {
        let b = at(&text, n);
        let ms = modules(&b.derived_text());
        let leaves = n.min(14) as usize;
        let pedicels = n.saturating_sub(14) as usize;
        let made = |s: u32| (15..=n).contains(&s);
        let fruits = (15..=n).filter(|&s| s + 6 <= n).count();
        let flowering = (15..=n).filter(|&s| made(s) && s < n && s + 6 > n).count();
        assert_eq!(
            count(&ms, "L"),
            usize::from((1..=14).contains(&n)),
            "n = {n}"
        );
        assert_eq!(count(&ms, "A"), usize::from(n >= 14), "n = {n}");
        assert_eq!(
            count(&ms, "X"),
            pedicels - fruits,
            "unripe fruits at n = {n}"
        );
        assert_eq!(count(&ms, "K"), if n >= 15 { 4 } else { 0 }, "n = {n}");
        let leaf_halves = 2 * (leaves - usize::from(n <= 14));
        assert_eq!(
            b.plant.skeleton.polygons.len(),
            leaf_halves + 8 * flowering + fruits,
            "polygons at n = {n}"
        );
    }
}

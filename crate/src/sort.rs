//! One sort for the whole core, small in WebAssembly (issue 22, the first load).
//!
//! The standard library's sorts are fast and large: each call site with its own element type and
//! comparison gets its own copy of driftsort or ipnsort, several KB of code apiece; the core's
//! sixteen sorts made 84 KB of the first plant's wasm before `wasm-opt`. Here the work is one
//! stable merge sort of indices through a `dyn` comparison, compiled once; a call site adds only
//! its comparison and a permutation of its slice. O(n log n) comparisons, O(n) extra indices,
//! stable (so it also stands in for `sort_unstable*`: equal elements keep their order).
//!
//! Every sort of the first plant's core (`crate/pkg-core`: parse, resolve, derive, growth, turtle,
//! mesh) goes through here. Code that only `crate/pkg` links keeps the standard library's sorts,
//! faster and costing nothing in the first load: the importers (`import/`), the SVG writer
//! (`export/svg.rs`), both behind the feature `io`, and branch editing (`branches/`, behind
//! `studio-extras`); so do tests.

use std::cmp::Ordering;

/// Sorts `v` by `compare`, stably (as `slice::sort_by`).
pub fn sort_by<T>(v: &mut [T], mut compare: impl FnMut(&T, &T) -> Ordering) {
    if v.len() < 2 {
        return;
    }
    let order = sorted_indices(v.len(), &mut |a, b| compare(&v[a], &v[b]));
    permute(v, order);
}

/// Sorts `v` by the key `key` gives each element, stably (as `slice::sort_by_key`).
pub fn sort_by_key<T, K: Ord>(v: &mut [T], mut key: impl FnMut(&T) -> K) {
    sort_by(v, |a, b| key(a).cmp(&key(b)));
}

/// Sorts `v` in ascending order, stably (as `slice::sort`).
pub fn sort<T: Ord>(v: &mut [T]) {
    sort_by(v, T::cmp);
}

/// Puts in `v[k]` the element a sort by `compare` would put there, smaller or equal ones before
/// it and greater or equal ones after (as `slice::select_nth_unstable_by`), and returns it: a
/// quickselect with three-way partitions (a slice of equal elements is one pass), pivots the
/// median of three, and after 2·log₂ n + 4 rounds without converging the rest sorted by
/// [`sort_by`] (no quadratic worst case). O(n) on average, no extra memory. Panics when `k` is
/// out of range.
/// Not `slice::select_nth_unstable_by`: for the one call there is (the mesh's median length), that
/// makes the first plant's core 1.4 KB gzipped larger than this does (measured 2026-11-26).
pub fn select_nth_by<T: Copy>(
    v: &mut [T],
    k: usize,
    mut compare: impl FnMut(&T, &T) -> Ordering,
) -> T {
    assert!(k < v.len(), "select_nth_by: index {k} of {}", v.len());
    let (mut lo, mut hi) = (0, v.len());
    let mut rounds = 2 * (usize::BITS - v.len().leading_zeros()) + 4;
    while hi - lo > 1 {
        if rounds == 0 {
            sort_by(&mut v[lo..hi], &mut compare);
            break;
        }
        rounds -= 1;
        let (a, b, c) = (v[lo], v[lo + (hi - lo) / 2], v[hi - 1]);
        let pivot = if (compare(&a, &b) == Ordering::Less) == (compare(&b, &c) == Ordering::Less) {
            b
        } else if (compare(&b, &a) == Ordering::Less) == (compare(&a, &c) == Ordering::Less) {
            a
        } else {
            c
        };
        // v[lo..less] < pivot, v[less..i] == pivot, v[greater..hi] > pivot.
        let (mut less, mut i, mut greater) = (lo, lo, hi);
        while i < greater {
            match compare(&v[i], &pivot) {
                Ordering::Less => {
                    v.swap(less, i);
                    less += 1;
                    i += 1;
                }
                Ordering::Greater => {
                    greater -= 1;
                    v.swap(i, greater);
                }
                Ordering::Equal => i += 1,
            }
        }
        if k < less {
            hi = less;
        } else if k >= greater {
            lo = greater;
        } else {
            break;
        }
    }
    v[k]
}

/// Runs of this many indices are sorted by insertion before the merges.
const RUN: usize = 16;

/// The indices `0..n` in the order `compare` gives their elements, equal ones in index order: a
/// bottom-up merge sort over runs sorted by insertion.
fn sorted_indices(n: usize, compare: &mut dyn FnMut(usize, usize) -> Ordering) -> Vec<usize> {
    let mut a: Vec<usize> = (0..n).collect();
    for start in (0..n).step_by(RUN) {
        let end = (start + RUN).min(n);
        for i in start + 1..end {
            let x = a[i];
            let mut j = i;
            while j > start && compare(a[j - 1], x) == Ordering::Greater {
                a[j] = a[j - 1];
                j -= 1;
            }
            a[j] = x;
        }
    }
    let mut b = vec![0; n];
    let mut width = RUN;
    while width < n {
        let mut lo = 0;
        while lo < n {
            let mid = (lo + width).min(n);
            let hi = (lo + 2 * width).min(n);
            let (mut i, mut j, mut k) = (lo, mid, lo);
            while i < mid && j < hi {
                // Only a strictly smaller right element goes first: stable.
                if compare(a[j], a[i]) == Ordering::Less {
                    b[k] = a[j];
                    j += 1;
                } else {
                    b[k] = a[i];
                    i += 1;
                }
                k += 1;
            }
            b[k..k + mid - i].copy_from_slice(&a[i..mid]);
            k += mid - i;
            b[k..k + hi - j].copy_from_slice(&a[j..hi]);
            lo = hi;
        }
        std::mem::swap(&mut a, &mut b);
        width *= 2;
    }
    a
}

/// Rearranges `v` so that position k holds what was at `order[k]` (`order` is a permutation),
/// following each cycle with swaps.
fn permute<T>(v: &mut [T], mut order: Vec<usize>) {
    const DONE: usize = usize::MAX;
    for start in 0..v.len() {
        let mut at = start;
        while order[at] != DONE {
            let next = order[at];
            order[at] = DONE;
            if next == start {
                break;
            }
            v.swap(at, next);
            at = next;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    /// Pairs (key, tag) with few distinct keys, so stability shows; tags number the elements.
    fn pairs(rng: &mut rand_pcg::Pcg64Mcg, n: usize, keys: u32) -> Vec<(u32, usize)> {
        (0..n).map(|tag| (rng.random_range(0..keys), tag)).collect()
    }

    #[test]
    fn sorts_like_the_standard_stable_sort_at_every_length_around_the_runs() {
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(22);
        for n in (0..70).chain([127, 128, 129, 500, 1000, 4097]) {
            for keys in [1, 3, 50, 1_000_000] {
                let v = pairs(&mut rng, n, keys);
                let mut ours = v.clone();
                sort_by_key(&mut ours, |p| p.0);
                let mut std = v.clone();
                std.sort_by_key(|p| p.0);
                assert_eq!(ours, std, "n = {n}, keys = {keys}");
            }
        }
    }

    #[test]
    fn sorts_by_a_comparison_and_by_order() {
        let mut words = vec!["pear", "fig", "apple", "kiwi", "date", "fig"];
        sort(&mut words);
        assert_eq!(words, ["apple", "date", "fig", "fig", "kiwi", "pear"]);
        sort_by(&mut words, |a, b| b.len().cmp(&a.len()));
        assert_eq!(words, ["apple", "date", "kiwi", "pear", "fig", "fig"]);
        let mut floats = vec![2.5f32, -1.0, f32::NAN, 0.0, -0.0];
        sort_by(&mut floats, |a, b| a.total_cmp(b));
        assert_eq!(format!("{floats:?}"), "[-1.0, -0.0, 0.0, 2.5, NaN]");
    }

    #[test]
    fn selects_the_element_a_sort_puts_at_each_place() {
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(20);
        for n in [1, 2, 3, 7, 16, 100, 1000] {
            for keys in [1, 2, 10, 1_000_000] {
                let v: Vec<u32> = (0..n).map(|_| rng.random_range(0..keys)).collect();
                let mut sorted = v.clone();
                sorted.sort();
                for k in [0, n / 3, n / 2, n - 1] {
                    let mut w = v.clone();
                    assert_eq!(
                        select_nth_by(&mut w, k, u32::cmp),
                        sorted[k],
                        "n {n} keys {keys} k {k}"
                    );
                    assert!(w[..k].iter().all(|x| *x <= w[k]) && w[k..].iter().all(|x| *x >= w[k]));
                    let mut both = w.clone();
                    both.sort();
                    assert_eq!(both, sorted, "a permutation");
                }
            }
        }
        // Sorted, reversed and organ-pipe inputs; floats by their total order.
        let n = 10_001;
        for v in [
            (0..n).collect::<Vec<u32>>(),
            (0..n).rev().collect(),
            (0..n).map(|i| i.min(n - i)).collect(),
        ] {
            let mut sorted = v.clone();
            sorted.sort();
            assert_eq!(
                select_nth_by(&mut v.clone(), n as usize / 2, u32::cmp),
                sorted[n as usize / 2]
            );
        }
        let mut floats = vec![2.5f64, -1.0, f64::NAN, 0.0, -0.0];
        assert_eq!(
            select_nth_by(&mut floats, 1, f64::total_cmp).to_bits(),
            (-0.0f64).to_bits()
        );
        assert!(select_nth_by(&mut floats, 4, f64::total_cmp).is_nan());
    }

    #[test]
    fn moves_elements_that_are_not_copy() {
        let mut names: Vec<String> = ["c", "a", "b", "a"].iter().map(|s| s.to_string()).collect();
        sort(&mut names);
        assert_eq!(names, ["a", "a", "b", "c"]);
    }
}

//! How the mesh's flat arrays grow: groups of values appended in one pass, and range lists.

/// Appends (first, value) to a range list unless the last range has that value already; a range
/// that would stay empty is overwritten.
pub(super) fn push_range(ranges: &mut Vec<u32>, first: u32, value: u32) {
    if let [.., last_first, last_value] = ranges[..] {
        if last_value == value {
            return;
        }
        if last_first == first {
            let n = ranges.len();
            ranges[n - 1] = value;
            return;
        }
    }
    push(ranges, [first, value]);
}

// The mesh's arrays grow through `append` and `push`, not `Vec::resize` and `Vec::extend`: the
// first plant's core (crate/pkg-core, which the studio builds with until its studio core has
// loaded) is built for size (opt-level "s", scripts/build-wasm.sh), which leaves those as calls
// that write one element at a time, and they took a third of the mesh stage (ABOP 1.24d n = 10,
// 1.09 M vertices: 69 ms against 47, and 41 at opt-level 3; measured in Node 2026-11-27). `append`
// writes each new element once: growing the arrays with zeros first and writing over them cost
// another tenth.

/// Appends `n` groups of `W` elements to `v`, group `k` being `group(k)`, the arrays grown once.
#[inline(always)]
pub(super) fn append<T: Copy, const W: usize>(
    v: &mut Vec<T>,
    n: usize,
    mut group: impl FnMut(usize) -> [T; W],
) {
    let (at, len) = (v.len(), n * W);
    if v.capacity() - at < len {
        v.reserve(len);
    }
    for (k, slot) in v.spare_capacity_mut()[..len]
        .chunks_exact_mut(W)
        .enumerate()
    {
        let values = group(k);
        // SAFETY: `slot` is a checked slice of `W` elements and `values` is `W` of them (`Copy`):
        // a copy of a constant size.
        unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), slot.as_mut_ptr().cast(), W) };
    }
    // SAFETY: the capacity holds `len` more, and the loop wrote all of them (`len / W` groups of
    // exactly `W`; a panic in `group` leaves the length as it was).
    unsafe { v.set_len(at + len) };
}

/// Appends `values` to `v`.
#[inline(always)]
pub(super) fn push<T: Copy, const N: usize>(v: &mut Vec<T>, values: [T; N]) {
    append(v, 1, |_| values);
}

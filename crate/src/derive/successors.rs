//! Writing successors fast: each successor copied as a fixed number of ids (4, 8 or 16, what lies
//! past its length overwritten by the next module), from a table padded for it. Shared by the D0L
//! path, the module classes' passes and the parametric pass.

use crate::model::ModuleId;

/// Ids of padding after the last successor, so that [`put`] may copy a fixed 16 ids.
pub(super) const PAD: usize = 16;

/// Appends `succ[start..start + len]` to `out`. A successor of at most 16 ids is copied as a fixed
/// 4 or 16 ids ([`put_wide`]; what lies past `len` is overwritten by the next module): wide stores
/// of a known size instead of a copy of a variable length.
#[inline(always)]
pub(super) fn put(out: &mut Vec<ModuleId>, succ: &[ModuleId], start: usize, len: usize) {
    if len <= 4 {
        put_wide::<4>(out, succ, start, len);
    } else {
        put_wide::<PAD>(out, succ, start, len);
    }
}

/// The spare room of an id buffer that a pass writes a successor at a time, each as a fixed `W`
/// ids ([`Room::put`]), for passes that know the next length and made room for it and [`PAD`]
/// more before the loop: what [`put_wide`] does without the `Vec`'s length and capacity, which in
/// WebAssembly live in memory, loaded and stored for every module.
/// [`put_wide`] stays for the passes that also extend the `Vec` in bulk (the neighbours pass
/// copies runs of quiet modules) or write parameters beside each successor (the parametric pass).
pub(super) struct Room<'a> {
    room: &'a mut [std::mem::MaybeUninit<ModuleId>],
    at: usize,
}

impl Room<'_> {
    /// Runs `write` on the spare room of `out`, then extends `out` by what it put.
    pub(super) fn fill<T>(out: &mut Vec<ModuleId>, write: impl FnOnce(&mut Room<'_>) -> T) -> T {
        let len = out.len();
        let mut room = Room {
            room: out.spare_capacity_mut(),
            at: 0,
        };
        let result = write(&mut room);
        let at = room.at;
        // SAFETY: `put` writes every id below `at` before moving it (at least the `n` it moves
        // by), within the spare room (checked slices), so the first `at` spare ids are written.
        unsafe { out.set_len(len + at) };
        result
    }

    /// Appends `succ[start..start + n]` by copying a fixed 4 ids when `n` is at most 4, else a
    /// fixed `W` (what lies past `n` is overwritten by the next module): `succ` holds `W` ids from
    /// `start` (its padding). Panics when the room is short, which the passes' lengths rule out.
    ///
    /// The branch between 4 and `W` pays where `W` is wider: most modules of a plant's string
    /// rewrite to 1 or 2 (`F -> FF`, brackets and turns copied), and the predictor follows the
    /// string's pattern, while `W` ids are `W / 4` 16-byte stores. Measured 2026-11-26 (Node, both
    /// packages alternating): 1.24d n = 10 on the D0L path 0.40 ms against 0.52, the stochastic E
    /// n = 11 3.66 against 4.34 ms.
    #[inline(always)]
    pub(super) fn put<const W: usize>(&mut self, succ: &[ModuleId], start: usize, n: usize) {
        if W > 4 && n <= 4 {
            self.put_fixed::<4>(succ, start, n);
        } else if n <= W {
            self.put_fixed::<W>(succ, start, n);
        } else {
            // Never taken when `W` is the table's width.
            let at = self.at;
            for (to, &from) in self.room[at..at + n]
                .iter_mut()
                .zip(&succ[start..start + n])
            {
                to.write(from);
            }
            self.at = at + n;
        }
    }

    /// Copies `C` ids and moves on by `n`, which is at most `C` (the callers check: [`Room::fill`]
    /// counts on every id below the new position being written).
    #[inline(always)]
    fn put_fixed<const C: usize>(&mut self, succ: &[ModuleId], start: usize, n: usize) {
        debug_assert!(n <= C);
        let at = self.at;
        let from = &succ[start..start + C];
        let to = &mut self.room[at..at + C];
        // SAFETY: `from` and `to` are checked slices of `C` ids (an id is `Copy`): a copy of a
        // constant size, wide stores, no call.
        unsafe { std::ptr::copy_nonoverlapping(from.as_ptr(), to.as_mut_ptr().cast(), C) };
        self.at = at + n;
    }
}

/// The copy width for successors of at most `longest` ids: 4, 8 or 16 ids, each module's
/// successor then copied as that many ids whatever its length ([`Room::put`] copies 4 for the
/// short ones); 0 when a successor is longer than [`PAD`].
pub(super) fn width(longest: usize) -> usize {
    match longest {
        0..=4 => 4,
        5..=8 => 8,
        9..=PAD => PAD,
        _ => 0,
    }
}

/// Appends `succ[start..start + len]` to `out` by copying a fixed `W` ids (what lies past `len`
/// is overwritten by the next module): `len` is at most `W`, and `succ` holds `W` ids from
/// `start` (its padding).
#[inline(always)]
pub(super) fn put_wide<const W: usize>(
    out: &mut Vec<ModuleId>,
    succ: &[ModuleId],
    start: usize,
    len: usize,
) {
    if len > W {
        // Never taken when `W` is the table's width.
        out.extend_from_slice(&succ[start..start + len]);
        return;
    }
    out.reserve(W);
    let from = &succ[start..start + W];
    let at = out.len();
    // SAFETY: `reserve` leaves room for W more ids after `at`; `from` holds W initialised ids;
    // the first `len` (at most W) ids written are the successor, so the new length covers only
    // them.
    unsafe {
        std::ptr::copy_nonoverlapping(from.as_ptr(), out.as_mut_ptr().add(at), W);
        out.set_len(at + len);
    }
}

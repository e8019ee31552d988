//! The mesh's normals and colours packed for a GPU: normals as 16-bit and colours as 8-bit
//! normalized integers (6 and 3 bytes a vertex instead of 12 and 12). The studio's view uploads
//! these: a million-vertex plant leaves the core, crosses to the page and reaches the GPU as
//! 38 MB instead of 52. Normals lose nothing visible (1/32767); colours are the palette's linear
//! values to 1/255.
//!
//! Each value is JavaScript's `Math.round` of the value clamped and scaled (ties upwards), computed
//! in `f64` as the page once did it, and NaN becomes 0 as a typed array stores it.

/// Each normal component `v` as `round(clamp(v, -1, 1) × 32767)`.
pub fn pack_normals(normals: &[f32]) -> Vec<i16> {
    let mut packed = Vec::with_capacity(normals.len());
    let eights = normals.chunks_exact(8);
    let rest = eights.remainder();
    for eight in eights {
        packed.extend_from_slice(&pack_eight_normals(eight));
    }
    packed.extend(rest.iter().map(|&v| pack_normal(v)));
    packed
}

fn pack_normal(v: f32) -> i16 {
    round_half_up((f64::from(v) * 32767.0).clamp(-32767.0, 32767.0)) as i16
}

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
fn pack_eight_normals(eight: &[f32]) -> [i16; 8] {
    std::array::from_fn(|k| pack_normal(eight[k]))
}

/// [`pack_normal`] of eight components with WebAssembly SIMD, in the same `f64` steps: each pair
/// widened, scaled and rounded (`floor(y + 0.5)`; `trunc_sat` makes NaN 0 and saturates), then
/// clamped as integers (the same as clamping before rounding, the bounds being integers): below
/// by `max`, above by the narrowing to 16 bits, which saturates at 32767. A third faster than
/// [`pack_normal`] one by one in V8 (a million-vertex mesh's normals: 8.5 → 5.8 ms).
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
fn pack_eight_normals(eight: &[f32]) -> [i16; 8] {
    use core::arch::wasm32::{
        f32x4, f64x2_add, f64x2_floor, f64x2_mul, f64x2_promote_low_f32x4, f64x2_splat,
        i16x8_narrow_i32x4, i32x4_max, i32x4_shuffle, i32x4_splat, i32x4_trunc_sat_f64x2_zero,
        v128, v128_store,
    };
    let round_pair = |pair: v128| {
        let scaled = f64x2_mul(f64x2_promote_low_f32x4(pair), f64x2_splat(32767.0));
        i32x4_trunc_sat_f64x2_zero(f64x2_floor(f64x2_add(scaled, f64x2_splat(0.5))))
    };
    let round_four = |four: v128| {
        let low = round_pair(four);
        let high = round_pair(i32x4_shuffle::<2, 3, 2, 3>(four, four));
        let both = i32x4_shuffle::<0, 1, 4, 5>(low, high);
        i32x4_max(both, i32x4_splat(-32767))
    };
    let a = round_four(f32x4(eight[0], eight[1], eight[2], eight[3]));
    let b = round_four(f32x4(eight[4], eight[5], eight[6], eight[7]));
    let mut out = [0i16; 8];
    // SAFETY: `out` is 16 bytes (`v128_store` needs no alignment).
    unsafe { v128_store(out.as_mut_ptr() as *mut v128, i16x8_narrow_i32x4(a, b)) };
    out
}

/// `floor(y + 0.5)` for `|y| < 2³¹` without a call to `floor` (none is an instruction on plain
/// x86-64), NaN giving 0.
fn round_half_up(y: f64) -> i32 {
    let t = y + 0.5;
    let i = t as i32; // towards zero; NaN: 0
    i - i32::from(f64::from(i) > t)
}

/// Each colour component `v` as `round(clamp(v, 0, 1) × 255)`, converted once per run of
/// vertices of one colour (a tube's rings have one) and written a byte at a time into the room
/// reserved: pushing three bytes a vertex onto the `Vec` took 2.7 ms for a million vertices in V8,
/// this 1.9.
pub fn pack_colors(colors: &[f32]) -> Vec<u8> {
    let vertices = colors.len() / 3;
    let rgbs = &colors[..3 * vertices];
    let bits = |c: &[f32]| [c[0].to_bits(), c[1].to_bits(), c[2].to_bits()];
    let mut packed: Vec<u8> = Vec::with_capacity(colors.len());
    let out = packed.as_mut_ptr();
    let mut i = 0;
    while i < vertices {
        let rgb = bits(&rgbs[3 * i..]);
        // The vertices of this colour from here (equal bits: equal bytes).
        let run = rgbs[3 * i..]
            .chunks_exact(3)
            .take_while(|c| bits(c) == rgb)
            .count();
        let [r, g, b] = rgb.map(|v| color_byte(f32::from_bits(v)));
        for k in i..i + run {
            // SAFETY: k < vertices, and the room is 3 × vertices bytes or more.
            unsafe {
                out.add(3 * k).write(r);
                out.add(3 * k + 1).write(g);
                out.add(3 * k + 2).write(b);
            }
        }
        i += run;
    }
    // SAFETY: the loop wrote the first 3 × vertices bytes (each run at least one vertex).
    unsafe { packed.set_len(3 * vertices) };
    packed.resize(colors.len(), 0);
    packed
}

fn color_byte(v: f32) -> u8 {
    round_half_up((f64::from(v) * 255.0).clamp(0.0, 255.0)) as u8
}

/// Normal components to pack in the tests (natively here, and under wasm32 with SIMD in
/// `tests/wasm_boundary.rs`, against JavaScript's `Math.round`): the bounds and beyond, NaN, -0,
/// halves (x.5 after scaling, as near as `f32` holds them) and pseudo-random values, 3,015 of them
/// (not a multiple of eight: the last seven take the scalar path).
pub fn normal_samples() -> Vec<f32> {
    let ties = [0.5f32, -0.5, 1.5, -1.5, 2.5, -2.5, 32766.5, -32766.5].map(|t| t / 32767.0);
    let mut normals = vec![0.0, 1.0, -1.0, 0.6, -0.8, 2.0, -2.0, f32::NAN, -0.0];
    normals.extend(ties);
    normals.extend([
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::MAX,
        f32::MIN_POSITIVE,
    ]);
    let mut seed = 20u64;
    for _ in 0..2994 {
        seed = (seed * 1_103_515_245 + 12_345) % 2_147_483_648;
        normals.push((seed as f64 / 2_147_483_648.0 * 2.4 - 1.2) as f32);
    }
    normals
}

#[cfg(test)]
mod tests {
    use super::*;

    /// JavaScript's `Math.round(x)`: the nearest integer, ties towards +∞.
    fn js_round(x: f64) -> f64 {
        let r = x.round(); // ties away from zero
        if x - r == 0.5 {
            r + 1.0 // a negative tie: towards +∞
        } else {
            r
        }
    }

    /// Each of `packed` is `Math.round` of its value clamped to `lo..=1` and scaled by `scale`
    /// (0 for NaN).
    fn assert_rounded<P: Copy + Into<f64>>(
        values: &[f32],
        packed: &[P],
        lo: f64,
        scale: f64,
        what: &str,
    ) {
        assert_eq!(packed.len(), values.len());
        for (&v, &p) in values.iter().zip(packed) {
            let want = if v.is_nan() {
                0.0
            } else {
                js_round(crate::maths::clamp(f64::from(v), lo, 1.0) * scale)
            };
            assert_eq!(p.into(), want, "{what} {v}");
        }
    }

    #[test]
    fn normals_and_colours_are_math_round_of_the_clamped_scaled_values() {
        let normals = normal_samples();
        let packed = pack_normals(&normals);
        assert_rounded(&normals, &packed, -1.0, 32767.0, "normal");
        assert_eq!(packed[..5], [0, 32767, -32767, 19660, -26214]);
    }

    #[test]
    fn colours_in_runs_and_changing_every_vertex() {
        let mut colors = vec![0.5, 0.25, 1.0, 0.0, 0.0031, 2.0, f32::NAN, -0.0, 1.0];
        colors.extend([0.5f32, 1.5, 254.5].map(|t| t / 255.0));
        for v in 0..600 {
            let run = if v < 300 { v / 7 } else { v };
            for k in 0..3 {
                colors.push(((run * 3 + k) as f32 * 0.37) % 1.3 - 0.1);
            }
        }
        let packed = pack_colors(&colors);
        assert_rounded(&colors, &packed, 0.0, 255.0, "colour");
        assert_eq!(packed[..6], [128, 64, 255, 0, 1, 255]);
    }
}

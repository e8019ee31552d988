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
    normals
        .iter()
        .map(|&v| round_half_up((f64::from(v) * 32767.0).clamp(-32767.0, 32767.0)) as i16)
        .collect()
}

/// `floor(y + 0.5)` for `|y| < 2³¹` without a call to `floor` (none is an instruction on plain
/// x86-64), NaN giving 0.
fn round_half_up(y: f64) -> i32 {
    let t = y + 0.5;
    let i = t as i32; // towards zero; NaN: 0
    i - i32::from(f64::from(i) > t)
}

/// Each colour component `v` as `round(clamp(v, 0, 1) × 255)`, converted once per run of
/// vertices of one colour (a tube's ring has one).
pub fn pack_colors(colors: &[f32]) -> Vec<u8> {
    let mut packed = Vec::with_capacity(colors.len());
    let mut run: Option<([f32; 3], [u8; 3])> = None;
    for rgb in colors.chunks_exact(3) {
        let rgb = [rgb[0], rgb[1], rgb[2]];
        let bytes = match run {
            Some((color, bytes)) if color == rgb => bytes,
            _ => {
                let bytes = rgb.map(color_byte);
                run = Some((rgb, bytes));
                bytes
            }
        };
        packed.extend_from_slice(&bytes);
    }
    packed.resize(colors.len(), 0);
    packed
}

fn color_byte(v: f32) -> u8 {
    round_half_up((f64::from(v) * 255.0).clamp(0.0, 255.0)) as u8
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

    #[test]
    fn normals_and_colours_are_math_round_of_the_clamped_scaled_values() {
        let ties = [0.5f32, -0.5, 1.5, -1.5, 2.5, -2.5].map(|t| t / 32767.0);
        let mut normals = vec![0.0, 1.0, -1.0, 0.6, -0.8, 2.0, -2.0, f32::NAN, -0.0];
        normals.extend(ties);
        let mut seed = 20u64;
        for _ in 0..3000 {
            seed = (seed * 1_103_515_245 + 12_345) % 2_147_483_648;
            normals.push((seed as f64 / 2_147_483_648.0 * 2.4 - 1.2) as f32);
        }
        let packed = pack_normals(&normals);
        for (&v, &p) in normals.iter().zip(&packed) {
            let want = if v.is_nan() {
                0.0
            } else {
                js_round(f64::from(v).clamp(-1.0, 1.0) * 32767.0)
            };
            assert_eq!(f64::from(p), want, "normal {v}");
        }
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
        assert_eq!(packed.len(), colors.len());
        for (&v, &p) in colors.iter().zip(&packed) {
            let want = if v.is_nan() {
                0.0
            } else {
                js_round(f64::from(v).clamp(0.0, 1.0) * 255.0)
            };
            assert_eq!(f64::from(p), want, "colour {v}");
        }
        assert_eq!(packed[..6], [128, 64, 255, 0, 1, 255]);
    }
}

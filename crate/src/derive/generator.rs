//! [`Generator`], the generator behind every random choice of a derivation: PCG-64 in its MCG
//! variant (rand_pcg's `Pcg64Mcg`, "pcg64_fast"), with the same seeding and the same stream of
//! numbers, bit for bit.
//!
//! Why not `rand_pcg::Pcg64Mcg` itself: its step is a `u128` multiplication, which wasm32 has no
//! instruction for, so every draw called compiler-builtins' `__multi3` (its 128-bit result
//! returned through the stack in linear memory). Here the state is two `u64` words and the step
//! multiplies them with four 32-bit products under wasm32 (natively the `u128` product, which is
//! one instruction). A stochastic grammar draws once per module rewritten by a weighted choice
//! (issue 20, case E). `tests` checks the stream against rand_pcg's.

use core::convert::Infallible;
use rand::{SeedableRng, TryRng};

/// PCG-64 (MCG variant): `state ← state × MULTIPLIER (mod 2¹²⁸)`, output XSL RR.
#[derive(Clone, Debug)]
pub struct Generator {
    hi: u64,
    lo: u64,
}

/// rand_pcg's `MULTIPLIER` for the 128-bit generators, as two words.
const MUL_HI: u64 = 2549297995355413924;
const MUL_LO: u64 = 4865540595714422341;

/// The high word of `a × b`.
#[inline(always)]
fn mul_hi(a: u64, b: u64) -> u64 {
    #[cfg(not(target_arch = "wasm32"))]
    {
        ((u128::from(a) * u128::from(b)) >> 64) as u64
    }
    #[cfg(target_arch = "wasm32")]
    {
        mul_hi_by_halves(a, b)
    }
}

/// The high word of `a × b` from four 32-bit products (what wasm32 can do without a library
/// call).
#[inline(always)]
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
fn mul_hi_by_halves(a: u64, b: u64) -> u64 {
    let (a0, a1) = (a & 0xffff_ffff, a >> 32);
    let (b0, b1) = (b & 0xffff_ffff, b >> 32);
    let (p00, p01, p10, p11) = (a0 * b0, a0 * b1, a1 * b0, a1 * b1);
    let middle = (p00 >> 32) + (p01 & 0xffff_ffff) + (p10 & 0xffff_ffff);
    p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32)
}

impl Generator {
    /// The next 64 random bits.
    #[inline(always)]
    fn step(&mut self) -> u64 {
        let hi = mul_hi(self.lo, MUL_LO)
            .wrapping_add(self.lo.wrapping_mul(MUL_HI))
            .wrapping_add(self.hi.wrapping_mul(MUL_LO));
        let lo = self.lo.wrapping_mul(MUL_LO);
        self.hi = hi;
        self.lo = lo;
        // XSL RR: the two words xor-ed, rotated by the state's top 6 bits.
        (hi ^ lo).rotate_right((hi >> 58) as u32)
    }
}

impl SeedableRng for Generator {
    type Seed = [u8; 16];

    /// As rand_pcg: the seed read as a little-endian `u128`, its lowest bit set.
    fn from_seed(seed: [u8; 16]) -> Generator {
        let word = |i: usize| {
            let mut w = [0u8; 8];
            w.copy_from_slice(&seed[8 * i..8 * i + 8]);
            u64::from_le_bytes(w)
        };
        Generator {
            hi: word(1),
            lo: word(0) | 1,
        }
    }
}

impl TryRng for Generator {
    type Error = Infallible;

    #[inline]
    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        Ok(self.step() as u32)
    }

    #[inline]
    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        Ok(self.step())
    }

    fn try_fill_bytes(&mut self, dest: &mut [u8]) -> Result<(), Infallible> {
        for chunk in dest.chunks_mut(8) {
            let bytes = self.step().to_le_bytes();
            chunk.copy_from_slice(&bytes[..chunk.len()]);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, RngExt};

    #[test]
    fn the_same_stream_as_rand_pcg() {
        for seed in [0u64, 1, 7, 42, 1 << 40, u64::MAX] {
            let mut ours = Generator::seed_from_u64(seed);
            let mut theirs = rand_pcg::Pcg64Mcg::seed_from_u64(seed);
            for _ in 0..10_000 {
                assert_eq!(ours.next_u64(), theirs.next_u64());
            }
            assert_eq!(ours.next_u32(), theirs.next_u32());
            assert_eq!(ours.random::<f64>(), theirs.random::<f64>());
            let (mut a, mut b) = ([0u8; 13], [0u8; 13]);
            ours.fill_bytes(&mut a);
            theirs.fill_bytes(&mut b);
            assert_eq!(a, b);
        }
    }

    #[test]
    fn the_high_word_by_halves_is_the_u128_product() {
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(3);
        let edges = [0, 1, 0xffff_ffff, 1 << 32, u64::MAX, MUL_HI, MUL_LO];
        for a in edges {
            for b in edges {
                assert_eq!(
                    mul_hi_by_halves(a, b),
                    ((u128::from(a) * u128::from(b)) >> 64) as u64
                );
            }
        }
        for _ in 0..100_000 {
            let (a, b) = (rng.next_u64(), rng.next_u64());
            assert_eq!(
                mul_hi_by_halves(a, b),
                ((u128::from(a) * u128::from(b)) >> 64) as u64
            );
        }
    }
}

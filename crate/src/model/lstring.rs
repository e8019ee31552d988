//! The derived string: the plain data that flows from `derive` to `turtle`.

use super::{Alphabet, ModuleId};
use std::fmt::Write;

/// A string of modules as flat arrays, with no allocation per module.
///
/// Module `i` is `ids[i]`; its parameters are `params[offsets[i]..offsets[i + 1]]`. When no
/// module of the string has parameters, `offsets` and `params` are both empty (the fast path of
/// non-parametric grammars writes module ids only).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LString {
    pub ids: Vec<ModuleId>,
    pub offsets: Vec<u32>,
    pub params: Vec<f64>,
}

impl LString {
    pub fn len(&self) -> usize {
        self.ids.len()
    }

    pub fn is_empty(&self) -> bool {
        self.ids.is_empty()
    }

    /// The bytes the string's modules take: ids, offsets and parameters (not spare capacity).
    #[inline]
    pub fn bytes(&self) -> usize {
        self.ids.len() * size_of::<ModuleId>()
            + self.offsets.len() * size_of::<u32>()
            + self.params.len() * size_of::<f64>()
    }

    /// True when the string stores parameters (`offsets` is filled).
    pub fn is_parametric(&self) -> bool {
        !self.offsets.is_empty()
    }

    /// The parameters of module `i`.
    #[inline]
    pub fn params_of(&self, i: usize) -> &[f64] {
        if self.offsets.is_empty() {
            &[]
        } else {
            &self.params[self.offsets[i] as usize..self.offsets[i + 1] as usize]
        }
    }

    /// Empties the string, keeping its buffers; `parametric` says whether offsets are kept.
    pub fn clear(&mut self, parametric: bool) {
        self.ids.clear();
        self.params.clear();
        self.offsets.clear();
        if parametric {
            self.offsets.push(0);
        }
    }

    /// Appends one module (in a parametric string).
    #[inline]
    /// Appends every module of `other`.
    pub fn extend_from(&mut self, other: &LString) {
        for j in 0..other.len() {
            self.push(other.ids[j], other.params_of(j));
        }
    }

    pub fn push(&mut self, id: ModuleId, params: &[f64]) {
        self.ids.push(id);
        if !self.offsets.is_empty() {
            self.params.extend_from_slice(params);
            self.offsets.push(self.params.len() as u32);
        }
    }

    /// The same string with offsets filled, so that parameters can be appended.
    pub fn into_parametric(mut self) -> LString {
        if self.offsets.is_empty() {
            self.offsets = vec![0; self.ids.len() + 1];
        }
        self
    }

    /// The canonical text form: module names as written, parameters in parentheses separated by
    /// commas, each number as Rust's `{}` prints an f64 (`1`, not `1.0`), no spaces.
    pub fn to_text(&self, alphabet: &Alphabet) -> String {
        self.to_text_truncated(alphabet, usize::MAX)
    }

    /// A 64-bit FNV-1a hash of the string's ids and parameter bits: equal strings (same modules,
    /// same numbers) hash equal on every platform, so a shared link can prove it reproduced the
    /// exact derivation. Names enter through `alphabet`, not through interning order.
    pub fn fingerprint(&self, alphabet: &Alphabet) -> u64 {
        const PRIME: u64 = 0x0000_0100_0000_01b3;
        let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
        let mut eat = |bytes: &[u8]| {
            for &b in bytes {
                hash ^= b as u64;
                hash = hash.wrapping_mul(PRIME);
            }
        };
        for i in 0..self.ids.len() {
            eat(alphabet.name(self.ids[i]).as_bytes());
            eat(&[0]);
            for p in self.params_of(i) {
                eat(&p.to_bits().to_le_bytes());
            }
            eat(&[1]);
        }
        hash
    }

    /// The text of module `i` alone, as [`LString::to_text`] writes it.
    pub fn module_text(&self, alphabet: &Alphabet, i: usize) -> String {
        let mut module = String::new();
        self.write_module(alphabet, i, &mut module);
        module
    }

    /// Appends the text of module `i` to `out`: its name, and its parameters in parentheses.
    fn write_module(&self, alphabet: &Alphabet, i: usize, out: &mut String) {
        out.push_str(alphabet.name(self.ids[i]));
        let params = self.params_of(i);
        if !params.is_empty() {
            out.push('(');
            for (k, p) in params.iter().enumerate() {
                if k > 0 {
                    out.push(',');
                }
                let _ = write!(out, "{}", crate::number::Decimal(*p));
            }
            out.push(')');
        }
    }

    /// Like [`LString::to_text`] but stops before passing `max_chars` characters, appending `…`
    /// when the string is longer.
    pub fn to_text_truncated(&self, alphabet: &Alphabet, max_chars: usize) -> String {
        let mut out = String::new();
        let mut module = String::new();
        let mut chars = 0usize;
        for i in 0..self.ids.len() {
            module.clear();
            self.write_module(alphabet, i, &mut module);
            let n = module.chars().count();
            if chars.saturating_add(n) > max_chars {
                out.push('…');
                return out;
            }
            chars += n;
            out.push_str(&module);
        }
        out
    }
}

//! Reading decimal numbers from grammar text: [`parse_f64`], what `str::parse::<f64>` does.
//!
//! Natively it is `str::parse`. Under wasm32 it checks the syntax here and lets JavaScript's
//! `parseFloat` convert the digits: both round correctly (to the nearest `f64`, ties to even), so
//! the value is the same bit for bit, and the core leaves out Rust's decimal-to-float code, whose
//! table of powers of five alone is 10 KB of incompressible bytes (issue 22, the first load:
//! about 12 KB gzipped of `crate/pkg-core`). A grammar's numbers are read once per build, so
//! the crossing into JavaScript costs nothing the preview notices. `tests/wasm_boundary.rs`
//! checks under wasm32 that both agree.
//!
//! The one place outside the boundaries (`main/`, `wasm/`) that calls JavaScript, and only
//! this function: `tests/architecture.rs` (`the_core_does_no_io_and_knows_nothing_of_the_browser`)
//! allows `js_sys` in this file by name and nowhere else. Behind the boundary it would cost a
//! callback threaded through the parser and the resolver (every number of the grammar is read
//! there), for no gain in size or speed.

/// `text` as an `f64`, exactly as `text.parse::<f64>().ok()`: an optional sign, then digits with
/// an optional `.` and fraction (at least one digit in all) and an optional exponent
/// (`e`/`E`, optional sign, digits), or `inf`, `infinity` or `nan` in any case; nothing else, no
/// spaces.
pub fn parse_f64(text: &str) -> Option<f64> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        text.parse().ok()
    }
    #[cfg(target_arch = "wasm32")]
    {
        let (negative, unsigned) = match text.as_bytes().first() {
            Some(b'-') => (true, &text[1..]),
            Some(b'+') => (false, &text[1..]),
            _ => (false, text),
        };
        let special =
            if unsigned.eq_ignore_ascii_case("inf") || unsigned.eq_ignore_ascii_case("infinity") {
                Some(f64::INFINITY)
            } else if unsigned.eq_ignore_ascii_case("nan") {
                Some(f64::NAN)
            } else {
                None
            };
        if let Some(v) = special {
            return Some(if negative { -v } else { v });
        }
        // JavaScript's parseFloat reads the longest prefix that is a number; the whole text must be one.
        decimal_syntax(unsigned.as_bytes()).then(|| js_sys::parse_float(text))
    }
}

/// A number as Rust's `{}` writes an `f64` (the shortest digits that read back as the number,
/// never an exponent: `0.1`, `1e21` as `1000000000000000000000`, `-0`, `inf`, `NaN`), for every
/// message and text of the core that shows a number. Natively it is Rust's `{}`. Under wasm32
/// JavaScript's `Number.prototype.toString` gives the digits (ECMA-262's Number::toString: the
/// shortest digits that read back, the closest when several do, as Rust's) and [`plain`] writes
/// them without JavaScript's exponent, so that the core leaves out Rust's float-to-decimal code
/// (Grisu, Dragon4 and their tables: about 6 KB gzipped of `crate/pkg-core`; issue 22, the first
/// load). Width and precision are not supported (no message uses them). One difference, which
/// reads back to the same number: when two 17-digit forms are equally close (a number of 10^15
/// or more with a fraction of a quarter, say: about 1 random double in 1,200, hardly a plant's),
/// JavaScript ends on the even digit and Rust rounds up (`1270994211038989.25` is
/// `…989.2` in the studio, `…989.3` natively). `tests/wasm_boundary.rs` checks under wasm32 that
/// both write the same otherwise.
#[derive(Clone, Copy, Debug)]
pub struct Decimal(pub f64);

impl std::fmt::Display for Decimal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        #[cfg(not(target_arch = "wasm32"))]
        {
            std::fmt::Display::fmt(&self.0, f)
        }
        #[cfg(target_arch = "wasm32")]
        {
            let text = js_sys::Number::from(self.0)
                .to_string(10)
                .map(String::from)
                .unwrap_or_default();
            f.write_str(&plain(&text, self.0))
        }
    }
}

/// `v`, of which `text` is JavaScript's `toString` (`1.5e-7`, `-1e+21`, `NaN`, `Infinity`), as
/// Rust's `{}` writes it.
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
fn plain(text: &str, v: f64) -> String {
    if v.is_nan() {
        return "NaN".into();
    }
    if v.is_infinite() {
        return if v > 0.0 { "inf" } else { "-inf" }.into();
    }
    if v == 0.0 {
        return if v.is_sign_negative() { "-0" } else { "0" }.into();
    }
    let Some((mantissa, exponent)) = text.split_once('e') else {
        return text.into();
    };
    let (sign, mantissa) = match mantissa.strip_prefix('-') {
        Some(m) => ("-", m),
        None => ("", mantissa),
    };
    let digits: String = mantissa.chars().filter(|c| c.is_ascii_digit()).collect();
    let (negative, magnitude) = match exponent.strip_prefix('-') {
        Some(m) => (true, m),
        None => (false, exponent.trim_start_matches('+')),
    };
    let magnitude = magnitude
        .bytes()
        .fold(0i64, |n, b| n * 10 + i64::from(b.wrapping_sub(b'0') % 10));
    // The decimal point stands after `point` digits (JavaScript's mantissa has one before it).
    let point = 1 + if negative { -magnitude } else { magnitude };
    let zeros = |n: i64| "0".repeat(n.max(0) as usize);
    let len = digits.len() as i64;
    if point <= 0 {
        format!("{sign}0.{}{digits}", zeros(-point))
    } else if point >= len {
        format!("{sign}{digits}{}", zeros(point - len))
    } else {
        let (whole, fraction) = digits.split_at(point as usize);
        format!("{sign}{whole}.{fraction}")
    }
}

/// Digits, an optional `.` and digits (at least one digit in all), then an optional exponent.
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
fn decimal_syntax(bytes: &[u8]) -> bool {
    let digits = |from: usize| {
        bytes[from..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count()
    };
    let whole = digits(0);
    let mut at = whole;
    let mut fraction = 0;
    if bytes.get(at) == Some(&b'.') {
        fraction = digits(at + 1);
        at += 1 + fraction;
    }
    if whole + fraction == 0 {
        return false;
    }
    if matches!(bytes.get(at), Some(b'e' | b'E')) {
        at += 1;
        if matches!(bytes.get(at), Some(b'+' | b'-')) {
            at += 1;
        }
        let exponent = digits(at);
        if exponent == 0 {
            return false;
        }
        at += exponent;
    }
    at == bytes.len()
}

/// Number texts as grammars hold them and as they must not, for the tests: `parse_f64` must read
/// each exactly as `str::parse::<f64>` does (the unit tests below natively, `tests/wasm_boundary.rs`
/// under wasm32, where JavaScript's `parseFloat` converts the digits).
#[doc(hidden)]
pub const PARSE_SAMPLES: &[&str] = &[
    "0",
    "1",
    "-1",
    "+1",
    "1.",
    ".5",
    "-.5",
    "1.5e3",
    "1E-3",
    "2.5e+10",
    "007",
    "0.1",
    "22.5",
    "1e400",
    "-1e400",
    "1e-400",
    "-0",
    "inf",
    "-Infinity",
    "NaN",
    "+nan",
    "-nan",
    "",
    ".",
    "-",
    "+",
    "e5",
    "1e",
    "1e+",
    "1.2.3",
    "1 ",
    " 1",
    "0x10",
    "1_000",
    "∞",
    "1,5",
    "infinit",
    "..5",
    "1e5.5",
    "9007199254740993",
    "2.2250738585072011e-308",
    "4.9e-324",
    "2.4703282292062328e-324",
    "1.7976931348623157e308",
    "1.7976931348623159e308",
    "0.30000000000000004",
    "123456789012345678901234567890",
    "1.00000000000000011102230246251565404236316680908203125",
    "0.000000000000000000000000000000000000000000001e+30",
    "in",
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_syntax_is_what_str_parse_accepts() {
        for text in PARSE_SAMPLES {
            let special = ["inf", "infinity", "nan"]
                .iter()
                .any(|s| text.trim_start_matches(['+', '-']).eq_ignore_ascii_case(s));
            let body = text.strip_prefix(['+', '-']).unwrap_or(text);
            assert_eq!(
                special || decimal_syntax(body.as_bytes()),
                text.parse::<f64>().is_ok(),
                "{text:?}"
            );
        }
    }

    #[test]
    fn parse_f64_is_str_parse() {
        for text in PARSE_SAMPLES {
            assert_eq!(
                parse_f64(text).map(f64::to_bits),
                text.parse::<f64>().ok().map(f64::to_bits),
                "{text:?}"
            );
        }
    }

    #[test]
    fn javascript_s_digits_are_written_as_rust_writes_them() {
        // (JavaScript's toString, the number): Rust's `{}` of the number is what plain must give.
        let samples = [
            ("1e+21", 1e21),
            ("-1.5e+300", -1.5e300),
            ("1.5e-7", 1.5e-7),
            ("-2.5e-8", -2.5e-8),
            ("5e-324", 5e-324),
            ("1.7976931348623157e+308", f64::MAX),
            ("0.000001", 1e-6),
            ("123.456", 123.456),
            ("100000000000000000000", 1e20),
            ("0.1", 0.1),
            ("-7", -7.0),
            ("0", 0.0),
            ("0", -0.0),
            ("NaN", f64::NAN),
            ("Infinity", f64::INFINITY),
            ("-Infinity", f64::NEG_INFINITY),
            ("1.2345678901234566e+25", 1.2345678901234567e25),
        ];
        for (js, v) in samples {
            assert_eq!(plain(js, v), format!("{v}"), "{js}");
            assert_eq!(format!("{}", Decimal(v)), format!("{v}"));
        }
    }
}

//! Comments are replaced by spaces before parsing, byte for byte, so every span the parser reports
//! is a span of the original text and line numbers do not move. A byte order mark at the start of
//! the text (a file saved by Notepad) is blanked the same way: spans stay byte offsets into the
//! text as given, with its mark.

use crate::diagnostics::Diagnostic;

/// Returns `source` with `// …` and `/* … */` comments and a leading byte order mark blanked
/// out (line ends inside block comments are kept), and a diagnostic for an unterminated block
/// comment. A line comment ends at `\n` or at `\r` (old Mac line ends).
pub fn blank_comments(source: &str) -> (String, Vec<Diagnostic>) {
    let bytes = source.as_bytes();
    let mut out = bytes.to_vec();
    let mut diagnostics = Vec::new();
    let mut i = 0;
    if source.starts_with('\u{feff}') {
        out[..BOM_LEN].fill(b' ');
        i = BOM_LEN;
    }
    let first = i;
    while i < bytes.len() {
        if bytes[i] == b'/'
            && bytes.get(i + 1) == Some(&b'/')
            && starts_line_comment(bytes, first, i)
        {
            while i < bytes.len() && bytes[i] != b'\n' && bytes[i] != b'\r' {
                out[i] = b' ';
                i += 1;
            }
        } else if bytes[i] == b'/' && bytes.get(i + 1) == Some(&b'*') {
            let start = i;
            out[i] = b' ';
            out[i + 1] = b' ';
            i += 2;
            let mut closed = false;
            while i < bytes.len() {
                if bytes[i] == b'*' && bytes.get(i + 1) == Some(&b'/') {
                    out[i] = b' ';
                    out[i + 1] = b' ';
                    i += 2;
                    closed = true;
                    break;
                }
                if bytes[i] != b'\n' && bytes[i] != b'\r' {
                    out[i] = b' ';
                }
                i += 1;
            }
            if !closed {
                diagnostics.push(Diagnostic::error(
                    "E0102",
                    start..start + 2,
                    "unterminated block comment: '/*' has no matching '*/'",
                ));
            }
        } else {
            i += 1;
        }
    }
    // Only whole characters were replaced by ASCII spaces, so the bytes are still UTF-8.
    let text = String::from_utf8(out)
        .unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned());
    (text, diagnostics)
}

/// The UTF-8 byte order mark's length in bytes.
const BOM_LEN: usize = '\u{feff}'.len_utf8();

/// A `//` starts a comment at the start of a line or after whitespace, unless it is part of a run
/// of three or more slashes: ABOP writes five rolls as `/////` (`F -> S/////F`).
/// `first` is where the text starts (after a byte order mark).
fn starts_line_comment(bytes: &[u8], first: usize, i: usize) -> bool {
    let after_space = i == first || bytes[i - 1].is_ascii_whitespace();
    let longer_run = bytes.get(i + 2) == Some(&b'/') || (i > 0 && bytes[i - 1] == b'/');
    after_space && !longer_run
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_become_spaces_of_the_same_length() {
        let src = "F // ωωω\n/* a\nb */G";
        let (text, diags) = blank_comments(src);
        assert!(diags.is_empty());
        assert_eq!(text.len(), src.len());
        assert_eq!(
            text.lines().collect::<Vec<_>>(),
            vec!["F          ", "    ", "    G"]
        );
    }

    #[test]
    fn runs_of_slashes_are_rolls_not_comments() {
        let (text, _) =
            blank_comments("F -> S/////F\nA -> [&FL!A] /////'[&FL!A] // note\nX -> F//F");
        assert_eq!(
            text.lines().collect::<Vec<_>>(),
            [
                "F -> S/////F",
                "A -> [&FL!A] /////'[&FL!A]        ",
                "X -> F//F"
            ]
        );
    }

    #[test]
    fn a_byte_order_mark_and_old_mac_line_ends_are_read() {
        let (text, diags) = blank_comments("\u{feff}F // a\rG /* b\r */H");
        assert!(diags.is_empty());
        assert_eq!(text, "   F     \rG     \r   H");
        assert_eq!(blank_comments("\u{feff}// a\nF").0, "       \nF");
    }

    #[test]
    fn unterminated_block_comment_is_reported_where_it_opens() {
        let (_, diags) = blank_comments("F\n  /* oops");
        assert_eq!(diags.len(), 1);
        assert_eq!(diags[0].span, 4..6);
    }
}

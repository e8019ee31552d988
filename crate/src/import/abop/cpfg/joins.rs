//! cpfg's lines joined as vlab objects write them: statement blocks, production heads and
//! two-line productions over several lines, the axiom continued; and the sections that keep
//! cpfg's default depth.

use super::super::statements::{keyword, section};
use super::super::{arrow, Flavour, Line};
use crate::vocabulary::KeywordKind;

/// cpfg's statement blocks `{ … }` may span lines: a line whose braces are not closed takes the
/// lines after it until they are.
pub(in crate::import::abop) fn join_blocks(lines: Vec<Line>, flavour: Flavour) -> Vec<Line> {
    if flavour != Flavour::Cpfg {
        return lines;
    }
    let mut joined: Vec<Line> = Vec::new();
    let mut open = 0i32;
    for line in lines {
        let delta = line.code.matches('{').count() as i32 - line.code.matches('}').count() as i32;
        match joined.last_mut() {
            Some(last) if open > 0 => {
                if !line.code.is_empty() {
                    last.code.push(' ');
                    last.code.push_str(&line.code);
                }
                if !line.comment.is_empty() {
                    last.comment.push(' ');
                    last.comment.push_str(&line.comment);
                }
            }
            _ => joined.push(line),
        }
        open = (open + delta).max(0);
    }
    joined
}

/// True when a line starts with one of the notation's keywords (it is no part of a production).
pub(in crate::import::abop) fn starts_with_keyword(code: &str) -> bool {
    let lower = code.to_ascii_lowercase();
    let compact: String = lower.chars().filter(|c| !c.is_whitespace()).collect();
    code.starts_with('#')
        || section(&lower).is_some()
        // dialect: cpfg's keywords, without their spaces
        || "axiom: derivationlength ignore: consider: maximumdepth lsystem: endlsystem start: starteach: end: endeach: define: seed:"
            .split(' ')
        .any(|k| compact.starts_with(k))
}

/// cpfg productions whose head (predecessor, condition, statement block) spans lines: a line at
/// the margin without an arrow, then indented lines (or lines opening with `{`, `:` or the
/// arrow) up to the one with the arrow, as vlab objects write them:
/// `N(k) < I(b,m,v,c) : b==0 && m==2` / `\t{flux=…;} -->` / `\tI(b,1,flux,c)`.
pub(in crate::import::abop) fn join_production_heads(lines: Vec<Line>) -> Vec<Line> {
    // A line joined to the one before is taken out of its place (`None`) rather than removed,
    // which would move every later line: linear in the lines (issue 50, 6).
    let mut lines: Vec<Option<Line>> = lines.into_iter().map(Some).collect();
    for i in 0..lines.len() {
        let Some(a) = &lines[i] else { continue };
        if a.indent > 0
            || a.code.is_empty()
            || arrow(&a.code).is_some()
            || starts_with_keyword(&a.code)
        {
            continue;
        }
        let mut run = Vec::new();
        let mut found = false;
        for (j, b) in lines.iter().enumerate().skip(i + 1) {
            let Some(b) = b else { continue };
            if b.code.is_empty() {
                if b.comment.is_empty() {
                    break;
                }
                continue;
            }
            let continues = b.indent > 0
                || ["{", ":", "-->", "->"]
                    .iter()
                    .any(|t| b.code.starts_with(t));
            if starts_with_keyword(&b.code) || !continues || run.len() == 6 {
                break;
            }
            run.push(j);
            if arrow(&b.code).is_some() {
                found = true;
                break;
            }
        }
        if !found {
            continue;
        }
        for j in run {
            let Some(b) = lines[j].take() else { continue };
            let Some(head) = lines[i].as_mut() else { break };
            head.code.push(' ');
            head.code.push_str(&b.code);
            if !b.comment.is_empty() {
                let comment = format!("{} {}", head.comment, b.comment);
                head.comment = comment.trim().to_string();
            }
        }
    }
    lines.into_iter().flatten().collect()
}

/// The lines that open a cpfg `homomorphism` or `decomposition` section with no `maximum
/// depth:` line before the next section.
pub(in crate::import::abop) fn sections_without_depth(all: &[Line]) -> Vec<usize> {
    let mut out = Vec::new();
    let mut open: Option<usize> = None;
    for line in all {
        let lower = line.code.to_ascii_lowercase();
        if let Some(s) = section(&lower) {
            out.extend(open.take());
            let word = lower.split(':').next().unwrap_or("").trim().to_string();
            if s == KeywordKind::Homomorphism.written() && word == "homomorphism"
                || s == KeywordKind::Decomposition.written()
            {
                open = Some(line.n);
            }
        // dialect: cpfg's keyword
        } else if keyword(&lower, &line.code, "maximum depth:").is_some() {
            open = None;
        } else if lower.trim() == KeywordKind::EndLSystem.written() {
            out.extend(open.take());
        }
    }
    out.extend(open);
    out
}

/// cpfg's axiom continued on the lines after `Axiom:` that are indented more than it (and are
/// no production): one line.
pub(in crate::import::abop) fn join_axiom_lines(lines: Vec<Line>) -> Vec<Line> {
    let mut out: Vec<Line> = Vec::with_capacity(lines.len());
    // While an axiom is being continued: its index in `out`.
    let mut axiom: Option<usize> = None;
    for line in lines {
        if let Some(head) = axiom.and_then(|k| out.get_mut(k)) {
            if !line.code.is_empty()
                && line.indent > head.indent
                && arrow(&line.code).is_none()
                && !starts_with_keyword(&line.code)
            {
                // Appended in place: linear in the axiom's length (issue 50, 6).
                head.code.push(' ');
                head.code.push_str(&line.code);
                continue;
            }
        }
        let compact: String = line
            .code
            .chars()
            .filter(|c| !c.is_whitespace())
            .collect::<String>()
            .to_ascii_lowercase();
        // dialect: cpfg's keyword
        let opens = compact.starts_with("axiom:") && arrow(&line.code).is_none();
        axiom = opens.then_some(out.len());
        out.push(line);
    }
    out
}

/// cpfg productions written over two lines: `pred : cond` then `--> succ` on the next line, or
/// `pred -->` then the successor (at any indentation) on the next.
pub(in crate::import::abop) fn join_two_line_productions(lines: Vec<Line>) -> Vec<Line> {
    two_line_productions(lines).0
}

/// [`join_two_line_productions`], with how many lines its search for the next line with code
/// looked at (a measure of its work, linear in the lines).
fn two_line_productions(lines: Vec<Line>) -> (Vec<Line>, usize) {
    // As in `join_production_heads`, a joined line is taken out of its place (`None`); and the
    // search for the next line with code starts after the last one searched: 200,000 empty lines
    // (a file of continuation lines) were searched once for each (issue 50, 6).
    let mut lines: Vec<Option<Line>> = join_production_heads(lines).into_iter().map(Some).collect();
    let has_code = |l: &Option<Line>| l.as_ref().is_some_and(|l| !l.code.is_empty());
    let mut looked = 0;
    let mut i = 0;
    let mut from = 1;
    while i < lines.len() {
        if !has_code(&lines[i]) {
            i += 1;
            from = from.max(i + 1);
            continue;
        }
        let next = (from.max(i + 1)..lines.len()).find(|&j| {
            looked += 1;
            has_code(&lines[j])
        });
        let Some(j) = next else { break };
        let (Some(a), Some(b)) = (&lines[i], &lines[j]) else {
            break;
        };
        let (a, b) = (&a.code, &b.code);
        let arrow_next = b.starts_with("-->") || b.starts_with("->");
        let open_arrow =
            arrow(a).is_some_and(|(_, end)| a[end..].trim().is_empty()) && arrow(b).is_none();
        let joins = !starts_with_keyword(a)
            && !starts_with_keyword(b)
            && ((arrow_next && arrow(a).is_none()) || open_arrow);
        if joins {
            // The joined line goes, so that the successor's own continuation lines (indented,
            // see `production_lines`) follow the production directly.
            if let (Some(joined), Some(head)) = (lines[j].take(), lines[i].as_mut()) {
                head.code.push(' ');
                head.code.push_str(&joined.code);
                if !joined.comment.is_empty() {
                    let comment = format!("{} {}", head.comment, joined.comment);
                    head.comment = comment.trim().to_string();
                }
            }
            // `pred : cond` + `-->` alone may now be an open arrow: look again.
            from = j + 1;
            continue;
        }
        i += 1;
        from = j;
    }
    (lines.into_iter().flatten().collect(), looked)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(n: usize, code: &str, indent: usize) -> Line {
        Line {
            n,
            code: code.into(),
            comment: String::new(),
            indent,
        }
    }

    #[test]
    fn the_search_for_the_next_line_with_code_looks_at_each_line_a_few_times() {
        // Issue 50, 6: 200,000 empty lines (what lines continued by `\` leave for the line
        // numbers) were each searched past to the end: 2·10¹⁰ looks, 15 s.
        let mut lines = vec![line(1, "A :", 0)];
        lines.extend((2..200_002).map(|n| line(n, "", 0)));
        lines.push(line(200_002, "--> B", 0));
        lines.extend((200_003..400_003).map(|n| line(n, "", 0)));
        lines.push(line(400_003, "C --> D", 0));
        let count = lines.len();
        let (joined, looked) = two_line_productions(lines);
        assert!(looked <= 2 * count, "{looked} looks at {count} lines");
        let code: Vec<&str> = joined
            .iter()
            .map(|l| l.code.as_str())
            .filter(|c| !c.is_empty())
            .collect();
        assert_eq!(code, ["A : --> B", "C --> D"]);
    }

    #[test]
    fn an_axiom_continued_on_many_lines_is_one_line() {
        let mut lines = vec![line(1, "Axiom: F", 0)];
        lines.extend((2..100_002).map(|n| line(n, "F", 2)));
        lines.push(line(100_002, "F --> FF", 0));
        let joined = join_axiom_lines(lines);
        assert_eq!(joined.len(), 2);
        assert_eq!(joined[0].code.matches('F').count(), 100_001);
        assert_eq!(joined[1].code, "F --> FF");
    }
}

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
pub(in crate::import::abop) fn join_production_heads(mut lines: Vec<Line>) -> Vec<Line> {
    let mut i = 0;
    while i < lines.len() {
        let a = &lines[i];
        if a.indent > 0
            || a.code.is_empty()
            || arrow(&a.code).is_some()
            || starts_with_keyword(&a.code)
        {
            i += 1;
            continue;
        }
        let mut run = Vec::new();
        let mut found = false;
        for (j, b) in lines.iter().enumerate().skip(i + 1) {
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
        if found {
            let taken: Vec<Line> = run.iter().rev().map(|&j| lines.remove(j)).collect();
            for b in taken.into_iter().rev() {
                let code = format!("{} {}", lines[i].code, b.code);
                lines[i].code = code;
                if !b.comment.is_empty() {
                    let comment = format!("{} {}", lines[i].comment, b.comment);
                    lines[i].comment = comment.trim().to_string();
                }
            }
        }
        i += 1;
    }
    lines
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
pub(in crate::import::abop) fn join_axiom_lines(mut lines: Vec<Line>) -> Vec<Line> {
    let mut i = 0;
    while i < lines.len() {
        let compact: String = lines[i]
            .code
            .chars()
            .filter(|c| !c.is_whitespace())
            .collect::<String>()
            .to_ascii_lowercase();
        // dialect: cpfg's keyword
        if compact.starts_with("axiom:") && arrow(&lines[i].code).is_none() {
            while i + 1 < lines.len()
                && !lines[i + 1].code.is_empty()
                && lines[i + 1].indent > lines[i].indent
                && arrow(&lines[i + 1].code).is_none()
                && !starts_with_keyword(&lines[i + 1].code)
            {
                let next = lines.remove(i + 1);
                lines[i].code = format!("{} {}", lines[i].code, next.code);
            }
        }
        i += 1;
    }
    lines
}

/// cpfg productions written over two lines: `pred : cond` then `--> succ` on the next line, or
/// `pred -->` then the successor (at any indentation) on the next.
pub(in crate::import::abop) fn join_two_line_productions(lines: Vec<Line>) -> Vec<Line> {
    let mut lines = join_production_heads(lines);
    let mut i = 0;
    while i < lines.len() {
        let next = (i + 1..lines.len()).find(|&j| !lines[j].code.is_empty());
        let Some(j) = next else { break };
        let (a, b) = (&lines[i].code, &lines[j].code);
        let arrow_next = b.starts_with("-->") || b.starts_with("->");
        let open_arrow =
            arrow(a).is_some_and(|(_, end)| a[end..].trim().is_empty()) && arrow(b).is_none();
        let joins = !a.is_empty()
            && !starts_with_keyword(a)
            && !starts_with_keyword(b)
            && ((arrow_next && arrow(a).is_none()) || open_arrow);
        if joins {
            // The joined line goes, so that the successor's own continuation lines (indented,
            // see `production_lines`) follow the production directly.
            let joined = lines.remove(j);
            lines[i].code = format!("{} {}", lines[i].code, joined.code);
            if !joined.comment.is_empty() {
                let comment = format!("{} {}", lines[i].comment, joined.comment);
                lines[i].comment = comment.trim().to_string();
            }
            // `pred : cond` + `-->` alone may now be an open arrow: look again.
            continue;
        }
        i += 1;
    }
    lines
}

//! cpfg's loops in statement blocks (`while (c) {…}`, `do {…} while (c);`), as the Ridley
//! objects of vlab's course integrate along a contour:
//! `A(s,a) : s<L {rho = …; while (a<rho^2 && s<L) {x = curveX(1,s/L); a = a+2*x*ds; s = s+ds;}
//! a = a-rho^2; …} --> [f(y)-(90)f(x)…]A(s,a)`.
//!
//! Meristem has no statements, but a loop is a module rewritten until its condition fails: the
//! production writes an auxiliary module `A_w1` carrying the pattern's parameters and every
//! variable the block has set or the loop sets, with their values at the loop's start; one
//! production of the same section (or of a decomposition section added for it, when the
//! production is an ordinary one) repeats the loop's body while its condition holds
//! (`A_w1(s,a,rho,x) : a<rho^2 && s<L -> A_w1(s+ds, a+2*curveX…, rho, …)`), and one gives
//! cpfg's successor when it fails, the statements after the loop applied. Decomposition and
//! homomorphism rewrite again until nothing changes, so the loop runs to its end within the
//! step; each round is one turn of the loop, so the section's depth is raised to Meristem's
//! most ([`LOOP_DEPTH`]). One loop a production, at the top level of its block (not inside
//! an `if`), after the condition.

use super::super::{Env, Importer};

/// The depth a section with a loop gets: Meristem's most (`maximum depth:`).
pub(in crate::import::abop) const LOOP_DEPTH: u32 = 10_000;

/// The loop of the production being read.
#[derive(Clone, Debug, Default)]
pub(in crate::import::abop) struct Loop {
    pub condition: String,
    pub body: String,
    /// The block's variables at the loop's start (translated values).
    pub entry: Env,
    /// The names the body assigns, in order.
    pub assigned: Vec<String>,
}

/// The names the statements of `body` assign (`x = …`, `x += …`), in order, once each.
fn assigned_names(body: &str) -> Vec<String> {
    let mut names = Vec::new();
    for statement in body.split([';', '{', '}']) {
        let Some((target, _)) = statement.split_once('=') else {
            continue;
        };
        let target = target.trim().trim_end_matches(['+', '-', '*', '/']).trim();
        let target = target
            .rsplit(|c: char| c.is_whitespace() || c == ')')
            .next()
            .unwrap_or("");
        let is_name = target.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            && target
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_');
        // `a == b` and `a <= b` compare: what follows `=` is another `=`, or `<`/`>`/`!` precede.
        let compares = statement.contains("==")
            || statement.contains("<=")
            || statement.contains(">=")
            || statement.contains("!=");
        if is_name && !compares && !names.iter().any(|n| n == target) {
            names.push(target.to_string());
        }
    }
    names
}

impl Importer {
    /// Records `while (condition) {body}` met in a block (see the module); after it, every
    /// variable is the auxiliary module's parameter of its name.
    pub(in crate::import::abop) fn loop_statement(
        &mut self,
        condition: &str,
        body: &str,
        env: &mut Env,
        depth: usize,
    ) -> Result<(), String> {
        let statement = format!("while ({}) {{…}}", condition.trim());
        let Some(state) = self.cpfg.loops.as_mut() else {
            return Err(format!(
                "the statement '{statement}' is a loop; Meristem has no statements"
            ));
        };
        if depth > 0 || state.is_some() {
            return Err(format!("the loop '{statement}' is inside an if or a second loop of the block; Meristem writes one loop a production, at the top of its block"));
        }
        *state = Some(Loop {
            condition: condition.to_string(),
            body: body.to_string(),
            entry: env.clone(),
            assigned: assigned_names(body),
        });
        env.clear();
        Ok(())
    }

    /// The production whose pattern, in Meristem's terms with its condition, is `head` (its
    /// predecessor's name `letter`, its formal parameters `params`) and whose block holds `l`: the production that starts the loop, with the loop's two productions (repeat, and
    /// the `successor` when it ends) kept to be written after it or in the section at the end.
    pub(in crate::import::abop) fn looped(
        &mut self,
        letter: &str,
        head: &str,
        params: &[String],
        successor: &str,
        l: &Loop,
        n: usize,
    ) -> Result<String, String> {
        // The carried names: the pattern's parameters, the block's variables, the loop's.
        let mut carried: Vec<String> = params.to_vec();
        let mut entry_names: Vec<&String> = l.entry.keys().collect();
        entry_names.sort();
        for name in entry_names.into_iter().chain(&l.assigned) {
            if !carried.contains(name) {
                carried.push(name.clone());
            }
        }
        let entry: Vec<String> = carried
            .iter()
            .map(|v| match l.entry.get(v) {
                Some(value) => value.clone(),
                None if params.contains(v) => v.clone(),
                // C's variable before its first assignment: cpfg's are 0.
                None => "0".into(),
            })
            .collect();
        let condition = self.expression(&l.condition, &Env::new()).map_err(|why| {
            format!(
                "the condition of the loop 'while ({})': {why}",
                l.condition.trim()
            )
        })?;
        let mut turn = Env::new();
        self.statements(&l.body, &mut turn, n, 1)?;
        let next: Vec<String> = carried
            .iter()
            .map(|v| turn.get(v).cloned().unwrap_or_else(|| v.clone()))
            .collect();
        self.cpfg.stage_count += 1;
        let aux = format!("{letter}_w{}", self.cpfg.stage_count);
        self.declared.push(aux.clone());
        let formal = carried.join(",");
        let successor = if successor.is_empty() {
            "ε".to_string()
        } else {
            super::super::separate(successor)
        };
        let lines = vec![
            format!("{aux}({formal}) : {condition} -> {aux}({})", next.join(",")),
            format!("{aux}({formal}) : !({condition}) -> {successor}"),
        ];
        if self.in_productions {
            self.cpfg.staged.extend(lines);
            self.cpfg.staged_depth = true;
        } else {
            self.cpfg.after.extend(lines);
            self.raise_depth();
        }
        Ok(format!("{head} -> {aux}({})", entry.join(",")))
    }
}

impl Importer {
    /// The section being read gets [`LOOP_DEPTH`]: its `maximum depth:` line is rewritten, or
    /// one is written after the production.
    fn raise_depth(&mut self) {
        let depth = crate::vocabulary::KeywordKind::MaximumDepth.written();
        match self.cpfg.depth_line.clone() {
            Some((_, value)) if value == LOOP_DEPTH.to_string() => {}
            Some((index, value)) => {
                self.out.replace(
                    index,
                    format!("{depth} {LOOP_DEPTH} // cpfg: {value}; each turn of a loop below is one round"),
                );
                self.cpfg.depth_line = Some((index, LOOP_DEPTH.to_string()));
            }
            None => {
                self.cpfg.after.push(format!("{depth} {LOOP_DEPTH}"));
                self.cpfg.depth_line = Some((usize::MAX, LOOP_DEPTH.to_string()));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::assigned_names;

    #[test]
    fn a_loop_body_assigns_the_names_left_of_its_assignments() {
        assert_eq!(
            assigned_names("x = curveX(1,s/L); a = a + 2*x*ds; s += ds; if (a == 1) {b = 2;}"),
            ["x", "a", "s", "b"]
        );
    }
}

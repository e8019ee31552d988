//! The vlab object's functions where an expression reads them: cpfg's and lpfg's `func(k, x)`,
//! lpfg's `tfunc(k, t)` (a timeline function, read at `(t − start)/(end − start)`) and `val(k)`
//! (a value of the timeline), each naming its entry by the name its file gives or by its number
//! from 1 (lpfg's `Interface::Func`, `TFunc` and `VFunc`), in Meristem's terms: the call of the
//! `#table` or `#curve` the function became, or the `#define` the value became.

use super::super::Importer;
use crate::import::number;
use crate::import::vlab::{Body, CurveFunction, FunctionKind, Span};
use std::collections::HashMap;

/// The most bytes the functions an L-system reads may take in its translation (a `#table` of
/// lpfg's 1,000 samples takes some 20 KB): a set of 5,000 functions made 125 MB (issue 50, 6).
const MAX_FUNCTION_BYTES: usize = 1 << 20;

/// A number as a factor or term of an expression: in parentheses when negative.
fn operand(v: f64) -> String {
    if v < 0.0 {
        format!("({})", number(v))
    } else {
        number(v)
    }
}

impl Importer {
    /// The tool whose call is being read: lpfg for an L+C file, else cpfg.
    fn function_tool(&self) -> &'static str {
        if self.lpfg.active {
            "lpfg"
        } else {
            "cpfg"
        }
    }

    /// The entry of the object's function list that `call(k, …)` names: by the name its file
    /// gives it, else by its number from 1.
    fn object_function(&self, call: &str, k: &str) -> Result<&CurveFunction, String> {
        let index = self.function_index(call, k)?;
        self.cpfg
            .view
            .as_ref()
            .and_then(|v| v.functions.get(index))
            .and_then(Option::as_ref)
            .ok_or_else(|| format!("{call}({k}, …): no such function"))
    }

    /// The index in the object's function list of the entry `call(k, …)` names (see
    /// [`Importer::object_function`]).
    fn function_index(&self, call: &str, k: &str) -> Result<usize, String> {
        let tool = self.function_tool();
        let k = k.trim();
        let Some(view) = &self.cpfg.view else {
            return Err(match call {
                "func" => format!("{tool}'s func({k}, …) reads function {k} of the object's view file (.v), which was not opened with this file (open the object's folder or .zip)"),
                "tfunc" => format!("lpfg's tfunc({k}, …) reads the timeline function {k} of the object's .tset file, which was not opened with this file (open the object's folder or .zip)"),
                _ => format!("lpfg's val({k}) reads the value {k} of the object's .vset file, which was not opened with this file (open the object's folder or .zip)"),
            });
        };
        // With function sets (`.fset`, `.tset`, `.vset`) each entry has a name: `func(BR_ANGLE, x)`.
        let named = view
            .functions
            .iter()
            .position(|f| f.as_ref().is_some_and(|f| f.source == k || f.name == k));
        if let Some(index) = named {
            return Ok(index);
        }
        // A number, or a `#define`d name whose value is one (`#define INT_LENGTH 1`).
        let constant = self
            .lpfg
            .constants
            .iter()
            .find(|(name, _)| name == k)
            .map(|&(_, v)| v);
        let index = constant
            .or_else(|| k.parse::<f64>().ok())
            .filter(|v| v.fract() == 0.0 && *v >= 1.0)
            .ok_or_else(|| format!("{tool}'s {call}({k}, …) chooses its function by an expression or a name the object's files do not give; Meristem names each function, so it is not translated"))?;
        match view.functions.get(index as usize - 1) {
            Some(Some(_)) => Ok(index as usize - 1),
            _ => Err(format!(
                "{tool}'s {call}({k}, …): the object's files list no function {k} that could be read"
            )),
        }
    }

    /// cpfg's `func(k, x)`: function k of the view file or function sets, as the
    /// `#curve`/`#table` it became (a timeline function is read at x, as lpfg's `func` does).
    pub(in crate::import::abop) fn func(&mut self, args: &[String]) -> Result<String, String> {
        let tool = self.function_tool();
        let [k, x] = args else {
            return Err(format!(
                "{tool}'s func(…) takes a function's number and a value"
            ));
        };
        let f = self.object_function("func", k)?;
        if matches!(f.kind, FunctionKind::Value(_)) {
            return Err(format!(
                "{tool}'s func({k}, …) reads a function, and {k} is a value of the object's .vset file (val({k}) reads it)"
            ));
        }
        let call = format!("{}({x})", f.name);
        self.use_function(self.function_index("func", k)?)?;
        Ok(call)
    }

    /// lpfg's `tfunc(k, t)`: timeline function k at `(t − start)/(end − start)`; the function
    /// (a `#table` of lpfg's samples) is level beyond 0 and 1, as lpfg clamps its argument. A
    /// function of a function set has start 0 and end 1.
    pub(in crate::import::abop) fn tfunc(&mut self, args: &[String]) -> Result<String, String> {
        let [k, t] = args else {
            return Err(
                "lpfg's tfunc(…) takes a timeline function's name or number and a time".into(),
            );
        };
        let f = self.object_function("tfunc", k)?;
        let t = t.trim();
        let name = &f.name;
        let call = match &f.kind {
            FunctionKind::Value(_) => {
                return Err(format!(
                    "lpfg's tfunc({k}, …) reads a function, and {k} is a value of the object's .vset file (val({k}) reads it)"
                ))
            }
            FunctionKind::Curve => format!("{name}({t})"),
            FunctionKind::Timeline(span) => format!("{name}({})", self.timeline_time(span, t)),
        };
        self.use_function(self.function_index("tfunc", k)?)?;
        Ok(call)
    }

    /// `(t − start)/(end − start)`, the argument lpfg gives a timeline function at time `t`. An
    /// end whose label names a value of the `.vset` that holds its time is that value's
    /// `#define`, as vlab's timeline tool keeps them equal (a slider moves both).
    fn timeline_time(&self, span: &Span, t: &str) -> String {
        let (start, end) = (span.start, span.end);
        // lpfg divides by 0: t before the start gives −∞ (clamped to 0), after it +∞ (1).
        if start == end {
            return format!("({t})<{}?0:1", operand(start));
        }
        let start_define = self.value_define(&span.start_label, start);
        let end_define = self.value_define(&span.end_label, end);
        if start_define.is_some() || end_define.is_some() {
            let start = start_define.unwrap_or_else(|| operand(start));
            let end = end_define.unwrap_or_else(|| operand(end));
            return format!("(({t})-{start})/({end}-{start})");
        }
        let from = if start == 0.0 {
            format!("({t})")
        } else {
            format!("(({t})-{})", operand(start))
        };
        let span = end - start;
        if span == 1.0 {
            from
        } else {
            format!("{from}/{}", operand(span))
        }
    }

    /// The Meristem name of the `.vset` value `label` names, when it holds `time`.
    fn value_define(&self, label: &str, time: f64) -> Option<String> {
        let view = self.cpfg.view.as_ref()?;
        view.functions
            .iter()
            .flatten()
            .find(|f| !label.is_empty() && f.source == label && f.kind == FunctionKind::Value(time))
            .map(|f| f.name.clone())
    }

    /// lpfg's `val(k)`: value k of the `.vset` file, as the `#define` it became.
    pub(in crate::import::abop) fn val(&self, args: &[String]) -> Result<String, String> {
        let [k] = args else {
            return Err("lpfg's val(…) takes a value's name or number".into());
        };
        let f = self.object_function("val", k)?;
        match f.kind {
            FunctionKind::Value(_) => Ok(f.name.clone()),
            FunctionKind::Curve | FunctionKind::Timeline(_) => Err(format!(
                "lpfg's val({k}) reads a value of the object's .vset file, and {k} is a function (lpfg gives no value for it)"
            )),
        }
    }

    /// cpfg's `curveX(k, t)`, `curveY`, `curveZ` (`axis` 0, 1, 2) and `curveGAL(k)` (`axis`
    /// `None`): contour k of the view file's `curve:` lines, as the tables it became (see
    /// `vlab/contour_file.rs`).
    pub(in crate::import::abop) fn contour(
        &self,
        call: &str,
        axis: Option<usize>,
        args: &[String],
    ) -> Result<String, String> {
        let k = args.first().map_or("", |k| k.trim());
        let Some(view) = &self.cpfg.view else {
            return Err(format!("cpfg's {call}({k}, …) reads contour {k} of the object's view file (.v), which was not opened with this file (open the object's folder or .zip)"));
        };
        let index = self
            .lpfg
            .constants
            .iter()
            .find(|(name, _)| name == k)
            .map(|&(_, v)| v)
            .or_else(|| k.parse::<f64>().ok())
            .filter(|v| v.fract() == 0.0 && *v >= 1.0)
            .ok_or_else(|| format!("cpfg's {call}({k}, …) chooses its contour by an expression; Meristem names each contour, so it is not translated"))?;
        let Some(Some(contour)) = view.contours.get(index as usize - 1) else {
            return Err(format!(
                "cpfg's {call}({k}, …): the view file gives no contour {k} that could be read"
            ));
        };
        match (axis, args) {
            (None, [_]) => Ok(format!("({})", crate::import::number(contour.length))),
            (Some(axis), [_, t]) => Ok(format!("{}({t})", contour.names[axis])),
            _ => Err(format!(
                "cpfg's {call}(…) takes a contour's number{}",
                if axis.is_some() {
                    " and a fraction of its length"
                } else {
                    ""
                }
            )),
        }
    }

    /// Marks entry `index` of the object's function list as read by the L-system, so that it is
    /// written; an error when its lines would take those written past [`MAX_FUNCTION_BYTES`].
    fn use_function(&mut self, index: usize) -> Result<(), String> {
        if self.cpfg.used_functions.iter().any(|(k, _)| *k == index) {
            return Ok(());
        }
        let Some(f) = self
            .cpfg
            .view
            .as_ref()
            .and_then(|v| v.functions.get(index))
            .and_then(Option::as_ref)
        else {
            return Ok(());
        };
        let lines = f.lines();
        let bytes: usize = lines.iter().map(|l| l.len() + 1).sum();
        if self.cpfg.function_bytes + bytes > MAX_FUNCTION_BYTES {
            return Err(format!(
                "the function {} is not written: with it, the functions the L-system reads would take more than {} MB of text",
                f.source,
                MAX_FUNCTION_BYTES >> 20
            ));
        }
        self.cpfg.function_bytes += bytes;
        self.cpfg.used_functions.push((index, lines));
        Ok(())
    }

    /// Writes the object's functions after the view's lines, once the L-system has been read:
    /// its values, and the functions it reads; a comment names the others (a function set's
    /// functions the L-system never reads are not written).
    pub(in crate::import::abop) fn function_lines(&mut self) {
        let (Some(at), Some(view)) = (self.cpfg.functions_at, &self.cpfg.view) else {
            return;
        };
        let used: HashMap<usize, &Vec<String>> = self
            .cpfg
            .used_functions
            .iter()
            .map(|(k, lines)| (*k, lines))
            .collect();
        let mut lines = Vec::new();
        let mut unused = Vec::new();
        for (k, f) in view.functions.iter().enumerate() {
            let Some(f) = f else { continue };
            match (used.get(&k).copied(), &f.body) {
                (Some(written), _) | (None, Body::Lines(written)) => {
                    lines.extend(written.iter().cloned())
                }
                (None, Body::Points { .. }) => unused.push(f.source.as_str()),
            }
        }
        if !unused.is_empty() {
            let more = unused.len().saturating_sub(10);
            // A name is the file's text: no line break may end the comment early.
            let names: String = unused[..unused.len().min(10)]
                .join(", ")
                .chars()
                .map(|c| if c.is_control() { ' ' } else { c })
                .collect();
            let more = if more > 0 {
                format!(" and {more} more")
            } else {
                String::new()
            };
            lines.push(format!(
                "// Not written: the object's functions {} (the L-system does not read them).",
                crate::import::defuse_comment(&format!("{names}{more}"))
            ));
        }
        self.out.insert(at, lines);
    }
}

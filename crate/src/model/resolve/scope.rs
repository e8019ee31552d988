//! What names mean inside expressions: a production's formal parameters, `#define`d names and
//! `#random` variables; compiling an expression in that scope.

use super::Resolver;
use crate::diagnostics::Diagnostic;
use crate::model::{Curve, Program, Scope};
use crate::syntax::ExprSyntax;
use std::collections::HashMap;
use std::sync::Arc;

/// The formal parameters of one production: name -> slot (the first slot bound to a name; a
/// name bound twice is an error). Found by hashing: a production of 65,000 parameters was
/// quadratic to resolve (issue 50).
#[derive(Default)]
pub(super) struct Slots {
    count: usize,
    first: HashMap<String, u16>,
}

impl Slots {
    /// How many slots are bound (the names, and the places of parameters that are not names).
    pub fn len(&self) -> usize {
        self.count
    }

    /// Whether `name` is bound already.
    pub fn binds(&self, name: &str) -> bool {
        self.first.contains_key(name)
    }

    /// Binds the next slot to `name`, or to no name (a parameter that is not a name).
    pub fn bind(&mut self, name: Option<&str>) {
        if let Some(name) = name {
            self.first
                .entry(name.to_string())
                .or_insert(self.count as u16);
        }
        self.count += 1;
    }

    fn slot(&self, name: &str) -> Option<u16> {
        self.first.get(name).copied()
    }
}

struct ScopeView<'a> {
    slots: &'a Slots,
    defines: &'a HashMap<String, ExprSyntax>,
    define_values: &'a HashMap<String, f64>,
    /// `#random` names and their indices; none in a directive's constant expression.
    random_names: Option<&'a HashMap<String, u16>>,
    curves: &'a HashMap<String, Arc<Curve>>,
    dt: f64,
}

impl Scope for ScopeView<'_> {
    fn slot(&self, name: &str) -> Option<u16> {
        self.slots.slot(name)
    }
    fn define(&self, name: &str) -> Option<&ExprSyntax> {
        self.defines.get(name)
    }
    fn define_value(&self, name: &str) -> Option<f64> {
        self.define_values.get(name).copied()
    }
    fn random_var(&self, name: &str) -> Option<u16> {
        self.random_names?.get(name).copied()
    }
    fn curve(&self, name: &str) -> Option<Arc<Curve>> {
        self.curves.get(name).cloned()
    }
    fn dt(&self) -> f64 {
        self.dt
    }
}

impl Resolver {
    /// Compiles `expr` with `slots` bound, reporting an error as a diagnostic.
    pub(super) fn compile(&mut self, expr: &ExprSyntax, slots: &Slots) -> Option<Program> {
        let scope = ScopeView {
            slots,
            defines: &self.defines,
            define_values: &self.define_values,
            random_names: Some(&self.random_names),
            curves: &self.curves,
            dt: self.dt,
        };
        match Program::compile(expr, &scope) {
            Ok(p) => Some(p),
            Err(d) => {
                self.diagnostics.push(d);
                None
            }
        }
    }

    /// Compiles a directive's constant expression: `#define`d names only (no slots, no random
    /// variables); the error is returned for the caller's message.
    pub(super) fn compile_constant(&self, expr: &ExprSyntax) -> Result<Program, Diagnostic> {
        let scope = ScopeView {
            slots: &Slots::default(),
            defines: &self.defines,
            define_values: &self.define_values,
            random_names: None,
            curves: &self.curves,
            dt: self.dt,
        };
        Program::compile(expr, &scope)
    }
}

//! `meristem help`: the usage, or the language's vocabulary as a table.

use super::USAGE;
use meristem::vocabulary::{Param, ParamDefault, DIRECTIVES, MODULES};
use std::process::ExitCode;

/// `meristem help [modules|directives]`: the usage, or a table of the vocabulary.
pub fn help(topic: &str) -> ExitCode {
    match topic {
        "" => super::print_out(format_args!("{USAGE}\n")),
        "modules" => {
            for m in MODULES {
                let params = params_text(m.params);
                super::print_out(format_args!("{:<10} {params:<24} {}\n", m.name, m.doc));
            }
        }
        "directives" => {
            for d in DIRECTIVES {
                let forms = d.forms_text();
                super::print_out(format_args!("#{:<20} {forms:<28} {}\n", d.name, d.doc));
            }
        }
        other => {
            eprintln!("meristem: no help on '{other}'; try 'meristem help modules' or 'meristem help directives'");
            return ExitCode::from(2);
        }
    }
    ExitCode::SUCCESS
}

/// `(l = #step)`, `(x, y, z)`, or nothing.
pub fn params_text(params: &[Param]) -> String {
    if params.is_empty() {
        return String::new();
    }
    let each: Vec<String> = params
        .iter()
        .map(|p| match p.default {
            Some(ParamDefault::Value(v)) => format!("{} = {v}", p.name),
            Some(ParamDefault::Directive(d)) => format!("{} = {}", p.name, d.written()),
            None => p.name.to_string(),
        })
        .collect();
    format!("({})", each.join(", "))
}

//! Which file of what was opened Python runs, and in which dialect, when the hand translation is
//! not enough ([`crate::import::needs_python`]): an lpfg object's L+C `.l`, or an L-Py `.lpy`.
//! cpfg, Lparser and Green files have no Python route.

use super::specifications::command;
use super::{lpfg_functions, lsystem_file, Files, ObjectFile};
use crate::import::vlab::specifications::Command;
use serde::Serialize;

/// The file to run (its name as given in the files) and the dialect to run it in.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct PythonMain {
    pub main: String,
    /// `lpy` or `lpfg`, as the runtime's `options["dialect"]`.
    pub dialect: &'static str,
}

/// The Python route of the files opened together (a vlab object, or one file): the object's `.l`
/// when it is lpfg's (its `specifications` starts lpfg, or the `.l` includes `lpfgall.h` or
/// declares modules as L+C does), else, with no `.l`, the first `.lpy`; `None` for cpfg and the
/// other dialects.
pub fn python_main(files: &[ObjectFile]) -> Option<PythonMain> {
    let all = Files::new(files);
    let specifications = all.text("specifications");
    let spec = specifications
        .as_deref()
        .and_then(command)
        .unwrap_or_else(|| Command {
            lpfg: lpfg_functions::LpfgFiles::guessed(&all),
            ..Command::default()
        });
    let full_name = |base: &str| {
        files
            .iter()
            .filter(|f| super::base(&f.name) == base)
            .min_by_key(|f| f.name.matches(['/', '\\']).count())
            .map(|f| f.name.clone())
    };
    if let Some(l) = lsystem_file(&all, &spec) {
        let by_spec = specifications.as_deref().is_some_and(|s| {
            s.lines()
                .any(|line| line.split_whitespace().next() == Some("lpfg"))
        });
        let text = all.text(&l).unwrap_or_default();
        let l_plus_c = text.contains("lpfgall.h")
            || text.lines().any(|line| {
                let line = line.trim();
                line.starts_with("module ") && line.ends_with(';')
            });
        return (by_spec || l_plus_c).then(|| PythonMain {
            main: full_name(&l).unwrap_or(l),
            dialect: "lpfg",
        });
    }
    let lpy = all.with(".lpy").first().map(|s| s.to_string())?;
    Some(PythonMain {
        main: full_name(&lpy).unwrap_or(lpy),
        dialect: "lpy",
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(name: &str, text: &str) -> ObjectFile {
        ObjectFile {
            name: name.into(),
            bytes: text.as_bytes().to_vec(),
        }
    }

    #[test]
    fn an_lpfg_object_runs_its_l_an_lpy_file_itself_and_cpfg_never() {
        let lpfg = [
            file(
                "obj/specifications",
                "model:\n\tgenerate:\n\t\tlpfg lsystem.l view.v\n",
            ),
            file("obj/lsystem.l", "Axiom: A();\n"),
            file("obj/view.v", ""),
        ];
        assert_eq!(
            python_main(&lpfg),
            Some(PythonMain {
                main: "obj/lsystem.l".into(),
                dialect: "lpfg"
            })
        );
        let by_content = [file("plant.l", "#include <lpfgall.h>\nmodule A(float);\n")];
        assert_eq!(python_main(&by_content).unwrap().dialect, "lpfg");
        let cpfg = [
            file("specifications", "cpfg plant.l plant.v\n"),
            file("plant.l", "Lsystem: 1\nAxiom: F\nendlsystem\n"),
        ];
        assert_eq!(python_main(&cpfg), None);
        let lpy = [file("tree.lpy", "Axiom: A\n")];
        assert_eq!(
            python_main(&lpy),
            Some(PythonMain {
                main: "tree.lpy".into(),
                dialect: "lpy"
            })
        );
        assert_eq!(python_main(&[file("x.ls", "")]), None);
    }
}

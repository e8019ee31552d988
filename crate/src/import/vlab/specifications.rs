//! The `specifications` file of a vlab object: which files cpfg or lpfg is started with (its
//! `cpfg …` or `lpfg …` line).

use super::lpfg_functions;

/// The files cpfg is started with: from the `cpfg …` line of `specifications`.
#[derive(Default, Debug)]
pub(super) struct Command {
    pub lsystem: Option<String>,
    pub view: Option<String>,
    pub colormap: Option<String>,
    pub materials: Option<String>,
    /// The communication file of the environmental program (`-e file.e`; lpfg: a `.e` named).
    pub environment: Option<String>,
    /// The function set (`.fset`), timeline functions (`.tset`), values (`.vset`) and function
    /// files (`.func`) lpfg is started with (of each set the last one named, as lpfg keeps).
    pub lpfg: lpfg_functions::LpfgFiles,
}

pub(super) fn command(specifications: &str) -> Option<Command> {
    let line = specifications.lines().find(|l| {
        let mut words = l.split_whitespace();
        matches!(words.next(), Some("cpfg" | "lpfg"))
    })?;
    let lpfg = line.split_whitespace().next() == Some("lpfg");
    let words: Vec<&str> = line.split_whitespace().skip(1).collect();
    let mut c = Command::default();
    let mut i = 0;
    while i < words.len() {
        let w = words[i];
        let next = words.get(i + 1).map(|s| s.to_string());
        match w {
            "-m" | "-m1" => {
                c.colormap = next;
                i += 1;
            }
            "-M" | "-M1" => {
                c.materials = next;
                i += 1;
            }
            "-w" | "-wp" | "-wr" => i += 2,
            "-e" => {
                c.environment = next;
                i += 1;
            }
            "-m2" | "-m3" | "-M2" | "-M3" | "-a" | "-s" | "-str" | "-o" | "-g" => i += 1,
            w if w.ends_with(".l") => c.lsystem = Some(w.to_string()),
            w if w.ends_with(".v") => c.view = Some(w.to_string()),
            // lpfg names its files without options.
            w if lpfg && w.ends_with(".mat") => c.materials = Some(w.to_string()),
            w if lpfg && w.ends_with(".map") => c.colormap = Some(w.to_string()),
            w if lpfg && w.ends_with(".e") => c.environment = Some(w.to_string()),
            w if lpfg => c.lpfg.name(w),
            _ => {}
        }
        i += 1;
    }
    Some(c)
}

//! The directive table: every `#directive` the resolver accepts, declared once with its arguments
//! and a one-line doc. The resolver's tests check that it accepts exactly these names, and the
//! table is exported to TypeScript for the editor's completion.

use serde::Serialize;

/// One row of the directive table.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct DirectiveInfo {
    /// The name without `#`.
    pub name: &'static str,
    /// How its arguments are written, e.g. `x y z e`.
    pub args: &'static str,
    pub doc: &'static str,
}

const fn row(name: &'static str, args: &'static str, doc: &'static str) -> DirectiveInfo {
    DirectiveInfo { name, args, doc }
}

/// Every directive, in the order of docs/LANGUAGE.md.
#[rustfmt::skip]
pub const DIRECTIVES: &[DirectiveInfo] = &[
    row("angle", "degrees", "The default turn angle δ of + - & ^ \\ / (default 90)."),
    row("iterations", "n", "The number of derivation steps (default 0)."),
    row("step", "length", "The default length of F, f, G and g (default 1)."),
    row("width", "w", "The initial segment width, in width units (default 1)."),
    row("width_step", "d", "How much ! without a parameter decreases the width (default 0.1)."),
    row("tropism", "x y z e", "The tropism vector T and susceptibility e (ABOP 2.3; default 0 -1 0 0)."),
    row("color", "index r g b | first last r g b r g b", "Set a palette entry, or a ramp of entries (components 0 to 255)."),
    row("colour", "index r g b | first last r g b r g b", "The same as #color."),
    row("seed", "n", "The seed of the random generator (default 1)."),
    row("define", "name expression", "A named constant or expression, inlined where it is used."),
    row("random", "name = distribution(...)", "A random variable (Green): one deviate per module while matching."),
    row("ignore", "modules", "Modules that context matching skips."),
    row("consider", "modules", "The only modules context matching sees (not with #ignore)."),
    row("module", "names", "Declare multi-letter module names."),
    row("draw", "modules", "Further modules that draw a segment like F."),
    row("max_modules", "n", "Stop with an error when the string would grow past n modules (default 5,000,000)."),
    row("max_steps", "n", "The largest number of derivation steps a build may run (default 10,000)."),
    row("homomorphism_depth", "n", "The maximum depth of homomorphism rules (default 16)."),
    row("decomposition_depth", "n", "The maximum depth of decomposition rules (default 16)."),
    row("apex", "modules", "Growth: the modules that are branch apices (default: modules with productions that are not turtle commands)."),
    row("lifetime", "MB VB [pu pm pl]", "Growth: MB + Round(Rand()·VB) apices keep growing each step, shared by the upper, middle and lower thirds (default 0.6 0.3 0.1); the others stop."),
    row("speed", "SM VR [PFu PFm PFl]", "Growth: each apex is rewritten PF + SM + Round(Rand()·VR) times per step (PF default 2 1 1)."),
    row("shape", "GR m [VR]", "Growth: a segment of age i is GR^i times as long up to maturity m, then log_GR(i) − log_GR(m) + GR^m, ± Round(Rand()·VR)."),
    row("shape_width", "[VR [PFu PFm PFl]]", "Growth: a segment of age i is i + PF + Round(Rand()·VR) times as wide (PF default 2 1 0)."),
    row("sun", "latitude season angle", "Growth: upper and middle segments turn towards the noon sun (+X side) by angle degrees per step; season summer, equinox or winter."),
    row("gravity", "angle [variation]", "Growth: every segment turns down by angle + Round(Rand()·variation) degrees per step."),
    row("wind", "x z angle [variation]", "Growth: every segment turns towards the horizontal direction (x, 0, z) by angle + Round(Rand()·variation) degrees per step."),
];

/// The directive table as JSON, for the TypeScript side.
pub fn directives_json() -> String {
    serde_json::to_string(DIRECTIVES).unwrap_or_else(|_| "[]".into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_resolver_accepts_every_directive_of_the_table() {
        for d in DIRECTIVES {
            let args = match d.name {
                "tropism" => "0 -1 0 0.1",
                "color" | "colour" => "1 10 20 30",
                "define" => "k 2",
                "random" => "r = uniform(0, 1)",
                "ignore" | "consider" | "draw" | "module" | "apex" => "A",
                "lifetime" => "34 32",
                "speed" => "0 1",
                "shape" => "1.5 3",
                "shape_width" => "1",
                "sun" => "38 summer 2",
                "gravity" => "5",
                "wind" => "1 0 3",
                _ => "3",
            };
            let text = format!("#{} {args}\naxiom: F", d.name);
            let (file, _) = crate::syntax::parse(&text);
            let (_, diagnostics) = crate::model::resolve(&file);
            assert!(
                diagnostics.iter().all(|x| x.code != "E0200"),
                "#{} is in the table but unknown to the resolver",
                d.name
            );
            assert!(
                diagnostics
                    .iter()
                    .all(|x| x.severity != crate::diagnostics::Severity::Error),
                "#{} {args}: {diagnostics:?}",
                d.name
            );
        }
    }

    #[test]
    fn the_resolver_rejects_a_name_outside_the_table() {
        let (file, _) = crate::syntax::parse("#colours 3\naxiom: F");
        let (_, diagnostics) = crate::model::resolve(&file);
        assert!(diagnostics.iter().any(|x| x.code == "E0200"));
    }
}

//! A vlab object's environmental program: the communication file (`.e`, named by cpfg's `-e` or
//! on lpfg's command line) names the program (`executable: chiba -e tree.e light.spec`) and its
//! specification file; the programs whose meaning matches one of Meristem's become `#environment`
//! lines with a note saying what differs (docs/LANGUAGE.md, "Importing other dialects"), the
//! others leave `?E` inert with a note naming the program Meristem lacks.
//!
//! Read from vlab's own programs (`ENVIRO/*/doc.txt` and sources): `chiba` (Chiba et al.'s light
//! through leaf balls: replies the light, then the brightest direction) and `shadowpyramid`
//! (Palubicki et al. 2009's shadow propagation: the light, then its gradient) are light models
//! and reply in the order Meristem's `light` does (exposure, dx, dy, dz); `honda81` (1 when no
//! other `?E` of at least its vigor is within a radius, else 0) is Meristem's `collision`;
//! `ecosystem` (the same with circles as wide as each `?E`'s first parameter) has no counterpart.

use super::Files;
use crate::import::number;
use crate::vocabulary::{DirectiveKind, EnvironmentProgram};

/// What the object's environment gives the import.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Environment {
    /// The program the `.e` file starts (`chiba`).
    pub program: String,
    /// `#environment` lines; empty when the program has no Meristem counterpart.
    pub lines: Vec<String>,
    /// What was mapped and what differs (line 0 of the import).
    pub notes: Vec<String>,
}

/// The settings of a specification file: each `key: values` line's key (lower case) and words
/// (numbers may be split by spaces, `,`, `;` or `x`, as vlab's programs read them).
struct Spec {
    lines: Vec<(String, Vec<String>)>,
}

impl Spec {
    fn read(text: &str) -> Spec {
        let lines = text
            .lines()
            .filter_map(|l| l.split_once(':'))
            .map(|(k, v)| {
                let words = v
                    .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
                    .flat_map(|w| split_x(w))
                    .filter(|w| !w.is_empty())
                    .map(str::to_string)
                    .collect();
                (k.trim().to_ascii_lowercase(), words)
            })
            .collect();
        Spec { lines }
    }

    /// The numbers of every line `key`, in order.
    fn all(&self, key: &str) -> Vec<Vec<f64>> {
        self.lines
            .iter()
            .filter(|(k, _)| k == key)
            .map(|(_, w)| w.iter().filter_map(|w| w.parse().ok()).collect())
            .collect()
    }

    /// The first number of the last line `key`.
    fn number(&self, key: &str) -> Option<f64> {
        self.all(key).last().and_then(|v| v.first().copied())
    }
}

/// `32x32x32` as three numbers; any other word as it is.
fn split_x(word: &str) -> Vec<&str> {
    let parts: Vec<&str> = word.split('x').collect();
    if parts.len() > 1 && parts.iter().all(|p| p.parse::<f64>().is_ok()) {
        parts
    } else {
        vec![word]
    }
}

/// The program and its specification file from the `.e` file's `executable:` line.
fn executable(e_text: &str) -> Option<(String, Option<String>)> {
    let line = e_text
        .lines()
        .find_map(|l| l.trim().strip_prefix("executable:"))?;
    let mut words = line.split_whitespace();
    let program = words.next()?.rsplit('/').next()?.to_string();
    let mut spec = None;
    while let Some(w) = words.next() {
        match w {
            "-e" | "-k" | "-ext" => {
                words.next();
            }
            w if w.starts_with('-') => {}
            w => spec = Some(w.to_string()),
        }
    }
    Some((program, spec))
}

/// Reads the object's communication file `e_name` and the program it names.
pub(crate) fn read(e_name: &str, all: &Files) -> Option<Environment> {
    let (program, spec_name) = executable(&all.text(e_name)?)?;
    let spec_text = spec_name.as_ref().and_then(|s| all.text(s));
    let spec = Spec::read(spec_text.as_deref().unwrap_or(""));
    let mut env = Environment {
        program: program.clone(),
        ..Environment::default()
    };
    if spec_name.is_some() && spec_text.is_none() {
        env.notes.push(format!(
            "{program}'s specification file {} is not in the object: its defaults are used",
            spec_name.unwrap_or_default()
        ));
    }
    match program.as_str() {
        "chiba" => chiba(&spec, &mut env),
        "shadowpyramid" => shadow_pyramid(&spec, &mut env),
        "ecosystem" => env.notes.push(format!(
            "{e_name} runs ecosystem (Honda 1981's test with each ?E a circle as wide as its first parameter: 1 when it overlaps no larger one, else 0: self-thinning of a stand); Meristem has no program that answers yes or no for the ?E themselves, so ?E keeps the parameters the L-system writes (the nearest is `space`, which counts the plants' parts within a radius)"
        )),
        "honda81" => {
            // Meristem's collision is honda81's test, its radius and its plane (`3d case: off`,
            // honda81's default, compares x and z): nothing to note.
            let radius = spec.number("radius").unwrap_or(0.0);
            let in_space = spec
                .lines
                .iter()
                .rev()
                .find(|(k, _)| k == "3d case")
                .is_some_and(|(_, w)| w.first().is_some_and(|w| w == "on"));
            let flat = if in_space { "" } else { " flat 1" };
            env.lines.push(format!(
                "{} {} radius {}{flat}",
                DirectiveKind::Environment.written(),
                EnvironmentProgram::Collision.info().name,
                number(radius)
            ));
        }
        "obcheck" => {
            let text = spec_text.as_deref().unwrap_or("");
            let lines = text
                .split_once("coordinates:")
                .map_or(0, |(_, c)| c.split_whitespace().filter(|w| w.parse::<f64>().is_ok()).count() / 4);
            env.notes.push(format!(
                "{e_name} runs obcheck: {lines} line obstacles in the plane, and a ?E(1) replies 1 when the turtle's path since the ?E before it crosses one, else 0; Meristem's obstacle is a solid (box, sphere, plane) that answers at one point whether it is free and how far its surface is, not whether a path crossed a line, so ?E keeps the parameters the L-system writes"
            ));
        }
        _ => env.notes.push(format!(
            "{e_name} runs the environmental program {program}, which Meristem does not have (it has light, obstacle, space, attractors and collision): ?E keeps the parameters the L-system writes"
        )),
    }
    Some(env)
}

/// The line `#environment light` with `settings` (word, numbers).
fn light_line(settings: &[(&str, Vec<f64>)]) -> String {
    let mut line = format!(
        "{} {}",
        DirectiveKind::Environment.written(),
        EnvironmentProgram::Light.info().name
    );
    for (word, values) in settings {
        line.push(' ');
        line.push_str(word);
        for v in values {
            line.push(' ');
            line.push_str(&number(*v));
        }
    }
    line
}

/// chiba's light sources: the strongest becomes Meristem's sun, the rest its diffuse sky.
fn chiba(spec: &Spec, env: &mut Environment) {
    let sources: Vec<([f64; 3], f64)> = spec
        .all("source direction")
        .into_iter()
        .filter_map(|v| match v[..] {
            [x, y, z, w] if w > 0.0 && (x, y, z) != (0.0, 0.0, 0.0) => Some(([x, y, z], w)),
            _ => None,
        })
        .collect();
    let total: f64 = sources.iter().map(|s| s.1).sum();
    let strongest = sources
        .iter()
        .copied()
        .reduce(|a, b| if b.1 > a.1 { b } else { a });
    let mut settings: Vec<(&str, Vec<f64>)> = Vec::new();
    match strongest {
        Some((direction, w)) => {
            let sun = w / total;
            settings.push(("sky", vec![1.0 - sun]));
            settings.push(("sun", vec![sun]));
            settings.push(("sun_direction", direction.to_vec()));
            if sources.len() > 1 {
                env.notes.push(format!(
                    "chiba's {} light sources: the strongest (towards {}, {:.0} % of the light) is Meristem's sun, the {} others its diffuse sky (a uniform sky, not those directions)",
                    sources.len(),
                    direction.map(number).join(" "),
                    100.0 * sun,
                    sources.len() - 1
                ));
            }
        }
        None => settings.push(("sky", vec![1.0])),
    }
    // chiba's leaf balls let `transmittance` of a ray through (0.6 unless the file says).
    let transmittance = spec.number("transmittance").unwrap_or(0.6).clamp(0.0, 1.0);
    settings.push(("absorb", vec![1.0 - transmittance]));
    env.lines.push(light_line(&settings));
    env.notes.push(format!(
        "chiba (light through leaf balls, Chiba et al.) becomes Meristem's light: {}. It replies as chiba does, the light (0 to 1) into the ?E's first parameter and the brightest direction into the next three. What differs: in chiba each ?E is a leaf ball (its first parameter, or `radius:`, its radius) that shades the others, in Meristem the parts the turtle draws shade and the ?E only asks; chiba's grid fitted around the ?E is Meristem's grid of cells one step long",
        settings_words(&settings)
    ));
}

/// Palubicki et al.'s shadow pyramids: the same model as Meristem's light grid.
fn shadow_pyramid(spec: &Spec, env: &mut Environment) {
    let span = spec.number("grid span").unwrap_or(200.0);
    let size = spec.number("grid size").unwrap_or(201.0).max(1.0);
    let settings: Vec<(&str, Vec<f64>)> = vec![
        ("sky", vec![1.0]),
        ("cell", vec![span / size]),
        ("shadow", vec![spec.number("shadow weight").unwrap_or(0.58)]),
        (
            "spread",
            vec![spec.number("shadow dissipation").unwrap_or(6.9)],
        ),
        ("depth", vec![spec.number("shadow depth").unwrap_or(6.0)]),
    ];
    env.lines.push(light_line(&settings));
    let slope = spec.number("shadow spread").unwrap_or(1.0);
    env.notes.push(format!(
        "shadowpyramid (Palubicki et al. 2009) becomes Meristem's light: {}, replying the light and its direction as shadowpyramid does. What differs: every part the turtle draws casts its shadow (shadowpyramid: each ?E whose first parameter is above 0){}; its grid of {} cells over a span of {} is Meristem's cells of that size around the plants",
        settings_words(&settings),
        if slope == 1.0 { String::new() } else { format!("; the pyramids' slope {} is Meristem's 1", number(slope)) },
        number(size),
        number(span)
    ));
}

/// `word numbers, …` for a note.
fn settings_words(settings: &[(&str, Vec<f64>)]) -> String {
    settings
        .iter()
        .map(|(w, v)| {
            format!(
                "{w} {}",
                v.iter().map(|x| number(*x)).collect::<Vec<_>>().join(" ")
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::import::ObjectFile;

    fn object(files: &[(&str, &str)]) -> Vec<ObjectFile> {
        files
            .iter()
            .map(|(n, t)| ObjectFile {
                name: n.to_string(),
                bytes: t.as_bytes().to_vec(),
            })
            .collect()
    }

    #[test]
    fn one_chiba_source_is_the_sun() {
        let files = object(&[
            ("balls.e", "executable: chiba -e balls.e light.spec\n"),
            (
                "light.spec",
                "grid size: 32x32x32\ntransmittance: 0.0\nsource direction:    50 100  0   4\n",
            ),
        ]);
        let env = read("balls.e", &Files::new(&files)).unwrap();
        assert_eq!(env.program, "chiba");
        assert_eq!(
            env.lines,
            ["#environment light sky 0 sun 1 sun_direction 50 100 0 absorb 1"]
        );
        assert_eq!(env.notes.len(), 1);
    }

    #[test]
    fn shadow_pyramids_keep_their_weight_fading_and_depth() {
        let files = object(&[
            ("a.e", "executable: shadowpyramid -e a.e sp.spec\n"),
            ("sp.spec", "grid size: 100\ngrid span: 50\nshadow weight: 0.5\nshadow dissipation: 3\nshadow depth: 4\nshadow spread: 2\n"),
        ]);
        let env = read("a.e", &Files::new(&files)).unwrap();
        assert_eq!(
            env.lines,
            ["#environment light sky 1 cell 0.5 shadow 0.5 spread 3 depth 4"]
        );
        assert!(env.notes[0].contains("slope 2"), "{:?}", env.notes);
    }

    #[test]
    fn a_program_meristem_lacks_is_named_and_a_missing_spec_said() {
        let files = object(&[("x.e", "executable: ./soil -e x.e soil.spec\n")]);
        let env = read("x.e", &Files::new(&files)).unwrap();
        assert!(env.lines.is_empty());
        assert!(env.notes[0].contains("soil.spec is not in the object"));
        assert!(env.notes[1].contains("program soil, which Meristem does not have"));
        assert!(read("none.e", &Files::new(&files)).is_none());
    }

    #[test]
    fn honda81_is_collision_in_its_plane_or_in_space() {
        let files = object(&[
            ("f.e", "executable: honda81 density.spec\n"),
            ("density.spec", "verbose: off\nradius:  0.01\n3d case: on\n"),
            ("g.e", "executable: honda81 -e g.e flat.spec\n"),
            ("flat.spec", "radius: 2\n"),
        ]);
        let env = read("f.e", &Files::new(&files)).unwrap();
        assert_eq!(env.lines, ["#environment collision radius 0.01"]);
        assert!(env.notes.is_empty(), "{:?}", env.notes);
        let env = read("g.e", &Files::new(&files)).unwrap();
        assert_eq!(env.lines, ["#environment collision radius 2 flat 1"]);
    }

    #[test]
    fn ecosystem_is_honda_with_circles_and_stays_inert() {
        let files = object(&[
            ("tree.e", "executable: ecosystem -e tree.e density.spec\n"),
            (
                "density.spec",
                "grid size: 100 100 100\n3D case: one\nvigor: off\n",
            ),
        ]);
        let env = read("tree.e", &Files::new(&files)).unwrap();
        assert!(env.lines.is_empty());
        assert_eq!(env.notes.len(), 1);
        assert!(env.notes[0].contains("as wide as its first parameter"));
    }
}

use crate::diagnostics::Severity;
use crate::vocabulary::{DirectiveKind, ParamKind, DIRECTIVES};

/// Arguments that a directive accepts, made from its table row: its enable arguments when it has
/// them, else a value of each parameter's kind within its range.
fn valid_arguments(kind: DirectiveKind) -> String {
    let info = kind.info();
    if !info.enable.is_empty() {
        return info.enable.join(" ");
    }
    let form = info.forms[0];
    form.iter()
        .map(|p| match p.kind {
            ParamKind::Name => "k".to_string(),
            ParamKind::Expression => "uniform(0, 1)".to_string(),
            ParamKind::Modules => "A".to_string(),
            ParamKind::Points if kind == DirectiveKind::Patch => vec!["0 0 0"; 16].join(", "),
            ParamKind::Points => "0 0 0.3 0.2 0.6 0.9 1 1".to_string(),
            ParamKind::Season => p.choices[0].to_string(),
            ParamKind::Ages => "A 2 B 1".to_string(),
            ParamKind::Surface => "petal precision 6 6".to_string(),
            ParamKind::Words if kind == DirectiveKind::Stand => "row 3 spacing 2".to_string(),
            ParamKind::Words => "obstacle sphere center 0 1 0 radius 1".to_string(),
            _ => {
                let v = p
                    .default_value(|_| 1.0)
                    .or(p.range.map(|r| r.0))
                    .unwrap_or(1.0);
                format!("{v}")
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn the_resolver_accepts_every_directive_of_the_table() {
    for d in DIRECTIVES {
        let text = format!("#{} {}\naxiom: F", d.name, valid_arguments(d.kind));
        let (file, _) = crate::syntax::parse(&text);
        let (_, diagnostics) = crate::model::resolve(&file);
        assert!(
            diagnostics.iter().all(|x| x.severity != Severity::Error),
            "{text}: {diagnostics:?}"
        );
    }
}

#[test]
fn the_resolver_rejects_a_name_outside_the_table() {
    let (file, _) = crate::syntax::parse("#colours 3\naxiom: F");
    let (_, diagnostics) = crate::model::resolve(&file);
    assert!(diagnostics.iter().any(|x| x.code == "E0200"));
}

#[test]
fn settings_default_to_the_table() {
    let (file, _) = crate::syntax::parse("axiom: F");
    let model = crate::model::resolve(&file).0.expect("model");
    assert_eq!(model.settings.angle, 90.0);
    assert_eq!(model.settings.max_modules, 5_000_000);
    assert_eq!(model.productions.max_depth, 1);
    assert_eq!(model.homomorphism.max_depth, 16);
}

#[test]
fn a_growth_directive_without_its_optional_arguments_takes_the_table_defaults() {
    let (file, _) = crate::syntax::parse("#lifetime 34 32\n#shape_width\naxiom: F");
    let model = crate::model::resolve(&file).0.expect("model");
    let lifetime = model.growth.lifetime.expect("lifetime");
    assert_eq!(lifetime.probabilities, [0.6, 0.3, 0.1]);
    assert_eq!(
        model.growth.shape_width.expect("width").positional,
        [2.0, 1.0, 0.0]
    );
}

#[test]
fn a_wrong_number_of_arguments_names_the_forms() {
    let (file, _) = crate::syntax::parse("#lifetime 34\naxiom: F");
    let (_, diagnostics) = crate::model::resolve(&file);
    let message = &diagnostics[0].message;
    assert!(
        message.starts_with("#lifetime needs 'MB VB' or 'MB VB pu pm pl' ("),
        "{message}"
    );
    assert!(message.ends_with("found 1 values"), "{message}");
}

#[test]
fn a_directive_set_three_times_names_the_line_just_before_each_repeat() {
    let text = "#angle 10\n#angle 20\n#angle 30\naxiom: F";
    let (file, _) = crate::syntax::parse(text);
    let (_, diagnostics) = super::resolve(&file);
    let messages: Vec<&str> = diagnostics.iter().map(|d| d.message.as_str()).collect();
    assert_eq!(
        messages,
        [
            "#angle is set twice; this one replaces the value on line 1",
            "#angle is set twice; this one replaces the value on line 2",
        ]
    );
}

//! A problem given as text (`problem::Source::Text`, what `phong serve` receives) is solved and
//! checked exactly as the same problem read from its file, and may not make phong read a file.

use std::path::Path;

use phong::check::{check_source, CheckOptions, Scale};
use phong::core::Precision;
use phong::problem::{ProblemError, Source};
use phong::report::file::{solve_json, solve_json_source};

fn text_of(path: &str) -> String {
    std::fs::read_to_string(path).expect("the exercise is bundled")
}

#[test]
fn text_solves_as_its_file_does() {
    for name in [
        "exercises/4.1.json",
        "exercises/4.2.json",
        "exercises/4.3.json",
    ] {
        let path = Path::new(name);
        let text = text_of(name);
        let from_file = solve_json(path, Precision::F64).expect("the exercise solves");
        let from_text = solve_json_source(
            Source::Text {
                name: path,
                text: &text,
            },
            Precision::F64,
        )
        .expect("the exercise solves");
        assert_eq!(from_file, from_text, "{name}");
    }
}

#[test]
fn text_is_checked_as_its_file_is() {
    // point here; any answer gives the same verdict from the file and from its text.
    let options = CheckOptions {
        answer: Some("0.245 0.28 0.21".into()),
        scale: Some(Scale::Unit),
        ..Default::default()
    };
    let path = Path::new("exercises/4.2.json");
    let text = text_of("exercises/4.2.json");
    let a = phong::check::check_file(path, &options);
    let b = check_source(
        Source::Text {
            name: path,
            text: &text,
        },
        &options,
    );
    assert_eq!(
        serde_json::to_value(phong::check::report::json(&a)).unwrap(),
        serde_json::to_value(phong::check::report::json(&b)).unwrap()
    );
}

#[test]
fn text_that_names_a_mesh_is_refused_without_reading_it() {
    // scenes/mesh.json names scenes/torus.obj, which exists beside it: from its file it loads;
    // as text it is refused, so a request cannot make phong read any path.
    let path = Path::new("scenes/mesh.json");
    assert!(phong::problem::load::<f64>(path).is_ok());
    let text = text_of("scenes/mesh.json");
    let e = Source::Text {
        name: Path::new("request"),
        text: &text,
    }
    .load::<f64>()
    .expect_err("a mesh in text is refused");
    match &e {
        ProblemError::Invalid { field, .. } => {
            assert!(
                field.starts_with("surfaces[") && field.ends_with("].file"),
                "{field}"
            );
            let message = e.message();
            assert!(message.contains("cannot name a mesh file"), "{message}");
        }
        other => panic!("expected an invalid field, got {other:?}"),
    }
    assert!(e.to_string().starts_with("request: "), "{e}");
}

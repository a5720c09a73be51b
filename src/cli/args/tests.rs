//! The command line's definition checked: clap's own consistency, and numeric flags fuzzed.

use super::*;
use clap::CommandFactory;

#[test]
fn the_command_line_definition_is_consistent() {
    Cli::command().debug_assert();
}

#[test]
fn numeric_flags_are_parsed_or_refused_never_a_panic() {
    // Moved from tests/fuzz.rs: the argument types are the crate's own (the binary's edge).
    use clap::Parser;
    use proptest::prelude::*;
    use proptest::sample::select;
    use proptest::test_runner::{Config, RngSeed, TestRunner};
    let value = prop_oneof![
        Just("0".to_owned()),
        Just("1".to_owned()),
        Just("4096".to_owned()),
        Just("4097".to_owned()),
        Just("1000".to_owned()),
        Just("1001".to_owned()),
        Just("4294967295".to_owned()),
        Just("4294967296".to_owned()),
        Just("18446744073709551616".to_owned()),
        Just("-1".to_owned()),
        Just("1e400".to_owned()),
        Just("1/255".to_owned()),
        Just("nan".to_owned()),
        Just("\u{2212}1".to_owned()),
        Just("64x48".to_owned()),
        Just("16384x16384".to_owned()),
        "[0-9x,./e\\-]{0,12}",
    ];
    let flag = select(vec![
        ("render", "--max-level"),
        ("render", "--samples"),
        ("render", "--threads"),
        ("render", "--min-weight"),
        ("render", "--explain-pixel"),
        ("tradeoff", "--runs"),
        ("tradeoff", "--levels"),
        ("tradeoff", "--samples"),
        ("tradeoff", "--reference-level"),
        ("tradeoff", "--reference-samples"),
        ("tradeoff", "--threads"),
        ("tradeoff", "--size"),
        ("tradeoff", "--budget"),
        ("tradeoff", "--min-weights"),
        ("check", "--tolerance"),
        ("grade", "--tolerance"),
        ("new", "--count"),
    ]);
    TestRunner::new(Config {
        cases: 400,
        rng_seed: RngSeed::Fixed(43),
        failure_persistence: None,
        ..Config::default()
    })
    .run(&(flag, value), |((command, flag), value)| {
        let mut args = vec!["phong", command, "x.json"];
        match command {
            "render" => args.extend(["-o", "x.png"]),
            "grade" => args.extend(["--exercises", "."]),
            "new" => args = vec!["phong", "new", "--kind", "point"],
            _ => {}
        }
        args.push(flag);
        args.push(&value);
        if let Ok(Cli { command, .. }) = Cli::try_parse_from(&args) {
            // What clap accepts is within the documented ranges.
            if let Command::Render(r) = &command {
                prop_assert!(r.settings.max_level.is_none_or(|l| (1..=1000).contains(&l)));
                prop_assert!(r.settings.samples.is_none_or(|n| (1..=4096).contains(&n)));
                prop_assert!(r.threads.is_none_or(|n| (1..=1024).contains(&n)));
                prop_assert!(r.settings.min_weight.is_none_or(f64::is_finite));
            }
            if let Command::Tradeoff(t) = &command {
                prop_assert!((1..=1000).contains(&t.runs));
                prop_assert!(t.levels.iter().all(|l| (1..=1000).contains(l)));
                prop_assert!(t.budget.is_finite());
            }
            if let Command::Check(c) = &command {
                prop_assert!(c.tolerance.is_none_or(f64::is_finite));
            }
        }
        Ok(())
    })
    .unwrap_or_else(|e| panic!("{e}"));
}

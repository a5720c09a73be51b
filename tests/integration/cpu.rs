//! A phong built for a newer CPU, run on an older one, refuses with a clear error instead of
//! crashing (src/cli/cpu.rs; `.cargo/config.toml` builds for the building machine's CPU). The
//! older CPU is QEMU's user-mode emulation of a 2010 Intel Westmere (SSE4.2, no AVX, AVX2, FMA,
//! BMI or MOVBE): QEMU answers CPUID as that CPU and raises an illegal instruction at the first
//! AVX one, as the CPU would.

use crate::support::{require, sh};

/// QEMU's older CPU, and the features of this build it lacks (those `target-cpu=native` turns
/// on for an AVX2 machine and a Westmere does not have).
const OLD_CPU: &str = "Westmere";
const WESTMERE_LACKS: [(&str, bool); 8] = [
    ("movbe", cfg!(target_feature = "movbe")),
    ("lzcnt", cfg!(target_feature = "lzcnt")),
    ("avx", cfg!(target_feature = "avx")),
    ("f16c", cfg!(target_feature = "f16c")),
    ("fma", cfg!(target_feature = "fma")),
    ("avx2", cfg!(target_feature = "avx2")),
    ("bmi1", cfg!(target_feature = "bmi1")),
    ("bmi2", cfg!(target_feature = "bmi2")),
];

/// `phong ARGS` under `qemu-x86_64 -cpu CPU`: (exit code or None for a signal, stdout, stderr).
fn under_qemu(cpu: &str, args: &str) -> (Option<i32>, String, String) {
    let qemu = require("qemu-x86_64", "apt-get install qemu-user").unwrap();
    let out = sh()
        .arg("-c")
        .arg(format!("exec \"$QEMU\" -cpu {cpu} \"$PHONG\" {args}"))
        .env("QEMU", qemu)
        .env("PHONG", crate::support::phong_path())
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
#[ignore = "needs qemu-x86_64: apt-get install qemu-user"]
fn a_build_for_a_newer_cpu_refuses_an_older_one_with_the_fix_in_both_languages() {
    let lacks: Vec<&str> = (WESTMERE_LACKS.iter())
        .filter(|(_, built)| *built)
        .map(|(name, _)| *name)
        .collect();
    let (code, stdout, stderr) = under_qemu(OLD_CPU, "solve exercises/4.1.json");
    if lacks.is_empty() {
        // A build for any x86-64 CPU (RUSTFLAGS="-C target-cpu=x86-64") runs there.
        assert_eq!(code, Some(0), "{stderr}");
        assert!(stdout.contains("4.1"), "{stdout}");
        return;
    }
    // Not a signal (an illegal instruction: no exit code), not a panic: exit 2 and the error.
    assert_eq!(code, Some(2), "stderr: {stderr}");
    assert!(stdout.is_empty(), "{stdout}");
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 2, "{stderr}");
    assert!(lines[0].starts_with("error: this phong was built for a CPU with "));
    assert!(lines[1].starts_with("erro: esta phong foi compilada para um processador com "));
    for line in &lines {
        for name in &lacks {
            // Each missing feature named, as a word of the list (not "avx" inside "avx2").
            let list = line
                .split(" com ")
                .nth(1)
                .or(line.split(" with ").nth(1))
                .unwrap();
            let list = list.split([',', ' ']).collect::<Vec<_>>();
            assert!(list.contains(name), "{name} not named in: {line}");
        }
        assert!(line.contains("cargo install --path ."), "{line}");
        assert!(
            line.contains("RUSTFLAGS=\"-C target-cpu=x86-64\""),
            "{line}"
        );
    }
}

#[test]
#[ignore = "needs qemu-x86_64: apt-get install qemu-user"]
fn a_cpu_with_every_feature_of_the_build_runs_it() {
    // QEMU's "max" CPU has every feature QEMU emulates (AVX2, FMA, BMI among them since 7.2):
    // the check lets it through and the exercise is solved as on the machine itself.
    let (code, stdout, stderr) = under_qemu("max", "solve exercises/4.1.json");
    // QEMU 7.2 emulates neither AVX-512 nor GFNI: a build for a CPU with them is refused
    // there, for those alone.
    let unemulated: Vec<&str> = [
        ("avx512f", cfg!(target_feature = "avx512f")),
        ("gfni", cfg!(target_feature = "gfni")),
    ]
    .iter()
    .filter(|(_, built)| *built)
    .map(|(name, _)| *name)
    .collect();
    if !unemulated.is_empty() {
        assert_eq!(code, Some(2), "stderr: {stderr}");
        let first = stderr.lines().next().unwrap_or("");
        assert!(!first.contains("avx2,"), "{first}");
        for name in unemulated {
            assert!(first.contains(name), "{name} not named in {first}");
        }
        return;
    }
    assert_eq!(code, Some(0), "stderr: {stderr}");
    let native = crate::support::phong()
        .args(["solve", "exercises/4.1.json"])
        .output()
        .unwrap();
    assert_eq!(stdout, String::from_utf8_lossy(&native.stdout));
}

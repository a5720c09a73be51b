//! `.ci/run`, the CI script, read as text: what it must do that no build would catch.

/// Every `apt-get` call waits for apt's lock (`-o DPkg::Lock::Timeout=600`), `update` included,
/// instead of failing at once ("Could not get lock", exit 100) when another apt runs on the
/// machine (issue 30, item 9).
#[test]
fn every_apt_get_call_waits_for_the_lock() {
    let script = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/.ci/run"))
        .expect(".ci/run is in the repository");
    let calls: Vec<&str> = script
        .lines()
        .map(str::trim_start)
        .filter(|l| !l.starts_with('#') && !l.starts_with("echo"))
        .filter(|l| l.starts_with("apt-get ") || l.contains(" apt-get "))
        .filter(|l| !l.contains("command -v apt-get"))
        .collect();
    // `apt-get update` and `apt-get install`.
    assert!(calls.len() >= 2, "the apt-get calls of .ci/run: {calls:?}");
    for call in &calls {
        assert!(
            call.contains("apt-get -o DPkg::Lock::Timeout=600 "),
            "this apt-get call does not wait for apt's lock: {call}"
        );
    }
    assert!(
        calls.iter().any(|c| c.contains(" update")),
        "no apt-get update: {calls:?}"
    );
}

//! The HTML explanation in a real browser: Debian's `chromium`, headless, loads the page from a
//! file (no network), and
//! - the DOM after rendering holds each light's diagram with N, L, R, V, the light and the
//!   viewer, labelled in the page's language;
//! - a screenshot is not blank: it shows the final colour's swatch and the light's marker in
//!   their exact colours;
//! - no label of a diagram overlaps another label or crosses a line, measured by the browser
//!   (`getBBox`) after layout; a spot's cone, θ and φ, and a ray problem's ray, origin and t
//!   are drawn.
//!
//! `.ci/run` installs chromium. Under `CI=true` a missing chromium is a failure; elsewhere the
//! test says it was skipped and why.

use crate::support;
use crate::support::screenshot;
use screenshot::pixels_of;

use std::path::{Path, PathBuf};
use std::time::Duration;

use assert_cmd::Command;

const INSTALL: &str = "apt-get install -y --no-install-recommends chromium";

/// Writes `phong solve FILE --format html --lang LANG` into `dir` and returns the page's path.
fn page(dir: &Path, exercise: &str, lang: &str) -> PathBuf {
    let path = dir.join(format!("{exercise}-{lang}.html"));
    let run = support::phong()
        .args(["solve", &format!("exercises/{exercise}.json")])
        .args(["--format", "html", "--lang", lang, "-o"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    path
}

/// Runs headless chromium with a fresh profile and no network services.
fn chromium(browser: &Path, profile: &Path, args: &[&str], url: &Path) -> std::process::Output {
    let out = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(args)
        .arg(format!("file://{}", url.display()))
        .timeout(Duration::from_secs(120))
        .output()
        .expect("chromium runs");
    assert!(
        out.status.success(),
        "chromium failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

#[test]
#[ignore = "needs chromium: apt-get install chromium fonts-dejavu-core (.ci/run does)"]
fn the_rendered_page_holds_the_diagram_of_each_light_with_its_labels() {
    let Some(browser) = support::require("chromium", INSTALL) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let profile = tempfile::tempdir().unwrap();
    // Vectors drawn along one another (within 6°) share one label (issue 29): 4.2's V is
    // drawn projected along N; several-lights' first light has V = −R (cos φ = 1).
    for (exercise, lang, labels) in [
        (
            "4.2",
            "en",
            [
                ("N-label", "N, V"),
                ("L-label", "L"),
                ("R-label", "R"),
                ("light-label", "light"),
                ("viewer-label", "viewer"),
            ],
        ),
        (
            "several-lights",
            "pt",
            [
                ("N-label", "N"),
                ("L-label", "L"),
                ("R-label", "R, V"),
                ("light-label", "fonte de luz"),
                ("viewer-label", "observador"),
            ],
        ),
    ] {
        let html = page(dir.path(), exercise, lang);
        let dom = chromium(&browser, profile.path(), &["--dump-dom"], &html);
        let dom = String::from_utf8(dom.stdout).unwrap();
        assert!(
            dom.contains("<svg id=\"diagram-0-0-light"),
            "{exercise}: no diagram"
        );
        // The first light of the solution as written.
        let first = if exercise == "4.2" { 0 } else { 1 };
        let id = format!("diagram-0-0-light{first}");
        for part in ["N", "L", "R", "V", "light", "viewer", "surface"] {
            assert!(
                dom.contains(&format!("id=\"{id}-{part}\"")),
                "{exercise}: no element {id}-{part} in the rendered DOM"
            );
        }
        for (part, text) in labels {
            let tag = format!("id=\"{id}-{part}\"");
            let at = dom
                .find(&tag)
                .unwrap_or_else(|| panic!("{exercise}: no {tag}"));
            let rest = &dom[at..];
            let content = &rest[rest.find('>').unwrap() + 1..rest.find("</text>").unwrap()];
            assert_eq!(content, text, "{exercise}: label {part}");
        }
    }
    // several-lights: one diagram per light with a direction at the point (lights[1]–[4]).
    let html = page(dir.path(), "several-lights", "en");
    let dom = String::from_utf8(chromium(&browser, profile.path(), &["--dump-dom"], &html).stdout)
        .unwrap();
    for light in 1..=4 {
        assert!(dom.contains(&format!("<svg id=\"diagram-0-0-light{light}\"")));
    }
}

#[test]
#[ignore = "needs chromium: apt-get install chromium fonts-dejavu-core (.ci/run does)"]
fn a_screenshot_shows_the_colour_swatch_and_the_diagram() {
    let Some(browser) = support::require("chromium", INSTALL) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let profile = tempfile::tempdir().unwrap();
    let shot = |exercise: &str| {
        let html = page(dir.path(), exercise, "en");
        let png = dir.path().join(format!("{exercise}.png"));
        chromium(
            &browser,
            profile.path(),
            &[
                "--window-size=900,1100",
                &format!("--screenshot={}", png.display()),
            ],
            &html,
        );
        png
    };
    // 4.1: the colour (0.5, 0.7, 0.3) is (128, 179, 77) in 8 bits (0.7·255 = 178.5 rounds up
    // in f64); the large swatch is 4rem square, at least 60×60 pixels.
    let png_bytes = std::fs::read(shot("4.1")).expect("the screenshot is written");
    let (white, total) = pixels_of(&png_bytes, [255, 255, 255]);
    assert!(white < total * 97 / 100, "the screenshot is blank");
    let (swatch, _) = pixels_of(&png_bytes, [128, 179, 77]);
    assert!(
        swatch >= 60 * 60,
        "only {swatch} pixels of the colour swatch"
    );
    // 4.2: the diagram is drawn: the light's marker is filled with #ffd633.
    let png_bytes = std::fs::read(shot("4.2")).expect("the screenshot is written");
    let (marker, _) = pixels_of(&png_bytes, [0xff, 0xd6, 0x33]);
    assert!(marker >= 100, "only {marker} pixels of the light's marker");
}

/// A script that measures, in the rendered page, every diagram's label boxes (`getBBox`) and
/// writes into `<pre id="overlaps">` each pair of labels whose boxes intersect and each label
/// whose box a vector's or the surface's line crosses (boxes shrunk by 1 px, for antialiasing).
const OVERLAPS: &str = r#"<script>
window.addEventListener('load', () => {
  const out = [];
  const meets = (b, x1, y1, x2, y2) => {
    let t0 = 0, t1 = 1;
    const dx = x2 - x1, dy = y2 - y1;
    for (const [p, q] of [[-dx, x1 - b.x0], [dx, b.x1 - x1], [-dy, y1 - b.y0], [dy, b.y1 - y1]]) {
      if (p === 0) { if (q < 0) return false; }
      else { const r = q / p; if (p < 0) t0 = Math.max(t0, r); else t1 = Math.min(t1, r); }
    }
    return t0 <= t1;
  };
  let labels = 0;
  for (const svg of document.querySelectorAll('svg.diagram')) {
    const boxes = [...svg.querySelectorAll('text')].map(t => {
      const b = t.getBBox();
      return { id: t.id, x0: b.x + 1, y0: b.y + 1, x1: b.x + b.width - 1, y1: b.y + b.height - 1 };
    });
    labels += boxes.length;
    for (let i = 0; i < boxes.length; i++) {
      for (let j = i + 1; j < boxes.length; j++) {
        const a = boxes[i], b = boxes[j];
        if (a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1) out.push(a.id + ' overlaps ' + b.id);
      }
    }
    for (const l of svg.querySelectorAll('line')) {
      const c = ['x1', 'y1', 'x2', 'y2'].map(k => parseFloat(l.getAttribute(k)));
      for (const b of boxes) if (meets(b, ...c)) out.push(l.id + ' crosses ' + b.id);
    }
  }
  const pre = document.createElement('pre');
  pre.id = 'overlaps';
  pre.textContent = 'labels ' + labels + '\n' + out.join('\n');
  document.body.appendChild(pre);
});
</script>"#;

#[test]
#[ignore = "needs chromium: apt-get install chromium fonts-dejavu-core (.ci/run does)"]
fn no_label_of_a_diagram_overlaps_another_or_a_line() {
    let Some(browser) = support::require("chromium", INSTALL) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let profile = tempfile::tempdir().unwrap();
    let mut problems = Vec::new();
    for exercise in [
        "4.2",
        "4.3",
        "several-lights",
        "spot-edge",
        "spot-inside",
        "sphere-hit",
    ] {
        for lang in ["en", "pt"] {
            let html = page(dir.path(), exercise, lang);
            let text = std::fs::read_to_string(&html).unwrap();
            std::fs::write(
                &html,
                text.replace("</body>", &format!("{OVERLAPS}</body>")),
            )
            .unwrap();
            let dom = chromium(&browser, profile.path(), &["--dump-dom"], &html);
            let dom = String::from_utf8(dom.stdout).unwrap();
            let at = dom
                .find("<pre id=\"overlaps\">")
                .unwrap_or_else(|| panic!("{exercise} ({lang}): the script did not run"));
            let report = &dom[at + 19..];
            let report = &report[..report.find("</pre>").unwrap()];
            let mut lines = report.lines();
            let count: usize = lines
                .next()
                .and_then(|l| l.strip_prefix("labels "))
                .and_then(|n| n.parse().ok())
                .unwrap();
            assert!(count > 0, "{exercise} ({lang}): no labels measured");
            problems.extend(lines.map(|l| format!("{exercise} ({lang}): {l}")));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn a_spot_draws_its_cone_and_a_ray_problem_its_ray_origin_and_t() {
    let dir = tempfile::tempdir().unwrap();
    let spot = std::fs::read_to_string(page(dir.path(), "spot-inside", "en")).unwrap();
    assert!(spot.contains("-cone\" class=\"cone\""), "no cone drawn");
    for angle in ["theta-label", "phi-label"] {
        assert!(spot.contains(angle), "no {angle}");
    }
    // 4.3: the line's point, behind the ray's origin, with the ray, its origin and t = −90.
    let ray = std::fs::read_to_string(page(dir.path(), "4.3", "pt")).unwrap();
    for part in [
        "-ray\"",
        "-line\"",
        "-origin\"",
        "-origin-label",
        "-t-label",
    ] {
        assert!(ray.contains(part), "4.3: no {part}");
    }
    assert!(ray.contains(">t = −90<"), "4.3: t is not labelled");
    assert!(ray.contains(">origem O do raio<"));
}

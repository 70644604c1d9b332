//! `vbi regress` end to end through the binary (issue 30): approve then
//! check passes; a 0.1 % stiffness change fails naming the quantity; a
//! 1e-13 relative change passes; a study's table change is caught; a scene
//! edit is reported as such; the JUnit XML has the structure CI tools read;
//! the example CI workflow's command lines run as written.

use crate::support;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use support::{Scratch, assert_exit, manifest_dir, text, vbi};

/// A shipped scene copied into the scratch folder.
fn copy_scene(dir: &Scratch, name: &str) -> PathBuf {
    let src = std::fs::read_to_string(manifest_dir().join("scenarios").join(name))
        .expect("read scenario");
    let path = dir.path(name);
    std::fs::write(&path, src).expect("write scenario");
    path
}

/// `vbi regress ACTION SCENES… --store STORE EXTRA…` in `cwd`.
fn regress<S: AsRef<Path>>(
    action: &str,
    scenes: &[S],
    store: &Path,
    extra: &[&str],
    cwd: &Path,
) -> Output {
    let mut args: Vec<std::ffi::OsString> = vec!["regress".into(), action.into()];
    args.extend(scenes.iter().map(|s| s.as_ref().as_os_str().to_owned()));
    args.push("--store".into());
    args.push(store.as_os_str().to_owned());
    args.extend(extra.iter().map(std::ffi::OsString::from));
    vbi(&args, cwd)
}

/// Replaces the one occurrence of `from` in the scene file by `to`.
fn edit(scene: &Path, from: &str, to: &str) {
    let text = std::fs::read_to_string(scene).expect("read scene");
    assert_eq!(
        text.matches(from).count(),
        1,
        "`{from}` once in {}",
        scene.display()
    );
    std::fs::write(scene, text.replace(from, to)).expect("write scene");
}

/// The moving-force scene (a 100 kN force at α = 0.1 over the Yang & Yau
/// beam, 77 325 steps, about 0.1 s) and a 2 ms time step variant.
const SLOW: &str = "moving-force-slow.yaml";

/// The report line of `quantity` (`quantity: old → new (…)`).
fn report_line<'a>(report: &'a str, quantity: &str) -> Option<&'a str> {
    report
        .lines()
        .map(str::trim)
        .find(|l| l.starts_with(&format!("{quantity}: ")))
}

/// The old and new value of a report line (`quantity: old → new …`).
fn old_new(line: &str) -> (f64, f64) {
    let values = line.split_once(": ").expect("quantity: values").1;
    let (old, rest) = values.split_once(" → ").expect("old → new");
    let new = rest.split(' ').next().expect("new value");
    (
        old.parse().expect("old number"),
        new.parse().expect("new number"),
    )
}

/// The relative change a report line gives (`(+1.000e-3 of its peak)`).
fn relative_of(line: &str) -> f64 {
    let start = line.find('(').expect("a relative change") + 1;
    let end = line[start..].find(" of its peak").expect("of its peak") + start;
    line[start..end].parse().expect("a number")
}

#[test]
fn approve_then_check_passes() {
    let dir = Scratch::new("regress", "approve_then_check");
    let scene = copy_scene(&dir, SLOW);
    let store = dir.path("golden");
    let out = regress("approve", &[&scene], &store, &[], dir.dir());
    assert_exit(&out, 0);
    assert!(text(&out.stdout).contains("moving-force-slow (new record)"));
    let record = std::fs::read_to_string(store.join("moving-force-slow/record.tsv"))
        .expect("record written");
    for part in [
        "scene_hash\tfnv1a64:",
        "[scalars]",
        "[table history]",
        "quantities.midspan.min.value\t",
    ] {
        assert!(record.contains(part), "record lacks {part}:\n{record}");
    }
    assert!(store.join("moving-force-slow/resolved.yaml").is_file());
    let out = regress("check", &[&scene], &store, &[], dir.dir());
    assert_exit(&out, 0);
    let report = text(&out.stdout);
    assert!(report.contains("PASS  moving-force-slow"), "{report}");
    assert!(
        report.contains("1 scene: 1 passed, 0 changed, 0 could not run"),
        "{report}"
    );
    // Approving again without a change leaves the record as it was.
    let out = regress("approve", &[&scene], &store, &[], dir.dir());
    assert_exit(&out, 0);
    assert!(
        text(&out.stdout).contains("(record unchanged)"),
        "{}",
        text(&out.stdout)
    );
}

/// A 0.1 % stiffer beam: the slow crossing is quasi-static, so the midspan
/// deflection scales as 1/EI (Euler–Bernoulli, static deflection under a
/// point load P L³ / (48 EI)): its extreme moves by −0.1 % of its peak,
/// far beyond the default 1e-5, and the report names it with that change.
#[test]
fn stiffness_change_of_a_tenth_percent_fails_naming_the_quantity() {
    let dir = Scratch::new("regress", "stiffness");
    let scene = copy_scene(&dir, SLOW);
    let store = dir.path("golden");
    assert_exit(&regress("approve", &[&scene], &store, &[], dir.dir()), 0);
    edit(
        &scene,
        "bending_stiffness: 8.323e9",
        "bending_stiffness: 8.331323e9",
    );
    let plots = dir.path("plots");
    let out = regress(
        "check",
        &[&scene],
        &store,
        &["--out", plots.to_str().expect("utf-8 path")],
        dir.dir(),
    );
    assert_exit(&out, 1);
    let report = text(&out.stdout);
    assert!(
        report.contains("FAIL  moving-force-slow: the scene changed"),
        "{report}"
    );
    assert!(report.contains("results changed"), "{report}");
    // The resolved diff shows the stiffness line, old and new.
    assert!(
        report.contains("- ") && report.contains("8323000000"),
        "{report}"
    );
    assert!(report.contains("8331323000"), "{report}");
    // The cause first (issue 40.7): right under the FAIL line the resolved
    // diff, its stiffness lines before the first of the quantities.
    let lines: Vec<&str> = report.lines().map(str::trim).collect();
    let fail = lines
        .iter()
        .position(|l| l.starts_with("FAIL  moving-force-slow"))
        .expect("FAIL line");
    assert_eq!(
        lines[fail + 1],
        "resolved scene, approved (-) against now (+):",
        "{report}"
    );
    let at = |what: &str| lines.iter().position(|l| l.contains(what));
    let (old_line, new_line) = (at("8323000000"), at("8331323000"));
    let first_quantity = at("quantities.").expect("a quantity line");
    assert!(
        old_line.is_some_and(|o| o < first_quantity)
            && new_line.is_some_and(|n| n < first_quantity),
        "the resolved diff comes after the quantities:\n{report}"
    );
    // The deflection extreme (negative, downward) shrinks by 1 − 1/1.001 =
    // 9.99e-4 of its peak, so new − old is positive; the dynamic share (DAF
    // 1.068 at α = 0.1) moves a little with the 0.05 % higher frequency.
    let line = report_line(&report, "quantities.midspan.min.value")
        .unwrap_or_else(|| panic!("midspan minimum not named:\n{report}"));
    let relative = relative_of(line);
    assert!(
        (8.0e-4..1.1e-3).contains(&relative),
        "midspan min moved by {relative:e}, expected about +9.99e-4: {line}"
    );
    assert!(line.contains(" at t = "), "{line}");
    // Its static share is exactly ∝ 1/EI: new / old = 1/1.001 to the 7
    // digits the report shows (measured 4e-8).
    let line = report_line(&report, "quantities.midspan.static_largest_magnitude.value")
        .unwrap_or_else(|| panic!("static deflection not named:\n{report}"));
    let (old, new) = old_new(line);
    assert!(
        (new / old - 1.0 / 1.001).abs() < 1e-6,
        "static deflection ratio {} against 1/1.001: {line}",
        new / old
    );
    // A plot of old against new for the changed history column.
    let plot = plots
        .join("moving-force-slow")
        .join("history-midspan_min_m.png");
    assert!(plot.is_file(), "no plot {}:\n{report}", plot.display());
    assert!(report.contains("plot: "), "{report}");
}

/// A 1e-13 relative change of the stiffness: the scene is the same to the
/// 12 digits the store compares, the results move at round-off level
/// (about 1e-13 relative), and the check passes.
#[test]
fn change_of_1e_13_relative_passes() {
    let dir = Scratch::new("regress", "tiny");
    let scene = copy_scene(&dir, SLOW);
    let store = dir.path("golden");
    assert_exit(&regress("approve", &[&scene], &store, &[], dir.dir()), 0);
    edit(
        &scene,
        "bending_stiffness: 8.323e9",
        "bending_stiffness: 8.3230000000008323e9",
    );
    let out = regress("check", &[&scene], &store, &[], dir.dir());
    assert_exit(&out, 0);
    assert!(text(&out.stdout).contains("PASS  moving-force-slow"));
}

/// A scene edit that does not move the results (its name) is reported as
/// a change of the scene, with the resolved diff, and results within
/// tolerance.
#[test]
fn scene_edit_is_reported_as_such() {
    let dir = Scratch::new("regress", "scene_edit");
    let scene = copy_scene(&dir, SLOW);
    let store = dir.path("golden");
    assert_exit(&regress("approve", &[&scene], &store, &[], dir.dir()), 0);
    edit(
        &scene,
        "name: moving-force-slow",
        "name: moving-force-slow-renamed",
    );
    let out = regress("check", &[&scene], &store, &[], dir.dir());
    assert_exit(&out, 1);
    let report = text(&out.stdout);
    assert!(
        report.contains("FAIL  moving-force-slow: the scene changed (its resolved diff first), results within tolerance"),
        "{report}"
    );
    let diff_line = |tag: &str, name: &str| {
        report.lines().map(str::trim).any(|l| {
            l.starts_with(&format!("{tag} name: ")) && l.trim_end_matches('"').ends_with(name)
        })
    };
    assert!(diff_line("-", "moving-force-slow"), "{report}");
    assert!(diff_line("+", "moving-force-slow-renamed"), "{report}");
}

/// The per-scene and per-quantity tolerances of `regress.yaml`: the
/// 0.1 % stiffness change passes with 1 % on the scene's displacement
/// and acceleration records, its frequencies and the time of the run.
#[test]
fn tolerances_from_the_store_file() {
    let dir = Scratch::new("regress", "tolerances");
    let scene = copy_scene(&dir, SLOW);
    let store = dir.path("golden");
    assert_exit(&regress("approve", &[&scene], &store, &[], dir.dir()), 0);
    std::fs::write(
        store.join("regress.yaml"),
        "scenes:\n  moving-force-slow:\n    relative: 1.0e-2\n",
    )
    .expect("write settings");
    edit(
        &scene,
        "bending_stiffness: 8.323e9",
        "bending_stiffness: 8.331323e9",
    );
    let out = regress("check", &[&scene], &store, &[], dir.dir());
    assert_exit(&out, 1);
    let report = text(&out.stdout);
    assert!(report.contains("results within tolerance"), "{report}");
    // A bad key is refused with its place.
    std::fs::write(
        store.join("regress.yaml"),
        "relative: 1.0e-5\nscenes:\n  a: {relativ: 1}\n",
    )
    .expect("write settings");
    let out = regress("check", &[&scene], &store, &[], dir.dir());
    assert_exit(&out, 2);
    let err = text(&out.stderr);
    assert!(
        err.contains("regress.yaml:3:") && err.contains("relativ"),
        "{err}"
    );
}

#[test]
fn missing_record_and_broken_scene_could_not_run() {
    let dir = Scratch::new("regress", "errors");
    let scene = copy_scene(&dir, SLOW);
    let store = dir.path("golden");
    let out = regress("check", &[&scene], &store, &[], dir.dir());
    assert_exit(&out, 2);
    assert!(text(&out.stdout).contains("ERROR moving-force-slow: could not run"));
    assert!(
        text(&out.stdout).contains("approve the scene first"),
        "{}",
        text(&out.stdout)
    );
    assert_exit(&regress("approve", &[&scene], &store, &[], dir.dir()), 0);
    edit(
        &scene,
        "mass_per_length: 2303.0",
        "mass_per_length: -2303.0",
    );
    let out = regress("check", &[&scene], &store, &[], dir.dir());
    assert_exit(&out, 2);
}

/// The slow crossing as a three-speed sweep (20, 25, 30 m/s) at a 0.2 ms
/// step: a study with a table.
fn sweep_scene(dir: &Scratch) -> PathBuf {
    let src = std::fs::read_to_string(manifest_dir().join("scenarios").join(SLOW))
        .expect("read scenario");
    assert!(src.contains("time_step: 2.0e-5"), "scenario changed");
    let text = src.replace("time_step: 2.0e-5", "time_step: 2.0e-4")
        + "study:\n  type: speed_sweep\n  speeds: {from: 20 m/s, to: 30 m/s, count: 3}\n";
    let path = dir.path("sweep.yaml");
    std::fs::write(&path, text).expect("write scenario");
    path
}

/// A study is compared table by table, row by row: the 0.1 % stiffer beam
/// moves the sweep's peak midspan deflection by about −0.1 % (quasi-static
/// share ∝ 1/EI) and the report names the column and the row's speed.
#[test]
fn study_table_change_is_caught() {
    let dir = Scratch::new("regress", "study");
    let scene = sweep_scene(&dir);
    let store = dir.path("golden");
    assert_exit(&regress("approve", &[&scene], &store, &[], dir.dir()), 0);
    let record = std::fs::read_to_string(store.join("sweep/record.tsv")).expect("record");
    assert!(record.contains("[table study]"), "{record}");
    assert_exit(&regress("check", &[&scene], &store, &[], dir.dir()), 0);
    edit(
        &scene,
        "bending_stiffness: 8.323e9",
        "bending_stiffness: 8.331323e9",
    );
    let plots = dir.path("plots");
    let out = regress(
        "check",
        &[&scene],
        &store,
        &["--out", plots.to_str().expect("utf-8 path")],
        dir.dir(),
    );
    assert_exit(&out, 1);
    let report = text(&out.stdout);
    let line = report_line(&report, "study: max_abs_midspan [m]")
        .unwrap_or_else(|| panic!("study column not named:\n{report}"));
    assert!(line.contains("speed [m/s] = "), "{line}");
    let relative = relative_of(line);
    assert!(
        (-1.5e-3..-0.5e-3).contains(&relative),
        "peak deflection moved by {relative:e}, expected about -1e-3: {line}"
    );
    assert!(
        plots
            .join("sweep")
            .join("study-max_abs_midspan_m.png")
            .is_file(),
        "{report}"
    );
}

// ---------------------------------------------------------------------------
// JUnit XML
// ---------------------------------------------------------------------------

/// An XML element: name, attributes, children, text.
#[derive(Debug, Default)]
struct Element {
    name: String,
    attributes: Vec<(String, String)>,
    children: Vec<Element>,
    text: String,
}

impl Element {
    fn attribute(&self, key: &str) -> Option<&str> {
        self.attributes
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }
}

fn unescape_xml(text: &str) -> Result<String, String> {
    let mut out = String::new();
    let mut rest = text;
    while let Some(i) = rest.find('&') {
        out.push_str(&rest[..i]);
        let end = rest[i..].find(';').ok_or("unterminated entity")? + i;
        out.push(match &rest[i + 1..end] {
            "amp" => '&',
            "lt" => '<',
            "gt" => '>',
            "quot" => '"',
            "apos" => '\'',
            other => return Err(format!("unknown entity &{other};")),
        });
        rest = &rest[end + 1..];
    }
    if rest.contains('<') {
        return Err("raw < in text".into());
    }
    out.push_str(rest);
    Ok(out)
}

/// A strict little parser of the XML subset JUnit files use (declaration,
/// elements, attributes in double quotes, text with the five entities):
/// enough to prove the file well formed (every tag closed in order, every
/// attribute quoted, no raw `<` or `&`).
fn parse_xml(xml: &str) -> Result<Element, String> {
    let body = xml
        .strip_prefix("<?xml version=\"1.0\" encoding=\"UTF-8\"?>")
        .ok_or("no XML declaration")?;
    let mut stack: Vec<Element> = vec![Element::default()];
    let mut rest = body;
    while !rest.is_empty() {
        let lt = rest.find('<').unwrap_or(rest.len());
        let text = unescape_xml(&rest[..lt])?;
        stack.last_mut().expect("root").text.push_str(&text);
        rest = &rest[lt..];
        if rest.is_empty() {
            break;
        }
        let gt = rest.find('>').ok_or("unterminated tag")?;
        let tag = &rest[1..gt];
        rest = &rest[gt + 1..];
        if let Some(name) = tag.strip_prefix('/') {
            let done = stack.pop().ok_or("too many closing tags")?;
            if done.name != name {
                return Err(format!("</{name}> closes <{}>", done.name));
            }
            stack
                .last_mut()
                .ok_or("closing tag at the top")?
                .children
                .push(done);
            continue;
        }
        let empty = tag.ends_with('/');
        let tag = tag.trim_end_matches('/');
        let (name, mut attrs) = tag.split_once(' ').unwrap_or((tag, ""));
        let mut element = Element {
            name: name.to_string(),
            ..Element::default()
        };
        loop {
            attrs = attrs.trim_start();
            if attrs.is_empty() {
                break;
            }
            let eq = attrs
                .find("=\"")
                .ok_or(format!("attribute without =\": {attrs}"))?;
            let key = attrs[..eq].to_string();
            let after = &attrs[eq + 2..];
            let close = after.find('"').ok_or("unterminated attribute")?;
            element
                .attributes
                .push((key, unescape_xml(&after[..close])?));
            attrs = &after[close + 1..];
        }
        if empty {
            stack.last_mut().expect("parent").children.push(element);
        } else {
            stack.push(element);
        }
    }
    let mut root = stack.pop().ok_or("empty")?;
    if !stack.is_empty() {
        return Err(format!("<{}> not closed", root.name));
    }
    if root.children.len() != 1 || !root.text.trim().is_empty() {
        return Err("not exactly one root element".into());
    }
    Ok(root.children.remove(0))
}

fn count(element: &Element, key: &str) -> usize {
    element
        .attribute(key)
        .unwrap_or_else(|| panic!("<{}> lacks {key}", element.name))
        .parse()
        .unwrap_or_else(|_| panic!("<{}> {key} not a count", element.name))
}

/// The JUnit XML is well formed and has the structure of the common JUnit
/// schema (the Ant/Jenkins junit.xsd that GitHub and GitLab read):
/// `testsuites` > `testsuite` (name, tests, failures, errors, time) >
/// `testcase` (name, classname, time) > at most one `failure` or `error`
/// (message, type); the counts agree with the cases.
#[test]
fn junit_xml_has_the_common_schema_structure() {
    let dir = Scratch::new("regress", "junit");
    let passing = copy_scene(&dir, SLOW);
    let changing = copy_scene(&dir, "two-axle-moving-force.yaml");
    let store = dir.path("golden");
    assert_exit(
        &regress("approve", &[&passing, &changing], &store, &[], dir.dir()),
        0,
    );
    let text_before = std::fs::read_to_string(&changing).expect("read");
    let speed = text_before
        .lines()
        .find(|l| l.trim_start().starts_with("speed:"))
        .expect("a speed line")
        .to_string();
    let value: f64 = speed
        .split(':')
        .nth(1)
        .expect("value")
        .trim()
        .parse()
        .expect("number");
    let indent = &speed[..speed.len() - speed.trim_start().len()];
    edit(
        &changing,
        &speed,
        &format!("{indent}speed: {}", value * 1.01),
    );
    let unapproved = copy_scene(&dir, "moving-force-fast.yaml");
    let junit = dir.path("junit.xml");
    let out = regress(
        "check",
        &[&passing, &changing, &unapproved],
        &store,
        &[
            "--junit",
            junit.to_str().expect("utf-8"),
            "--out",
            dir.path("plots").to_str().expect("utf-8"),
        ],
        dir.dir(),
    );
    assert_exit(&out, 2);
    let xml = std::fs::read_to_string(&junit).expect("junit written");
    let root = parse_xml(&xml).unwrap_or_else(|e| panic!("not well formed: {e}\n{xml}"));
    assert_eq!(root.name, "testsuites");
    assert_eq!(root.children.len(), 1, "{xml}");
    let suite = &root.children[0];
    assert_eq!(suite.name, "testsuite");
    assert!(suite.attribute("name").is_some_and(|n| !n.is_empty()));
    for element in [&root, suite] {
        assert_eq!(count(element, "tests"), 3, "{xml}");
        assert_eq!(count(element, "failures"), 1, "{xml}");
        assert_eq!(count(element, "errors"), 1, "{xml}");
        let time: f64 = element
            .attribute("time")
            .expect("time")
            .parse()
            .expect("seconds");
        assert!(time >= 0.0);
    }
    let names: Vec<&str> = suite
        .children
        .iter()
        .map(|c| c.attribute("name").unwrap_or(""))
        .collect();
    assert_eq!(
        names,
        [
            "moving-force-slow",
            "two-axle-moving-force",
            "moving-force-fast"
        ]
    );
    for case in &suite.children {
        assert_eq!(case.name, "testcase");
        assert!(case.attribute("classname").is_some_and(|c| !c.is_empty()));
        let _: f64 = case
            .attribute("time")
            .expect("time")
            .parse()
            .expect("seconds");
        assert!(case.children.len() <= 1);
        for outcome in &case.children {
            assert!(
                ["failure", "error"].contains(&outcome.name.as_str()),
                "{}",
                outcome.name
            );
            assert!(
                outcome.attribute("message").is_some_and(|m| !m.is_empty()),
                "{xml}"
            );
            assert!(outcome.attribute("type").is_some(), "{xml}");
        }
    }
    let kinds: Vec<Option<&str>> = suite
        .children
        .iter()
        .map(|c| c.children.first().map(|o| o.name.as_str()))
        .collect();
    assert_eq!(kinds, [None, Some("failure"), Some("error")]);
    // The failure's text names what moved.
    assert!(
        suite.children[1].children[0].text.contains("quantities."),
        "{xml}"
    );
}

// ---------------------------------------------------------------------------
// The documented CI workflow and the shipped scenes
// ---------------------------------------------------------------------------

/// The `vbi regress …` command lines of a documentation file (a YAML list
/// item, a `run:` step or a shell line), comments aside.
fn regress_commands(file: &str) -> Vec<String> {
    let text = std::fs::read_to_string(manifest_dir().join(file)).expect("read doc");
    text.lines()
        .map(str::trim)
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.trim_start_matches("- ").trim_start_matches("run: "))
        .filter(|l| l.starts_with("vbi regress "))
        .map(str::to_string)
        .collect()
}

fn shell(command: &str, cwd: &Path) -> Output {
    let bin = Path::new(env!("CARGO_BIN_EXE_vbi"))
        .parent()
        .expect("bin dir");
    let path = std::env::join_paths(std::iter::once(bin.to_path_buf()).chain(
        std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()),
    ))
    .expect("PATH");
    Command::new("sh")
        .arg("-c")
        .arg(command)
        .env("PATH", path)
        .current_dir(cwd)
        .output()
        .expect("run sh")
}

/// The guide's approve command (docs/guide/regression.md) and the check of the GitHub Actions and
/// GitLab CI examples, run as written on a folder `scenes/` of two shipped
/// scenes: pass, then fail (exit 1, JUnit written) after a scene edit.
#[test]
fn documented_ci_commands_run_as_written() {
    let readme = regress_commands("docs/guide/regression.md");
    let approve: Vec<&String> = readme.iter().filter(|c| c.contains(" approve ")).collect();
    assert!(
        !approve.is_empty(),
        "docs/guide/regression.md shows no `vbi regress approve` line"
    );
    let mut checks = regress_commands("docs/ci/github-actions.yml");
    checks.extend(regress_commands("docs/ci/gitlab-ci.yml"));
    assert_eq!(checks.len(), 2, "one check per workflow: {checks:?}");
    let dir = Scratch::new("regress", "ci");
    std::fs::create_dir_all(dir.path("scenes")).expect("mkdir");
    for name in [SLOW, "two-axle-moving-force.yaml"] {
        std::fs::copy(
            manifest_dir().join("scenarios").join(name),
            dir.path("scenes").join(name),
        )
        .expect("copy");
    }
    for command in &approve {
        assert_exit(&shell(command, dir.dir()), 0);
    }
    for command in &checks {
        let out = shell(command, dir.dir());
        assert_exit(&out, 0);
        assert!(
            text(&out.stdout).contains("2 scenes: 2 passed"),
            "{command}: {}",
            text(&out.stdout)
        );
    }
    edit(
        &dir.path("scenes").join(SLOW),
        "bending_stiffness: 8.323e9",
        "bending_stiffness: 8.4e9",
    );
    for command in &checks {
        let _ = std::fs::remove_file(dir.path("regress-junit.xml"));
        assert_exit(&shell(command, dir.dir()), 1);
        assert!(dir.path("regress-junit.xml").is_file(), "{command}");
    }
}

/// `vbi regress` over a few cheap shipped scenarios (single runs and a
/// railway resonance check, a study), into a temporary store: approve,
/// then check passes. This keeps the command working in the project's own
/// test suite, beside the insta snapshots of tests/golden.rs.
#[test]
fn shipped_scenarios_approve_and_check() {
    let dir = Scratch::new("regress", "shipped");
    let scenes: Vec<PathBuf> = [
        "moving-force-slow.yaml",
        "two-axle-moving-force.yaml",
        "yang-yau-sprung-mass.yaml",
        "hslm-resonance-20m.yaml",
    ]
    .iter()
    .map(|n| manifest_dir().join("scenarios").join(n))
    .collect();
    let refs: Vec<&Path> = scenes.iter().map(PathBuf::as_path).collect();
    let store = dir.path("store");
    let out = regress("approve", &refs, &store, &[], manifest_dir());
    assert_exit(&out, 0);
    let record =
        std::fs::read_to_string(store.join("hslm-resonance-20m/record.tsv")).expect("record");
    assert!(record.contains("[table resonance]"), "{record}");
    let out = regress("check", &refs, &store, &[], manifest_dir());
    assert_exit(&out, 0);
    let report = text(&out.stdout);
    assert!(
        report.contains("4 scenes: 4 passed, 0 changed, 0 could not run"),
        "{report}"
    );
    // Output order is the order given, whatever finished first.
    let order: Vec<&str> = report
        .lines()
        .filter_map(|l| l.strip_prefix("PASS  "))
        .collect();
    assert_eq!(
        order,
        [
            "moving-force-slow",
            "two-axle-moving-force",
            "yang-yau-sprung-mass",
            "hslm-resonance-20m"
        ]
    );
}

/// The cells of `[table NAME]` of a record: its header and rows.
fn record_table(record: &str, name: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = record
        .lines()
        .skip_while(|l| *l != format!("[table {name}]"))
        .skip(1)
        .take_while(|l| !l.is_empty());
    let header = lines
        .next()
        .map(|l| l.split('\t').map(String::from).collect())
        .unwrap_or_default();
    let rows = lines
        .map(|l| l.split('\t').map(String::from).collect())
        .collect();
    (header, rows)
}

/// Issue 40.7: a 16-sample Monte Carlo study at every one of its 96 000
/// steps (the LCP Fig. 7 scene at a 5 µs step) made a 15.4 MB record, its
/// envelopes written step by step. Binned like the history, the record is
/// under 1 MB, and the largest and smallest value of every envelope column
/// over the whole run (from the study's own `envelopes.csv`, unbinned) are
/// the record's, exactly at the record's 10 significant digits.
#[test]
fn monte_carlo_record_is_compact_and_keeps_every_peak() {
    let dir = Scratch::new("regress", "monte_carlo_compact");
    let scene = copy_scene(&dir, "lcp-fig7-monte-carlo.yaml");
    edit(&scene, "samples: 20", "samples: 16");
    edit(&scene, "time_step: 2.0e-3", "time_step: 5.0e-6");
    let store = dir.path("golden");
    assert_exit(&regress("approve", &[&scene], &store, &[], dir.dir()), 0);
    let path = store.join("lcp-fig7-monte-carlo/record.tsv");
    let bytes = std::fs::metadata(&path).expect("record written").len();
    assert!(bytes <= 1 << 20, "record of {bytes} bytes");
    let record = std::fs::read_to_string(&path).expect("read record");
    let (header, rows) = record_table(&record, "envelopes");
    assert!(
        header.contains(&"time_from [s]".to_string()) && rows.len() <= 200,
        "{header:?}, {} rows",
        rows.len()
    );

    let out = dir.path("run");
    let args = [
        "run".as_ref(),
        scene.as_os_str(),
        "--out".as_ref(),
        out.as_os_str(),
    ];
    assert_exit(&vbi(&args, dir.dir()), 0);
    let csv = std::fs::read_to_string(out.join("envelopes.csv")).expect("envelopes.csv");
    let mut lines = csv.lines();
    let csv_header: Vec<&str> = lines.next().expect("header").split(',').collect();
    let csv_rows: Vec<Vec<f64>> = lines
        .map(|l| {
            l.split(',')
                .map(|c| c.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect();
    assert!(csv_rows.len() > 90_000, "{} steps", csv_rows.len());
    let time = csv_header
        .iter()
        .position(|h| *h == "time [s]")
        .expect("time");
    let column = |name: &str| -> Vec<f64> {
        let c = header.iter().position(|h| h == name).unwrap_or_else(|| {
            panic!("record has no column {name}: {header:?}");
        });
        rows.iter()
            .map(|r| r[c].parse().expect("a number"))
            .collect()
    };
    for (c, label) in csv_header.iter().enumerate().skip(time + 1) {
        let all: Vec<f64> = csv_rows.iter().map(|r| r[c]).collect();
        let (hi, lo) = all
            .iter()
            .fold((f64::MIN, f64::MAX), |(h, l), &x| (h.max(x), l.min(x)));
        let (name, unit) = label.split_once(" [").expect("a unit");
        let binned_hi = column(&format!("{name}_max [{unit}"))
            .into_iter()
            .fold(f64::MIN, f64::max);
        let binned_lo = column(&format!("{name}_min [{unit}"))
            .into_iter()
            .fold(f64::MAX, f64::min);
        let digits = vbi::regress::record::format_number;
        assert_eq!(digits(binned_hi), digits(hi), "{label}: largest value");
        assert_eq!(digits(binned_lo), digits(lo), "{label}: smallest value");
    }
}

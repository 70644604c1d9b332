//! Regression stores, `vbi init` targets and terminal output from someone
//! else (issue 39, points 1–4): every case below once hung, exhausted
//! memory, wrote outside its folder, quoted a file it should not have,
//! passed a forged record, or put a raw control character on the terminal.
//! Each command runs under a 20 s watchdog, as the hostile corpus does.

use crate::support;

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

use support::{Scratch, manifest_dir, text};

/// The shipped quick scene (a 100 kN force over the Yang & Yau beam).
const SCENE: &str = "moving-force-slow.yaml";

/// `vbi ARGS` in `cwd`, killed after 20 s (a hang fails the test instead
/// of stalling the suite).
fn vbi_timed(args: &[&str], cwd: &Path) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_vbi"))
        .args(args)
        .current_dir(cwd)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("vbi starts");
    let start = Instant::now();
    while child.try_wait().expect("wait").is_none() {
        if start.elapsed() > Duration::from_secs(20) {
            let _ = child.kill();
            panic!("vbi {args:?} hung for 20 s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().expect("output")
}

fn copy_scene(dir: &Scratch, name: &str) -> PathBuf {
    let path = dir.path(name);
    std::fs::copy(manifest_dir().join("scenarios").join(SCENE), &path).expect("copy scene");
    path
}

/// No raw control character but line breaks and tabs in `out`'s streams.
fn assert_no_raw_controls(out: &Output) {
    for stream in [&out.stdout, &out.stderr] {
        let t = text(stream);
        assert!(
            !t.chars()
                .any(|c| c.is_control() && !matches!(c, '\n' | '\t')),
            "a raw control character reached the terminal: {t:?}"
        );
    }
}

/// An approved store of the quick scene in `dir`; returns (scene, store).
fn approved(dir: &Scratch) -> (PathBuf, PathBuf) {
    let scene = copy_scene(dir, "scene.yaml");
    let store = dir.path("store");
    let out = vbi_timed(
        &["regress", "approve", "scene.yaml", "--store", "store"],
        dir.dir(),
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    (scene, store)
}

#[cfg(unix)]
fn mkfifo(path: &Path) {
    let ok = Command::new("mkfifo").arg(path).status().expect("mkfifo");
    assert!(ok.success());
}

/// A FIFO or a link to /dev/zero as `record.tsv` or `regress.yaml`: refused
/// at once (exit 2), not read (once a hang, or memory until it ran out).
#[cfg(unix)]
#[test]
fn pipes_and_devices_in_a_store_are_refused_not_read() {
    for (entry, kind) in [
        ("scene/record.tsv", "fifo"),
        ("regress.yaml", "fifo"),
        ("scene/record.tsv", "zero"),
        ("regress.yaml", "zero"),
    ] {
        let dir = Scratch::new(
            "hostile_store",
            &format!("dev-{kind}-{}", entry.replace('/', "-")),
        );
        let (_, store) = approved(&dir);
        let path = store.join(entry);
        let _ = std::fs::remove_file(&path);
        match kind {
            "fifo" => mkfifo(&path),
            _ => std::os::unix::fs::symlink("/dev/zero", &path).unwrap(),
        }
        let out = vbi_timed(
            &["regress", "check", "scene.yaml", "--store", "store"],
            dir.dir(),
        );
        assert_eq!(
            out.status.code(),
            Some(2),
            "{entry} {kind}: {}",
            text(&out.stderr)
        );
        let all = format!("{}{}", text(&out.stdout), text(&out.stderr));
        assert!(
            all.contains("not a regular file") || all.contains("symbolic link"),
            "{entry} {kind}: {all}"
        );
    }
}

/// A sparse 3 GB `record.tsv` is refused by its size before it is read.
#[cfg(unix)]
#[test]
fn a_huge_record_is_refused_by_its_size() {
    let dir = Scratch::new("hostile_store", "huge-record");
    let (_, store) = approved(&dir);
    let file = std::fs::OpenOptions::new()
        .write(true)
        .open(store.join("scene/record.tsv"))
        .unwrap();
    file.set_len(3 << 30).unwrap();
    let out = vbi_timed(
        &["regress", "check", "scene.yaml", "--store", "store"],
        dir.dir(),
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(
        text(&out.stdout).contains("more than the"),
        "{}",
        text(&out.stdout)
    );
}

/// A scene file `...yaml` has the stem `..`: refused as a store key (it
/// wrote its record into the store's parent).
#[test]
fn a_dots_only_store_key_is_refused() {
    let dir = Scratch::new("hostile_store", "dots-key");
    copy_scene(&dir, "...yaml");
    std::fs::create_dir_all(dir.path("sub/st")).unwrap();
    let out = vbi_timed(
        &["regress", "approve", "../...yaml", "--store", "st"],
        &dir.path("sub"),
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(text(&out.stderr).contains("cannot name a folder of the store"));
    assert!(text(&out.stderr).contains("help: rename the scene file"));
    assert!(!dir.path("sub/record.tsv").exists());
    assert!(!dir.path("sub/resolved.yaml").exists());
}

/// A store entry that is a link out of the store is neither written through
/// nor read; a `regress.yaml` that is such a link is not quoted.
#[cfg(unix)]
#[test]
fn links_in_a_store_are_neither_followed_nor_quoted() {
    let dir = Scratch::new("hostile_store", "links");
    copy_scene(&dir, "scene.yaml");
    std::fs::create_dir_all(dir.path("store")).unwrap();
    std::fs::create_dir_all(dir.path("outside")).unwrap();
    std::os::unix::fs::symlink("../outside", dir.path("store/scene")).unwrap();
    let out = vbi_timed(
        &["regress", "approve", "scene.yaml", "--store", "store"],
        dir.dir(),
    );
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(
        text(&out.stderr).contains("symbolic link"),
        "{}",
        text(&out.stderr)
    );
    assert_eq!(std::fs::read_dir(dir.path("outside")).unwrap().count(), 0);
    let out = vbi_timed(
        &["regress", "check", "scene.yaml", "--store", "store"],
        dir.dir(),
    );
    assert_eq!(out.status.code(), Some(2));
    std::fs::write(dir.path("secret.yaml"), "CANARY-SECRET-77: 1\n").unwrap();
    std::fs::remove_file(dir.path("store/scene")).unwrap();
    std::os::unix::fs::symlink("../secret.yaml", dir.path("store/regress.yaml")).unwrap();
    let out = vbi_timed(
        &["regress", "check", "scene.yaml", "--store", "store"],
        dir.dir(),
    );
    assert_eq!(out.status.code(), Some(2));
    let all = format!("{}{}", text(&out.stdout), text(&out.stderr));
    assert!(!all.contains("CANARY-SECRET"), "{all}");
    assert!(all.contains("symbolic link"), "{all}");
}

/// Forged golden values are refused with the record's line, never widened
/// into a pass: an infinite scalar (its relative tolerance was infinite).
#[test]
fn forged_infinite_golden_values_do_not_pass() {
    for (name, forged) in [
        ("quantities.midspan.min.value", "inf"),
        ("quantities.midspan.min.value", "-inf"),
        ("run.frequencies.0", "-inf"),
        ("run.frequencies.0", "NaN"),
    ] {
        let dir = Scratch::new(
            "hostile_store",
            &format!("forged-{}-{forged}", name.replace('.', "-")),
        );
        let (_, store) = approved(&dir);
        let path = store.join("scene/record.tsv");
        let record = std::fs::read_to_string(&path).unwrap();
        let prefix = format!("{name}\t");
        let line = record
            .lines()
            .position(|l| l.starts_with(&prefix))
            .unwrap_or_else(|| panic!("no {name} in\n{record}"));
        let forged_text: String = record
            .lines()
            .enumerate()
            .map(|(i, l)| {
                if i == line {
                    let mut f: Vec<&str> = l.split('\t').collect();
                    f[1] = forged;
                    f.join("\t")
                } else {
                    l.to_owned()
                }
            })
            .collect::<Vec<_>>()
            .join("\n");
        std::fs::write(&path, forged_text + "\n").unwrap();
        let out = vbi_timed(
            &["regress", "check", "scene.yaml", "--store", "store"],
            dir.dir(),
        );
        let report = text(&out.stdout);
        assert_ne!(
            out.status.code(),
            Some(0),
            "{name} = {forged} passed:\n{report}"
        );
        assert!(
            report.contains(&format!("line {}", line + 1)),
            "{name} = {forged}: the line is not named:\n{report}"
        );
    }
}

/// A scene file name with ESC and U+FFFF: the report shows it escaped and
/// the JUnit XML stays well-formed (once `invalid token`).
#[test]
fn strange_scene_names_stay_escaped_in_the_report_and_valid_in_xml() {
    let dir = Scratch::new("hostile_store", "strange-names");
    // ESC cannot name a store folder: refused, and shown escaped.
    let name = "a\u{1b}[2Jb.yaml";
    copy_scene(&dir, name);
    let out = vbi_timed(&["regress", "approve", name, "--store", "store"], dir.dir());
    assert_no_raw_controls(&out);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(
        text(&out.stderr).contains("a\\u{1b}[2Jb"),
        "{}",
        text(&out.stderr)
    );
    // U+FFFF can (it is no control), but not appear raw in XML 1.0.
    let name = "a\u{202e}b\u{ffff}.yaml";
    copy_scene(&dir, name);
    let out = vbi_timed(&["regress", "approve", name, "--store", "store"], dir.dir());
    assert_no_raw_controls(&out);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let out = vbi_timed(
        &[
            "regress",
            "check",
            name,
            "--store",
            "store",
            "--junit",
            "junit.xml",
        ],
        dir.dir(),
    );
    assert_no_raw_controls(&out);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("PASS"), "{}", text(&out.stdout));
    let xml = std::fs::read_to_string(dir.path("junit.xml")).unwrap();
    let bad = xml.chars().find(|&c| {
        !(matches!(c, '\t' | '\n' | '\r')
            || ('\u{20}'..='\u{d7ff}').contains(&c)
            || ('\u{e000}'..='\u{fffd}').contains(&c)
            || c >= '\u{10000}')
    });
    assert_eq!(bad, None, "a character XML 1.0 forbids:\n{xml}");
    assert!(xml.contains("b\\u{ffff}"), "{xml}");
}

/// A YAML escape in a unit, a variant name, an unknown key or a data-file
/// name is shown escaped, never raw (it could clear the terminal).
#[test]
fn yaml_escapes_in_a_scene_reach_the_terminal_escaped() {
    let dir = Scratch::new("hostile_store", "yaml-escapes");
    const FE: &str = "fe-import-lcp-fig4-rigid.yaml";
    for (what, file, from, to) in [
        (
            "unit",
            SCENE,
            "mass_per_length: ",
            "mass_per_length: \"1000 kg/m\\e[31mRED\" #",
        ),
        ("variant", SCENE, "type: beam", "type: \"be\\e[2Jam\""),
        (
            "key",
            SCENE,
            "mass_per_length: ",
            "\"ma\\0ss\\e[2J\": 1\n  mass_per_length: ",
        ),
        (
            "data file",
            FE,
            "stiffness: fe-import-lcp-fig4/K.mtx",
            "stiffness: \"K\\e[2J.mtx\"",
        ),
    ] {
        let base = std::fs::read_to_string(manifest_dir().join("scenarios").join(file)).unwrap();
        assert!(base.contains(from), "{what}: `{from}` not in the scene");
        let scene = dir.path(&format!("{}.yaml", what.replace(' ', "-")));
        std::fs::write(&scene, base.replacen(from, to, 1)).unwrap();
        let out = vbi_timed(&["check", scene.to_str().unwrap()], dir.dir());
        assert_eq!(out.status.code(), Some(2), "{what}: {}", text(&out.stderr));
        assert_no_raw_controls(&out);
        assert!(
            text(&out.stderr).contains("\\u{1b}") || text(&out.stderr).contains("\\0"),
            "{what}: {}",
            text(&out.stderr)
        );
    }
}

/// `vbi init` never writes the schema over the scene, replaces neither
/// file without --force, and leaves nothing behind when it refuses.
#[test]
fn init_writes_nothing_it_may_not() {
    let dir = Scratch::new("hostile_store", "init");
    // The scene named as the schema: refused, nothing written.
    let out = vbi_timed(&["init", "vbi.schema.json"], dir.dir());
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(!dir.path("vbi.schema.json").exists());
    // A schema of someone else's beside the scene: kept without --force,
    // and the scene is not written either.
    std::fs::write(dir.path("vbi.schema.json"), "{\"mine\": true}").unwrap();
    let out = vbi_timed(&["init", "scene.yaml"], dir.dir());
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(
        text(&out.stderr).contains("--force"),
        "{}",
        text(&out.stderr)
    );
    assert_eq!(
        std::fs::read_to_string(dir.path("vbi.schema.json")).unwrap(),
        "{\"mine\": true}"
    );
    assert!(!dir.path("scene.yaml").exists());
    // With --force both are written; a second scene beside the current
    // schema needs no --force.
    let out = vbi_timed(&["init", "scene.yaml", "--force"], dir.dir());
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let out = vbi_timed(&["init", "second.yaml"], dir.dir());
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // A folder where the schema goes: refused before the scene is written.
    let sub = dir.path("sub");
    std::fs::create_dir_all(sub.join("vbi.schema.json")).unwrap();
    let out = vbi_timed(&["init", "sub/scene.yaml", "--force"], dir.dir());
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(!sub.join("scene.yaml").exists());
    // A link in the scene's place is not written through, even with --force.
    #[cfg(unix)]
    {
        std::fs::write(dir.path("target.txt"), "keep").unwrap();
        std::os::unix::fs::symlink("target.txt", dir.path("link.yaml")).unwrap();
        let out = vbi_timed(&["init", "link.yaml", "--force"], dir.dir());
        assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
        assert_eq!(
            std::fs::read_to_string(dir.path("target.txt")).unwrap(),
            "keep"
        );
    }
}

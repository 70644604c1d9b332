//! Issue 10: continuous fuzzing of the loader and the resolver on the stable
//! toolchain. A mutation fuzzer (no coverage guidance, no nightly): seeds
//! are every shipped scenario, every `tests/bad` file and the hostile corpus;
//! each input is a seed with one to four mutations — byte edits, numbers
//! replaced by boundary values (0, −1, 2⁶³, 2⁶⁴, ±1e308, .nan, …), lines
//! spliced in from other seeds, YAML control tokens (tabs, tags, anchors,
//! brackets, NUL, BOM) — and goes through `load_str` exactly as `vbi check`
//! would; an accepted scene of at most 20,000 steps is also run. A panic
//! fails the test and the input is saved under
//! `target/fuzz-crashes/` to become a case in `tests/hostile`.
//!
//! The run is deterministic: a fixed seed (xorshift) and a fixed number of
//! inputs (30,000 by default, about 30 s in `cargo test --release` on two
//! cores), so a failure in CI reproduces on any machine. A time cap (120 s)
//! only guards against a machine far slower than that. A long run is bounded
//! by time instead; `VBI_FUZZ_TRACE=FILE` keeps the input being tried on disk,
//! so an input that hangs can be recovered:
//!
//! ```sh
//! VBI_FUZZ_SECONDS=3600 VBI_FUZZ_SEED=7 cargo test --release --test fuzz -- --nocapture
//! ```

use std::fs;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Inputs tried by default inside the test suite (the data-file fuzzer
/// below takes the rest of the 30 s budget).
const DEFAULT_INPUTS: u64 = 26_000;
/// Data files tried by default by the data-file fuzzer.
const DEFAULT_DATA_INPUTS: u64 = 2_000;
/// Time cap of the default run, s (a guard, not the bound that applies).
const DEFAULT_CAP_SECONDS: u64 = 120;
/// Inputs slower than this to check are reported (a check must not do work
/// proportional to a run; the largest eigenproblem the default budget lets
/// through takes a few seconds).
const SLOW: Duration = Duration::from_secs(15);
/// Seeds larger than this are skipped: big hostile files make each
/// iteration slow without exercising new code.
const MAX_SEED_BYTES: u64 = 64 * 1024;

/// xorshift64*: small, fast, and the same sequence on every machine.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.next() % n as u64) as usize
        }
    }

    fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// Values at the edges of what the format's numbers and sizes take.
const NUMBERS: &[&str] = &[
    "0",
    "-0.0",
    "-1",
    "1",
    "2",
    "1e-308",
    "5e-324",
    "1e308",
    "-1e308",
    "1e400",
    ".nan",
    ".inf",
    "-.inf",
    "4294967296",
    "9223372036854775807",
    "9223372036854775808",
    "18446744073709551615",
    "18446744073709551616",
    "1e9",
    "1e20",
    "100000",
    "0x10",
    "0o7",
    "~",
    "''",
    "[]",
    "{}",
    "true",
    "2.5",
];

/// Fragments that stress the YAML layer.
const TOKENS: &[&str] = &[
    "\t", "\0", "\u{feff}", "!foo ", "!!str ", "&a ", "*a", "[", "]", "{", "}", ": ", ":", "- ",
    "? ", "<<: ", "---\n", "...\n", "#", "'", "\"", "|\n", ">\n", "\r", "\r\n", "\u{1b}", "é",
    "\u{2028}", "  ", "\n",
];

fn seeds() -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out = Vec::new();
    for dir in ["scenarios", "tests/bad", "tests/hostile/cases"] {
        let Ok(entries) = fs::read_dir(root.join(dir)) else {
            continue;
        };
        // Scenes only (the corpus also holds the data files its cases name).
        let mut paths: Vec<PathBuf> = entries
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
            .collect();
        paths.sort(); // read_dir order differs between file systems
        for path in paths {
            if fs::metadata(&path).map(|m| m.len()).unwrap_or(u64::MAX) > MAX_SEED_BYTES {
                continue;
            }
            if let Ok(bytes) = fs::read(&path) {
                out.push(String::from_utf8_lossy(&bytes).into_owned());
            }
        }
    }
    out
}

/// Byte offsets of the char boundaries of `s` (so edits keep valid UTF-8,
/// which is what `load_str` takes; invalid UTF-8 is tested in the corpus).
fn boundary(s: &str, rng: &mut Rng) -> usize {
    let mut at = rng.below(s.len() + 1);
    while !s.is_char_boundary(at) {
        at -= 1;
    }
    at
}

/// Spans of number-like words in `s`.
fn numbers(s: &str) -> Vec<(usize, usize)> {
    let bytes = s.as_bytes();
    let mut spans = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i].is_ascii_digit()
            || (bytes[i] == b'-' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit))
        {
            let start = i;
            i += 1;
            while i < bytes.len()
                && (bytes[i].is_ascii_alphanumeric() || matches!(bytes[i], b'.' | b'-' | b'+'))
            {
                i += 1;
            }
            spans.push((start, i));
        } else {
            i += 1;
        }
    }
    spans
}

fn mutate(input: &str, seeds: &[String], rng: &mut Rng) -> String {
    let mut s = input.to_string();
    for _ in 0..1 + rng.below(4) {
        match rng.below(9) {
            // A number replaced by a boundary value.
            0..=2 => {
                let spans = numbers(&s);
                if spans.is_empty() {
                    continue;
                }
                let (a, b) = *rng.pick(&spans);
                let value = *rng.pick::<&str>(NUMBERS);
                s.replace_range(a..b, value);
            }
            // A YAML token inserted.
            3 => {
                let at = boundary(&s, rng);
                let token = *rng.pick::<&str>(TOKENS);
                s.insert_str(at, token);
            }
            // A range deleted.
            4 => {
                let a = boundary(&s, rng);
                let mut b = (a + rng.below(40)).min(s.len());
                while !s.is_char_boundary(b) {
                    b -= 1;
                }
                s.replace_range(a..b, "");
            }
            // A line of another seed spliced in.
            5 => {
                let other = rng.pick(seeds);
                let lines: Vec<&str> = other.lines().collect();
                if lines.is_empty() {
                    continue;
                }
                let line = format!("{}\n", rng.pick(&lines));
                let starts: Vec<usize> = std::iter::once(0)
                    .chain(s.match_indices('\n').map(|(i, _)| i + 1))
                    .collect();
                let at = *rng.pick(&starts);
                s.insert_str(at, &line);
            }
            // A line duplicated many times (sizes, duplicate keys).
            6 => {
                let lines: Vec<&str> = s.lines().collect();
                if lines.is_empty() {
                    continue;
                }
                let line = rng.pick(&lines).to_string();
                let times = 1 + rng.below(200);
                s.push('\n');
                for _ in 0..times {
                    s.push_str(&line);
                    s.push('\n');
                }
            }
            // A random byte (ASCII, to stay UTF-8).
            7 => {
                let at = boundary(&s, rng);
                let c = (rng.below(128) as u8) as char;
                s.insert(at, c);
            }
            // Indentation shifted on one line.
            _ => {
                let starts: Vec<usize> = std::iter::once(0)
                    .chain(s.match_indices('\n').map(|(i, _)| i + 1))
                    .collect();
                let at = *rng.pick(&starts);
                if rng.below(2) == 0 {
                    s.insert_str(at, "  ");
                } else if s[at..].starts_with(' ') {
                    s.remove(at);
                }
            }
        }
    }
    s
}

/// Steps of a scene without a study at most this many are run too.
const RUN_STEPS: f64 = 20_000.0;

/// Whether `scenario` is a single scene of at most [`RUN_STEPS`] steps.
fn short(scenario: &vbi::scenario::resolved::Scenario) -> bool {
    let length = scenario.bridge.length();
    let end = scenario
        .vehicles
        .iter()
        .map(|v| v.entry_time() + (length + v.length()) / v.speed())
        .fold(0.0, f64::max)
        + scenario.solver.free_vibration;
    scenario.study.is_none() && end / scenario.solver.time_step <= RUN_STEPS
}

#[test]
fn mutated_scenes_never_panic_in_the_loader() {
    let timed: Option<u64> = std::env::var("VBI_FUZZ_SECONDS")
        .ok()
        .and_then(|v| v.parse().ok());
    let (seconds, inputs) = match timed {
        Some(seconds) => (seconds, u64::MAX),
        None => (DEFAULT_CAP_SECONDS, DEFAULT_INPUTS),
    };
    let seed = std::env::var("VBI_FUZZ_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0x0005_EED0_F7B1_u64);
    let seeds = seeds();
    assert!(seeds.len() > 100, "only {} seeds", seeds.len());
    let mut rng = Rng(seed | 1);
    let began = Instant::now();
    let deadline = began + Duration::from_secs(seconds);
    let crashes = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/fuzz-crashes");
    let (mut runs, mut accepted) = (0u64, 0u64);
    let mut failures = Vec::new();
    let trace = std::env::var_os("VBI_FUZZ_TRACE").map(PathBuf::from);
    while runs < inputs && Instant::now() < deadline {
        let base = rng.pick(&seeds).clone();
        let input = mutate(&base, &seeds, &mut rng);
        if let Some(trace) = &trace {
            // A hang never reaches the report below: keep the input on disk.
            fs::write(trace, &input).unwrap();
        }
        let start = Instant::now();
        let result = catch_unwind(AssertUnwindSafe(|| {
            let loaded = vbi::plan::load_str(&input, "fuzz.yaml")?;
            // A short accepted scene is also run: what the loader lets
            // through must not panic in the solvers either.
            if short(&loaded.scenario) {
                let _ = vbi::run::simulate(loaded, &mut |_, _| {});
            }
            Ok::<(), vbi::scenario::LoadError>(())
        }));
        let took = start.elapsed();
        runs += 1;
        let problem = match &result {
            Err(_) => Some("panicked".to_string()),
            Ok(_) if took > SLOW => Some(format!("took {took:?}")),
            Ok(Ok(())) => {
                accepted += 1;
                None
            }
            Ok(Err(e)) => {
                // Every refusal is located and says something.
                let text = e.to_string();
                (!text.starts_with("fuzz.yaml:") || text.len() < 15)
                    .then(|| format!("unlocated error: {text}"))
            }
        };
        if let Some(problem) = problem {
            fs::create_dir_all(&crashes).unwrap();
            let file = crashes.join(format!("crash-{seed}-{runs}.yaml"));
            fs::write(&file, &input).unwrap();
            failures.push(format!("{problem}: input saved as {}", file.display()));
            if failures.len() >= 10 {
                break;
            }
        }
    }
    eprintln!(
        "fuzz: {runs} inputs in {:.1} s (seed {seed}), {accepted} accepted, {} failures",
        began.elapsed().as_secs_f64(),
        failures.len()
    );
    assert!(runs > 100, "only {runs} inputs were tried");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A secret the data fuzzer splices into data files in place of numbers: a
/// message may quote at most [`vbi::text_table::MAX_QUOTED`] characters of a
/// field, so the whole of it must never come back (issue 23).
const CANARY: &str = "CANARY-SECRET-8a41f2";

/// What a fuzzed data file is to its scene.
#[derive(Clone, Copy, Debug)]
enum Role {
    Stiffness,
    Mass,
    DofMap,
    Rail,
    Record,
    Profile,
}

/// Data files the scenes name, each with its role and file extension:
/// the imported model of `scenarios/fe-import-lcp-fig4`, the corpus's FE
/// files, the shipped and corpus ground-motion records (also used as
/// measured profiles, two numeric columns each).
fn data_seeds() -> Vec<(Role, &'static str, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out = Vec::new();
    let mut add = |role: Role, ext: &'static str, path: PathBuf| {
        if fs::metadata(&path).map(|m| m.len()).unwrap_or(u64::MAX) <= MAX_SEED_BYTES
            && let Ok(text) = fs::read_to_string(&path)
        {
            out.push((role, ext, text));
        }
    };
    let fig4 = root.join("scenarios/fe-import-lcp-fig4");
    add(Role::Stiffness, "mtx", fig4.join("K.mtx"));
    add(Role::Mass, "mtx", fig4.join("M.mtx"));
    add(Role::DofMap, "csv", fig4.join("dofs.csv"));
    add(Role::Rail, "csv", fig4.join("rail.csv"));
    for dir in [
        "tests/hostile/cases/fe",
        "tests/hostile/cases",
        "scenarios/records",
    ] {
        let Ok(entries) = fs::read_dir(root.join(dir)) else {
            continue;
        };
        let mut paths: Vec<PathBuf> = entries.map(|e| e.unwrap().path()).collect();
        paths.sort();
        for path in paths {
            // Regular files only (the corpus's symlinks lead outside).
            if !fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
                continue;
            }
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            let ext = path.extension().map(|e| e.to_string_lossy().to_lowercase());
            match ext.as_deref() {
                Some("mtx") if name.starts_with('M') => add(Role::Mass, "mtx", path),
                Some("mtx") => add(Role::Stiffness, "mtx", path),
                Some("csv") if name.starts_with("rail") => add(Role::Rail, "csv", path),
                Some("csv") if name.starts_with("dofs") => add(Role::DofMap, "csv", path),
                Some("csv") => {
                    add(Role::Record, "csv", path.clone());
                    add(Role::Profile, "csv", path);
                }
                Some("at2") => add(Role::Record, "AT2", path),
                _ => {}
            }
        }
    }
    out
}

/// The scene that names the fuzzed file `fuzz.EXT` in its role; the other
/// files of the imported model are the fig4 originals beside it.
fn host_scene(role: Role, ext: &str, rng: &mut Rng) -> String {
    let fuzz = format!("fuzz.{ext}");
    let pick = |r: &str, original: &str| -> String {
        let matches = match role {
            Role::Stiffness => r == "K",
            Role::Mass => r == "M",
            Role::DofMap => r == "D",
            Role::Rail => r == "R",
            _ => false,
        };
        if matches {
            fuzz.clone()
        } else {
            original.to_string()
        }
    };
    let beam = "name: data-fuzz\nbridge: {type: beam, spans: [25.0], bending_stiffness: 8.323e9, \
                mass_per_length: 2303.0}\nvehicles:\n  - {type: oscillator, sprung_mass: 5750.0, \
                stiffness: 1.595e6, speed: 27.7}\n";
    match role {
        Role::Record => {
            let units = if rng.below(2) == 0 { ", units: g" } else { "" };
            format!("{beam}ground_motion:\n  - {{file: {fuzz}{units}}}\n")
        }
        Role::Profile => format!("{beam}surface: {{type: measured, file: {fuzz}}}\n"),
        _ => format!(
            "name: data-fuzz\nbridge:\n  type: fe_import\n  stiffness: {}\n  mass: {}\n  \
             dof_map: {}\n  constrained: [{{node: 1, direction: uz}}, {{node: 21, direction: uz}}]\n  \
             rails: [{{name: rail, file: {}}}]\n  modes: {{count: 10}}\nvehicles:\n  - \
             {{type: moving_force, speed: 20.0, loads: [1.0e5]}}\n",
            pick("K", "K.mtx"),
            pick("M", "M.mtx"),
            pick("D", "dofs.csv"),
            pick("R", "rail.csv"),
        ),
    }
}

/// Issue 23 point 6: the data files scenes name (matrices, DOF maps,
/// rails, records, profiles) mutated like the scenes above and loaded
/// through a scene that names them: no panic, no hang, every refusal
/// located at the scene's key, and a canary spliced into a file never
/// comes back whole in a message.
#[test]
fn mutated_data_files_never_panic_or_leak_in_the_loader() {
    let timed: Option<u64> = std::env::var("VBI_FUZZ_SECONDS")
        .ok()
        .and_then(|v| v.parse().ok());
    let (seconds, inputs) = match timed {
        Some(seconds) => (seconds, u64::MAX),
        None => (DEFAULT_CAP_SECONDS, DEFAULT_DATA_INPUTS),
    };
    let seed = std::env::var("VBI_FUZZ_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0x0D47_A5EE_D001_u64);
    let seeds = data_seeds();
    assert!(seeds.len() >= 20, "only {} data seeds", seeds.len());
    let texts: Vec<String> = seeds.iter().map(|s| s.2.clone()).collect();
    let dir = std::env::temp_dir().join(format!("vbi-fuzz-data-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    let fig4 = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/fe-import-lcp-fig4");
    for name in ["K.mtx", "M.mtx", "dofs.csv", "rail.csv"] {
        fs::copy(fig4.join(name), dir.join(name)).unwrap();
    }
    let label = dir.join("fuzz.yaml").display().to_string();
    let mut rng = Rng(seed | 1);
    let deadline = Instant::now() + Duration::from_secs(seconds);
    let crashes = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/fuzz-crashes");
    let (mut runs, mut accepted) = (0u64, 0u64);
    let mut failures = Vec::new();
    while runs < inputs && Instant::now() < deadline {
        let (role, ext, base) = rng.pick(&seeds).clone();
        let mut data = mutate(&base, &texts, &mut rng);
        if rng.below(4) == 0 {
            let spans = numbers(&data);
            if !spans.is_empty() {
                let (a, b) = *rng.pick(&spans);
                data.replace_range(a..b, CANARY);
            }
        }
        let scene = host_scene(role, ext, &mut rng);
        fs::write(dir.join(format!("fuzz.{ext}")), &data).unwrap();
        let start = Instant::now();
        let result = catch_unwind(AssertUnwindSafe(|| {
            vbi::plan::load_str(&scene, &label).map(|_| ())
        }));
        let took = start.elapsed();
        runs += 1;
        let problem = match &result {
            Err(_) => Some("panicked".to_string()),
            Ok(_) if took > SLOW => Some(format!("took {took:?}")),
            Ok(Ok(())) => {
                accepted += 1;
                None
            }
            Ok(Err(e)) => {
                let text = e.to_string();
                if text.contains(CANARY) {
                    Some(format!("quoted the whole canary: {text}"))
                } else {
                    (!text.starts_with(&format!("{label}:")))
                        .then(|| format!("unlocated error: {text}"))
                }
            }
        };
        if let Some(problem) = problem {
            fs::create_dir_all(&crashes).unwrap();
            let file = crashes.join(format!("data-crash-{seed}-{runs}.{ext}"));
            fs::write(&file, &data).unwrap();
            fs::write(file.with_extension("yaml"), &scene).unwrap();
            failures.push(format!(
                "{problem} ({role:?}): input saved as {}",
                file.display()
            ));
            if failures.len() >= 10 {
                break;
            }
        }
    }
    let _ = fs::remove_dir_all(&dir);
    eprintln!(
        "data fuzz: {runs} inputs (seed {seed}), {accepted} accepted, {} failures",
        failures.len()
    );
    assert!(runs > 100, "only {runs} inputs were tried");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Issue 39.2: a regression store's golden record is data from someone
/// else. Records (and `regress.yaml` settings) mutated like the scenes
/// above: reading them never panics, and a mutated record that the
/// comparison passes against the true one holds no value far from it —
/// a forged value (`inf`, `1e308`, a NaN) is refused or fails, never
/// widened into a pass.
#[test]
fn mutated_golden_records_never_panic_or_pass_a_forged_value() {
    use vbi::regress::{compare, record::Record, settings::Settings};
    let timed: Option<u64> = std::env::var("VBI_FUZZ_SECONDS")
        .ok()
        .and_then(|v| v.parse().ok());
    let (seconds, inputs) = match timed {
        Some(seconds) => (seconds, u64::MAX),
        None => (DEFAULT_CAP_SECONDS, 3_000),
    };
    let seed = std::env::var("VBI_FUZZ_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0x0D47_A5EE_D039_u64);
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/moving-force-slow.yaml");
    let truth = vbi::regress::run_scene(&scene, &vbi::scenario::LoadOptions::default(), 200)
        .expect("the quick scene runs")
        .record;
    let base = truth.to_text();
    let settings_seeds = [
        "relative: 1e-5\nabsolute: 1e-12\nhistory_bins: 400\n".to_string(),
        "quantities:\n  midspan: {relative: 1e-3}\nscenes:\n  moving-force-slow:\n    \
         relative: 1e-4\n    quantities:\n      history.midspan: {absolute: 1e-9}\n"
            .to_string(),
    ];
    let texts = vec![
        base.clone(),
        settings_seeds[0].clone(),
        settings_seeds[1].clone(),
    ];
    let peak = truth
        .scalars
        .iter()
        .filter_map(|s| s.value.number())
        .filter(|x| x.is_finite())
        .fold(0.0_f64, |m, x| m.max(x.abs()));
    let settings = Settings::default();
    let mut rng = Rng(seed | 1);
    let deadline = Instant::now() + Duration::from_secs(seconds);
    let (mut runs, mut read, mut passed) = (0u64, 0u64, 0u64);
    let mut failures = Vec::new();
    while runs < inputs && Instant::now() < deadline && failures.len() < 10 {
        runs += 1;
        if rng.below(5) == 0 {
            let seed_text = rng.pick(&settings_seeds[..]).clone();
            let text = mutate(&seed_text, &texts, &mut rng);
            if catch_unwind(AssertUnwindSafe(|| Settings::parse(&text).map(|_| ()))).is_err() {
                failures.push(format!("Settings::parse panicked on {text:?}"));
            }
            continue;
        }
        let mut text = mutate(&base, &texts, &mut rng);
        // Half the time, one scalar's value forged to a value no run gives.
        if rng.below(2) == 0 {
            let lines: Vec<&str> = text.lines().collect();
            let scalars: Vec<usize> = (0..lines.len())
                .filter(|&i| lines[i].split('\t').nth(1).is_some_and(|v| v.contains('e')))
                .collect();
            if !scalars.is_empty() {
                let i = *rng.pick(&scalars);
                let forged = *rng.pick(&["inf", "-inf", "NaN", "1e308", "-1e308", "1e-320"]);
                let mut fields: Vec<String> = lines[i].split('\t').map(str::to_owned).collect();
                fields[1] = forged.to_owned();
                let mut out: Vec<String> = lines.iter().map(|l| (*l).to_owned()).collect();
                out[i] = fields.join("\t");
                text = out.join("\n");
            }
        }
        let outcome = catch_unwind(AssertUnwindSafe(|| {
            let old = Record::from_text(&text).ok()?;
            let comparison = compare::compare("moving-force-slow", &old, &truth, &settings);
            Some((old, comparison.results_pass()))
        }));
        let Ok(outcome) = outcome else {
            failures.push(format!("panicked on a record:\n{text}"));
            continue;
        };
        let Some((old, pass)) = outcome else { continue };
        read += 1;
        if !pass {
            continue;
        }
        passed += 1;
        for s in &old.scalars {
            let (Some(a), Some(b)) = (
                s.value.number(),
                truth
                    .scalars
                    .iter()
                    .find(|t| t.name == s.name)
                    .and_then(|t| t.value.number()),
            ) else {
                continue;
            };
            let close = (a.is_nan() && b.is_nan()) || (a - b).abs() <= 1e-3 * peak + 1e-9;
            if !close {
                failures.push(format!(
                    "a record with {} = {a} passed against the true {b}",
                    s.name
                ));
            }
        }
    }
    eprintln!(
        "record fuzz: {runs} inputs (seed {seed}), {read} records read, {passed} passed, {} failures",
        failures.len()
    );
    assert!(runs > 100, "only {runs} inputs were tried");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Bytes mutated the way a damaged or forged binary file is: bits flipped,
/// a range cut or duplicated, the file truncated, a length field's bytes
/// set to their extremes; with `rechecksum` the file's trailing 8-byte
/// checksum is then recomputed (a forger who knows the format), so the
/// checks past it are reached.
fn mutate_bytes(good: &[u8], rng: &mut Rng, rechecksum: bool) -> Vec<u8> {
    let mut b = if rechecksum {
        good[..good.len().saturating_sub(8)].to_vec()
    } else {
        good.to_vec()
    };
    for _ in 0..1 + rng.below(3) {
        if b.is_empty() {
            break;
        }
        match rng.below(6) {
            0 | 1 => {
                let at = rng.below(b.len());
                b[at] ^= 1 << rng.below(8);
            }
            2 => b.truncate(rng.below(b.len())),
            3 => {
                let a = rng.below(b.len());
                let end = (a + rng.below(64)).min(b.len());
                let copy = b[a..end].to_vec();
                b.splice(a..a, copy);
            }
            4 => {
                let at = rng.below(b.len());
                let end = (at + 8).min(b.len());
                let fill = if rng.below(2) == 0 { 0xff } else { 0x00 };
                b[at..end].fill(fill);
            }
            _ => {
                let a = rng.below(b.len());
                let end = (a + rng.below(64)).min(b.len());
                b.drain(a..end);
            }
        }
    }
    if rechecksum {
        let mut h = vbi::bridge::eigen::cache::Hasher::default();
        h.bytes(&b);
        b.extend_from_slice(&h.finish().to_le_bytes());
    }
    b
}

/// Issue 39.6: the modes cache and the shard parts are files from disk
/// too. A cache file mutated (bits, cuts, truncation, a forged checksum
/// over changed bytes) never panics and never hands back modes that are not
/// the solve's: a file that passes every re-check gives the fresh
/// eigenvalues to 1e-10 (a change in an entry's last bits is still a valid
/// mode), a refused one the fresh solve bit for bit. A shard part mutated
/// like a scene (numbers at their edges, tokens, cuts, splices) never
/// panics the merge, and a refusal names no raw control character.
#[test]
fn mutated_caches_and_parts_never_panic_or_pass_unchecked() {
    use vbi::bridge::eigen::cache::{CacheOutcome, ModesCache};
    let timed: Option<u64> = std::env::var("VBI_FUZZ_SECONDS")
        .ok()
        .and_then(|v| v.parse().ok());
    let (seconds, inputs) = match timed {
        Some(s) => (s, u64::MAX),
        None => (DEFAULT_CAP_SECONDS, 300),
    };
    let seed: u64 = std::env::var("VBI_FUZZ_SEED")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(0x39_06);
    let mut rng = Rng(seed | 1);
    let scratch = crate::support::Scratch::new("fuzz", "caches_parts");
    // The cache: a small generated viaduct's 12 lowest modes.
    let params = vbi::generate::viaduct::ViaductParams {
        spans: 2,
        span_length: 6.0,
        approach_length: 1.2,
        rail_divisions: 1,
        pier_elements: 2,
        ..Default::default()
    };
    let pencil = vbi::generate::reduce(&vbi::generate::viaduct::assemble(&params).unwrap())
        .pencil()
        .unwrap();
    let cache = ModesCache {
        folder: scratch.path("cache"),
        kind: "fe_import".into(),
    };
    let (fresh, _) = pencil.lowest_cached(12, &cache).unwrap();
    let path = cache.path(cache.key(&pencil, 12));
    let good_cache = fs::read(&path).unwrap();
    // The parts: a two-shard Monte Carlo study.
    let study = "name: mc-fuzz
bridge: {type: beam, spans: [20.0], bending_stiffness: 3.2423e9, mass_per_length: 2000.0, elements_per_span: 10, modes: {count: 4}, damping: {type: modal, ratio: 0.02}}
vehicles:
  - {type: oscillator, sprung_mass: 4000.0, unsprung_mass: 1000.0, stiffness: 4.0e6, damping: 2.53e4, speed: 25.0}
contact: {type: elastic, stiffness: 4.0e8}
surface: {type: random, coefficient: 2.56e-4, sampling_length: 40.0, terms: 40, seed: 3}
solver: {method: lcp, time_step: 2.0e-3, free_vibration: 0.02}
record:
  - {name: midspan, quantity: bridge_displacement, x: 10.0}
study: {type: monte_carlo, samples: 4, seed: 2}
";
    fs::write(scratch.path("mc.yaml"), study).unwrap();
    for k in 1..=2 {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_vbi"))
            .args([
                "run",
                "mc.yaml",
                "-q",
                "--shard",
                &format!("{k}/2"),
                "--out",
                "parts",
            ])
            .current_dir(scratch.dir())
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let parts: Vec<String> = (1..=2)
        .map(|k| fs::read_to_string(scratch.path(&format!("parts/part-{k}-of-2.json"))).unwrap())
        .collect();
    let start = Instant::now();
    let (mut tried, mut cache_hits, mut merged) = (0u64, 0u64, 0u64);
    while tried < inputs && start.elapsed() < Duration::from_secs(seconds) {
        tried += 1;
        // One cache file.
        let forged = rng.below(2) == 0;
        let damaged = mutate_bytes(&good_cache, &mut rng, forged);
        fs::write(&path, &damaged).unwrap();
        let result = catch_unwind(AssertUnwindSafe(|| pencil.lowest_cached(12, &cache)));
        let Ok(result) = result else {
            let saved = scratch.path(&format!("cache-crash-{tried}.bin"));
            fs::write(&saved, &damaged).unwrap();
            panic!(
                "the modes cache panicked on a mutated file (saved {})",
                saved.display()
            );
        };
        let (pairs, outcome) = result.unwrap();
        assert_eq!(pairs.eigenvalues.len(), fresh.eigenvalues.len());
        match outcome {
            CacheOutcome::Rejected(_) => assert!(
                pairs.eigenvalues == fresh.eigenvalues,
                "a refused file did not give the fresh solve"
            ),
            _ => {
                cache_hits += 1;
                for (a, b) in pairs.eigenvalues.iter().zip(&fresh.eigenvalues) {
                    assert!(
                        (a - b).abs() <= 1e-10 * b.abs(),
                        "a mutated cache file was used: eigenvalue {a} against {b}"
                    );
                }
            }
        }
        // One part of the two mutated (as text, like a scene).
        let k = rng.below(2);
        let mutated = mutate(&parts[k], &parts, &mut rng);
        let dir = scratch.path("mutated");
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        let paths: Vec<PathBuf> = (0..2)
            .map(|i| {
                let p = dir.join(format!("part-{}-of-2.json", i + 1));
                fs::write(&p, if i == k { &mutated } else { &parts[i] }).unwrap();
                p
            })
            .collect();
        let options = vbi::scenario::LoadOptions::default();
        let result = catch_unwind(AssertUnwindSafe(|| {
            vbi::study::shard::merge(&paths, &options)
        }));
        match result {
            Err(_) => {
                let saved = scratch.path(&format!("part-crash-{tried}.json"));
                fs::write(&saved, &mutated).unwrap();
                panic!(
                    "the merge panicked on a mutated part (saved {})",
                    saved.display()
                );
            }
            Ok(Ok(_)) => merged += 1,
            Ok(Err(e)) => {
                let text = e.to_string();
                assert!(
                    !text
                        .chars()
                        .any(|c| c.is_control() && c != '\n' && c != '\t'),
                    "a raw control character in the refusal: {text:?}"
                );
            }
        }
    }
    eprintln!(
        "caches and parts: {tried} inputs each in {:.1} s; {cache_hits} cache files passed \
         every re-check (same modes), {merged} mutated parts merged",
        start.elapsed().as_secs_f64()
    );
    assert!(tried > 0);
}

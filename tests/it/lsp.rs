//! The editor experience, tested with the real YAML language server.
//!
//! The schema exists so that editors complete and check scenes; a schema that
//! validates with `jsonschema` can still break in an editor (82
//! `"default": null` once made yaml-language-server 1.25 stop completing the
//! top level). These tests start the server the editors use
//! (`yaml-language-server`, pinned in tests/lsp/package.json; VS Code's YAML
//! extension and most other editors embed it) and talk LSP to it over stdio,
//! on documents that never touch the disk but sit in `scenarios/` so that the
//! scenarios' own modeline (`$schema=../schema/vbi.schema.json`) finds the
//! committed schema.
//!
//! Needs node and `npm ci` in tests/lsp (`.ci/run` does both). Without them
//! each test says so on stderr and passes, unless `VBI_REQUIRE_LSP` is set
//! (as CI sets it), when it fails.

use std::collections::BTreeSet;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, RecvTimeoutError, channel};
use std::time::{Duration, Instant};

use serde_json::{Value, json};

const MODELINE: &str = "# yaml-language-server: $schema=../schema/vbi.schema.json\n";
/// Longest wait for one answer of the server (its first answer loads the schema).
const PATIENCE: Duration = Duration::from_secs(30);

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn server_script() -> PathBuf {
    root().join("tests/lsp/node_modules/yaml-language-server/bin/yaml-language-server")
}

/// The server, or `None` (with the reason on stderr) when node or the npm
/// package is missing and CI did not ask for them.
fn start() -> Option<Server> {
    let node = Command::new("node")
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    let missing = if !node {
        Some("node is not on the PATH".to_string())
    } else if !server_script().is_file() {
        Some(format!(
            "{} is missing: run `npm ci` in tests/lsp",
            server_script().display()
        ))
    } else {
        None
    };
    if let Some(why) = missing {
        if std::env::var_os("VBI_REQUIRE_LSP").is_some() {
            panic!("VBI_REQUIRE_LSP is set but {why}");
        }
        eprintln!(
            "skipped: the language-server test needs node and tests/lsp/node_modules ({why})"
        );
        return None;
    }
    Some(Server::start())
}

/// One yaml-language-server process and the messages it sent.
struct Server {
    child: Child,
    stdin: ChildStdin,
    incoming: Receiver<Value>,
    next_id: i64,
    /// Notifications and requests seen while waiting for something else.
    diagnostics: Vec<(String, Value)>,
}

fn yaml_settings() -> Value {
    json!({
        "validate": true,
        "hover": true,
        "completion": true,
        "format": {"enable": false},
        "schemas": {}
    })
}

impl Server {
    fn start() -> Server {
        let mut child = Command::new("node")
            .arg(server_script())
            .arg("--stdio")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("node starts yaml-language-server");
        let stdin = child.stdin.take().expect("piped stdin");
        let stdout = child.stdout.take().expect("piped stdout");
        let (send, incoming) = channel();
        std::thread::spawn(move || {
            let mut reader = BufReader::new(stdout);
            while let Some(message) = read_message(&mut reader) {
                if send.send(message).is_err() {
                    return;
                }
            }
        });
        let mut server = Server {
            child,
            stdin,
            incoming,
            next_id: 0,
            diagnostics: Vec::new(),
        };
        let root_uri = uri(&root().join("scenarios"));
        server.request(
            "initialize",
            json!({
                "processId": std::process::id(),
                "rootUri": root_uri,
                "capabilities": {
                    "textDocument": {
                        "completion": {"completionItem": {
                            "snippetSupport": true,
                            "documentationFormat": ["markdown", "plaintext"]}},
                        "hover": {"contentFormat": ["markdown", "plaintext"]},
                        "publishDiagnostics": {}
                    },
                    "workspace": {"configuration": true}
                }
            }),
        );
        server.notify("initialized", json!({}));
        server.notify(
            "workspace/didChangeConfiguration",
            json!({"settings": {"yaml": yaml_settings()}}),
        );
        server
    }

    fn send(&mut self, message: &Value) {
        let body = message.to_string();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{body}", body.len())
            .and_then(|()| self.stdin.flush())
            .expect("the language server reads its stdin");
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.send(&json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    /// Waits for the next message, answering the server's own requests
    /// (configuration, capability registration) and keeping diagnostics;
    /// `None` at the deadline.
    fn next(&mut self, deadline: Instant) -> Option<Value> {
        let left = deadline.saturating_duration_since(Instant::now());
        let message = match self.incoming.recv_timeout(left) {
            Ok(m) => m,
            Err(RecvTimeoutError::Timeout) => return None,
            Err(RecvTimeoutError::Disconnected) => panic!("the language server exited"),
        };
        match (
            message.get("method").and_then(Value::as_str),
            message.get("id"),
        ) {
            (Some("workspace/configuration"), Some(id)) => {
                let items = message["params"]["items"]
                    .as_array()
                    .cloned()
                    .unwrap_or_default();
                let answers: Vec<Value> = items
                    .iter()
                    .map(|item| match item.get("section").and_then(Value::as_str) {
                        Some("yaml") => yaml_settings(),
                        _ => Value::Null,
                    })
                    .collect();
                let id = id.clone();
                self.send(&json!({"jsonrpc": "2.0", "id": id, "result": answers}));
            }
            (Some(_), Some(id)) => {
                let id = id.clone();
                self.send(&json!({"jsonrpc": "2.0", "id": id, "result": null}));
            }
            (Some("textDocument/publishDiagnostics"), None) => {
                let params = &message["params"];
                let at = params["uri"].as_str().unwrap_or_default().to_string();
                self.diagnostics.push((at, params["diagnostics"].clone()));
            }
            _ => {}
        }
        Some(message)
    }

    fn request(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        self.send(&json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        let deadline = Instant::now() + PATIENCE;
        loop {
            let Some(message) = self.next(deadline) else {
                panic!("no answer to {method} within {PATIENCE:?}");
            };
            if message.get("id") == Some(&json!(id)) {
                if let Some(error) = message.get("error") {
                    panic!("{method} failed: {error}");
                }
                return message.get("result").cloned().unwrap_or(Value::Null);
            }
        }
    }

    /// Opens `text` as a document named `name` in `scenarios/` (not written
    /// to disk) and returns its URI.
    fn open(&mut self, name: &str, text: &str) -> String {
        let at = uri(&root().join("scenarios").join(name));
        self.notify(
            "textDocument/didOpen",
            json!({"textDocument": {"uri": at, "languageId": "yaml", "version": 1, "text": text}}),
        );
        at
    }

    /// Completion items at the end of the line `line` (0-based) of `text`.
    fn complete(&mut self, name: &str, text: &str, line: usize) -> Vec<Value> {
        let character = text.lines().nth(line).map_or(0, |l| l.chars().count());
        let at = self.open(name, text);
        let result = self.request(
            "textDocument/completion",
            json!({"textDocument": {"uri": at}, "position": {"line": line, "character": character}}),
        );
        let items = match result {
            Value::Array(items) => items,
            Value::Object(mut list) => match list.remove("items") {
                Some(Value::Array(items)) => items,
                _ => Vec::new(),
            },
            _ => Vec::new(),
        };
        assert!(
            !items.is_empty(),
            "no completion at line {line} of:\n{text}"
        );
        items
    }

    /// Hover text at (line, character) (0-based).
    fn hover(&mut self, name: &str, text: &str, line: usize, character: usize) -> String {
        let at = self.open(name, text);
        let result = self.request(
            "textDocument/hover",
            json!({"textDocument": {"uri": at}, "position": {"line": line, "character": character}}),
        );
        result["contents"]["value"]
            .as_str()
            .or_else(|| result["contents"].as_str())
            .unwrap_or_default()
            .to_string()
    }

    /// The diagnostics the server publishes for a newly opened document.
    fn diagnose(&mut self, name: &str, text: &str) -> Vec<Value> {
        let at = self.open(name, text);
        let deadline = Instant::now() + PATIENCE;
        loop {
            if let Some(i) = self.diagnostics.iter().position(|(u, _)| *u == at) {
                let (_, list) = self.diagnostics.remove(i);
                return list.as_array().cloned().unwrap_or_default();
            }
            if self.next(deadline).is_none() {
                panic!("no diagnostics for {name} within {PATIENCE:?}");
            }
        }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn read_message(reader: &mut impl BufRead) -> Option<Value> {
    let mut length = None;
    loop {
        let mut line = String::new();
        if reader.read_line(&mut line).ok()? == 0 {
            return None;
        }
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        if let Some((key, value)) = line.split_once(':')
            && key.eq_ignore_ascii_case("content-length")
        {
            length = value.trim().parse::<usize>().ok();
        }
    }
    let mut body = vec![0; length?];
    reader.read_exact(&mut body).ok()?;
    serde_json::from_slice(&body).ok()
}

fn uri(path: &Path) -> String {
    format!("file://{}", path.display())
}

fn labels(items: &[Value]) -> BTreeSet<String> {
    items
        .iter()
        .filter_map(|i| i["label"].as_str().map(str::to_owned))
        .collect()
}

fn item<'a>(items: &'a [Value], label: &str) -> &'a Value {
    items
        .iter()
        .find(|i| i["label"] == label)
        .unwrap_or_else(|| panic!("no completion `{label}` among {:?}", labels(items)))
}

fn insert_text(item: &Value) -> String {
    item["insertText"]
        .as_str()
        .or_else(|| item["textEdit"]["newText"].as_str())
        .unwrap_or_default()
        .to_string()
}

fn documentation(item: &Value) -> String {
    item["documentation"]["value"]
        .as_str()
        .or_else(|| item["documentation"].as_str())
        .unwrap_or_default()
        .to_string()
}

fn committed_schema() -> Value {
    let path = root().join("schema/vbi.schema.json");
    serde_json::from_str(&std::fs::read_to_string(path).expect("schema file")).expect("JSON")
}

const BEAM: &str = "name: lsp\nbridge:\n  type: beam\n  spans: [20.0]\n  bending_stiffness: 3.2e9\n  mass_per_length: 2000.0\nvehicles:\n  - type: moving_force\n    loads: [1.0e5]\n    speed: 20.0\n";

#[test]
fn every_top_level_key_is_completed() {
    let Some(mut server) = start() else { return };
    let text = format!("{MODELINE}name: lsp\n\n");
    let items = server.complete("top.yaml", &text, 2);
    let offered = labels(&items);
    let schema = committed_schema();
    let keys: Vec<&String> = schema["properties"]
        .as_object()
        .expect("top-level properties")
        .keys()
        .filter(|k| *k != "name")
        .collect();
    for key in ["record", "study", "bridge", "vehicles", "solver"] {
        assert!(
            keys.iter().any(|k| *k == key),
            "`{key}` is not in the schema"
        );
    }
    let missing: Vec<&&String> = keys.iter().filter(|k| !offered.contains(**k)).collect();
    assert!(
        missing.is_empty(),
        "top-level keys not offered: {missing:?} (offered {offered:?})"
    );
    // Accepting a key that holds an object (a tagged union included) gives
    // `key:` and a new line, not a bare `key`.
    for key in ["bridge", "surface", "contact", "study", "solver"] {
        let text = insert_text(item(&items, key));
        assert!(
            text.starts_with(&format!("{key}:\n")),
            "`{key}` inserts {text:?}"
        );
    }
    // Defaults are real values, never null.
    let gravity = insert_text(item(&items, "gravity"));
    assert_eq!(gravity, "gravity: ${1:9.81}");
    assert!(
        items.iter().all(|i| !insert_text(i).contains("null")),
        "a completion inserts null: {items:#?}"
    );
}

#[test]
fn each_variant_completes_its_own_fields() {
    let Some(mut server) = start() else { return };
    let cases: &[(&str, &[&str], &[&str])] = &[
        (
            "bridge:\n  type: beam\n  ",
            &[
                "spans",
                "bending_stiffness",
                "mass_per_length",
                "elements_per_span",
                "modes",
                "damping",
            ],
            &["width", "rigidity"],
        ),
        (
            "bridge:\n  type: plate\n  ",
            &[
                "spans",
                "width",
                "rigidity",
                "girder_lines",
                "terms",
                "edges",
            ],
            &["bending_stiffness"],
        ),
        (
            "bridge:\n  type: plate\n  rigidity:\n    type: orthotropic\n    ",
            &[
                "flexural_rigidity_x",
                "flexural_rigidity_y",
                "torsional_rigidity",
                "poisson_ratio",
            ],
            &["youngs_modulus"],
        ),
        (
            "vehicles:\n  - type: h20_44\n    ",
            &["speed", "parameters", "lateral_position"],
            &["loads", "sprung_mass"],
        ),
        (
            "vehicles:\n  - type: oscillator\n    ",
            &["sprung_mass", "unsprung_mass", "stiffness", "dimensionless"],
            &["loads", "parameters"],
        ),
        (
            "contact:\n  type: hertz\n  ",
            &["coefficient", "wheel_radius", "profile"],
            &["stiffness"],
        ),
        (
            "study:\n  type: speed_sweep\n  ",
            &["speeds", "roughness", "samples", "span", "girder"],
            &["velocity_ratio"],
        ),
    ];
    for (i, (body, wanted, unwanted)) in cases.iter().enumerate() {
        let text = format!("{MODELINE}name: lsp\n{body}");
        let line = text.lines().count() - usize::from(!text.ends_with('\n'));
        let items = server.complete(&format!("variant{i}.yaml"), &text, line);
        let offered = labels(&items);
        for key in *wanted {
            assert!(
                offered.contains(*key),
                "`{key}` not offered after\n{body}\n(offered {offered:?})"
            );
        }
        for key in *unwanted {
            assert!(
                !offered.contains(*key),
                "`{key}` offered after\n{body}\n(offered {offered:?})"
            );
        }
    }
}

#[test]
fn values_are_completed_from_enums_with_their_descriptions() {
    let Some(mut server) = start() else { return };
    let cases: &[(&str, &[&str])] = &[
        ("bridge:\n  type: ", &["beam", "plate"]),
        (
            "vehicles:\n  - type: ",
            &["moving_force", "oscillator", "h20_44"],
        ),
        (
            "contact:\n  type: ",
            &["permanent", "rigid", "elastic", "hertz"],
        ),
        ("solver:\n  method: ", &["coupled", "lcp", "iterative"]),
        (
            "surface:\n  type: random\n  class: ",
            &["very_good", "good", "average", "poor", "very_poor"],
        ),
        (
            "surface:\n  type: ",
            &[
                "smooth",
                "harmonic",
                "random",
                "fra",
                "german",
                "iso8608",
                "measured",
                "ramp",
                "step",
                "bump",
                "dip",
                "piecewise_linear",
            ],
        ),
        (
            "surface:\n  type: german\n  interference: ",
            &["low", "high"],
        ),
        ("surface:\n  type: iso8608\n  class: ", &["A", "C", "H"]),
        (
            "surface:\n  type: fra\n  rails: ",
            &["identical", "independent"],
        ),
        (
            "record:\n  - quantity: ",
            &[
                "bridge_displacement",
                "bridge_acceleration",
                "contact_force",
                "contact_gap",
                "vehicle_displacement",
                "vehicle_acceleration",
            ],
        ),
        (
            "vehicles:\n  - type: moving_force\n    speed: ",
            &["100 km/h"],
        ),
        (
            "record:\n  - dof: ",
            &[
                "sprung",
                "wheel",
                "body_bounce",
                "body_pitch",
                "body_roll",
                "front_axle_bounce",
                "front_axle_roll",
                "rear_axle_bounce",
                "rear_axle_roll",
            ],
        ),
    ];
    for (i, (body, wanted)) in cases.iter().enumerate() {
        let text = format!("{MODELINE}name: lsp\n{body}\n");
        let line = text.lines().count() - 1;
        let items = server.complete(&format!("value{i}.yaml"), &text, line);
        let offered = labels(&items);
        for value in *wanted {
            assert!(
                offered.contains(*value),
                "`{value}` not offered after `{body}` (offered {offered:?})"
            );
        }
    }
    // A tag's completion carries the variant's own text, not a placeholder.
    let text = format!("{MODELINE}name: lsp\nbridge:\n  type: \n");
    let items = server.complete("tag.yaml", &text, 3);
    let doc = documentation(item(&items, "plate"));
    assert!(
        doc.contains("Rayleigh–Ritz"),
        "the `plate` tag says {doc:?}"
    );
    let text = format!("{MODELINE}name: lsp\nrecord:\n  - quantity: \n");
    let items = server.complete("quantity.yaml", &text, 3);
    let doc = documentation(item(&items, "bridge_acceleration"));
    assert!(doc.contains("m/s²"), "`bridge_acceleration` says {doc:?}");
}

#[test]
fn hover_shows_the_field_and_variant_text_with_units() {
    let Some(mut server) = start() else { return };
    let text = format!("{MODELINE}{BEAM}");
    // Line 4 is `  spans: [20.0]`, line 3 `  type: beam`.
    let spans = server.hover("hover.yaml", &text, 4, 4);
    assert!(
        spans.contains("Span lengths, m"),
        "hover on `spans`: {spans:?}"
    );
    let beam = server.hover("hover.yaml", &text, 3, 10);
    assert!(
        beam.contains("Euler–Bernoulli beam"),
        "hover on `beam`: {beam:?}"
    );
    let speed = server.hover("hover.yaml", &text, 10, 6);
    assert!(speed.contains("m/s"), "hover on `speed`: {speed:?}");
}

#[test]
fn a_bad_file_gets_diagnostics_where_vbi_check_would_object() {
    let Some(mut server) = start() else { return };
    // Each line breaks one rule `vbi check` enforces (see tests/it/schema.rs).
    let bad = format!(
        "{MODELINE}name: lsp\n\
         bridge:\n  type: beam\n  spans: [-20.0]\n  bending_stiffness: 3.2e9\n  mass_per_length: 2000.0\n  elements_per_span: 0\n\
         vehicles:\n  - type: moving_force\n    loads: []\n    speed: -20.0\n\
         \x20 - type: h20_44\n    speed: 80 kmh\n\
         colour: red\n\
         record:\n  - {{name: body, quantity: vehicle_displacement, dof: body}}\n"
    );
    let found = server.diagnose("bad.yaml", &bad);
    let lines: BTreeSet<u64> = found
        .iter()
        .filter_map(|d| d["range"]["start"]["line"].as_u64())
        .collect();
    // 0-based lines: 4 spans, 7 elements, 10 loads, 11 speed, 13 speed
    // unit, 14 colour, 16 dof.
    for (line, what) in [
        (4, "negative span"),
        (7, "0 elements"),
        (10, "no loads"),
        (11, "negative speed"),
        (13, "unknown speed unit"),
        (14, "unknown key"),
        (16, "unknown dof"),
    ] {
        assert!(
            lines.contains(&line),
            "no diagnostic for the {what} on line {}: {found:#?}",
            line + 1
        );
    }
    // …and the good scene gets none.
    let good = format!("{MODELINE}{BEAM}");
    let found = server.diagnose("good.yaml", &good);
    assert!(found.is_empty(), "diagnostics on a valid scene: {found:#?}");
}

#[test]
fn every_example_scenario_is_clean_in_the_editor() {
    let Some(mut server) = start() else { return };
    let mut files: Vec<PathBuf> = std::fs::read_dir(root().join("scenarios"))
        .expect("scenarios/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .collect();
    files.sort();
    let mut dirty = Vec::new();
    for path in files {
        let text = std::fs::read_to_string(&path).expect("scenario text");
        let name = path
            .file_name()
            .expect("file name")
            .to_string_lossy()
            .into_owned();
        let found = server.diagnose(&name, &text);
        if !found.is_empty() {
            dirty.push(format!("{name}: {found:#?}"));
        }
    }
    assert!(
        dirty.is_empty(),
        "the language server objects to:\n{}",
        dirty.join("\n")
    );
}

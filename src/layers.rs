//! The import-layer check (issue 25.1): every `crate::` reference in src/
//! points to the same or a lower layer, and no top-level modules import each
//! other in a circle. Compiled only into the library's unit tests, so it runs
//! in every `cargo test`.
//!
//! Granularity: a top-level module of src/ (a file `src/x.rs` or a folder
//! `src/x/`). The crate root (`lib.rs`) and the command line (`main.rs` and
//! the files only it declares) are the front end, above everything, and are
//! not checked. Comments are ignored: a doc link may point anywhere.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The declared layers, bottom first; a module may import its own layer
/// (without a circle) and every layer below it. See ARCHITECTURE.md.
const LAYERS: &[&[&str]] = &[
    // Plumbing that knows no physics and no format.
    &[
        "advice",
        "atomic_file",
        "guarded_file",
        "text_table",
        "timings",
    ],
    // The scene description: the resolved, validated, SI scene, plain data.
    &["scene"],
    // The scenario format: YAML → raw types → the resolved scene, and its
    // JSON Schema.
    &["scenario"],
    // The key reference generated from the format's schema, and the
    // starter scenes of `vbi init` (text only).
    &["format_reference", "init"],
    // Physics building blocks.
    &["contact", "ground", "surface"],
    &["vehicle"],
    &["bridge"],
    // The planning stage: the bridge's modal model built from the described
    // scene and every automatic choice that needs physics made.
    &["plan"],
    // The built system, its integration, the observer, the files.
    &["model"],
    &["solve"],
    &["record"],
    &["report"],
    // One scene end to end; studies composing it; the dispatch between them.
    &["run"],
    &["study"],
    &["execute", "export", "generate"],
    // Golden-file regression of users' scenes: runs scenes and studies.
    &["regress"],
];

/// Imports that still run upward, as (from, to) top-level modules, listed
/// so that any NEW one fails: none since the planning stage (`plan`) makes
/// the choices that need physics and the format reads its files itself
/// (issue 25). A line added here must be removed when its imports are gone
/// (the test fails on a stale line too).
const KNOWN_UPWARD: &[(&str, &str)] = &[];

/// Files not checked: the crate root, the command line (`main.rs` and the
/// files only it declares: `cli.rs`, `studies.rs`, the `*_cmd.rs`) and this
/// check (its test text names modules on purpose).
const FRONT_END_FILES: &[&str] = &[
    "lib.rs",
    "main.rs",
    "studies.rs",
    "regress_cmd.rs",
    "cli.rs",
    "run_cmd.rs",
    "modes_cmd.rs",
    "man_cmd.rs",
    "converge_cmd.rs",
    "generate_cmd.rs",
    "init_cmd.rs",
    "layers.rs",
];

fn layer_of(module: &str) -> Option<usize> {
    LAYERS.iter().position(|layer| layer.contains(&module))
}

/// `text` without `//` comments (line, doc and inner doc) and string
/// literals' contents are kept: a `crate::` inside a string is rare and
/// would only make the check stricter.
fn strip_comments(text: &str) -> String {
    text.lines()
        .map(|line| match line.find("//") {
            Some(i) => &line[..i],
            None => line,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Every top-level module named after `crate::` in `text`, including the
/// ones inside a `use crate::{a, b::c}` group.
fn referenced_modules(text: &str) -> BTreeSet<String> {
    let ident = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect()
    };
    let mut found = BTreeSet::new();
    let mut rest = text;
    while let Some(i) = rest.find("crate::") {
        rest = &rest[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            // Top-level names of the group: after `{` and after each `,` at depth 0.
            let mut depth = 0usize;
            let mut start = true;
            for (k, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => break,
                    '}' => depth -= 1,
                    ',' if depth == 0 => start = true,
                    c if c.is_whitespace() => {}
                    _ if start => {
                        let name = ident(&group[k..]);
                        if !name.is_empty() {
                            found.insert(name);
                        }
                        start = false;
                    }
                    _ => {}
                }
            }
        } else {
            let name = ident(rest);
            if !name.is_empty() {
                found.insert(name);
            }
        }
    }
    found
}

fn collect(dir: &Path, files: &mut Vec<std::path::PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .expect("src/ is readable")
        .flatten()
        .map(|e| e.path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            collect(&path, files);
        } else if path.extension().is_some_and(|e| e == "rs") {
            files.push(path);
        }
    }
}

/// module → (imported module → first file that imports it).
fn import_graph() -> BTreeMap<String, BTreeMap<String, String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    collect(&src, &mut files);
    let mut graph: BTreeMap<String, BTreeMap<String, String>> = BTreeMap::new();
    for file in files {
        let rel = file.strip_prefix(&src).expect("under src/");
        let parts: Vec<_> = rel
            .iter()
            .map(|p| p.to_string_lossy().into_owned())
            .collect();
        if parts.len() == 1 && FRONT_END_FILES.contains(&parts[0].as_str()) {
            continue;
        }
        let module = parts[0].trim_end_matches(".rs").to_string();
        let text = std::fs::read_to_string(&file).expect("source is readable");
        let edges = graph.entry(module.clone()).or_default();
        for target in referenced_modules(&strip_comments(&text)) {
            if target != module {
                edges
                    .entry(target)
                    .or_insert_with(|| rel.display().to_string());
            }
        }
    }
    graph
}

/// Strongly connected components of more than one module (Tarjan).
fn circles(graph: &BTreeMap<String, BTreeMap<String, String>>) -> Vec<Vec<String>> {
    struct State<'a> {
        graph: &'a BTreeMap<String, BTreeMap<String, String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        found: Vec<Vec<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        let i = s.index.len();
        s.index.insert(v, i);
        s.low.insert(v, i);
        s.stack.push(v);
        let targets: Vec<&'a str> = s
            .graph
            .get(v)
            .map(|e| e.keys().map(String::as_str).collect())
            .unwrap_or_default();
        for w in targets {
            if !s.index.contains_key(w) {
                visit(s, w);
                let lw = s.low[w];
                let lv = s.low.get_mut(v).expect("visited");
                *lv = (*lv).min(lw);
            } else if s.stack.contains(&w) {
                let iw = s.index[w];
                let lv = s.low.get_mut(v).expect("visited");
                *lv = (*lv).min(iw);
            }
        }
        if s.low[v] == s.index[v] {
            let mut component = Vec::new();
            while let Some(w) = s.stack.pop() {
                component.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if component.len() > 1 {
                component.sort();
                s.found.push(component);
            }
        }
    }
    let mut s = State {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        found: Vec::new(),
    };
    for v in graph.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    s.found
}

#[test]
fn every_module_has_a_layer() {
    let graph = import_graph();
    let unplaced: Vec<_> = graph
        .iter()
        .flat_map(|(m, e)| std::iter::once(m).chain(e.keys()))
        .filter(|m| layer_of(m).is_none())
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect();
    assert!(
        unplaced.is_empty(),
        "top-level modules in no layer of src/layers.rs: {unplaced:?}"
    );
}

#[test]
fn imports_run_only_downward() {
    let graph = import_graph();
    let mut upward = Vec::new();
    let mut used = BTreeSet::new();
    for (module, edges) in &graph {
        let (Some(from), true) = (layer_of(module), true) else {
            continue;
        };
        for (target, file) in edges {
            let Some(to) = layer_of(target) else { continue };
            if to > from {
                if KNOWN_UPWARD.contains(&(module.as_str(), target.as_str())) {
                    used.insert((module.as_str(), target.as_str()));
                } else {
                    upward.push(format!("{file} imports crate::{target} (a higher layer)"));
                }
            }
        }
    }
    let stale: Vec<_> = KNOWN_UPWARD.iter().filter(|e| !used.contains(*e)).collect();
    assert!(
        upward.is_empty(),
        "imports that run up the layers:\n{}",
        upward.join("\n")
    );
    assert!(
        stale.is_empty(),
        "KNOWN_UPWARD lists imports that are gone (remove them): {stale:?}"
    );
}

#[test]
fn no_import_circle() {
    let graph = import_graph();
    // The known upward imports close circles by construction; a circle made
    // only of downward and same-layer imports is a new one.
    let mut downward = graph.clone();
    for (module, edges) in &mut downward {
        edges.retain(|target, _| !KNOWN_UPWARD.contains(&(module.as_str(), target.as_str())));
    }
    let found = circles(&downward);
    assert!(found.is_empty(), "import circles: {found:?}");
}

#[test]
fn the_check_sees_grouped_and_nested_imports() {
    let text = "use crate::{report::{self, number}, solve::StepView};\nlet g = crate::contact::SEPARATION_GAP; // crate::run";
    let found = referenced_modules(&strip_comments(text));
    let expected: BTreeSet<String> = ["report", "solve", "contact"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(found, expected);
    let mut graph: BTreeMap<String, BTreeMap<String, String>> = BTreeMap::new();
    graph
        .entry("a".into())
        .or_default()
        .insert("b".into(), "a.rs".into());
    graph
        .entry("b".into())
        .or_default()
        .insert("a".into(), "b.rs".into());
    assert_eq!(
        circles(&graph),
        vec![vec!["a".to_string(), "b".to_string()]]
    );
}

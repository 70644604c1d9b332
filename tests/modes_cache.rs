//! The modes cache (src/bridge/eigen/cache.rs): a hit equals the miss bit
//! for bit, a truncated or corrupted file is recomputed (never trusted), a
//! changed matrix misses, a different request or bridge kind misses.

use vbi::bridge::eigen::Pencil;
use vbi::bridge::eigen::cache::{CacheOutcome, ModesCache};
use vbi::generate::reduce;
use vbi::generate::viaduct::{self, ViaductParams};

fn pencil(span_length: f64) -> Pencil {
    let params = ViaductParams {
        spans: 2,
        span_length,
        approach_length: 1.2,
        rail_divisions: 1,
        pier_elements: 2,
        ..Default::default()
    };
    reduce(&viaduct::assemble(&params).unwrap())
        .pencil()
        .unwrap()
}

fn bits(pairs: &vbi::bridge::eigen::Eigenpairs) -> Vec<u64> {
    pairs
        .eigenvalues
        .iter()
        .chain(pairs.vectors.col_iter().flat_map(|c| c.iter()))
        .map(|v| v.to_bits())
        .collect()
}

fn folder(tag: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("vbi-modes-cache-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn a_hit_equals_the_miss_bit_for_bit() {
    let dir = folder("hit");
    let cache = ModesCache {
        folder: dir.clone(),
        kind: "fe_import".into(),
    };
    let p = pencil(6.0);
    let (first, outcome) = p.lowest_cached(12, &cache).unwrap();
    assert_eq!(outcome, CacheOutcome::Miss);
    let (second, outcome) = p.lowest_cached(12, &cache).unwrap();
    assert_eq!(outcome, CacheOutcome::Hit);
    assert_eq!(bits(&first), bits(&second));
    assert_eq!(first.check, second.check);
    // And both equal an uncached solve.
    assert_eq!(bits(&p.lowest(12).unwrap()), bits(&first));
    // Another request, another kind: other keys.
    assert_eq!(p.lowest_cached(10, &cache).unwrap().1, CacheOutcome::Miss);
    let other = ModesCache {
        folder: dir.clone(),
        kind: "beam".into(),
    };
    assert_eq!(p.lowest_cached(12, &other).unwrap().1, CacheOutcome::Miss);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_changed_matrix_misses() {
    let dir = folder("changed");
    let cache = ModesCache {
        folder: dir.clone(),
        kind: "fe_import".into(),
    };
    let a = pencil(6.0);
    let b = pencil(6.6);
    assert_ne!(cache.key(&a, 12), cache.key(&b, 12));
    a.lowest_cached(12, &cache).unwrap();
    let (pairs, outcome) = b.lowest_cached(12, &cache).unwrap();
    assert_eq!(outcome, CacheOutcome::Miss);
    assert_eq!(bits(&pairs), bits(&b.lowest(12).unwrap()));
    // One value changed in its last bit changes the key.
    let mut k = a.stiffness.clone();
    let v = k.val_mut();
    v[7] = f64::from_bits(v[7].to_bits() ^ 1);
    let nudged = Pencil::new(k, a.mass.clone());
    assert_ne!(cache.key(&a, 12), cache.key(&nudged, 12));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn truncated_or_corrupted_files_are_recomputed() {
    let dir = folder("corrupt");
    let cache = ModesCache {
        folder: dir.clone(),
        kind: "fe_import".into(),
    };
    let p = pencil(6.0);
    let (fresh, _) = p.lowest_cached(12, &cache).unwrap();
    let path = cache.path(cache.key(&p, 12));
    let good = std::fs::read(&path).unwrap();
    let damaged: Vec<Vec<u8>> = vec![
        good[..good.len() / 2].to_vec(),
        Vec::new(),
        {
            // One bit of one vector entry flipped: the checksum catches it.
            let mut b = good.clone();
            let at = b.len() - 100;
            b[at] ^= 0x10;
            b
        },
        {
            // A consistent checksum over a wrong mode (a forged file: the
            // exponent byte of a vector entry changed): the re-check of the
            // residuals catches it. (A change in the last bits of an entry
            // would leave a mode that passes every check, a valid one.)
            let mut b = good[..good.len() - 16].to_vec();
            let at = b.len() - 1 - 8 * 50;
            b[at] ^= 0x40;
            let mut h = vbi::bridge::eigen::cache::Hasher::default();
            h.bytes(&b);
            b.extend_from_slice(&h.finish().to_le_bytes());
            b
        },
    ];
    for (i, bytes) in damaged.into_iter().enumerate() {
        std::fs::write(&path, &bytes).unwrap();
        let (pairs, outcome) = p.lowest_cached(12, &cache).unwrap();
        assert_eq!(outcome, CacheOutcome::Miss, "case {i}");
        assert_eq!(bits(&pairs), bits(&fresh), "case {i}");
        assert_eq!(
            std::fs::read(&path).unwrap(),
            good,
            "case {i}: rewritten whole"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Copies the shipped imported scene and its matrices into `dir`, so a
/// test may change a matrix file; returns the scene's path.
fn imported_scene(dir: &std::path::Path) -> std::path::PathBuf {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let data = dir.join("fe-import-lcp-fig4");
    std::fs::create_dir_all(&data).unwrap();
    for name in ["K.mtx", "M.mtx", "dofs.csv", "rail.csv"] {
        std::fs::copy(root.join("fe-import-lcp-fig4").join(name), data.join(name)).unwrap();
    }
    let scene = dir.join("scene.yaml");
    std::fs::copy(root.join("fe-import-lcp-fig4-rigid.yaml"), &scene).unwrap();
    scene
}

/// `vbi run SCENE --out OUT [extra]`: (summary.json's
/// `run.modes_from_cache`, history.csv's bytes).
fn run_cli(
    scene: &std::path::Path,
    out: &std::path::Path,
    extra: &[&str],
) -> (Option<bool>, Vec<u8>) {
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_vbi"))
        .arg("run")
        .arg(scene)
        .arg("--out")
        .arg(out)
        .arg("-q")
        .args(extra)
        .output()
        .unwrap();
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    (
        summary["run"]["modes_from_cache"].as_bool(),
        std::fs::read(out.join("history.csv")).unwrap(),
    )
}

/// `vbi run` of an imported model caches its modes in `<out>/.vbi-cache`
/// by default: the second run reads them (summary says so) and writes the
/// same bytes; a truncated cache file is solved again, a changed matrix
/// misses, `--modes-cache DIR` shares one folder between output folders,
/// and `--no-modes-cache` writes none.
#[test]
fn runs_read_their_modes_from_the_cache() {
    let dir = folder("cli");
    let scene = imported_scene(&dir);
    let out = dir.join("out");
    let (first, history) = run_cli(&scene, &out, &[]);
    assert_eq!(first, Some(false), "the first run solves");
    let (second, again) = run_cli(&scene, &out, &[]);
    assert_eq!(second, Some(true), "the second run reads the cache");
    assert!(history == again, "a cached run writes the same bytes");
    // Truncate every cache file: never trusted, solved again.
    let cache = out.join(".vbi-cache");
    let files: Vec<_> = std::fs::read_dir(&cache)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert!(!files.is_empty());
    for file in &files {
        let bytes = std::fs::read(file).unwrap();
        std::fs::write(file, &bytes[..bytes.len() / 2]).unwrap();
    }
    let (truncated, after) = run_cli(&scene, &out, &[]);
    assert_eq!(truncated, Some(false));
    assert!(history == after);
    // A changed stiffness entry of a free DOF (row 2 is node 1's ry; the
    // uz rows of nodes 1 and 21 are constrained away) misses.
    let k = dir.join("fe-import-lcp-fig4").join("K.mtx");
    let text = std::fs::read_to_string(&k).unwrap();
    let changed = text.replacen("\n2 2 12969200000.0\n", "\n2 2 12969200000.5\n", 1);
    assert_ne!(text, changed);
    std::fs::write(&k, changed).unwrap();
    let (changed_run, _) = run_cli(&scene, &out, &[]);
    assert_eq!(changed_run, Some(false), "a changed matrix misses");
    std::fs::write(&k, text).unwrap();
    // One shared folder for two output folders.
    let shared = dir.join("shared");
    let shared_arg = shared.to_str().unwrap();
    let (a, _) = run_cli(&scene, &dir.join("a"), &["--modes-cache", shared_arg]);
    let (b, _) = run_cli(&scene, &dir.join("b"), &["--modes-cache", shared_arg]);
    assert_eq!((a, b), (Some(false), Some(true)));
    assert!(!dir.join("a").join(".vbi-cache").exists());
    // No cache at all.
    let (none, plain) = run_cli(&scene, &dir.join("plain"), &["--no-modes-cache"]);
    assert_eq!(none, None);
    assert!(plain == history);
    assert!(!dir.join("plain").join(".vbi-cache").exists());
}

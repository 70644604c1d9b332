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
        assert!(
            matches!(outcome, CacheOutcome::Rejected(_)),
            "case {i}: {outcome:?}"
        );
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
    let (from_cache, history, _) = run_cli_noting(scene, out, extra);
    (from_cache, history)
}

/// [`run_cli`] and the run's standard error.
fn run_cli_noting(
    scene: &std::path::Path,
    out: &std::path::Path,
    extra: &[&str],
) -> (Option<bool>, Vec<u8>, String) {
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
        String::from_utf8_lossy(&status.stderr).into_owned(),
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
    let (truncated, after, stderr) = run_cli_noting(&scene, &out, &[]);
    assert_eq!(truncated, Some(false));
    assert!(history == after);
    assert!(
        stderr.contains("modes cache file of this model was not used (its length"),
        "{stderr}"
    );
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

/// A forged cache file (issue 23): modes 1 and 3–11 of an 11-mode solve
/// stored under the key of a 10-mode request, with that solve's Sturm
/// shift and count (the gap above mode 11, 11 below it), the check figures
/// a forger computes for the set (so a re-check that compares figures
/// passes) and the public FNV-1a checksum recomputed. Every stored pair is
/// a true eigenpair and the set is M-orthonormal, so only a Sturm count
/// made afresh against the stored eigenvalues can see that the 2nd mode is
/// missing: the file must not be used, and the modes must equal a fresh
/// solve bit for bit.
#[test]
fn a_forged_file_missing_a_mode_is_not_used() {
    let dir = folder("forged");
    let cache = ModesCache {
        folder: dir.clone(),
        kind: "fe_import".into(),
    };
    let p = pencil(6.0);
    let (eleven, _) = p.lowest_cached(11, &cache).unwrap();
    let (shift, counted) = eleven.check.inertia.expect("a cut above mode 11");
    assert_eq!(counted, 11);
    let kept: Vec<usize> = std::iter::once(0).chain(2..11).collect();
    let mut forged = vbi::bridge::eigen::Eigenpairs {
        eigenvalues: kept.iter().map(|&m| eleven.eigenvalues[m]).collect(),
        vectors: faer::Mat::from_fn(eleven.vectors.nrows(), 10, |i, j| {
            eleven.vectors[(i, kept[j])]
        }),
        check: eleven.check,
    };
    // The residual and orthonormality checks pass on the forged set: it is
    // made of true modes.
    p.verify(&mut forged, |x, y| {
        vbi::bridge::eigen::sparse::multiply(&p.stiffness, x, y)
    })
    .unwrap();
    let key = cache.key(&p, 10);
    let (order, count) = (forged.vectors.nrows(), 10usize);
    let mut bytes = b"VBIMODE1".to_vec();
    bytes.extend_from_slice(&key.to_le_bytes());
    let c = &forged.check;
    for word in [
        order as u64,
        count as u64,
        c.largest_residual.to_bits(),
        c.largest_plain_residual.to_bits(),
        c.orthonormality_error.to_bits(),
        shift.to_bits(),
        1,
        counted as u64,
        u64::from(c.dense),
        0,
    ] {
        bytes.extend_from_slice(&word.to_le_bytes());
    }
    for &lambda in &forged.eigenvalues {
        bytes.extend_from_slice(&lambda.to_bits().to_le_bytes());
    }
    for j in 0..count {
        for &v in forged.vectors.col(j).iter() {
            bytes.extend_from_slice(&v.to_bits().to_le_bytes());
        }
    }
    let mut h = vbi::bridge::eigen::cache::Hasher::default();
    h.bytes(&bytes);
    bytes.extend_from_slice(&h.finish().to_le_bytes());
    std::fs::write(cache.path(key), &bytes).unwrap();
    let (pairs, outcome) = p.lowest_cached(10, &cache).unwrap();
    assert_eq!(
        outcome,
        CacheOutcome::Rejected("a Sturm count of the model disagrees (a mode is missing)"),
        "the forged file was used"
    );
    let fresh = p.lowest(10).unwrap();
    assert_eq!(bits(&pairs), bits(&fresh));
    // The fresh 2nd mode is there (the forged file skipped it): the
    // 11-mode solve's, to round-off (another Krylov run).
    let (a, b) = (pairs.eigenvalues[1], eleven.eigenvalues[1]);
    assert!((a - b).abs() <= 1e-10 * b, "{a} against {b}");
    std::fs::remove_dir_all(&dir).unwrap();
}

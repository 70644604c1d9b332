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

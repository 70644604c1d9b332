//! The lowest modes of a Matrix Market pencil (K.mtx, M.mtx in a folder, as
//! `vbi generate` writes them) through vbi's checked eigen path, timed per
//! phase; the vbi side of benches/viaduct_eigen.sh (scipy's side:
//! benches/viaduct_eigen.py).
//!
//! Usage: mtx_modes DIR [COUNT=100] [--phases | --cache CACHE_DIR]
//! Threads: `VBI_THREADS` (default every core); the modes are bit-identical
//! whatever the number.
//! With `--cache`, the modes go through the modes cache (a second run reads
//! them back and re-checks them).
//! Prints the phases' times, the frequencies (Hz, one per line after a
//! `frequencies` line) and the checks.
//!
//! The reader here is a minimal one for the generator's own files (the
//! validated reader of every format is the `fe_import` bridge's).

use std::time::Instant;

use vbi::bridge::eigen::Pencil;
use vbi::bridge::eigen::sparse::symmetric_from_entries;

fn read(path: &std::path::Path) -> (usize, Vec<(usize, usize, f64)>) {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines().filter(|l| !l.starts_with('%'));
    let header: Vec<usize> = lines
        .next()
        .expect("size line")
        .split_whitespace()
        .map(|t| t.parse().expect("size"))
        .collect();
    let entries = lines
        .map(|l| {
            let mut t = l.split_whitespace();
            let r: usize = t.next().expect("row").parse().expect("row");
            let c: usize = t.next().expect("col").parse().expect("col");
            let v: f64 = t.next().expect("value").parse().expect("value");
            (r - 1, c - 1, v)
        })
        .collect();
    (header[0], entries)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let dir = std::path::Path::new(args.get(1).expect("usage: mtx_modes DIR [COUNT]"));
    let count: usize = args.get(2).map_or(100, |c| c.parse().expect("count"));
    let start = Instant::now();
    let (n, k) = read(&dir.join("K.mtx"));
    let (_, m) = read(&dir.join("M.mtx"));
    let threads = std::env::var("VBI_THREADS")
        .ok()
        .and_then(|v| v.parse::<std::num::NonZeroUsize>().ok())
        .or_else(|| std::thread::available_parallelism().ok())
        .unwrap_or(std::num::NonZeroUsize::MIN);
    let par = if threads.get() == 1 {
        faer::Par::Seq
    } else {
        faer::Par::Rayon(threads)
    };
    let pencil = Pencil::new(
        symmetric_from_entries(n, k, true).expect("K"),
        symmetric_from_entries(n, m, true).expect("M"),
    )
    .with_parallelism(par);
    let read_time = start.elapsed().as_secs_f64();
    let t = Instant::now();
    pencil.stiffness_factor().expect("factor");
    let factor_time = t.elapsed().as_secs_f64();
    if args.get(3).is_some_and(|a| a == "--phases") {
        // The phases of lowest_unverified, timed one by one.
        let factor = pencil.stiffness_factor().expect("factor");
        let t = Instant::now();
        let (_, single) =
            vbi::bridge::eigen::lanczos::lowest(&pencil.mass, factor, 0.0, count + 4, None)
                .expect("lanczos");
        let single_time = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let ritz = vbi::bridge::eigen::block::lowest(&pencil.mass, factor, count + 4, par)
            .expect("block lanczos")
            .map_or(single, |(_, ritz)| ritz);
        let lanczos_time = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let product = |x: &[f64], y: &mut [f64]| {
            vbi::bridge::eigen::sparse::multiply(&pencil.stiffness, x, y)
        };
        let (values, _) =
            vbi::bridge::eigen::lanczos::polish(&pencil.mass, factor, None, &product, &ritz)
                .expect("polish");
        let polish_time = t.elapsed().as_secs_f64();
        let t = Instant::now();
        vbi::bridge::eigen::lanczos::polish_block(
            &pencil.mass,
            &pencil.stiffness,
            factor,
            &ritz,
            par,
        )
        .expect("block polish");
        let block_time = t.elapsed().as_secs_f64();
        let t = Instant::now();
        let counted = pencil.count_below(values[count] * 0.999).expect("inertia");
        println!(
            "phases: single-vector lanczos {single_time:.2} s, block lanczos (used here) {lanczos_time:.2} s, polish per vector (beams) {polish_time:.2} s, block Rayleigh-Ritz polish (used here) {block_time:.2} s, inertia count {:.2} s ({counted})",
            t.elapsed().as_secs_f64()
        );
    }
    if args.get(3).is_some_and(|a| a == "--cache") {
        let cache = vbi::bridge::eigen::cache::ModesCache {
            folder: args.get(4).expect("--cache DIR").into(),
            kind: "fe_import".into(),
        };
        let t = Instant::now();
        let (pairs, outcome) = pencil.lowest_cached(count, &cache).expect("modes");
        println!("order {n}, modes {count}");
        println!(
            "read {read_time:.2} s, factor K {factor_time:.2} s, modes through the cache ({outcome:?}, checks included) {:.2} s, total {:.2} s",
            t.elapsed().as_secs_f64(),
            start.elapsed().as_secs_f64()
        );
        println!("checks {:?}", pairs.check);
        println!("frequencies");
        for lambda in &pairs.eigenvalues {
            println!("{:.12e}", lambda.sqrt() / (2.0 * std::f64::consts::PI));
        }
        return;
    }
    let t = Instant::now();
    let mut pairs = pencil.lowest_unverified(count, None).expect("modes");
    let solve_time = t.elapsed().as_secs_f64();
    let t = Instant::now();
    pencil
        .verify(&mut pairs, |x, y| {
            vbi::bridge::eigen::sparse::multiply(&pencil.stiffness, x, y)
        })
        .expect("checks");
    let verify_time = t.elapsed().as_secs_f64();
    println!("order {n}, modes {count}");
    println!(
        "read {read_time:.2} s, factor K {factor_time:.2} s, lanczos+polish+inertia {solve_time:.2} s, verify {verify_time:.2} s, total {:.2} s",
        start.elapsed().as_secs_f64()
    );
    println!("checks {:?}", pairs.check);
    println!("frequencies");
    for lambda in &pairs.eigenvalues {
        println!("{:.12e}", lambda.sqrt() / (2.0 * std::f64::consts::PI));
    }
}

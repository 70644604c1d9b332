//! The planning stage checks the cheap budgets first (issue 23, last point of
//! 3): a scene whose step count is over budget is refused before any eigen
//! solve. The evidence is timing-free: an imported model's solve writes its
//! modes to the `--modes-cache` folder, so a refusal that leaves the folder
//! empty never reached the solve, while the same scene at a valid time step
//! fills it (the check can fail).

use std::path::{Path, PathBuf};

use crate::support::{assert_exit, manifest_dir, text, vbi};

/// A scratch copy of the shipped 1,584-DOF viaduct scene (its matrices
/// beside it), with `solver:` replaced by `solver_line`.
fn viaduct_scene(tag: &str, solver_line: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("vbi-plan-order-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let data = dir.join("viaduct-2span");
    std::fs::create_dir_all(&data).unwrap();
    let shipped = manifest_dir().join("scenarios");
    for entry in std::fs::read_dir(shipped.join("viaduct-2span")).unwrap() {
        let path = entry.unwrap().path();
        std::fs::copy(&path, data.join(path.file_name().unwrap())).unwrap();
    }
    let yaml = std::fs::read_to_string(shipped.join("viaduct-2span-axle-loads.yaml")).unwrap();
    let yaml = yaml
        .replace(
            "# yaml-language-server: $schema=../schema/vbi.schema.json\n",
            "",
        )
        .replace("solver: {free_vibration: 0.2}", solver_line);
    assert!(
        yaml.contains(solver_line),
        "the shipped scene's solver line moved"
    );
    std::fs::write(dir.join("scene.yaml"), yaml).unwrap();
    dir
}

fn cache_files(folder: &Path) -> usize {
    std::fs::read_dir(folder).map_or(0, |d| d.flatten().count())
}

#[test]
fn a_step_budget_refusal_comes_before_the_eigen_solve() {
    // 0.2 s of free vibration plus the ~0.6 s crossing at 300 km/h over
    // 1e-8 s steps: ~8e7 steps, over the default budget of 1e7.
    let dir = viaduct_scene("over", "solver: {free_vibration: 0.2, time_step: 1.0e-8}");
    let cache = dir.join("cache");
    let out = vbi(
        &[
            "check",
            "scene.yaml",
            "--modes-cache",
            cache.to_str().unwrap(),
        ],
        &dir,
    );
    assert_exit(&out, 2);
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("scene.yaml:") && stderr.contains("time steps of 1.000e-8 s"),
        "{stderr}"
    );
    assert_eq!(
        cache_files(&cache),
        0,
        "the step budget was checked after the eigen solve (it wrote the modes cache)"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_same_scene_within_budget_does_solve() {
    // The control: at a valid step the check solves the eigenproblem and
    // writes the cache, so an empty folder above means the solve never ran.
    let dir = viaduct_scene("within", "solver: {free_vibration: 0.2, time_step: 1.0e-4}");
    let cache = dir.join("cache");
    let out = vbi(
        &[
            "check",
            "scene.yaml",
            "--modes-cache",
            cache.to_str().unwrap(),
        ],
        &dir,
    );
    assert_exit(&out, 0);
    assert!(
        cache_files(&cache) > 0,
        "no modes cache written: {}",
        text(&out.stderr)
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

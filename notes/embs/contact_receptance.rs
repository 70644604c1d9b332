//! Diagnostic (issue 24.4, helper EMBS): how the contact receptance of an
//! imported track converges with the modes kept, at the wheel–track frequency.
use std::f64::consts::PI;
use vbi::contact::ContactDirection;
use vbi::scenario;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = std::path::Path::new(&args[1]);
    let options = scenario::LoadOptions {
        allow_large: true,
        trust_limits: true,
        modes_cache: Some("notes/embs/.cache".into()),
        data: scenario::DataAccess {
            data_dirs: vec![std::path::PathBuf::from("scenarios").canonicalize().unwrap()],
            confine_to: None,
        },
    };
    let mut loaded = scenario::load_file_with(path, options).unwrap();
    let bridge = &mut loaded.bridge;
    bridge.prepare_contact_correction().unwrap();
    let n = bridge.mode_count();
    let f = bridge.frequencies();
    let gravity = loaded.scenario.gravity;
    for vehicle in &loaded.scenario.vehicles {
        let model = vbi::vehicle::VehicleModel::build(vehicle, gravity);
        for w in model.wheels.iter().take(4) {
            if let vbi::vehicle::WheelKind::Dof(d) = w.kind {
                println!("wheel dof {d} mass {:.1} kg", model.mass[(d, d)]);
            }
        }
    }
    for &(x, y) in &[(10.955, 0.88), (10.655, 0.88), (3.3, 0.88), (19.5, 0.88)] {
        for dir in [ContactDirection::Vertical, ContactDirection::Lateral] {
            let mut v = vec![0.0; n];
            bridge.contact_mode_values_in(dir, x, y, &mut v);
            let c = (dir, x, y);
            let zero = vec![0.0; n];
            // G: residual with no modes = green.
            let g = bridge.residual_flexibility(c, c, &zero, &zero);
            let w = |i: usize| 2.0 * PI * f[i];
            println!("x {x} y {y} {dir:?}: G = {g:.4e} m/N");
            for fexc in [20.0, 40.0, 60.0] {
                let om = 2.0 * PI * fexc;
                let full: f64 = (0..n).map(|i| v[i] * v[i] / (w(i).powi(2) - om * om)).sum();
                let mut line = format!("  f {fexc} H_full/G {:.4}:", full / g);
                for keep in [100, 200, 300, 400, 500, 564, 700, 846, 1000, 1128, 1300] {
                    if keep > n { continue; }
                    let modal: f64 = (0..keep).map(|i| v[i] * v[i] / (w(i).powi(2) - om * om)).sum();
                    let stat: f64 = (0..keep).map(|i| v[i] * v[i] / w(i).powi(2)).sum();
                    let h = modal + (g - stat);
                    let bound = (g - stat) * om * om / (w(keep.min(n - 1)).powi(2) - om * om);
                    line += &format!(" {keep}:{:.2e}|R/G {:.3}|b {:.1e}", (h - full) / full, (g - stat) / g, bound / full);
                }
                println!("{line}");
            }
        }
    }
}

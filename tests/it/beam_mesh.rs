//! Issue 40.6: a beam's mesh per span. `elements_per_span` is one count for
//! every span or a list with one per span; `element_length` gives each
//! span ceil(span / element_length) elements. Each test states its
//! reference and tolerance.

use std::fs;

use crate::support;

use support::{Scratch, assert_exit, text, vbi};
use vbi::bridge::ModalBridge;
use vbi::bridge::beam::BeamModel;
use vbi::plan::load_str;
use vbi::scene::{Beam, Bridge};

const SPANS: [f64; 3] = [20.0, 25.0, 20.0];
const EI: f64 = 8.323e9;
const M: f64 = 2303.0;

fn scene(mesh: &str) -> String {
    format!(
        "name: mesh\n\
         bridge:\n  type: beam\n  spans: [20.0, 25.0, 20.0]\n  bending_stiffness: {EI}\n\
         \x20 mass_per_length: {M}\n{mesh}  modes: {{count: 3}}\n\
         vehicles: [{{type: moving_force, loads: [1.0e5], speed: 20.0}}]\n"
    )
}

fn beam(mesh: &str) -> Beam {
    let loaded = load_str(&scene(mesh), "mesh.yaml").unwrap_or_else(|e| panic!("{e}"));
    match loaded.scenario.bridge {
        Bridge::Beam(b) => b,
        other => panic!("not a beam: {other:?}"),
    }
}

fn first_frequency(mesh: &str) -> f64 {
    let loaded = load_str(&scene(mesh), "mesh.yaml").unwrap_or_else(|e| panic!("{e}"));
    ModalBridge::build(&loaded.scenario.bridge)
        .unwrap()
        .frequencies()[0]
}

/// `[8, 10, 8]` on 20-25-20 m: nodes exactly at the supports 0, 20, 45
/// and 65 m (deflection fixed there, nowhere else) and every element
/// 2.5 m long, exactly (the node positions are multiples of 0.5 m, which
/// binary floating point holds exactly).
#[test]
fn a_list_meshes_each_span_with_its_count() {
    let beam = beam("  elements_per_span: [8, 10, 8]\n");
    assert_eq!(beam.elements_per_span, [8, 10, 8]);
    let model = BeamModel::new(&beam).unwrap();
    assert_eq!(model.node_x.len(), 8 + 10 + 8 + 1);
    for pair in model.node_x.windows(2) {
        assert_eq!(pair[1] - pair[0], 2.5, "element {pair:?}");
    }
    let supports: Vec<f64> = model
        .node_x
        .iter()
        .enumerate()
        .filter(|(n, _)| model.free_index[2 * n].is_none())
        .map(|(_, &x)| x)
        .collect();
    assert_eq!(supports, [0.0, 20.0, 45.0, 65.0]);
}

/// `element_length: 2.5` (and `2500 mm`) gives the same counts, [8, 10, 8]
/// (25 / 2.5 is 10, not 11: the ratio's round-off does not add an
/// element), so the same model and the same first frequency, bit for bit;
/// 2.4 m gives ceil(20/2.4) = 9 and ceil(25/2.4) = 11.
#[test]
fn an_element_length_gives_each_span_its_count() {
    assert_eq!(
        beam("  element_length: 2.5\n").elements_per_span,
        [8, 10, 8]
    );
    assert_eq!(
        beam("  element_length: 2500 mm\n").elements_per_span,
        [8, 10, 8]
    );
    assert_eq!(
        beam("  element_length: 2.4\n").elements_per_span,
        [9, 11, 9]
    );
    assert_eq!(
        beam("  element_length: 100.0\n").elements_per_span,
        [1, 1, 1]
    );
    let listed = first_frequency("  elements_per_span: [8, 10, 8]\n");
    let by_length = first_frequency("  element_length: 2.5\n");
    assert!(
        (listed - by_length).abs() <= 1e-14 * listed,
        "{listed} against {by_length}"
    );
}

/// The continuous beam's exact first circular frequency (rad/s): the
/// lowest β > 0 at which the 12 conditions on w = a sin βx + b cos βx +
/// c sinh βx + d cosh βx in each span (x from the span's start) have a
/// nontrivial solution — w = 0 at every support, w″ = 0 at both ends,
/// w′ and w″ continuous over the two inner supports — then ω = β²√(EI/m).
/// The determinant is an entire function of β (no poles), so the first
/// sign change above β = 0 (a trivial root) found on a fine scan and
/// bisected to round-off is the fundamental.
fn exact_first_omega() -> f64 {
    fn det(mut a: Vec<[f64; 12]>) -> f64 {
        let mut d = 1.0;
        for col in 0..12 {
            let pivot = (col..12)
                .max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
                .unwrap();
            if a[pivot][col] == 0.0 {
                return 0.0;
            }
            if pivot != col {
                a.swap(pivot, col);
                d = -d;
            }
            d *= a[col][col];
            let pivot_row = a[col];
            for row in a.iter_mut().skip(col + 1) {
                let f = row[col] / pivot_row[col];
                for (v, p) in row.iter_mut().zip(&pivot_row).skip(col) {
                    *v -= f * p;
                }
            }
        }
        d
    }
    // Derivative `order` (0–2) of the four functions at βx, in units of β^order.
    fn basis(beta: f64, x: f64, order: usize) -> [f64; 4] {
        let (s, c, sh, ch) = (
            (beta * x).sin(),
            (beta * x).cos(),
            (beta * x).sinh(),
            (beta * x).cosh(),
        );
        match order {
            0 => [s, c, sh, ch],
            1 => [c, -s, ch, sh],
            _ => [-s, -c, sh, ch],
        }
    }
    let conditions = |beta: f64| {
        let mut rows = Vec::new();
        let row = |span: usize, x: f64, order: usize, sign: f64| {
            let mut r = [0.0; 12];
            for (k, v) in basis(beta, x, order).into_iter().enumerate() {
                r[4 * span + k] = sign * v;
            }
            r
        };
        let add = |a: [f64; 12], b: [f64; 12]| {
            let mut r = a;
            for k in 0..12 {
                r[k] += b[k];
            }
            r
        };
        rows.push(row(0, 0.0, 2, 1.0));
        rows.push(row(2, SPANS[2], 2, 1.0));
        for (span, &length) in SPANS.iter().enumerate() {
            rows.push(row(span, 0.0, 0, 1.0));
            rows.push(row(span, length, 0, 1.0));
        }
        for (span, &length) in SPANS.iter().enumerate().take(2) {
            for order in [1, 2] {
                rows.push(add(
                    row(span, length, order, 1.0),
                    row(span + 1, 0.0, order, -1.0),
                ));
            }
        }
        det(rows)
    };
    let mut lo = 0.2 * std::f64::consts::PI / 25.0;
    let step = 1e-4 * lo;
    let start = conditions(lo).signum();
    let mut hi = lo + step;
    while conditions(hi).signum() == start {
        lo = hi;
        hi += step;
        assert!(hi < 1.0, "no root found");
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if conditions(mid).signum() == start {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let beta = 0.5 * (lo + hi);
    beta * beta * (EI / M).sqrt()
}

/// The first frequency against the continuous beam's exact one
/// ([`exact_first_omega`], 6.046865 Hz): 2.5 m elements within 2e-5
/// (measured 1.08e-5; Hermite cubics converge as h⁴ in the frequency, from
/// above: a conforming mesh), and halving the elements (`element_length:
/// 1.25`) divides the error by 16 ± 25 % (the h⁴ rate of a uniform
/// refinement; measured 6.8e-7, a ratio of 15.95).
#[test]
fn the_first_frequency_converges_to_the_continuous_beam_s_at_h4() {
    let exact = exact_first_omega() / (2.0 * std::f64::consts::PI);
    let coarse = first_frequency("  elements_per_span: [8, 10, 8]\n");
    let fine = first_frequency("  element_length: 1.25\n");
    let (e_coarse, e_fine) = ((coarse - exact) / exact, (fine - exact) / exact);
    eprintln!(
        "exact {exact:.9} Hz; 2.5 m {coarse:.9} ({e_coarse:.2e}), 1.25 m {fine:.9} ({e_fine:.2e})"
    );
    assert!(
        e_coarse > 0.0 && e_fine > 0.0,
        "a conforming mesh is stiffer"
    );
    assert!(e_coarse < 2e-5, "2.5 m elements: {e_coarse:.2e}");
    let ratio = e_coarse / e_fine;
    assert!(
        (12.0..=20.0).contains(&ratio),
        "refinement ratio {ratio:.2}"
    );
}

/// One number is every span's count, and the resolved scenario writes it
/// as one number again; a list of equal counts reads the same.
#[test]
fn one_number_is_every_span_s_count() {
    assert_eq!(
        beam("  elements_per_span: 12\n").elements_per_span,
        [12, 12, 12]
    );
    assert_eq!(beam("").elements_per_span, [20, 20, 20]);
    let loaded = load_str(&scene("  elements_per_span: 12\n"), "mesh.yaml").unwrap();
    let resolved = vbi::report::folder::resolved_yaml(&loaded.scenario);
    assert!(resolved.contains("elements_per_span: 12\n"), "{resolved}");
    let loaded = load_str(&scene("  element_length: 2.5\n"), "mesh.yaml").unwrap();
    let resolved = vbi::report::folder::resolved_yaml(&loaded.scenario);
    assert!(resolved.contains("elements_per_span:"), "{resolved}");
    assert!(!resolved.contains("element_length"), "{resolved}");
}

/// Each bad form is refused by `vbi check` with exit 2, located at
/// `FILE:LINE:COL` on the offending value.
#[test]
fn bad_forms_are_located_errors() {
    let scratch = Scratch::new("beam_mesh", "bad");
    // (what, the mesh lines, line:column, a part of the message)
    let cases: &[(&str, &str, &str, &str)] = &[
        (
            "both",
            "  elements_per_span: 10\n  element_length: 2.5\n",
            "8:19",
            "not both",
        ),
        (
            "too short a list",
            "  elements_per_span: [8, 10]\n",
            "7:22",
            "2 counts for 3 spans",
        ),
        (
            "too long a list",
            "  elements_per_span: [8, 10, 8, 8]\n",
            "7:22",
            "4 counts for 3 spans",
        ),
        (
            "a zero count",
            "  elements_per_span: [8, 0, 8]\n",
            "7:26",
            "between 1 and 4000, got 0",
        ),
        (
            "a negative count",
            "  elements_per_span: [8, -1, 8]\n",
            "7:26",
            "out of range",
        ),
        (
            "a fractional count",
            "  elements_per_span: [8, 2.5, 8]\n",
            "7:26",
            "expected a whole number",
        ),
        (
            "too many on a span",
            "  elements_per_span: [8, 4001, 8]\n",
            "7:26",
            "between 1 and 4000, got 4001",
        ),
        (
            "a zero length",
            "  element_length: 0.0\n",
            "7:19",
            "element length",
        ),
        (
            "a time for a length",
            "  element_length: 2 s\n",
            "7:19",
            "length",
        ),
        (
            "too short an element",
            "  element_length: 1 mm\n",
            "7:19",
            "20000 elements on span 1",
        ),
    ];
    let mut failures = Vec::new();
    for (i, (what, mesh, at, message)) in cases.iter().enumerate() {
        let file = format!("bad-{i}.yaml");
        fs::write(scratch.path(&file), scene(mesh)).unwrap();
        let out = vbi(&["check", &file], scratch.dir());
        let stderr = text(&out.stderr);
        let located = format!("{file}:{at}: ");
        if out.status.code() != Some(2) || !stderr.contains(&located) || !stderr.contains(message) {
            failures.push(format!(
                "{what}: exit {:?}, expected 2 with `{located}` and `{message}`:\n{stderr}",
                out.status.code()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    // And the good forms pass.
    for (i, mesh) in [
        "  elements_per_span: [8, 10, 8]\n",
        "  element_length: 2.5 m\n",
    ]
    .iter()
    .enumerate()
    {
        let file = format!("good-{i}.yaml");
        fs::write(scratch.path(&file), scene(mesh)).unwrap();
        assert_exit(&vbi(&["check", &file], scratch.dir()), 0);
    }
}

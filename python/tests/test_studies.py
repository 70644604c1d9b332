"""Studies return their tables as DataFrames equal to the CSV files `vbi
run` writes (small copies of shipped study scenes, so the test is quick),
and `vbi.modes` gives `vbi modes`' frequencies and shapes bit for bit."""

import json
import subprocess
from pathlib import Path

import numpy as np
import pytest

import vbi
from conftest import REPO, SCENARIOS, assert_bitwise_equal, cli_run, read_csv, vbi_binary


def shrunk(name: str, replacements, folder: Path) -> Path:
    """A copy of a shipped scene with its study made small."""
    text = (SCENARIOS / name).read_text()
    for old, new in replacements:
        assert old in text, (name, old)
        text = text.replace(old, new)
    path = folder / name
    path.write_text(text)
    return path


STUDIES = {
    "separation_map": (
        "lcp-fig6-smooth.yaml",
        [("count: 20}\n  mass_ratio", "count: 3}\n  mass_ratio"), ("to: 2.0, count: 20}", "to: 2.0, count: 2}")],
    ),
    "speed_sweep": (
        "moving-force-slow.yaml",
        [
            ("time_step: 2.0e-5", "time_step: 2.0e-4"),
            ("record:", "study: {type: speed_sweep, speeds: {from: 10.0, to: 40.0, count: 3}}\nrecord:"),
        ],
    ),
    "monte_carlo": ("lcp-fig7-monte-carlo.yaml", [("samples: 20, seed: 7, show: 5", "samples: 3, seed: 7, show: 2")]),
    "resonance_check": (
        "hslm-resonance-20m.yaml",
        [("trains: [A1, A5, A10]", "trains: [A1]"), ("step: 20 km/h", "step: 80 km/h")],
    ),
}


@pytest.mark.parametrize("study", sorted(STUDIES))
def test_study_tables_equal_csv_files(study, tmp_path):
    name, replacements = STUDIES[study]
    scene = shrunk(name, replacements, tmp_path)
    out = cli_run(scene, tmp_path / "out") if study != "resonance_check" else _cli_run_any(scene, tmp_path / "out")
    result = vbi.run(scene)
    assert isinstance(result, vbi.StudyResult)
    assert result.study == study
    files = sorted(p.stem for p in out.glob("*.csv"))
    assert sorted(result.tables) == files and files
    for stem in files:
        expected = read_csv(out / f"{stem}.csv")
        actual = result.tables[stem]
        assert list(actual.columns) == list(expected.columns), stem
        assert actual.equals(expected), stem
    expected_summary = json.loads((out / "summary.json").read_text())
    assert set(result.summary) == set(expected_summary)
    assert "<table" in result._repr_html_()


def _cli_run_any(scene: Path, out: Path) -> Path:
    """`vbi run` of a check that may fail (exit 3: a failed check still
    writes its tables)."""
    done = subprocess.run(
        [str(vbi_binary()), "run", str(scene), "--out", str(out), "--quiet"],
        cwd=REPO,
        stdout=subprocess.DEVNULL,
    )
    assert done.returncode in (0, 3)
    return out


def test_separation_map_as_2d_array(tmp_path):
    name, replacements = STUDIES["separation_map"]
    result = vbi.run(shrunk(name, replacements, tmp_path))
    values, velocity_ratio, mass_ratio = result.separation_map()
    # Grids from the scene: velocity ratio 0.05..1.0 (3), mass ratio 0.1..2.0 (2).
    assert values.shape == (3, 2)
    np.testing.assert_allclose(velocity_ratio, [0.05, 0.525, 1.0], rtol=1e-12)
    np.testing.assert_allclose(mass_ratio, [0.1, 2.0], rtol=1e-12)
    table = result.tables["study"]
    column = table.columns[2]
    first = table[(table.iloc[:, 0] == velocity_ratio[0]) & (table.iloc[:, 1] == mass_ratio[1])]
    assert values[0, 1] == first[column].iloc[0]


def test_modes_equal_cli(tmp_path):
    scene = SCENARIOS / "yang-yau-sprung-mass.yaml"
    shapes_csv = tmp_path / "shapes.csv"
    done = subprocess.run(
        [str(vbi_binary()), "modes", str(scene), "--json"],
        cwd=REPO, capture_output=True, text=True, check=True,
    )
    subprocess.run(
        [str(vbi_binary()), "modes", str(scene), "--shapes", str(shapes_csv)],
        cwd=REPO, stdout=subprocess.DEVNULL, check=True,
    )
    expected = json.loads(done.stdout)
    modes = vbi.modes(scene)
    assert modes.frequencies.shape == (10,)
    assert_bitwise_equal(modes.frequencies, [m["frequency_hz"] for m in expected["modes"]], "frequency")
    assert_bitwise_equal(modes.damping_ratios, [m["damping_ratio"] for m in expected["modes"]], "damping")
    table = read_csv(shapes_csv)
    assert modes.shapes.shape == (len(table), 10)
    assert_bitwise_equal(modes.x, table["x [m]"].to_numpy(), "x")
    for i in range(10):
        assert_bitwise_equal(modes.shapes[:, i], table.iloc[:, 1 + i].to_numpy(), f"mode {i + 1}")
    # Closed form, simply supported Euler–Bernoulli beam:
    # f1 = (π / 2 L²) √(EI / m) = 4.7779 Hz for this bridge; the FE model with
    # 20 elements is within 1e-4 of it.
    f1 = np.pi / (2 * 25.0**2) * np.sqrt(8.323e9 / 2303.0)
    assert abs(modes.frequencies[0] - f1) / f1 < 1e-4

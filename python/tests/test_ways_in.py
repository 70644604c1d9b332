"""Each way in (path, YAML string, dict) gives `vbi run`'s history.csv bit
for bit, and the DataFrame has the documented shape: time index in s,
one column per record named as in the scene, units in attrs."""

from pathlib import Path

import pytest

import vbi
from conftest import SCENARIOS, assert_history_equals_csv, cli_run

YANG_YAU = SCENARIOS / "yang-yau-sprung-mass.yaml"

# scenarios/yang-yau-sprung-mass.yaml written as a dict (the description
# left out: it does not change the run).
YANG_YAU_DICT = {
    "name": "yang-yau-sprung-mass",
    "bridge": {
        "type": "beam",
        "spans": [25.0],
        "bending_stiffness": 8.323e9,
        "mass_per_length": 2303.0,
        "elements_per_span": 20,
        "modes": {"count": 10},
    },
    "vehicles": [
        {
            "type": "oscillator",
            "sprung_mass": 5750.0,
            "unsprung_mass": 0.0,
            "stiffness": 1.595e6,
            "speed": 27.777777777777778,
        }
    ],
    "solver": {"method": "coupled", "time_step": 1.0e-4},
    "record": [
        {"name": "midspan", "quantity": "bridge_displacement", "x": 12.5},
        {"name": "midspan_acceleration", "quantity": "bridge_acceleration", "x": 12.5},
        {"name": "body", "quantity": "vehicle_displacement", "vehicle": 1, "dof": "sprung"},
        {"name": "body_acceleration", "quantity": "vehicle_acceleration", "vehicle": 1, "dof": "sprung"},
        {"name": "contact_force", "quantity": "contact_force", "vehicle": 1, "wheel": 1},
    ],
}

RECORDS = ["midspan", "midspan_acceleration", "body", "body_acceleration", "contact_force"]


@pytest.fixture(scope="module")
def cli_history(tmp_path_factory) -> Path:
    out = cli_run(YANG_YAU, tmp_path_factory.mktemp("cli") / "out")
    return out / "history.csv"


def test_path_equals_cli(cli_history):
    result = vbi.run(str(YANG_YAU))
    assert_history_equals_csv(result.history, cli_history)


def test_pathlike_equals_cli(cli_history):
    assert_history_equals_csv(vbi.run(YANG_YAU).history, cli_history)


def test_yaml_string_equals_cli(cli_history):
    result = vbi.run(YANG_YAU.read_text())
    assert_history_equals_csv(result.history, cli_history)


def test_dict_equals_cli(cli_history):
    result = vbi.run(YANG_YAU_DICT)
    assert_history_equals_csv(result.history, cli_history)


def test_history_columns_index_and_units():
    result = vbi.run(YANG_YAU)
    h = result.history
    # One column per record, named as in the scene, and the static
    # crossing response beside the bridge displacement.
    assert list(h.columns) == ["midspan", "midspan_static", *RECORDS[1:]]
    assert h.index.name == "time"
    assert h.index[0] == 0.0
    # 25 m at 100 km/h: the crossing takes 0.9 s; Δt = 1e-4 s.
    assert h.index[1] == 1.0e-4
    assert h.index.is_monotonic_increasing
    assert h.attrs["units"] == {
        "time": "s",
        "midspan": "m",
        "midspan_static": "m",
        "midspan_acceleration": "m/s^2",
        "body": "m",
        "body_acceleration": "m/s^2",
        "contact_force": "N",
    }
    assert result.units == h.attrs["units"]
    # The summary is summary.json's content: its extremes are the history's.
    quantities = {q["name"]: q for q in result.summary["quantities"]}
    assert quantities["midspan"]["min"]["value"] == h["midspan"].min()
    assert 'name: "yang-yau-sprung-mass"' in result.resolved
    assert result.separation is None  # permanent contact
    assert result.envelopes is None
    html = result._repr_html_()
    assert "yang-yau-sprung-mass" in html and "midspan" in html


def test_summary_equals_summary_json(tmp_path):
    """The summary dict is summary.json's content but for the wall time."""
    import json

    out = cli_run(YANG_YAU, tmp_path / "out")
    expected = json.loads((out / "summary.json").read_text())
    actual = vbi.run(YANG_YAU).summary
    for summary in (expected, actual):
        assert summary["run"].pop("wall_time") >= 0.0
    assert actual == expected


def test_check_returns_resolved_yaml(tmp_path):
    """`vbi.check` gives resolved.yaml's text; the dict (without the
    description) resolves to the same scene as the file."""
    out = cli_run(YANG_YAU, tmp_path / "out")
    # `vbi run` adds the line naming the file the folder's results are from.
    written = (out / "resolved.yaml").read_text().splitlines(keepends=True)
    assert vbi.check(YANG_YAU) == "".join(l for l in written if not l.startswith("# From: "))
    without_description = lambda text: [  # noqa: E731
        line for line in text.splitlines() if not line.startswith("description:")
    ]
    assert without_description(vbi.check(YANG_YAU_DICT)) == without_description(vbi.check(YANG_YAU))

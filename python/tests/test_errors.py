"""An invalid scene raises one ScenarioError (a ValueError) with every
diagnostic located: file, line and column for a file or string, the key
path for a dict; the messages are `vbi check`'s."""

import subprocess

import pytest

import vbi
from conftest import REPO, vbi_binary

# Three type errors, all reported in one round: a word for a number, a
# misspelt key, a speed without a unit.
THREE_ERRORS = """\
name: three-errors
bridge:
  type: beam
  spans: [25.0]
  bending_stiffness: 8.323e9
  mass_per_length: heavy
  modes: {count: 4}
vehicles:
  - type: oscillator
    sprung_mas: 5750.0
    unsprung_mass: 0.0
    stiffness: 1.595e6
    speed: fast
solver:
  time_step: 1.0e-4
record:
  - {name: midspan, quantity: bridge_displacement, x: 12.5}
"""

THREE_ERRORS_DICT = {
    "name": "three-errors",
    "bridge": {
        "type": "beam",
        "spans": [25.0],
        "bending_stiffness": 8.323e9,
        "mass_per_length": "heavy",
        "modes": {"count": 4},
    },
    "vehicles": [
        {
            "type": "oscillator",
            "sprung_mas": 5750.0,
            "unsprung_mass": 0.0,
            "stiffness": 1.595e6,
            "speed": "fast",
        }
    ],
    "solver": {"time_step": 1.0e-4},
    "record": [{"name": "midspan", "quantity": "bridge_displacement", "x": 12.5}],
}


def test_file_raises_three_located_diagnostics(tmp_path):
    scene = tmp_path / "three.yaml"
    scene.write_text(THREE_ERRORS)
    with pytest.raises(vbi.ScenarioError) as caught:
        vbi.run(scene)
    error = caught.value
    assert isinstance(error, ValueError)
    located = [(d.file, d.line, d.column) for d in error.diagnostics]
    assert located == [(str(scene), 6, 20), (str(scene), 10, 5), (str(scene), 13, 12)]
    assert "expected a number" in error.diagnostics[0].message
    assert "sprung_mas" in error.diagnostics[1].message
    assert "fast" in error.diagnostics[2].message
    # The same text as `vbi check` prints after its `error: ` prefix.
    check = subprocess.run(
        [str(vbi_binary()), "check", str(scene)], cwd=REPO, capture_output=True, text=True
    )
    assert check.returncode == 2
    # `vbi check` starts each diagnostic with `error: ` (issue 38.8).
    lines = check.stderr.strip().splitlines()
    assert lines[0].startswith("error: ")
    unprefixed = "\n".join(l[len("error: "):] if l.startswith("error: ") else l for l in lines)
    assert unprefixed == str(error)


def test_string_is_located_in_the_string():
    with pytest.raises(vbi.ScenarioError) as caught:
        vbi.check(THREE_ERRORS)
    assert [(d.line, d.column) for d in caught.value.diagnostics] == [(6, 20), (10, 5), (13, 12)]
    assert all(d.file == "<string>" for d in caught.value.diagnostics)


def test_dict_diagnostics_name_key_paths():
    with pytest.raises(vbi.ScenarioError) as caught:
        vbi.run(THREE_ERRORS_DICT)
    paths = [d.path for d in caught.value.diagnostics]
    assert paths == [
        "bridge.mass_per_length",
        "vehicles[0].sprung_mas",
        "vehicles[0].speed",
    ]
    assert str(caught.value).splitlines()[0].startswith("bridge.mass_per_length: ")


def test_dict_semantic_error_names_the_key():
    scene = {**THREE_ERRORS_DICT, "bridge": {**THREE_ERRORS_DICT["bridge"], "mass_per_length": 2303.0}}
    scene["vehicles"] = [{**THREE_ERRORS_DICT["vehicles"][0], "speed": 25.0}]
    del scene["vehicles"][0]["sprung_mas"]
    scene["vehicles"][0]["sprung_mass"] = -5750.0
    with pytest.raises(vbi.ScenarioError) as caught:
        vbi.check(scene)
    assert [d.path for d in caught.value.diagnostics] == ["vehicles[0].sprung_mass"]


def test_missing_file_is_an_os_error(tmp_path):
    with pytest.raises(OSError):
        vbi.run(tmp_path / "missing.yaml")


def test_bad_type_is_a_type_error():
    with pytest.raises(TypeError):
        vbi.run(42)
    with pytest.raises(TypeError):
        vbi.run({"name": object()})

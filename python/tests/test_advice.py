"""Advice reaches Python (issue 38, point 2): ``result.advice`` holds the
same values as ``summary.json``, each unallowed warning is raised through
``warnings.warn`` as a ``vbi.VbiWarning`` (so ``pytest -W error`` sees it),
``strict=True`` raises ``vbi.VbiWarningError`` holding the result, and an
``allow`` entry silences one id while its reason stays in the result.

The warning scene: a 100 kN force at alpha = v / (2 f1 L) = 2 over the Yang
& Yau beam (f1 = 4.7779 Hz, L = 25 m: v = 477.8 m/s) with no free
vibration. Above alpha = 1 the largest deflection comes after the force
has left the span (Fryba 1972, section 1.3), so the midspan record ends at
its largest value: advice id ``run-ends-at-peak``.
"""

import warnings

import pytest

import vbi
from conftest import SCENARIOS

ALPHA_2 = """name: advice-alpha-2
bridge:
  type: beam
  spans: [25.0]
  bending_stiffness: 8.323e9
  mass_per_length: 2303.0
  modes: {count: 4}
  damping: {type: modal, ratio: 0.02}
vehicles:
  - {type: moving_force, loads: [100.0e3], speed: 477.8 m/s}
solver: {time_step: 2.0e-4, free_vibration: 0.0}
record:
  - {name: midspan, quantity: bridge_displacement, x: 12.5}
"""

ALLOW = """allow:
  - {id: run-ends-at-peak, reason: only the crossing itself is wanted}
"""


def test_result_advice_matches_the_summary():
    with pytest.warns(vbi.VbiWarning, match=r"\[run-ends-at-peak\]"):
        result = vbi.run(ALPHA_2)
    ids = [a.id for a in result.advice]
    assert "run-ends-at-peak" in ids
    assert ids == [a["id"] for a in result.summary["advice"]]
    peak = next(a for a in result.advice if a.id == "run-ends-at-peak")
    assert peak.severity == "warning"
    assert peak.counts
    assert peak.help


def test_strict_raises_with_the_result():
    with pytest.raises(vbi.VbiWarningError) as raised:
        vbi.run(ALPHA_2, strict=True)
    assert [a.id for a in raised.value.advice] == ["run-ends-at-peak"]
    assert raised.value.result.history.shape[0] > 0


def test_warnings_as_errors_stop_the_run():
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.VbiWarning)
        with pytest.raises(vbi.VbiWarning):
            vbi.run(ALPHA_2)


def test_an_allowed_id_is_kept_with_its_reason_and_not_raised():
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.VbiWarning)
        result = vbi.run(ALPHA_2 + ALLOW, strict=True)
    peak = next(a for a in result.advice if a.id == "run-ends-at-peak")
    assert peak.allowed == "only the crossing itself is wanted"
    assert not peak.counts


def test_a_clean_scene_has_no_warnings():
    with warnings.catch_warnings():
        warnings.simplefilter("error", vbi.VbiWarning)
        result = vbi.run(SCENARIOS / "yang-yau-sprung-mass.yaml", strict=True)
    assert [a for a in result.advice if a.counts] == []


def test_a_study_carries_its_points_advice():
    sweep = ALPHA_2 + "study: {type: speed_sweep, speeds: {from: 400.0, to: 480.0, count: 3}}\n"
    with pytest.warns(vbi.VbiWarning, match=r"run-ends-at-peak"):
        result = vbi.run(sweep)
    peak = next(a for a in result.advice if a.id == "run-ends-at-peak")
    assert len(peak.points) >= 1

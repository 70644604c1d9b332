"""Shared helpers: the repository, the `vbi` command-line binary built from
it, and reading its CSV files with every number exact."""

import os
import subprocess
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

REPO = Path(__file__).resolve().parents[2]
SCENARIOS = REPO / "scenarios"


def vbi_binary() -> Path:
    """The command line to compare against: $VBI_BIN, else the release
    build of this repository (`cargo build --release`; python/ci.sh does it)."""
    path = Path(os.environ.get("VBI_BIN", REPO / "target" / "release" / "vbi"))
    if not path.exists():
        pytest.skip(f"no vbi binary at {path}: run `cargo build --release` first")
    return path


def cli_run(scene: Path, out: Path) -> Path:
    """`vbi run SCENE --out OUT --quiet`; returns OUT."""
    subprocess.run(
        [str(vbi_binary()), "run", str(scene), "--out", str(out), "--quiet"],
        check=True,
        cwd=REPO,
        stdout=subprocess.DEVNULL,
    )
    return out


def read_csv(path: Path) -> pd.DataFrame:
    """A CSV table with every number parsed to the double its shortest
    round-trip text names (pandas' C parser before 3.0 may be off by an ulp
    unless asked for round-trip parsing; 3.0 is exact by default)."""
    exact = {} if int(pd.__version__.split(".")[0]) >= 3 else {"float_precision": "round_trip"}
    return pd.read_csv(path, **exact)


def bits(values) -> np.ndarray:
    """The IEEE-754 bit patterns of `values`, with -0 as +0 (the CSV
    writes both as `0`), for comparisons bit for bit."""
    a = np.ascontiguousarray(np.asarray(values, dtype=np.float64)) + 0.0
    return a.view(np.uint64)


def assert_bitwise_equal(actual, expected, what: str) -> None:
    a, e = bits(actual), bits(expected)
    assert a.shape == e.shape, f"{what}: shape {a.shape} != {e.shape}"
    differ = np.flatnonzero(a != e)
    assert differ.size == 0, (
        f"{what}: {differ.size} values differ, first at row {differ[0]}: "
        f"{np.asarray(actual)[differ[0]]!r} != {np.asarray(expected)[differ[0]]!r}"
    )


def assert_history_equals_csv(history: pd.DataFrame, csv: Path) -> None:
    """The DataFrame equals history.csv bit for bit: the index is the time
    column, each DataFrame column the CSV column at the same position (the
    CSV header carries the unit, the DataFrame the bare record name)."""
    table = read_csv(csv)
    assert table.shape[1] == history.shape[1] + 1, (list(table.columns), list(history.columns))
    assert_bitwise_equal(history.index.to_numpy(), table.iloc[:, 0].to_numpy(), "time")
    for k, name in enumerate(history.columns):
        header = table.columns[k + 1]
        assert header.startswith(name), f"column {k}: {name!r} vs CSV header {header!r}"
        assert_bitwise_equal(history[name].to_numpy(), table.iloc[:, k + 1].to_numpy(), name)

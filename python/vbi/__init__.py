"""vbi from Python: run vehicle–bridge interaction scenes and get the
results as pandas DataFrames and numpy arrays.

A scene is given one of three ways, all giving the same results bit for bit
as ``vbi run`` on the command line:

* a path to a YAML file (``str`` without a line break, or ``os.PathLike``);
* YAML text (a ``str`` with a line break or starting with ``{``);
* a plain ``dict`` nested as the YAML.

>>> import vbi
>>> result = vbi.run("scenarios/yang-yau-sprung-mass.yaml")   # doctest: +SKIP
>>> result.history["midspan"].min()                            # doctest: +SKIP

Units are SI throughout; a DataFrame's units are in ``df.attrs["units"]``.
A scene that fails its checks raises :class:`ScenarioError` with every
diagnostic. Runs release the GIL (threads run scenes in parallel) and stop
on Ctrl-C with ``KeyboardInterrupt``. Nothing is printed: what vbi knows
about a result (its warnings and notes, docs/advice.md) is in
``result.advice`` and each warning is raised through :func:`warnings.warn`
as a :class:`VbiWarning` (so ``pytest -W error`` and notebooks show it);
``run(scene, strict=True)`` raises :class:`VbiWarningError` instead.
"""

from __future__ import annotations

import io
import json
import os
import tempfile
import warnings
from dataclasses import dataclass, field
from html import escape
from pathlib import Path
from typing import Any, Callable, Dict, List, Mapping, Optional, Tuple, Union

import numpy as np
import pandas as pd

from . import _vbi
from ._dict_yaml import path_at, to_yaml

__all__ = [
    "Advice",
    "Diagnostic",
    "Modes",
    "Result",
    "ScenarioError",
    "StudyResult",
    "VbiWarning",
    "VbiWarningError",
    "check",
    "modes",
    "run",
    "__version__",
]

__version__: str = _vbi.__version__

Scene = Union[str, "os.PathLike[str]", Mapping[str, Any]]
Progress = Callable[[int, int], Any]


@dataclass(frozen=True)
class Diagnostic:
    """One located problem in a scene, as ``vbi check`` reports it.

    ``file``, ``line`` and ``column`` (1-based) locate it in the YAML file or
    string; for a dict scene ``file`` is ``"<dict>"``, ``line``/``column``
    refer to the YAML vbi wrote from it and ``path`` is the key path
    (``vehicles[0].speed``), ``""`` for the scene as a whole.
    """

    file: str
    line: int
    column: int
    message: str
    path: Optional[str] = None
    rendered: str = ""

    def __str__(self) -> str:
        if self.path is not None:
            where = self.path or "<scene>"
            return f"{where}: {self.message}"
        return self.rendered or f"{self.file}:{self.line}:{self.column}: {self.message}"


class ScenarioError(ValueError):
    """A scene failed its checks. ``diagnostics`` holds every problem found
    (file, line, column or key path, message); ``str()`` shows them as
    ``vbi check`` does."""

    def __init__(self, diagnostics: List[Diagnostic]):
        self.diagnostics: List[Diagnostic] = list(diagnostics)
        super().__init__("\n".join(str(d) for d in self.diagnostics))


@dataclass
class _Source:
    kind: str  # "path" or "text"
    scene: str
    name: str
    # For a dict: the key path of each line of the YAML written, and the
    # lines where a mapping starts (``to_yaml``).
    dict_lines: Optional[List[str]] = None
    dict_starts: Optional[Dict[int, str]] = None


def _source(scene: Scene) -> _Source:
    if isinstance(scene, Mapping):
        text, paths, starts = to_yaml(scene)
        return _Source("text", text, "<dict>", paths, starts)
    if isinstance(scene, os.PathLike):
        return _Source("path", os.fspath(scene), os.fspath(scene))
    if isinstance(scene, str):
        if "\n" in scene or scene.lstrip().startswith("{"):
            return _Source("text", scene, "<string>")
        return _Source("path", scene, scene)
    raise TypeError(
        "a scene is a path, a YAML string or a dict; got " + type(scene).__name__
    )


def _raise_invalid(error: Exception, source: _Source) -> None:
    items = error.args[0]
    diagnostics = []
    for file, line, column, message, rendered in items:
        path = None
        if source.dict_lines is not None:
            path = path_at(
                source.scene, source.dict_lines, source.dict_starts or {}, line, column, message
            )
        diagnostics.append(Diagnostic(file, line, column, message, path, rendered))
    raise ScenarioError(diagnostics) from None


def check(scene: Scene) -> str:
    """Checks ``scene`` and returns its resolved YAML (every default and
    automatic choice written out); raises :class:`ScenarioError`."""
    source = _source(scene)
    try:
        return _vbi.check(source.kind, source.scene, source.name)
    except _vbi.InvalidScene as e:
        _raise_invalid(e, source)
        raise  # unreachable


# pandas' C parser before 3.0 may round a number's last bit unless asked
# for round-trip parsing; 3.0 parses exactly by default and deprecates the
# option.
_EXACT: Dict[str, Any] = (
    {} if int(pd.__version__.split(".")[0]) >= 3 else {"float_precision": "round_trip"}
)


def _read_csv(text_or_path: Union[str, Path]) -> pd.DataFrame:
    """A CSV table read with every number exact (shortest round-trip text
    parsed to the same double)."""
    if isinstance(text_or_path, Path):
        return pd.read_csv(text_or_path, **_EXACT)
    return pd.read_csv(io.StringIO(text_or_path), **_EXACT)


def _summary_table(summary: Mapping[str, Any]) -> str:
    quantities = summary.get("quantities") or []
    if not quantities:
        return ""
    rows = []
    for q in quantities:
        cells = [escape(str(q.get("name", ""))), escape(str(q.get("unit", "")))]
        for key in ("max", "min", "max_abs"):
            v = q.get(key)
            value = v.get("value") if isinstance(v, Mapping) else v
            cells.append(f"{value:.6g}" if isinstance(value, (int, float)) else "")
        rows.append("<tr>" + "".join(f"<td>{c}</td>" for c in cells) + "</tr>")
    head = "".join(f"<th>{h}</th>" for h in ("record", "unit", "max", "min", "max |·|"))
    return f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(rows)}</tbody></table>"


class VbiWarning(UserWarning):
    """A warning vbi made about a scene or its result (docs/advice.md)."""


@dataclass(frozen=True)
class Advice:
    """One piece of what vbi knows about a scene or a result.

    Attributes:
        id: the stable id (docs/advice.md), e.g. ``run-ends-at-peak``.
        severity: ``"warning"`` or ``"note"``.
        location: the key path of the cause (``record.midspan``), or ``None``.
        message: what vbi found.
        help: what to change, or ``None``.
        figures: the measured figures the message quotes, by name (SI).
        allowed: the scene's reason for allowing it (``allow:``), or ``None``.
        points: in a study, the points it was made at.
    """

    id: str
    severity: str
    message: str
    location: Optional[str] = None
    help: Optional[str] = None
    figures: Dict[str, float] = field(default_factory=dict)
    allowed: Optional[str] = None
    points: List[str] = field(default_factory=list)

    @classmethod
    def _from_json(cls, raw: Mapping[str, Any]) -> "Advice":
        return cls(
            id=raw["id"],
            severity=raw["severity"],
            message=raw["message"],
            location=raw.get("location"),
            help=raw.get("help"),
            figures=dict(raw.get("figures", {})),
            allowed=raw.get("allowed"),
            points=list(raw.get("points", [])),
        )

    @property
    def counts(self) -> bool:
        """A warning the scene does not allow (what ``strict=True`` refuses)."""
        return self.severity == "warning" and self.allowed is None

    def __str__(self) -> str:
        text = f"[{self.id}] {self.message}"
        if self.help:
            text += f"; help: {self.help}"
        if self.points:
            text += f" (at {self.points[0]}"
            text += f" and {len(self.points) - 1} more)" if len(self.points) > 1 else ")"
        return text


class VbiWarningError(RuntimeError):
    """``run(..., strict=True)`` made warnings the scene does not allow.

    Attributes:
        advice: those warnings.
        result: the complete result, computed all the same.
    """

    def __init__(self, advice: List[Advice], result: Any):
        self.advice = advice
        self.result = result
        lines = "\n".join(f"  {a}" for a in advice)
        super().__init__(f"{len(advice)} warning(s) (strict=True):\n{lines}")


@dataclass
class Result:
    """A single scene's results.

    Attributes:
        name: the scene's ``name``.
        history: DataFrame indexed by time (s, index name ``"time"``), one
            column per record named as in the scene (bridge displacements
            also ``<name>_static``); units in ``history.attrs["units"]``.
        summary: the content of ``summary.json`` as a dict.
        resolved: the resolved scene as YAML text (``resolved.yaml``).
        separation: loss of contact per wheel (one row per wheel) under
            unilateral contact, else ``None``.
        envelopes: the envelopes along the deck (``envelopes.csv``) when the
            scene asks for them, else ``None``.
        daf_table: the DAF per span and girder line (``daf_table.csv``) on a
            plate deck, else ``None``.
        advice: what vbi knows about the scene and its result (warnings and
            notes, :class:`Advice`), as ``summary["advice"]`` holds it.
    """

    name: str
    history: pd.DataFrame
    summary: Dict[str, Any]
    resolved: str
    separation: Optional[pd.DataFrame] = None
    envelopes: Optional[pd.DataFrame] = None
    daf_table: Optional[pd.DataFrame] = None
    advice: List[Advice] = field(default_factory=list)

    @property
    def units(self) -> Dict[str, str]:
        """Unit of each history column (SI), and of the index ``time``."""
        return dict(self.history.attrs.get("units", {}))

    def _repr_html_(self) -> str:
        h = self.history
        span = f"{h.index[0]:.6g}–{h.index[-1]:.6g} s" if len(h) else "empty"
        parts = [
            f"<div><strong>vbi result</strong> <code>{escape(self.name)}</code>: "
            f"{len(h)} rows × {h.shape[1]} columns, t = {span}</div>",
            _summary_table(self.summary),
        ]
        if self.separation is not None:
            parts.append(f"<div>separation: {int(self.separation['separated'].sum())} "
                         f"of {len(self.separation)} wheels lost contact</div>")
        return "".join(parts)

    def __repr__(self) -> str:
        return (f"Result(name={self.name!r}, history={self.history.shape[0]}×"
                f"{self.history.shape[1]}, records={list(self.history.columns)!r})")


@dataclass
class StudyResult:
    """A study's results: its tables exactly as ``vbi run`` writes them.

    Attributes:
        name: the scene's ``name``.
        study: the study type (``speed_sweep``, ``separation_map``,
            ``monte_carlo``, ``resonance_check``).
        summary: the study's ``summary.json`` as a dict.
        resolved: the resolved scene as YAML text.
        tables: every CSV table of the study by file stem (``study``,
            ``envelopes``, ``separation``, ``resonance``,
            ``resonance_trains``), each equal to the file ``vbi run`` writes.
        advice: the study's advice (its scene's, then its points' by id, each
            with the points it was made at in ``Advice.points``).
    """

    name: str
    study: str
    summary: Dict[str, Any]
    resolved: str
    tables: Dict[str, pd.DataFrame] = field(default_factory=dict)
    advice: List[Advice] = field(default_factory=list)

    @property
    def table(self) -> pd.DataFrame:
        """The study's main table: ``study.csv`` (sweep, map, Monte Carlo
        samples) or ``resonance.csv``."""
        return self.tables["study"] if "study" in self.tables else self.tables["resonance"]

    @property
    def sweep(self) -> Optional[pd.DataFrame]:
        """A speed sweep's table (``study.csv``), else ``None``."""
        return self.tables.get("study") if self.study == "speed_sweep" else None

    @property
    def resonance(self) -> Optional[pd.DataFrame]:
        """A resonance check's table per speed (``resonance.csv``)."""
        return self.tables.get("resonance")

    @property
    def envelopes(self) -> Optional[pd.DataFrame]:
        """Monte Carlo envelopes (``envelopes.csv``), else ``None``."""
        return self.tables.get("envelopes")

    @property
    def statistics(self) -> Optional[pd.DataFrame]:
        """Monte Carlo per-sample results (``study.csv``), else ``None``."""
        return self.tables.get("study") if self.study == "monte_carlo" else None

    @property
    def separation(self) -> Optional[pd.DataFrame]:
        """Monte Carlo separation statistics (``separation.csv``), else ``None``."""
        return self.tables.get("separation")

    def separation_map(self, value: Optional[str] = None) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        """A separation map as a 2-D array with its axes:
        ``(values, velocity_ratio, mass_ratio)``, ``values[i, j]`` at
        ``velocity_ratio[i]``, ``mass_ratio[j]``. ``value`` picks the column
        of ``study.csv`` (default: the first after the two ratios)."""
        if self.study != "separation_map":
            raise ValueError(f"a {self.study} study has no separation map")
        table = self.tables["study"]
        alpha, mass = table.columns[0], table.columns[1]
        value = value or table.columns[2]
        grid = table.pivot(index=alpha, columns=mass, values=value)
        return grid.to_numpy(), grid.index.to_numpy(), grid.columns.to_numpy()

    def _repr_html_(self) -> str:
        parts = [f"<div><strong>vbi {escape(self.study)}</strong> "
                 f"<code>{escape(self.name)}</code></div>"]
        for stem, table in self.tables.items():
            parts.append(f"<div><code>{escape(stem)}.csv</code>: {table.shape[0]} rows × "
                         f"{table.shape[1]} columns</div>")
            parts.append(table.head(10).to_html())
        return "".join(parts)


def _history(raw: Mapping[str, Any]) -> pd.DataFrame:
    data: Dict[str, np.ndarray] = {}
    units: Dict[str, str] = {"time": "s"}
    for name, unit, values, statics in raw["columns"]:
        data[name] = values
        units[name] = unit
        if statics is not None:
            data[f"{name}_static"] = statics
            units[f"{name}_static"] = unit
    index = pd.Index(raw["time"], name="time")
    frame = pd.DataFrame(data, index=index, copy=False)
    frame.attrs["units"] = units
    return frame


def run(
    scene: Scene, *, progress: Optional[Progress] = None, strict: bool = False
) -> Union[Result, StudyResult]:
    """Runs ``scene`` (a path, YAML text or a dict) and returns its results:
    a :class:`Result` for a single scene, a :class:`StudyResult` for a
    study.

    ``progress(done, total)`` is called about every 0.1 s (steps of a scene,
    runs of a study); an exception it raises stops the run and propagates.
    The GIL is released while the scene computes; Ctrl-C raises
    ``KeyboardInterrupt``. Raises :class:`ScenarioError` for an invalid
    scene, ``OSError`` for an unreadable file and ``RuntimeError`` when the
    run fails (e.g. the solution diverged).

    Every warning in ``result.advice`` that the scene does not allow is
    raised through :func:`warnings.warn` as a :class:`VbiWarning`; with
    ``strict=True`` the run raises :class:`VbiWarningError` (holding the
    result) instead, as ``vbi run --deny-warnings`` exits with code 4.
    """
    result = _run(scene, progress)
    denied = [a for a in result.advice if a.counts]
    if strict and denied:
        raise VbiWarningError(denied, result)
    for a in denied:
        warnings.warn(str(a), VbiWarning, stacklevel=2)
    return result


def _run(scene: Scene, progress: Optional[Progress]) -> Union[Result, StudyResult]:
    source = _source(scene)
    with tempfile.TemporaryDirectory(prefix="vbi-") as workdir:
        try:
            raw = _vbi.run(source.kind, source.scene, source.name, progress, workdir)
        except _vbi.InvalidScene as e:
            _raise_invalid(e, source)
            raise  # unreachable
        resolved = raw["resolved"]
        advice = [Advice._from_json(a) for a in json.loads(raw["advice"])]
        if raw["kind"] == "study":
            folder = Path(workdir)
            summary = json.loads((folder / "summary.json").read_text())
            tables = {p.stem: _read_csv(p) for p in sorted(folder.glob("*.csv"))}
            return StudyResult(
                name=str(summary.get("scenario", summary.get("name", ""))),
                study=_study_type(summary, resolved),
                summary=summary,
                resolved=resolved,
                tables=tables,
                advice=advice,
            )
    summary = json.loads(raw["summary"])
    separation = json.loads(raw["separation"])
    return Result(
        name=str(summary.get("scenario", "")),
        history=_history(raw),
        summary=summary,
        resolved=resolved,
        separation=pd.DataFrame(separation) if separation else None,
        envelopes=_read_csv(raw["envelopes_csv"]) if "envelopes_csv" in raw else None,
        daf_table=_read_csv(raw["daf_table_csv"]) if "daf_table_csv" in raw else None,
        advice=advice,
    )


def _study_type(summary: Mapping[str, Any], resolved: str) -> str:
    study = summary.get("study")
    if isinstance(study, str):
        return study
    if isinstance(study, Mapping) and isinstance(study.get("type"), str):
        return study["type"]
    for kind in ("speed_sweep", "separation_map", "monte_carlo", "resonance_check"):
        if f"type: {kind}" in resolved:
            return kind
    return "study"


@dataclass
class Modes:
    """The bridge's modes, as ``vbi modes`` computes them.

    Attributes:
        name: the scene's ``name``.
        frequencies: natural frequencies, Hz (shape ``(modes,)``).
        circular_frequencies: ω, rad/s.
        damping_ratios: modal damping ratios, 1.
        x: sample points along the bridge, m (shape ``(points,)``).
        y: their transverse position on a plate deck, m (edges and centre
            line), else ``None``.
        shapes: mass-normalised mode shapes at the points, 1/√kg (shape
            ``(points, modes)``), as ``vbi modes --shapes`` writes them.
        characters: what each mode is (``bending``, ``torsion``, …).
    """

    name: str
    frequencies: np.ndarray
    circular_frequencies: np.ndarray
    damping_ratios: np.ndarray
    x: np.ndarray
    y: Optional[np.ndarray]
    shapes: np.ndarray
    characters: List[str]

    def _repr_html_(self) -> str:
        rows = "".join(
            f"<tr><td>{i + 1}</td><td>{f:.6g}</td><td>{z:.4g}</td><td>{escape(c)}</td></tr>"
            for i, (f, z, c) in enumerate(zip(self.frequencies, self.damping_ratios, self.characters))
        )
        return (f"<div><strong>vbi modes</strong> <code>{escape(self.name)}</code></div>"
                "<table><thead><tr><th>mode</th><th>f [Hz]</th><th>ζ</th><th>character</th>"
                f"</tr></thead><tbody>{rows}</tbody></table>")


def modes(scene: Scene) -> Modes:
    """The bridge's natural frequencies and mode shapes (numpy arrays); the
    scene needs no vehicles. Raises :class:`ScenarioError`."""
    source = _source(scene)
    try:
        raw = _vbi.modes(source.kind, source.scene, source.name)
    except _vbi.InvalidScene as e:
        _raise_invalid(e, source)
        raise  # unreachable
    return Modes(
        name=raw["name"],
        frequencies=raw["frequency"],
        circular_frequencies=raw["circular_frequency"],
        damping_ratios=raw["damping_ratio"],
        x=raw["x"],
        y=raw["y"],
        shapes=raw["shapes"],
        characters=list(raw["character"]),
    )

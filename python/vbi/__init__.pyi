"""Type stubs of the `vbi` package: run vehicle–bridge interaction scenes
from Python (see the package docstring)."""

import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt
import pandas as pd

__version__: str

Scene = Union[str, os.PathLike[str], Mapping[str, Any]]
"""A YAML file path, YAML text (with a line break or starting with `{`), or
a dict nested as the YAML."""
Progress = Callable[[int, int], Any]
"""`progress(done, total)`: steps of a scene or runs of a study."""

class Diagnostic:
    """One located problem, as `vbi check` reports it."""

    file: str
    line: int
    column: int
    message: str
    path: Optional[str]
    """The key path (`vehicles[0].speed`) for a dict scene, else None."""
    rendered: str
    def __init__(
        self,
        file: str,
        line: int,
        column: int,
        message: str,
        path: Optional[str] = ...,
        rendered: str = ...,
    ) -> None: ...

class ScenarioError(ValueError):
    """A scene failed its checks; every problem is in `diagnostics`."""

    diagnostics: List[Diagnostic]
    def __init__(self, diagnostics: List[Diagnostic]) -> None: ...

class VbiWarning(UserWarning):
    """A warning vbi made about a scene or its result (docs/advice.md)."""

class Advice:
    """One piece of what vbi knows about a scene or a result."""

    id: str
    """Stable id (docs/advice.md)."""
    severity: str
    """"warning" or "note"."""
    message: str
    location: Optional[str]
    help: Optional[str]
    figures: Dict[str, float]
    allowed: Optional[str]
    """The scene's reason for allowing it, or None."""
    points: List[str]
    """In a study: the points it was made at."""
    @property
    def counts(self) -> bool: ...

class VbiWarningError(RuntimeError):
    """`run(..., strict=True)` made warnings the scene does not allow."""

    advice: List[Advice]
    result: Union["Result", "StudyResult"]

class Result:
    """A single scene's results."""

    name: str
    history: pd.DataFrame
    """Indexed by time (s), one column per record; units in attrs["units"]."""
    summary: Dict[str, Any]
    """summary.json's content."""
    resolved: str
    """The resolved scene as YAML."""
    separation: Optional[pd.DataFrame]
    envelopes: Optional[pd.DataFrame]
    daf_table: Optional[pd.DataFrame]
    advice: List[Advice]
    """Warnings and notes about the scene and its result."""
    @property
    def units(self) -> Dict[str, str]: ...
    def _repr_html_(self) -> str: ...

class StudyResult:
    """A study's results: its tables as `vbi run` writes them."""

    name: str
    study: str
    summary: Dict[str, Any]
    resolved: str
    tables: Dict[str, pd.DataFrame]
    advice: List[Advice]
    """The study's advice, each with the points it was made at."""
    @property
    def table(self) -> pd.DataFrame: ...
    @property
    def sweep(self) -> Optional[pd.DataFrame]: ...
    @property
    def resonance(self) -> Optional[pd.DataFrame]: ...
    @property
    def envelopes(self) -> Optional[pd.DataFrame]: ...
    @property
    def statistics(self) -> Optional[pd.DataFrame]: ...
    @property
    def separation(self) -> Optional[pd.DataFrame]: ...
    def separation_map(
        self, value: Optional[str] = ...
    ) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def _repr_html_(self) -> str: ...

class Modes:
    """The bridge's modes, as `vbi modes` computes them."""

    name: str
    frequencies: npt.NDArray[np.float64]
    """Hz."""
    circular_frequencies: npt.NDArray[np.float64]
    """rad/s."""
    damping_ratios: npt.NDArray[np.float64]
    x: npt.NDArray[np.float64]
    """Sample points along the bridge, m."""
    y: Optional[npt.NDArray[np.float64]]
    """Transverse positions on a plate deck, m."""
    shapes: npt.NDArray[np.float64]
    """(points, modes), mass-normalised, 1/√kg."""
    characters: List[str]
    def _repr_html_(self) -> str: ...

def check(scene: Scene) -> str:
    """Checks a scene and returns its resolved YAML; raises ScenarioError."""

def run(
    scene: Scene, *, progress: Optional[Progress] = ..., strict: bool = ...
) -> Union[Result, StudyResult]:
    """Runs a scene (GIL released, Ctrl-C raises KeyboardInterrupt); each
    warning is raised as a VbiWarning, or with strict=True as VbiWarningError."""

def modes(scene: Scene) -> Modes:
    """The bridge's natural frequencies and mode shapes."""

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

def run(scene: Scene, *, progress: Optional[Progress] = ...) -> Union[Result, StudyResult]:
    """Runs a scene (GIL released, Ctrl-C raises KeyboardInterrupt)."""

def modes(scene: Scene) -> Modes:
    """The bridge's natural frequencies and mode shapes."""

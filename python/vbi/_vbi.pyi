"""Type stubs of the Rust extension `vbi._vbi` (private: use `vbi`)."""

from typing import Any, Callable, Dict, Optional

__version__: str

class InvalidScene(ValueError):
    """args[0]: list of (file, line, column, message, rendered) tuples."""

def check(kind: str, scene: str, name: str = "<string>") -> str: ...
def run(
    kind: str,
    scene: str,
    name: str = "<string>",
    progress: Optional[Callable[[int, int], Any]] = None,
    workdir: Optional[str] = None,
) -> Dict[str, Any]: ...
def modes(kind: str, scene: str, name: str = "<string>") -> Dict[str, Any]: ...

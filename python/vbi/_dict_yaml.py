"""A plain dict (nested as the YAML) written as YAML text, with the key path
of every line, so that a diagnostic at a line of that text can say
``vehicles[0].speed`` instead of a line number of text the user never saw.

Every mapping entry and every sequence item gets a line of its own (block
style), so a line names exactly one entry. Numbers are written as Python's
``repr``: the shortest text that reads back to the same double, so a dict
and the YAML file it came from give bit-identical runs.
"""

from __future__ import annotations

import json
import math
import numbers
import re
from collections.abc import Mapping, Sequence
from typing import Any, Dict, List, Tuple

# A key written without quotes: letters, digits, `_`, `-`, `.`, not looking
# like a number, a boolean or null.
_PLAIN_KEY = re.compile(r"^[A-Za-z_][A-Za-z0-9_.\-]*$")
_RESERVED = {"true", "false", "null", "yes", "no", "on", "off", "y", "n", "~"}


def _key(key: Any) -> str:
    if not isinstance(key, str):
        raise TypeError(f"a scene's keys are strings; got {key!r} ({type(key).__name__})")
    if _PLAIN_KEY.match(key) and key.lower() not in _RESERVED:
        return key
    return json.dumps(key)


def _scalar(value: Any) -> str:
    if hasattr(value, "item") and getattr(value, "ndim", None) == 0:
        value = value.item()  # a numpy scalar
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        x = float(value)
        if math.isnan(x):
            return ".nan"
        if math.isinf(x):
            return ".inf" if x > 0 else "-.inf"
        # repr is the shortest round-trip form; YAML 1.2 reads it back as
        # the same double.
        return repr(x)
    if isinstance(value, str):
        # A JSON string is a valid YAML double-quoted scalar.
        return json.dumps(value, ensure_ascii=False)
    raise TypeError(
        f"a scene holds mappings, lists, strings, numbers, booleans and None; "
        f"got {value!r} ({type(value).__name__})"
    )


def _is_sequence(value: Any) -> bool:
    if isinstance(value, (str, bytes)):
        return False
    if isinstance(value, Sequence):
        return True
    # numpy arrays and the like (a 0-d array is a scalar)
    return (
        hasattr(value, "tolist")
        and getattr(value, "ndim", 1) > 0
        and hasattr(value, "__len__")
        and not isinstance(value, Mapping)
    )


def to_yaml(scene: Mapping) -> Tuple[str, List[str], Dict[int, str]]:
    """The YAML text of ``scene``; for each line (index 0 = line 1) the key
    path of the entry on it; and the lines (1-based) where a mapping's first
    entry starts, with that mapping's path (``""`` for the scene)."""
    lines: List[str] = []
    paths: List[str] = []
    starts: Dict[int, str] = {}

    def emit(text: str, path: str) -> None:
        lines.append(text)
        paths.append(path)

    def node(value: Any, indent: int, path: str) -> None:
        """Writes the entries of a mapping or the items of a sequence."""
        pad = " " * indent
        if isinstance(value, Mapping):
            starts[len(lines) + 1] = path
            for k, v in value.items():
                sub = f"{path}.{k}" if path else str(k)
                head = f"{pad}{_key(k)}:"
                if isinstance(v, Mapping) and len(v) > 0:
                    emit(head, sub)
                    node(v, indent + 2, sub)
                elif _is_sequence(v) and len(v) > 0:
                    emit(head, sub)
                    node(v, indent + 2, sub)
                elif isinstance(v, Mapping):
                    emit(head + " {}", sub)
                elif _is_sequence(v):
                    emit(head + " []", sub)
                else:
                    emit(f"{head} {_scalar(v)}", sub)
            return
        items = value.tolist() if hasattr(value, "tolist") else value
        for i, v in enumerate(items):
            sub = f"{path}[{i}]"
            if isinstance(v, Mapping) and len(v) > 0:
                # The first entry shares the dash's line.
                first = len(lines)
                node(v, indent + 2, sub)
                lines[first] = f"{pad}- " + lines[first][indent + 2 :]
                # The dash line names the item's first entry; an error
                # about the item itself (e.g. a missing key) is located at
                # the dash too, so that line keeps the entry's path, which
                # still starts with the item's.
            elif _is_sequence(v) and len(v) > 0:
                emit(f"{pad}-", sub)
                node(v, indent + 2, sub)
            elif isinstance(v, Mapping):
                emit(f"{pad}- {{}}", sub)
            elif _is_sequence(v):
                emit(f"{pad}- []", sub)
            else:
                emit(f"{pad}- {_scalar(v)}", sub)

    if not isinstance(scene, Mapping):
        raise TypeError(f"a scene dict must be a mapping; got {type(scene).__name__}")
    node(scene, 0, "")
    return "\n".join(lines) + "\n", paths, starts


def path_at(
    text: str, paths: List[str], starts: Dict[int, str], line: int, column: int, message: str
) -> str:
    """The key path of a diagnostic at ``line``:``column`` (1-based) of the
    ``text`` that ``to_yaml`` wrote with ``paths`` and ``starts``.

    A mapping is located at its first key, so a problem of the mapping as a
    whole (a missing key) and one of that first key share a place: the
    message tells them apart. The dash of ``- key: value`` names the item.
    """
    if not 1 <= line <= len(paths):
        return ""
    row = text.split("\n")[line - 1]
    indent = len(row) - len(row.lstrip(" -"))
    if line in starts and column <= indent + 1 and message.startswith("missing"):
        return starts[line]
    stripped = row.lstrip(" ")
    if stripped.startswith("- ") and column <= len(row) - len(stripped) + 1:
        path = paths[line - 1]
        cut = path.rfind(".")
        if cut > path.rfind("]"):
            return path[:cut]
        return path
    return paths[line - 1]

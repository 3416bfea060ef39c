"""TOML values as text, for the description files thermobear writes
(spindles, gear systems): floats by their shortest repr, so a file read
back gives every value to the last bit."""

from __future__ import annotations

import json
from typing import Any, Optional


def toml_value(value: Any, per_line: Optional[int] = None) -> str:
    """``value`` (bool, str, int, float, or a list of them) as TOML text;
    a list longer than ``per_line`` items is written ``per_line`` to a
    line (None: on one line)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return repr(value)
    items = [toml_value(v, per_line) for v in value]
    if per_line is None or len(items) <= per_line:
        return "[" + ", ".join(items) + "]"
    rows = [", ".join(items[i : i + per_line]) for i in range(0, len(items), per_line)]
    return "[\n" + ",\n".join("    " + r for r in rows) + ",\n]"

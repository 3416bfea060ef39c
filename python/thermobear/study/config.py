"""A study described in TOML::

    [study]
    kind = "thermal"          # bearing, thermal, spindle, gear
    chunk_size = 200          # optional: points per chunk
    max_points = 2000000      # optional: raise the cap on the grid's size

    [grid]                    # the dimensions: a list, or a range table
    bearing = ["7008C", "7008C-hybrid"]
    speed_rpm = { start = 2000, stop = 20000, num = 10 }
    axial_n = [300, 600]

    [fixed]                   # other inputs (default where not given)
    lubricant = "ISO VG 32"

Unknown tables and keys are rejected with a ConfigError naming the key and
where it is."""

from __future__ import annotations

import tomllib
from typing import Any, Optional

from ..errors import ConfigError
from .study import Study

#: Tables of a study file and the keys of ``[study]``.
TABLES = ("study", "grid", "fixed")
STUDY_KEYS = ("kind", "chunk_size", "max_points", "max_steps")


def _table(doc: dict, name: str) -> dict:
    value = doc.get(name, {})
    if not isinstance(value, dict):
        raise ConfigError(f"invalid {name} = {value!r}: must be a table [{name}]")
    return value


def _check_names(study_kind: Any, table: dict, where: str) -> None:
    for key in table:
        known = [p.name for p in study_kind.params]
        if key not in known:
            raise ConfigError(
                f"invalid key = {key!r} in [{where}]: not an input of a {study_kind.name} point; "
                f"known: {', '.join(known)}"
            )


def parse_study(
    text: str, *, max_points: Optional[int] = None, max_steps: Optional[int] = None
) -> Study:
    """A [`Study`][thermobear.Study] from TOML text; ``max_points`` and
    ``max_steps``, when given, take the place of the file's caps."""
    from .kinds import kind_of

    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise ConfigError(f"invalid study file = not TOML: {e}") from None
    for key in doc:
        if key not in TABLES:
            raise ConfigError(
                f"invalid key = {key!r} at the top level: a study file has the tables "
                + ", ".join(f"[{t}]" for t in TABLES)
            )
    head = _table(doc, "study")
    for key in head:
        if key not in STUDY_KEYS:
            raise ConfigError(f"invalid key = {key!r} in [study]: known: {', '.join(STUDY_KEYS)}")
    if "kind" not in head:
        raise ConfigError(
            "invalid [study] = no kind: give kind = bearing, thermal, spindle or gear"
        )
    kind = kind_of(head["kind"])
    grid, fixed = _table(doc, "grid"), _table(doc, "fixed")
    _check_names(kind, grid, "grid")
    _check_names(kind, fixed, "fixed")
    caps = {
        k: given if given is not None else head[k]
        for k, given in (("max_points", max_points), ("max_steps", max_steps))
        if given is not None or k in head
    }
    return Study(kind.name, grid, fixed, chunk_size=head.get("chunk_size"), **caps)


def load_study(
    path_or_text: Any, *, max_points: Optional[int] = None, max_steps: Optional[int] = None
) -> Study:
    """A [`Study`][thermobear.Study] from a TOML file (a path) or TOML text
    (``max_points``, ``max_steps``: when given, in place of the file's caps)."""
    text = str(path_or_text)
    if "\n" not in text and "=" not in text:
        from ..config import read_text_file

        text = read_text_file(text)
    return parse_study(text, max_points=max_points, max_steps=max_steps)

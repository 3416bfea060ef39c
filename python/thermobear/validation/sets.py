"""The validation sets shipped with the package (``validation/data/*.toml``,
package data): one published measurement or catalogue set per file, with
its source, geometry, conditions, points and the sigma of each point with
its justification."""

from __future__ import annotations

import tomllib
from importlib import resources
from typing import TYPE_CHECKING, Any

from ..errors import ConfigError

if TYPE_CHECKING:
    import polars


def set_names() -> list[str]:
    """The names of the shipped validation sets (file stems)."""
    root = resources.files("thermobear.validation").joinpath("data")
    return sorted(p.name[:-5] for p in root.iterdir() if p.name.endswith(".toml"))


def load_set(name: str) -> dict[str, Any]:
    """One validation set as a dict (the TOML's tables); ConfigError naming
    the known sets for an unknown name."""
    names = set_names()
    if name not in names:
        raise ConfigError(f"invalid set = {name!r}: known: {', '.join(names)}")
    path = resources.files("thermobear.validation").joinpath("data").joinpath(f"{name}.toml")
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    for key in ("name", "kind", "title", "source", "geometry", "sigma"):
        if key not in data:
            raise ConfigError(f"invalid set = {name!r}: the file has no {key!r}")
    if "points" not in data and "bearings" not in data:
        raise ConfigError(f"invalid set = {name!r}: the file has no points")
    return data


def points_frame(data: dict) -> polars.DataFrame:
    """The set's points as a polars frame: its ``[[points]]``, or for a
    catalogue set the rows expanded from ``[[bearings]]``
    (``thermobear.validation.catalogue.catalogue_points``) or, for a
    reference-speed set, one row per bearing
    (``thermobear.validation.reference_speed.reference_points``); every row has
    ``quantity``, ``value`` and ``sigma``."""
    import polars as pl

    if "points" in data:
        return pl.DataFrame(data["points"])
    if data.get("kind") == "reference_speed":
        from .reference_speed import reference_points

        return reference_points(data)
    from .catalogue import catalogue_points

    return catalogue_points(data)

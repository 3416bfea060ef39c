"""System descriptions (TOML). The Rust side parses and validates them and
rejects unknown keys by name; the built-in seed configurations ship inside
the package (``thermobear/configs/``)."""

from __future__ import annotations

import tomllib
from importlib import resources
from pathlib import Path

import numpy as np

from . import _native

_CONFIG_PACKAGE = "thermobear.configs"


def seed_config_names() -> list[str]:
    """Names of the built-in seed configurations."""
    files = resources.files(_CONFIG_PACKAGE)
    return sorted(p.name[:-5] for p in files.iterdir() if p.name.endswith(".toml"))


def seed_config(name: str) -> str:
    """The TOML text of a built-in seed configuration."""
    from .errors import ConfigError

    if name not in seed_config_names():
        raise ConfigError(
            f"invalid config = {name}: unknown seed configuration; known: "
            + ", ".join(seed_config_names())
        )
    return resources.files(_CONFIG_PACKAGE).joinpath(name + ".toml").read_text()


def load_config(path_or_text: str | Path) -> str:
    """Read a system description from a path (or take TOML text as is),
    check it on the Rust side and return the text."""
    text = str(path_or_text)
    p = Path(text)
    if "\n" not in text and "=" not in text:
        from .errors import ConfigError

        try:
            text = p.read_text()
        except OSError as e:
            raise ConfigError(f"invalid path = {p}: cannot read: {e}") from None
    _native.check_config(text)
    return text


def read_toml(text: str) -> dict:
    """The parsed TOML of a system description's text."""
    return tomllib.loads(text)


def sweep_speeds(cfg: dict, quick: bool = False) -> np.ndarray:
    """The speeds [rpm] of a parsed system description's ``[sweep]``:
    ``speeds_rpm``, or ``speed_count`` (default 51; at most 11 when
    ``quick``) from ``speed_start_rpm`` to ``speed_stop_rpm``."""
    sw = cfg.get("sweep", {})
    if "speeds_rpm" in sw:
        return np.asarray(sw["speeds_rpm"], dtype=float)
    n = int(sw.get("speed_count", 51))
    if quick:
        n = min(n, 11)
    return np.linspace(float(sw["speed_start_rpm"]), float(sw["speed_stop_rpm"]), n)

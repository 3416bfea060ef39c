"""Optional feature dependencies, imported by name in one place.

A feature extra (``pip install "thermobear[dask]"``) brings a module the
plain install does not. The package never imports such a module at the top
of a file: the feature asks for it here when it is used, and without it the
user gets a ``ConfigError`` naming the field, the value and the pip command.
``tests/test_dependencies.py`` checks that every module named here is
declared in the extra named beside it."""

from __future__ import annotations

import importlib
from types import ModuleType
from typing import Any

from .errors import ConfigError


def optional_module(module: str, extra: str, field: str, value: Any, purpose: str) -> ModuleType:
    """``module`` (e.g. ``"dask.distributed"``) from the feature ``extra``,
    or a ConfigError on ``field = value`` saying what to install."""
    try:
        return importlib.import_module(module)
    except ImportError:
        top = module.split(".")[0]
        raise ConfigError(
            f"invalid {field} = {value!r}: {purpose} needs {top}; "
            f'install it with: pip install "thermobear[{extra}]"'
        ) from None

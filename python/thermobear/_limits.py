"""Limits that protect the machine, for the thread pools on the Python
side (the native calls apply the same rules themselves).

A ``threads`` argument above the number of available cores (CPU affinity
and cgroup quotas included: ``available_cores``) is capped to it with a
[`ThreadsWarning`][thermobear.ThreadsWarning]; ``threads=0`` or a negative
count is a [`ConfigError`][thermobear.ConfigError].
"""

from __future__ import annotations

import os
import sys
import warnings
from types import FrameType
from typing import Optional

from . import _native
from .errors import ConfigError, ThreadsWarning


def available_cores() -> int:
    """The number of cores a ``threads`` argument is capped to."""
    return int(_native.available_cores())


_PACKAGE = os.path.dirname(os.path.abspath(__file__))


def _outside_stacklevel() -> int:
    """The ``stacklevel`` of the first frame outside this package, seen
    from a function of this module (the user's line that asked)."""
    level = 1
    frame: Optional[FrameType] = sys._getframe(1)
    while frame is not None and os.path.abspath(frame.f_code.co_filename).startswith(_PACKAGE):
        frame = frame.f_back
        level += 1
    return level


def cap_threads(threads: Optional[int]) -> Optional[int]:
    """``threads`` as it will be used: None stays None (all cores); above
    ``available_cores`` it is capped with a ``ThreadsWarning`` that
    points at the first line outside thermobear."""
    if threads is None:
        return None
    from ._validate import is_number

    if (
        not is_number(threads)
        or not threads - threads == 0
        or int(threads) != threads
        or threads < 1
    ):
        raise ConfigError(
            f"invalid threads = {threads!r}: must be a whole number of at least 1 "
            "(or None for all cores)"
        )
    n = int(threads)
    cores = available_cores()
    if n > cores:
        warnings.warn(
            f"threads={n} exceeds the {cores} available cores; using {cores}",
            ThreadsWarning,
            stacklevel=_outside_stacklevel(),
        )
        return cores
    return n

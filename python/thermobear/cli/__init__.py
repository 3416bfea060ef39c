"""The ``thermobear`` command line: ``demo`` (the seed studies), ``solve``
(a system description), ``presets``, ``effects``, ``diagnose``."""

from .main import main

__all__ = ["main"]

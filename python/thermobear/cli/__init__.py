"""The ``thermobear`` command line: ``demo`` (the seed studies), ``solve``
(a system description), ``presets``, ``effects``, ``diagnose``,
``calibrate``, ``predict`` (a saved calibrated model's prediction with its
band), ``study`` and ``validate``. Exit status 0 (ok), 1 (data,
model or convergence error), 2 (usage), 130 (interrupted); see
``thermobear.cli.main``."""

from .main import main

__all__ = ["main"]

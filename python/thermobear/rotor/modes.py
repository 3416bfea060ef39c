"""Natural frequencies of the spindle rotor: the Campbell diagram and the
critical speeds."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Optional, Sequence

import numpy as np
from numpy.typing import ArrayLike

from .. import _native
from .. import _validate as val
from .._model_hook import takes_calibrated
from .supports import _effects, _offsets, _resolve, _rotor, _speeds

if TYPE_CHECKING:
    import polars


#: The most modes a Campbell diagram can report: the seed spindle's rotor has
#: 100 degrees of freedom (``src/rotor/presets.rs``) and the modal basis
#: keeps 8 modes more than those asked for (``src/rotor/spindle_vibration.rs``).
MAX_MODES = 92


@takes_calibrated()
def campbell(
    spindle: Any,
    speeds_rpm: Optional[ArrayLike] = None,
    modes: int = 8,
    *,
    coupled: bool = False,
    effects: Optional[Sequence[str]] = None,
    progress: Optional[Callable[[int, int], None]] = None,
) -> polars.DataFrame:
    """Campbell diagram: damped natural frequencies of the lowest ``modes``
    modes against speed, with the rows' stiffness solved at each speed.

    Columns ``speed_rpm, mode, frequency_hz, damping_ratio, whirl``
    (``forward``/``backward``/``undetermined``). Default speeds 0..30,000 rpm
    in 31 steps. ``effects`` (names of [`thermobear.effects`][thermobear.effects]) go to the
    ball solver; ``"unbalanced_magnetic_pull"`` adds the UMP (off by default).
    """
    import polars as pl

    mat, preload, _ = _resolve(spindle)
    s = _speeds(speeds_rpm, np.linspace(0.0, 30_000.0, 31))
    d = _native.rotor_campbell(
        mat,
        preload,
        s,
        modes=val.whole("modes", modes, 1, MAX_MODES),
        effects=_effects(effects),
        offsets=_offsets(spindle, s, val.flag("coupled", coupled)),
        rotor=_rotor(spindle),
        progress=progress,
    )
    return pl.DataFrame(d)


@takes_calibrated()
def critical_speeds(
    spindle: Any,
    speeds_rpm: Optional[ArrayLike] = None,
    modes: int = 8,
    *,
    harmonic: float = 1.0,
    coupled: bool = False,
    effects: Optional[Sequence[str]] = None,
) -> polars.DataFrame:
    """Speeds where a Campbell branch crosses f = harmonic x speed / 60
    (linear interpolation on the speed grid). Columns ``speed_rpm,
    frequency_hz, branch, whirl``. Default grid 0..120,000 rpm (121
    speeds): the seed spindle on its preloaded rows is stiff, its first
    1X crossings lie above 60,000 rpm, far beyond its 30,000 rpm service
    speed."""
    import polars as pl

    mat, preload, _ = _resolve(spindle)
    s = _speeds(speeds_rpm, np.linspace(0.0, 120_000.0, 121))
    d = _native.rotor_critical_speeds(
        mat,
        preload,
        s,
        modes=val.whole("modes", modes, 1, MAX_MODES),
        harmonic=val.real("harmonic", harmonic, 0.0, open_lo=True),
        effects=_effects(effects),
        offsets=_offsets(spindle, s, val.flag("coupled", coupled)),
        rotor=_rotor(spindle),
    )
    return pl.DataFrame(d)

"""thermobear: how the heat in a rolling bearing changes its stiffness, and
with it the vibration of the machine it carries.

Rust core (``thermobear._native``) with a Python front that returns polars
DataFrames and draws matplotlib figures. Units are in every name:
``speed_rpm``, ``axial_n``, ``ball_diameter_mm``, ``stiffness_n_per_m``.
Results are SI unless the name says otherwise.

The package, bottom layer first (a module imports only from its own layer
or below; ``tests/test_layout.py`` checks it):

* ``errors``, ``plausibility``, ``config`` -- exceptions, plausibility limits
  and system descriptions (TOML);
* ``bearing`` -- materials, the bearing solve; ``thermal`` -- heat, the
  thermal network, stiffness against speed; ``gear``, ``spindle``,
  ``rotor`` -- the machines;
* ``diagnosis`` -- model against measurements, step by step;
* ``study`` -- design studies: grids in chunks, parquet, resume, Dask;
* ``predict`` -- a calibrated model's predictions with uncertainty bands
  (the name ``thermobear.predict`` is the function; its modules are
  ``thermobear.predict.band`` ...);
* ``plot`` -- figures, one module per topic;
* ``studies`` (the seed studies, ``thermobear demo``) and ``validation``
  (published data sets, ``thermobear validate``), ``cli`` on top.
"""

from typing import TYPE_CHECKING as _TYPE_CHECKING

from . import (
    _native,
    bearing,
    config,
    diagnosis,
    errors,
    gear,
    plausibility,
    plot,
    rotor,
    spindle,
    study,
    thermal,
    validation,
)
from .bearing import Bearing, BearingSolution, Material
from .config import load_config, seed_config, seed_config_names
from .diagnosis import (
    BearingModelSpec,
    CalibratedModel,
    Calibration,
    Diagnosis,
    GearModelSpec,
    SpindleModelSpec,
    calibrate,
    candidates,
    diagnose,
    diagnose_spindle,
    load_measurements,
    load_spindle_measurements,
    seed_b_measurements,
    spindle_candidates,
)
from .errors import (
    AmbiguousModelWarning,
    ConfigError,
    ConvergenceError,
    DataError,
    ExtrapolationWarning,
    Interrupted,
    PlausibilityWarning,
    ThermalRunawayError,
    ThermobearError,
    ThreadsWarning,
)
from .gear import (
    GearPair,
    GearSystem,
    bifurcation,
    bifurcation_set,
    gear_defaults,
    largest_lyapunov,
    regime_map,
    regimes,
)
from .glossary import glossary
from .plausibility import Limits, get_limits, limits, set_limits
from .predict import (  # the function shadows the subpackage
    predict,
    regime_boundaries,
    separating_measurement,
)
from .rotor import campbell, critical_speeds, spectrum, spectrum_orders, vibration
from .spindle import (
    BearingSet,
    Cooling,
    Housing,
    Lubrication,
    MagneticPull,
    Motor,
    Preload,
    Shaft,
    ShaftSegment,
    Spindle,
    ToolLoad,
    compensation_preload,
    optimal_preload,
    spindle_grid,
    transient,
)
from .study import Study, load_study
from .thermal import (
    IsothermalHeat,
    ThermalState,
    isothermal_heat,
    lubrication_defaults,
    stiffness_curve,
    thermal_state,
    thermal_state_many,
)
from .validation import validate

if _TYPE_CHECKING:  # for annotations only; polars loads with the first result
    import polars

    from ._types import EffectKind

__version__: str = _native.__version__


def effects(kind: "EffectKind | None" = None) -> "polars.DataFrame":
    """The effects registry: every physical effect a model can include or
    leave out, one row each (see ``thermobear.diagnosis.effect_registry``
    for the columns). ``kind="switch"``: the named effects for
    ``effects=[...]``; ``kind="term"``: the terms with a calibratable input
    whose null value leaves them out (extra heat, housing conductance ...);
    ``kind="model"``: alternative models chosen by an option
    (``heat_model:skf``)."""
    return diagnosis.effect_registry(kind)


__all__ = [
    # subpackages and modules, bottom layer first
    "errors",
    "plausibility",
    "config",
    "bearing",
    "thermal",
    "gear",
    "spindle",
    "rotor",
    "diagnosis",
    "study",
    "plot",
    "validation",
    # errors
    "AmbiguousModelWarning",
    "ConfigError",
    "ConvergenceError",
    "DataError",
    "ExtrapolationWarning",
    "Interrupted",
    "PlausibilityWarning",
    "ThermalRunawayError",
    "ThermobearError",
    "ThreadsWarning",
    # plausibility limits
    "Limits",
    "get_limits",
    "limits",
    "set_limits",
    # system descriptions
    "load_config",
    "seed_config",
    "seed_config_names",
    # bearing and thermal state
    "Bearing",
    "BearingSolution",
    "Material",
    "IsothermalHeat",
    "ThermalState",
    "isothermal_heat",
    "lubrication_defaults",
    "stiffness_curve",
    "thermal_state",
    "thermal_state_many",
    # gear dynamics
    "GearPair",
    "GearSystem",
    "bifurcation",
    "bifurcation_set",
    "gear_defaults",
    "largest_lyapunov",
    "regime_map",
    "regimes",
    # spindle
    "Spindle",
    "Shaft",
    "ShaftSegment",
    "BearingSet",
    "Preload",
    "Housing",
    "Motor",
    "MagneticPull",
    "Cooling",
    "Lubrication",
    "ToolLoad",
    "compensation_preload",
    "optimal_preload",
    "spindle_grid",
    "transient",
    # rotor
    "campbell",
    "critical_speeds",
    "spectrum",
    "spectrum_orders",
    "vibration",
    # diagnosis
    "effects",
    "BearingModelSpec",
    "CalibratedModel",
    "Calibration",
    "Diagnosis",
    "GearModelSpec",
    "SpindleModelSpec",
    "calibrate",
    "candidates",
    "diagnose",
    "diagnose_spindle",
    "load_measurements",
    "load_spindle_measurements",
    "seed_b_measurements",
    "spindle_candidates",
    # design studies
    "Study",
    "load_study",
    # prediction with uncertainty (the subpackage is thermobear.predict.band ...)
    "predict",
    "regime_boundaries",
    "separating_measurement",
    # validation against published data
    "validate",
    # the one name of each quantity
    "glossary",
]

# One rule for the arguments of every public call (an unknown keyword, a
# missing or extra argument, a wrong type: ConfigError naming it), applied
# here once to the functions above, the methods of the public classes and
# the figures of thermobear.plot.
from . import _keywords as _keywords  # noqa: E402

_keywords.guard_namespace(globals(), __all__)
_keywords.guard_namespace(vars(plot), plot.__all__, prefix="plot.")

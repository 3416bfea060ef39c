"""Model-vs-measurement discrepancy workflow: find where a model
misses measured data, name the missing effect the data support, show the
gap shrink -- and refuse to name one the data cannot support.

[`diagnose`][thermobear.diagnose] runs the steps, one module each:

* ``thermobear.diagnosis.measurements`` -- read and check the measured table, hold out points;
* ``thermobear.diagnosis.registry``, ``thermobear.diagnosis.candidates`` -- the effects registry and
the
  candidates (missing effects, miscalibrated inputs, sensor-offset decoys);
* ``thermobear.diagnosis.audit`` -- the baseline's residual per quantity and speed band, and
  the held-out gap before/after;
* ``thermobear.diagnosis.identifiability`` -- fingerprints, look-alike pairs, the extra
  measurement that separates them;
* ``thermobear.diagnosis.screening`` -- each candidate calibrated alone and scored (BIC,
  AICc, cross-validated chi^2, the extrapolation check, 95 % profile
  interval); ``thermobear.diagnosis.control`` -- the generic smooth control;
* ``thermobear.diagnosis.outliers`` -- the robust outlier audit;
* ``thermobear.diagnosis.ties`` -- each tie member's calibration and gap;
* ``thermobear.diagnosis.acceptance`` -- the best candidate, ties, the joint refit;
* ``thermobear.diagnosis.verdict`` -- the verdict in words; ``thermobear.diagnosis.result`` --
  [`Diagnosis`][thermobear.Diagnosis];
* ``thermobear.diagnosis.workflow`` -- [`diagnose`][thermobear.diagnose], the sequence of the steps;
* ``thermobear.diagnosis.joint`` -- [`calibrate`][thermobear.calibrate], joint
  calibration over data sets.

The machines behind the protocol of ``thermobear.diagnosis.protocol``: one bearing
(``thermobear.diagnosis.bearing_spec``) and the seed B spindle
(``thermobear.diagnosis.spindle_spec``).
"""

from .bearing_spec import BearingModelSpec, model_from_toml
from .calibrated import CalibratedModel
from .candidates import Candidate, candidates, sensor_offset_candidates
from .gear_spec import GEAR_QUANTITIES, GearModelSpec
from .joint import Calibration, calibrate
from .measurements import QUANTITIES, load_measurements, synthetic_measurements, typical_sigma
from .protocol import ModelSpec
from .registry import NOT_IN_BEARING, effect_registry
from .result import Diagnosis
from .spindle_spec import (
    SPINDLE_QUANTITIES,
    THERMAL_DISPLACEMENT_EFFECTS,
    SpindleModelSpec,
    diagnose_spindle,
    load_spindle_measurements,
    seed_b_measurements,
    spindle_candidates,
)
from .statistics import residual_shape
from .workflow import diagnose

__all__ = [
    "QUANTITIES",
    "SPINDLE_QUANTITIES",
    "THERMAL_DISPLACEMENT_EFFECTS",
    "BearingModelSpec",
    "CalibratedModel",
    "Calibration",
    "GEAR_QUANTITIES",
    "GearModelSpec",
    "Candidate",
    "Diagnosis",
    "ModelSpec",
    "NOT_IN_BEARING",
    "SpindleModelSpec",
    "calibrate",
    "candidates",
    "diagnose",
    "diagnose_spindle",
    "effect_registry",
    "load_measurements",
    "load_spindle_measurements",
    "model_from_toml",
    "residual_shape",
    "seed_b_measurements",
    "sensor_offset_candidates",
    "spindle_candidates",
    "synthetic_measurements",
    "typical_sigma",
]

"""Prediction with uncertainty: a calibrated model's outputs with the band
its calibrated values' uncertainty gives, and, when the data leave several
explanations standing, each explanation's prediction and the envelope of
them all.

* ``thermobear.predict.conditions`` -- what is predicted (the quantities of
  each ``what``) and where (the operating conditions), the units;
* ``thermobear.predict.uncertainty`` -- the delta method and quasi-random
  (Sobol) sampling of the calibrated values;
* ``thermobear.predict.band`` -- [`predict`][thermobear.predict.band.predict], the
  tidy band frame, the members and their envelope;
* ``thermobear.predict.separation`` --
  [`separating_measurement`][thermobear.separating_measurement], where the
  explanations differ most;
* ``thermobear.predict.regimes`` -- the gear regimes under the calibrated
  bearings' uncertainty (``predict(model, "regimes", ...)``) and
  [`regime_boundaries`][thermobear.regime_boundaries].
"""

from .band import predict
from .regimes import regime_boundaries
from .separation import separating_measurement

__all__ = ["predict", "regime_boundaries", "separating_measurement"]

"""[`predict`][thermobear.predict.band.predict]: a calibrated model's prediction with its
band, for a single explanation or for each member of a tie (and the
envelope that covers them all).

Under a tie or "unresolved" each member (explanation) gets its rows,
with its ``weight`` (from how well it predicts the points it was not
fitted to: pseudo-BMA+ weights of leave-one-out predictive densities, see
``thermobear.diagnosis.weights``), and ``band`` chooses the combined
reading: ``"mixture"`` (default; ``member`` "mixture") is the band of
the weighed mixture of the members' predictions at ``level`` (each
member's band read as a normal of its value and half-width / z; value:
the mixture's mean), ``"envelope"`` (``member`` "envelope") covers
every member's band (value: the members' mean), the conservative
reading. The unknown member of "unresolved" is, on a bearing, an
unknown heat source with its own speed law fitted to the data
(``thermobear.diagnosis.unknown_heat``: it predicts every quantity,
through the heat balance, with a band from its two coefficients), and
on every machine the posterior of a model-discrepancy term on top (a
Gaussian process in speed fitted to what is left on the training
points; ``method`` "discrepancy"): narrow at the measured speeds,
wider away from them. A quantity that no part of a member constrains
(no calibrated value acts on it and it was not measured) gets
``method`` "unconstrained" and null bounds, never a band of zero
width. A model with no calibrated value and no discrepancy term (the
baseline) has a band of zero width, ``method`` "none".
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Literal, Mapping, Optional, Sequence

import numpy as np

from ..errors import ConfigError
from .conditions import What, condition_columns, condition_frame, quantities_for, unit_of_quantity
from .engine import check_engine, study_band
from .model_input import as_calibrated, measured_conditions
from .regimes import Direction, predict_regimes
from .uncertainty import check_level, delta_band, parameters_of, sampling_band

if TYPE_CHECKING:
    import polars

Method = Literal["auto", "delta", "sampling"]
_METHODS = ("auto", "delta", "sampling")

#: The combined reading of a tie's or an "unresolved" model's members:
#: "mixture" (the members' bands weighed by their weights) or "envelope"
#: (the union of every member's band: the conservative reading).
Band = Literal["mixture", "envelope"]
BANDS = ("mixture", "envelope")

#: The outputs "auto" treats as smooth in the calibrated values (delta
#: method); any other goes to sampling. Every ``what`` of
#: [`predict`][thermobear.predict.band.predict] is a steady-state solution, smooth in
#: the model's inputs.
SMOOTH_WHATS = frozenset({"measured", "stiffness", "temperatures", "growth", "vibration"})

#: The ``member`` label of the rows that cover every member's band.
ENVELOPE = "envelope"

#: The ``member`` (and ``method``) of the rows of the weighed mixture of
#: the members' bands.
MIXTURE = "mixture"

#: The ``method`` of a band no member's data can constrain (a quantity the
#: unknown smooth term was not measured on): bounds null, never zero width.
UNCONSTRAINED = "unconstrained"

#: Below this total weight, members whose band is unconstrained are left
#: out of the mixture (the others' weights renormalised); above it the
#: mixture is unconstrained too.
UNCONSTRAINED_WEIGHT = 1e-3

#: The ``method`` of the rows whose band is the model-discrepancy term's
#: (with the calibrated values' part, if any); the key of its fitted
#: Gaussian process in ``CalibratedModel.discrepancy``.
DISCREPANCY = "discrepancy"
GAUSSIAN_PROCESS = "gaussian_process"


class ModelOutputs:
    """The model's outputs at a vector of calibrated values: every
    quantity at every condition row (quantity-major), one model run per
    distinct vector (cached)."""

    def __init__(self, model: Any, conditions: polars.DataFrame, quantities: Sequence[str]):
        self.model = model
        self.conditions = conditions
        self.quantities = list(quantities)
        self._cache: dict[tuple[float, ...], np.ndarray] = {}

    @property
    def runs(self) -> int:
        """Model runs so far (distinct vectors of calibrated values)."""
        return len(self._cache)

    def __call__(self, theta: np.ndarray) -> np.ndarray:
        key = tuple(float(x) for x in np.asarray(theta, dtype=float))
        if key not in self._cache:
            spec = self.model.spec_at(np.asarray(key)) if key else self.model.spec
            p = spec.predict(self.conditions)
            self._cache[key] = np.concatenate(
                [np.asarray(p[q], dtype=float).reshape(-1) for q in self.quantities]
            )
        return self._cache[key]


def predict(
    model: Any,
    what: What = "measured",
    conditions: Any = None,
    level: float = 0.95,
    method: Method = "auto",
    samples: int = 64,
    seed: int = 0,
    *,
    gear: Any = None,
    gear_options: Optional[Mapping[str, Any]] = None,
    direction: Direction = "down",
    sweep_options: Optional[Mapping[str, Any]] = None,
    engine: Any = None,
    band: Band = "mixture",
) -> polars.DataFrame:
    """A calibrated model's prediction with its uncertainty band.

    ``model``: a calibrated model (``Calibration.model``,
    ``Diagnosis.model``; a [`Calibration`][thermobear.Calibration] or
    [`Diagnosis`][thermobear.Diagnosis] stands for its model). ``what``:
    ``"measured"`` (every quantity the model predicts but the changes from
    a reference speed), ``"stiffness"``, ``"temperatures"``, ``"growth"``
    (axial growth, bearing displacements and their changes from the
    lowest speed of the conditions)
    or ``"vibration"`` (a spindle's velocity RMS); a gear model's transition
    speeds (``"measured"``; rows of its conditions) are always sampled. ``conditions``: a frame of
    ``speed_rpm`` and the loads (``axial_n``, ``radial_n``; a spindle's
    ``preload_n``), a dict ``{"speeds_rpm": [...], "axial_n": ...,
    "radial_n": ...}`` (every combination) or None for the measured ones.

    The band holds the calibrated values' uncertainty at probability
    ``level``: ``method="delta"`` linearises (central differences of 0.1
    standard deviations, variance g^T C g, value +- z sd), ``"sampling"``
    runs the model at ``samples`` scrambled Sobol points (``seed``) of the
    estimates' normal, clipped to the bounds, and takes the empirical
    quantiles; ``"auto"`` uses the delta method for the smooth outputs
    (all of these).

    Under a tie or "unresolved" each member (explanation) gets its rows
    with its ``weight``; ``band`` chooses the combined reading:
    ``"mixture"`` (default) the band of the weighed mixture of the members,
    ``"envelope"`` the union of their bands (see the module docstring for
    both, the unknown member and an "unconstrained" band).

    Returns a tidy frame: the condition columns, ``quantity``, ``value``,
    ``lower``, ``upper``, ``unit`` (of value and bounds), ``member`` (the
    explanation's label; "" for a single model), ``method`` and
    ``weight`` (1 for a single model, a member's weight, null on the
    combined rows), and the ``*_beyond_measured`` columns (``thermobear.predict.extrapolation``).

    ``engine``: None runs a sampled band's samples (or the regimes' sweeps)
    in this process; ``"local"``, a Dask ``Client`` or a scheduler address
    runs them as a [`Study`][thermobear.Study] (``thermobear.predict.engine``):
    the same band.

    ``what="regimes"``: the motion regimes of a gear pair on the calibrated
    bearings, sampled (``gear``, ``gear_options``, ``direction``,
    ``sweep_options``: see
    [`predict_regimes`][thermobear.predict.regimes.predict_regimes]; read the
    boundaries with [`regime_boundaries`][thermobear.regime_boundaries])."""
    from .extrapolation import with_extrapolation

    if not isinstance(band, str) or band not in BANDS:
        raise ConfigError(f"invalid band = {band!r}: one of {', '.join(BANDS)}")
    cm = as_calibrated(model)
    lv = check_level(level)
    samples, seed = check_arguments(method, samples, engine, what, seed)
    if what == "regimes":
        run = (gear, gear_options, direction, sweep_options, engine)
        return predict_regimes(cm, conditions, lv, method, samples, seed, *run)
    measured = measured_conditions(cm)
    cond = condition_frame(cm.spec, conditions, measured if measured is not None else (
        measured_conditions(model)))  # fmt: skip
    quantities = quantities_for(cm.spec, what)
    used = _method_used(cm.spec, what, method)
    opts = (lv, used, samples, seed)
    return with_extrapolation(_bands(cm, cond, quantities, opts, engine, band), model)


def _bands(
    cm: Any,
    cond: polars.DataFrame,
    quantities: Sequence[str],
    opts: tuple[float, str, int, int],
    engine: Any,
    band: str,
) -> polars.DataFrame:
    """The band rows of a model, or of each member and their combined
    reading (``band``)."""
    import polars as pl

    members = tuple(getattr(cm, "members", ()) or ())
    if not members:
        return band_frame(cm, "", cond, quantities, *opts, engine=engine)
    frames = [band_frame(m, str(m.label), cond, quantities, *opts, engine=engine) for m in members]
    cols = condition_columns(cm.spec)
    combined = mixture(frames, cols, opts[0]) if band == MIXTURE else envelope(frames, cols)
    return pl.concat(frames + [combined])


def _method_used(spec: Any, what: str, method: str) -> str:
    """The band method of ``method`` for ``what``: "auto" is the delta
    method for the smooth outputs and sampling otherwise; a gear pair's
    transition speeds (which jump with its inputs) are always sampled."""
    if getattr(spec, "conditions", None) is not None:
        if method == "delta":
            raise ConfigError(
                "invalid method = 'delta': a gear pair's transition speeds jump with its inputs; "
                "'auto' or 'sampling'"
            )
        return "sampling"
    return ("delta" if what in SMOOTH_WHATS else "sampling") if method == "auto" else method


#: The most samples a sampled band takes (each is a model run).
MAX_SAMPLES = 2**20


def check_arguments(
    method: Any, samples: Any, engine: Any, what: Any = "measured", seed: Any = 0
) -> tuple[int, int]:
    """Refuse an unknown ``method``, ``samples`` outside [8, ``MAX_SAMPLES``],
    a bad ``engine``, a ``what`` that is not a string, a ``seed`` that is
    not a whole number >= 0; returns ``(samples, seed)``."""
    from .. import _validate as val

    if not isinstance(what, str):
        raise ConfigError(f"invalid what = {what!r}: a string (see the docs of predict)")
    if not isinstance(method, str) or method not in _METHODS:
        raise ConfigError(f"invalid method = {method!r}: one of {', '.join(_METHODS)}")
    if isinstance(samples, float):  # a count is written as an integer here
        raise ConfigError(f"invalid samples = {samples!r}: an integer >= 8")
    n = val.whole("samples", samples, 8, MAX_SAMPLES)
    check_engine(engine)
    return n, val.whole("seed", seed, 0, None)


def band_frame(
    model: Any,
    member: str,
    cond: polars.DataFrame,
    quantities: Sequence[str],
    level: float,
    method: str,
    samples: int,
    seed: int,
    engine: Any = None,
) -> polars.DataFrame:
    """The band of one calibrated model (no members) as the tidy frame
    (a sampled band's runs on the study ``engine`` when one is given)."""
    import polars as pl
    from scipy.stats import norm

    par = parameters_of(model)
    f = ModelOutputs(model, cond, quantities)
    if not par.names:  # nothing calibrated (a baseline; the generic control's member)
        method = "none"
    z = float(norm.ppf(0.5 + 0.5 * level))
    if method == "delta":
        value, lower, upper, sd = delta_band(f, par, z)
    elif engine is not None and method == "sampling":
        value, lower, upper, sd = study_band(model, cond, quantities, level, samples, seed, engine)
    else:
        value, lower, upper, sd = sampling_band(f, par, level, samples, seed)
    methods = np.full(value.size, method, dtype=object)
    term = discrepancy_part(model, cond, quantities)
    if term is not None:  # the unknown smooth term: its mean and variance added
        mean, var, has = term
        value = value + mean
        total = np.sqrt(sd * sd + var)
        lower = np.where(has, value - z * total, lower)
        upper = np.where(has, value + z * total, upper)
        methods[has] = DISCREPANCY
        if not par.names:  # nothing else of this member acts on the other quantities
            free = ~has
            lower = np.where(free, np.nan, lower)
            upper = np.where(free, np.nan, upper)
            methods[free] = UNCONSTRAINED
    n = cond.height
    weight = getattr(model, "weight", None)
    rep = pl.concat([cond] * len(quantities))
    return rep.with_columns(
        pl.Series("quantity", np.repeat(quantities, n).tolist(), dtype=pl.String),
        pl.Series("value", value),
        pl.Series("lower", lower),
        pl.Series("upper", upper),
        pl.Series("unit", [unit_of_quantity(q) for q in quantities for _ in range(n)]),
        pl.lit(member).alias("member"),
        pl.Series("method", methods.tolist(), dtype=pl.String),
        pl.lit(1.0 if not member else weight, dtype=pl.Float64).alias("weight"),
    ).with_columns(pl.col("lower", "upper").fill_nan(None))


def discrepancy_part(
    model: Any, cond: polars.DataFrame, quantities: Sequence[str]
) -> Optional[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """The model-discrepancy term a model carries (the generic control's
    member of an "unresolved" verdict: a Gaussian process in speed per
    measured quantity, ``thermobear.diagnosis.discrepancy``) at every
    output (quantity-major): (posterior mean, posterior variance, whether
    the quantity has a term); None without one. A quantity that was not
    measured has no term: mean and variance 0."""
    from ..diagnosis.discrepancy import discrepancy_at

    fitted = (getattr(model, "discrepancy", None) or {}).get(GAUSSIAN_PROCESS)
    if not fitted:
        return None
    speeds = cond["speed_rpm"].to_numpy()
    n = speeds.size
    mean, var = np.zeros(n * len(quantities)), np.zeros(n * len(quantities))
    has = np.zeros(n * len(quantities), dtype=bool)
    for k, q in enumerate(quantities):
        got = discrepancy_at(fitted, q, speeds)
        if got is not None:
            rows = slice(k * n, (k + 1) * n)
            mean[rows], var[rows], has[rows] = got[0], got[1], True
    return mean, var, has


def envelope(frames: Sequence[polars.DataFrame], cols: Sequence[str]) -> polars.DataFrame:
    """The envelope rows of the members' bands: lower the least lower,
    upper the greatest upper, value the members' mean."""
    import polars as pl

    keys = [*cols, "quantity", "unit"]
    return (
        pl.concat(frames)
        .group_by(keys, maintain_order=True)
        .agg(pl.col("value").mean(), pl.col("lower").min(), pl.col("upper").max())
        .with_columns(
            pl.lit(ENVELOPE).alias("member"),
            pl.lit(ENVELOPE).alias("method"),
            pl.lit(None, dtype=pl.Float64).alias("weight"),
        )
        .select([*cols, "quantity", *_TAIL])
    )


_TAIL = ("value", "lower", "upper", "unit", "member", "method", "weight")


def mixture(
    frames: Sequence[polars.DataFrame], cols: Sequence[str], level: float
) -> polars.DataFrame:
    """The rows of the weighed mixture of the members' bands (``member``
    and ``method`` "mixture"): each member's prediction read as a normal of
    mean ``value`` and standard deviation (upper - lower) / (2 z), weighed
    by its ``weight`` (equal weights where the members carry none); the
    mixture's mean and its quantiles at (1 -+ ``level``) / 2. Members with
    an unconstrained band are left out while their weight is below
    ``UNCONSTRAINED_WEIGHT``; above it the mixture is unconstrained."""
    import polars as pl
    from scipy.stats import norm

    z = float(norm.ppf(0.5 + 0.5 * level))
    k = len(frames)
    val = np.column_stack([f["value"].to_numpy() for f in frames])
    lo = np.column_stack([f["lower"].to_numpy().astype(float) for f in frames])
    hi = np.column_stack([f["upper"].to_numpy().astype(float) for f in frames])
    w = np.array([f["weight"][0] for f in frames], dtype=float) if k else np.ones(0)
    w = np.where(np.isfinite(w), w, 1.0)
    w = w / w.sum() if w.sum() > 0 else np.full(k, 1.0 / k)
    free = ~(np.isfinite(lo) & np.isfinite(hi))
    sd = np.where(free, 0.0, (hi - lo) / (2.0 * z))
    ww = np.where(free, 0.0, w[None, :])
    lost = np.sum(np.where(free, w[None, :], 0.0), axis=1)
    ww = ww / np.clip(ww.sum(axis=1, keepdims=True), 1e-300, None)
    mean = np.sum(ww * val, axis=1)
    a = 0.5 - 0.5 * level
    lower = mixture_quantile(val, sd, ww, a)
    upper = mixture_quantile(val, sd, ww, 1.0 - a)
    gone = lost > UNCONSTRAINED_WEIGHT
    method = np.where(gone, UNCONSTRAINED, MIXTURE)
    first = frames[0]
    return (
        first.select([*cols, "quantity"])
        .with_columns(
            pl.Series("value", np.where(gone & (ww.sum(axis=1) == 0), np.nan, mean)),
            pl.Series("lower", np.where(gone, np.nan, lower)),
            pl.Series("upper", np.where(gone, np.nan, upper)),
            first["unit"],
            pl.lit(MIXTURE).alias("member"),
            pl.Series("method", method.tolist(), dtype=pl.String),
            pl.lit(None, dtype=pl.Float64).alias("weight"),
        )
        .with_columns(pl.col("value", "lower", "upper").fill_nan(None))
    )


def mixture_quantile(mean: Any, sd: Any, weight: Any, p: float) -> np.ndarray:
    """The ``p`` quantile of each row's mixture of normals (``mean``,
    ``sd``, ``weight``: rows x members; a zero sd is a point mass), by
    bisection of the mixture's distribution function between the
    components' own quantiles (it lies between the least and the greatest
    of them)."""
    from scipy.stats import norm

    m = np.asarray(mean, dtype=float)
    s = np.asarray(sd, dtype=float)
    w = np.asarray(weight, dtype=float)
    zq = float(norm.ppf(p))
    ends = m + zq * s
    a = np.where(w > 0, ends, np.inf).min(axis=1)
    b = np.where(w > 0, ends, -np.inf).max(axis=1)
    a, b = np.minimum(a, b), np.maximum(a, b)
    tiny = 1e-12 * (np.abs(m).max(axis=1, keepdims=True) + 1.0)
    ss = np.maximum(s, tiny)
    for _ in range(100):
        mid = 0.5 * (a + b)
        cdf = np.sum(w * norm.cdf((mid[:, None] - m) / ss), axis=1)
        below = cdf < p
        a = np.where(below, mid, a)
        b = np.where(below, b, mid)
    return 0.5 * (a + b)

"""Gear regimes under the uncertainty of a calibrated bearing model: the
probability of each motion regime at each speed, and the speeds where the
regime changes, each with an interval.

Each quasi-random sample of the calibrated values (scrambled Sobol points
through the estimates' normal, clipped to the bounds: the sampling of
``thermobear.predict.uncertainty``) gives the bearing model at that sample;
the gear pair on those bearings (``GearSystem(gear, bearings=...,
stiffness="thermal")``: the thermal stiffness schedule of the sampled
bearing) is swept over the speeds, every sample's sweep in parallel
(``bifurcation_set``; or each sample a chunk of a ``regime_prediction``
study, ``engine=...``) with the RK4 steps its own speeds need, and each
speed's regime label is read off. A sample whose bearing model or sweep
fails is left out and counted (more than 10 % refuse the prediction).

* The probability of a regime at a speed is the share of samples with that
  label there; its interval is the Wilson score interval of a binomial
  share at ``level``.
* A boundary is a change of label between neighbouring speeds of a
  sample's sweep (in sweep order). Changes are matched across samples by
  their labels and their order along the sweep: the k-th change from
  regime A to regime B of one sample goes with the k-th of every other.
  Each sample's boundary lies between the two speeds that bracket it; the
  boundary speed is their midpoint's median over the samples, and its
  interval runs from the lower quantile ((1 - level) / 2) of the lower
  bracketing speeds to the upper quantile of the upper ones (a sample's own
  boundary is known only to the grid step). The probability of a change is
  the share of samples showing it.

Regime labels are not smooth functions of the calibrated values, so only
sampling applies; there is no delta-method check of these bands."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal, Mapping, Optional, Sequence

import numpy as np

from ..errors import ConfigError, ThermobearError
from . import sweeps
from .uncertainty import MAX_FAILED_FRACTION, Parameters, parameters_of, sobol_points

if TYPE_CHECKING:
    import polars

Direction = Literal["down", "up", "independent"]
_DIRECTIONS = ("down", "up", "independent")

#: The quantities of a regime prediction (the ``quantity`` column).
PROBABILITY = "regime_probability"
BOUNDARY = "regime_boundary_rpm"
CHANGE = "regime_change_probability"

#: Separates the two labels of a change in the ``regime`` column of the
#: boundary rows ("period-1 -> chaotic").
ARROW = " -> "

#: The ``member`` label of the rows that cover every member's probabilities.
ENVELOPE = "envelope"

#: Options of ``GearSystem`` a regime prediction sets itself.
_OWN_GEAR_OPTIONS = ("bearings", "stiffness")

#: Sweep options a regime prediction sets itself.
_OWN_SWEEP_OPTIONS = ("systems", "speeds_rpm", "directions", "progress")

COLUMNS = ("speed_rpm", "quantity", "regime", "value", "lower", "upper", "unit", "member", "method")


@dataclass
class Labels:
    """The regime labels of one member: ``labels`` (runs x speeds, in sweep
    order ``speeds``), ``method`` ("sampling", or "none" for a model with
    no calibrated value: one run)."""

    member: str
    speeds: np.ndarray
    labels: np.ndarray
    method: str


def wilson(k: np.ndarray, n: int, level: float) -> tuple[np.ndarray, np.ndarray]:
    """The Wilson score interval of ``k`` successes in ``n`` trials at
    probability ``level``."""
    from scipy.stats import norm

    z = float(norm.ppf(0.5 + 0.5 * level))
    p = np.asarray(k, dtype=float) / n
    den = 1.0 + z * z / n
    centre = (p + z * z / (2 * n)) / den
    half = z * np.sqrt(p * (1.0 - p) / n + z * z / (4.0 * n * n)) / den
    return np.clip(centre - half, 0.0, 1.0), np.clip(centre + half, 0.0, 1.0)


def sweep_speeds(conditions: Any) -> np.ndarray:
    """The speeds of a regime prediction: ``{"speeds_rpm": [...]}`` or a
    frame with ``speed_rpm`` (distinct, finite, > 0)."""
    import polars as pl

    if isinstance(conditions, Mapping):
        extra = sorted(set(conditions) - {"speeds_rpm"})
        if extra or "speeds_rpm" not in conditions:
            raise ConfigError(
                f"invalid conditions = {dict(conditions)!r}: a regime prediction takes only "
                "speeds_rpm (the torque and the rest go in gear_options)"
            )
        v = np.atleast_1d(np.asarray(conditions["speeds_rpm"], dtype=float))
    elif isinstance(conditions, pl.DataFrame) and "speed_rpm" in conditions.columns:
        v = conditions["speed_rpm"].cast(pl.Float64).to_numpy()
    else:
        raise ConfigError(
            f"invalid conditions = {conditions!r}: give {{'speeds_rpm': [...]}} (a gear pair's "
            "regimes have no measured conditions to default to)"
        )
    v = np.unique(v)
    if v.size < 2 or not np.all(np.isfinite(v)) or np.any(v <= 0.0):
        raise ConfigError(f"invalid speeds_rpm = {v.tolist()}: at least 2 finite speeds > 0")
    return v


def _checked_options(
    gear_options: Optional[Mapping[str, Any]],
    sweep_options: Optional[Mapping[str, Any]],
    gear_model: bool = False,
) -> tuple[dict, dict]:
    import inspect

    from ..gear.dynamics import bifurcation_set

    g, s = dict(gear_options or {}), dict(sweep_options or {})
    own = ("bearings",) if gear_model else _OWN_GEAR_OPTIONS
    for k in own:
        if k in g:
            raise ConfigError(
                f"invalid gear_options {k} = {g[k]!r}: a regime prediction puts the calibrated "
                "bearings on the thermal stiffness schedule itself"
            )
    known = set(inspect.signature(bifurcation_set).parameters) - set(_OWN_SWEEP_OPTIONS)
    for k in s:
        if k not in known:
            raise ConfigError(
                f"invalid sweep_options {k} = {s[k]!r}: one of {', '.join(sorted(known))}"
            )
    return g, s


def member_labels(
    model: Any,
    member: str,
    speeds: np.ndarray,
    run: tuple[Any, dict, dict, str],
    samples: int,
    seed: int,
    engine: Any = None,
) -> Labels:
    """Sample ``model``'s calibrated values, build each sample's gear
    system and sweep them (``run``: gear, gear options, sweep options,
    direction): all at once in this process (``engine`` None), or each
    sample a chunk of a ``regime_prediction`` study on ``engine``.
    Identical samples (a zero covariance) run once. A sample whose bearing
    model or sweep fails is left out and counted; more than
    ``MAX_FAILED_FRACTION`` of them refuse the prediction."""
    par: Parameters = parameters_of(model)
    method = "sampling" if par.names else "none"
    thetas = sobol_points(par, samples, seed) if par.names else par.values[None, :]
    keys = [tuple(float(x) for x in t) for t in thetas]
    distinct = list(dict.fromkeys(keys))
    order = sweep_order(speeds, run[3])
    if engine is None:
        got = _labels_here(model, distinct, speeds, run)
    else:
        from .engine import study_labels

        first = [keys.index(k) + 1 if par.names else 0 for k in distinct]
        got = dict(zip(distinct, study_labels(model, first, order, run, samples, seed, engine),
                       strict=True))  # fmt: skip
    failed = [k for k in keys if not isinstance(got[k], dict)]
    if len(failed) > MAX_FAILED_FRACTION * len(keys) or len(failed) == len(keys):
        raise ThermobearError(
            f"regime prediction ({member or 'model'}): the bearing model or its sweep failed at "
            f"{len(failed)} of {len(keys)} samples of the calibrated values ({got[failed[0]]}); "
            "check the calibration"
        )
    rows = [[got[k][v] for v in order] for k in keys if isinstance(got[k], dict)]
    return Labels(member, order, np.array(rows, dtype=object), method)


def sweep_order(speeds: np.ndarray, direction: str) -> np.ndarray:
    """The speeds in the order a sweep in ``direction`` visits them."""
    return np.sort(speeds)[::-1] if direction == "down" else np.sort(speeds)


def _labels_here(
    model: Any, distinct: Sequence[tuple], speeds: np.ndarray, run: tuple[Any, dict, dict, str]
) -> dict[tuple, Any]:
    """Each distinct sample's labels by speed (a dict), or the message of
    its failure (a str): every sample's system swept in this process."""
    gear, gear_options, sweep_options, direction = run
    out: dict[tuple, Any] = {}
    systems = {}
    for i, key in enumerate(distinct):
        try:
            systems[str(i)] = sweeps.regime_system(model, np.asarray(key), gear, gear_options)
        except ThermobearError as e:
            out[key] = f"{type(e).__name__}: {e}"
    labels, failed = (
        sweeps.sweep_labels(systems, speeds, direction, sweep_options) if systems else ({}, {})
    )
    for i, key in enumerate(distinct):
        if str(i) in systems:
            out[key] = labels[str(i)] if str(i) in labels else failed[str(i)]
    return out


def regime_order(names: Sequence[str]) -> list[str]:
    """Regime labels in a reading order: period-n by n, quasi-periodic,
    chaotic, then any other."""

    def key(r: str) -> tuple[int, int, str]:
        if r.startswith("period-") and r[7:].isdigit():
            return (0, int(r[7:]), r)
        return ({"quasi-periodic": 1, "chaotic": 2}.get(r, 3), 0, r)

    return sorted(set(names), key=key)


def probability_rows(lab: Labels, regimes: Sequence[str], level: float) -> polars.DataFrame:
    """The ``regime_probability`` rows of one member: every regime of
    ``regimes`` at every speed (speed-major, sweep order)."""
    import polars as pl

    n = lab.labels.shape[0]
    k = np.stack([(lab.labels == r).sum(axis=0) for r in regimes], axis=1)  # speeds x regimes
    value = k / n
    if lab.method == "none":
        lower, upper = value, value
    else:
        lower, upper = wilson(k, n, level)
    return pl.DataFrame(
        {
            "speed_rpm": np.repeat(lab.speeds, len(regimes)),
            "quantity": PROBABILITY,
            "regime": list(regimes) * len(lab.speeds),
            "value": value.reshape(-1),
            "lower": np.asarray(lower, dtype=float).reshape(-1),
            "upper": np.asarray(upper, dtype=float).reshape(-1),
            "unit": "1",
            "member": lab.member,
            "method": lab.method,
        }
    ).select(COLUMNS)


def changes(speeds: np.ndarray, labels: Sequence[str]) -> dict[tuple[str, str, int], tuple]:
    """A sweep's label changes: (from, to, k) -> (lower, upper) bracketing
    speeds, k counting the changes from ``from`` to ``to`` along the sweep."""
    out: dict[tuple[str, str, int], tuple] = {}
    seen: dict[tuple[str, str], int] = {}
    for i in range(len(labels) - 1):
        a, b = labels[i], labels[i + 1]
        if a != b:
            k = seen.get((a, b), 0)
            seen[(a, b)] = k + 1
            s0, s1 = float(speeds[i]), float(speeds[i + 1])
            out[(a, b, k)] = (min(s0, s1), max(s0, s1))
    return out


def boundary_rows(lab: Labels, level: float) -> polars.DataFrame:
    """The ``regime_boundary_rpm`` and ``regime_change_probability`` rows of
    one member, one pair per change (in the order of the median speed
    along the sweep)."""
    import polars as pl

    n = lab.labels.shape[0]
    groups: dict[tuple[str, str, int], list[tuple[float, float]]] = {}
    for row in lab.labels:
        for key, bracket in changes(lab.speeds, list(row)).items():
            groups.setdefault(key, []).append(bracket)
    a = 0.5 * (1.0 - level)
    rows = []
    for (frm, to, _), brackets in groups.items():
        lo, hi = np.array(brackets).T
        mid = np.quantile(0.5 * (lo + hi), 0.5, method="inverted_cdf")
        lower = float(np.quantile(lo, a, method="inverted_cdf"))
        upper = float(np.quantile(hi, 1.0 - a, method="inverted_cdf"))
        share = len(brackets) / n
        if lab.method == "none":
            plo, phi = share, share
        else:
            plo, phi = (float(x) for x in wilson(np.array(len(brackets)), n, level))
        label = f"{frm}{ARROW}{to}"
        rows.append((float(mid), BOUNDARY, label, float(mid), lower, upper, "rpm"))
        rows.append((float(mid), CHANGE, label, share, plo, phi, "1"))
    types = [pl.Float64, pl.Utf8, pl.Utf8, pl.Float64, pl.Float64, pl.Float64, pl.Utf8]
    schema = dict(zip(COLUMNS[:7], types, strict=True))
    df = pl.DataFrame(rows, schema=schema, orient="row")
    sign = -1.0 if lab.speeds.size > 1 and lab.speeds[0] > lab.speeds[-1] else 1.0
    df = df.with_columns(pl.lit(lab.member).alias("member"), pl.lit(lab.method).alias("method"))
    return df.sort(pl.col("speed_rpm") * sign, maintain_order=True)


def envelope_rows(frames: Sequence[polars.DataFrame]) -> polars.DataFrame:
    """The envelope of the members' regime probabilities: value the
    members' mean, lower the least lower, upper the greatest upper."""
    import polars as pl

    keys = ["speed_rpm", "quantity", "regime", "unit"]
    return (
        pl.concat([f.filter(pl.col("quantity") == PROBABILITY) for f in frames])
        .group_by(keys, maintain_order=True)
        .agg(pl.col("value").mean(), pl.col("lower").min(), pl.col("upper").max())
        .with_columns(pl.lit(ENVELOPE).alias("member"), pl.lit(ENVELOPE).alias("method"))
        .select(COLUMNS)
    )


def predict_regimes(
    model: Any,
    conditions: Any,
    level: float = 0.95,
    method: str = "auto",
    samples: int = 32,
    seed: int = 0,
    gear: Any = None,
    gear_options: Optional[Mapping[str, Any]] = None,
    direction: Direction = "down",
    sweep_options: Optional[Mapping[str, Any]] = None,
    engine: Any = None,
) -> polars.DataFrame:
    """The motion regimes of a gear pair on a calibrated bearing model's
    bearings, with the uncertainty of its calibrated values:
    ``predict(model, "regimes", ...)`` (see the module
    ``thermobear.predict.regimes`` for the method).

    ``model``: a calibrated bearing model (the gear pair ``gear`` on its
    bearings' thermal stiffness schedule), or a calibrated gear model (its
    own pair with its calibrated inputs, in the stiffness case of
    ``gear_options["stiffness"]`` or its own; the samples are of its
    inputs); ``conditions``:
    ``{"speeds_rpm": [...]}`` (or a frame with ``speed_rpm``); ``level``:
    probability of the intervals; ``method``: ``"auto"`` or ``"sampling"``
    (regime labels are not smooth in the calibrated values: no delta
    method); ``samples`` scrambled Sobol points (``seed``) of the
    estimates' normal, clipped to the bounds; ``gear``: a
    [`GearPair`][thermobear.GearPair] (None: the seed pair);
    ``gear_options``: keywords of [`GearSystem`][thermobear.GearSystem]
    (``torque_n_m``, ``te_amplitude_um``, ``stiffness_speeds_rpm``, ...;
    the bearings sit on each sample's thermal stiffness schedule);
    ``direction`` of the sweeps (``"down"``, ``"up"``, ``"independent"``);
    ``sweep_options``: keywords of
    [`bifurcation_set`][thermobear.bifurcation_set] (``transient_periods``,
    ``record_periods``, ``lyapunov_periods``, ``steps_per_period``, the
    classifier settings; without ``steps_per_period`` each sample's sweep
    takes the steps its own speeds need); ``engine``: None sweeps every
    sample in this process (in parallel), ``"local"``, a Dask ``Client`` or
    a scheduler address runs each sample's sweep as a chunk of a
    ``regime_prediction`` [`Study`][thermobear.Study]: the same labels. A
    sample whose bearing model or sweep fails (at any speed) is left out;
    more than 10 % failed samples refuse the prediction.

    Returns the tidy frame (``speed_rpm``, ``quantity``, ``regime``,
    ``value``, ``lower``, ``upper``, ``unit``, ``member``, ``method``):
    ``"regime_probability"`` rows, every regime seen at every speed (in
    sweep order) with its share of the samples and the Wilson interval;
    then per regime change a ``"regime_boundary_rpm"`` row (``regime``
    "from -> to", value the median boundary speed, lower and upper its
    interval, unit rpm) and a ``"regime_change_probability"`` row (the
    share of samples with that change, Wilson interval), ``speed_rpm`` the
    median boundary. Under a tie or "unresolved" each member gets its rows
    and the ``member`` "envelope" rows span the members' probabilities
    (value their mean, lower the least lower, upper the greatest upper). A
    model with no calibrated value runs once (``method`` "none", zero-width
    intervals)."""
    import polars as pl

    if method not in ("auto", "sampling"):
        raise ConfigError(
            f"invalid method = {method!r}: regime labels are not smooth in the calibrated "
            "values; 'auto' or 'sampling'"
        )
    pair = _checked_gear(model, gear, direction)
    speeds = sweep_speeds(conditions)
    g, s = _checked_options(gear_options, sweep_options, sweeps.is_gear_spec(model.spec))
    run = (pair, g, s, direction)
    members = tuple(getattr(model, "members", ()) or ())
    targets = [(m, str(m.label)) for m in members] if members else [(model, "")]
    labs = [member_labels(m, tag, speeds, run, samples, seed, engine) for m, tag in targets]
    regimes = regime_order([str(x) for lab in labs for x in lab.labels.reshape(-1)])
    frames = [
        pl.concat([probability_rows(lab, regimes, level), boundary_rows(lab, level)])
        for lab in labs
    ]
    if members:
        frames.append(envelope_rows(frames))
    return pl.concat(frames)


def _checked_gear(model: Any, gear: Any, direction: str) -> Any:
    """The gear pair (None: the seed pair; a calibrated gear model's own),
    after checking ``direction`` and that ``model`` is a bearing or a gear
    model."""
    from ..gear.pair import GearPair

    if direction not in _DIRECTIONS:
        raise ConfigError(f"invalid direction = {direction!r}: one of {', '.join(_DIRECTIONS)}")
    if sweeps.is_gear_spec(model.spec):
        if gear is not None:
            raise ConfigError(
                f"invalid gear = {gear!r}: a calibrated gear model brings its own pair"
            )
        return model.spec.gear
    pair = GearPair.preset("seed-electric-drive") if gear is None else gear
    if not isinstance(pair, GearPair):
        raise ConfigError(f"invalid gear = {gear!r}: a thermobear.GearPair")
    if not hasattr(model.spec, "bearing"):
        raise ConfigError(
            f"invalid model = {model!r}: gear regimes need a calibrated bearing model (the "
            "bearings of the gear pair)"
        )
    return pair


def regime_boundaries(prediction: polars.DataFrame) -> polars.DataFrame:
    """The regime boundaries of a regime prediction
    (``thermobear.predict(model, "regimes", ...)``): one row per change of
    regime along the sweep (per member), in sweep order. Columns:
    ``from_regime``, ``to_regime``, ``speed_rpm`` (the median over the
    samples of the boundary, each sample's boundary the midpoint of the two
    speeds bracketing its change), ``lower_rpm``, ``upper_rpm`` (the
    interval over the samples at the prediction's level: the lower
    quantile of the lower bracketing speeds, the upper quantile of the
    upper ones), ``probability`` (the share of samples showing that
    change), ``probability_lower``, ``probability_upper`` (its Wilson
    interval), ``member``, ``method``. The k-th change from one regime to
    another along a sample's sweep is matched with the k-th of every other
    sample."""
    import polars as pl

    need = {"quantity", "regime", "speed_rpm", "value", "lower", "upper", "member"}
    if not isinstance(prediction, pl.DataFrame) or not need <= set(prediction.columns):
        got = list(prediction.columns) if isinstance(prediction, pl.DataFrame) else prediction
        raise ConfigError(
            f"invalid prediction = {got!r}: give the frame of a regime prediction, "
            "thermobear.predict(model, 'regimes', ...)"
        )
    b = prediction.filter(pl.col("quantity") == BOUNDARY)
    c = prediction.filter(pl.col("quantity") == CHANGE)
    if b.height != c.height:
        raise ConfigError("invalid prediction: boundary and change rows do not pair up")
    parts = pl.col("regime").str.split_exact(ARROW, 1)
    return b.select(
        parts.struct.field("field_0").alias("from_regime"),
        parts.struct.field("field_1").alias("to_regime"),
        pl.col("value").alias("speed_rpm"),
        pl.col("lower").alias("lower_rpm"),
        pl.col("upper").alias("upper_rpm"),
        pl.Series("probability", c["value"]),
        pl.Series("probability_lower", c["lower"]),
        pl.Series("probability_upper", c["upper"]),
        pl.col("member"),
        pl.col("method"),
    )

"""The reference-speed set (``kind = "reference_speed"``): catalogue
reference speeds as a heat balance (docs/concepts/physics.md §9,
"Reference speed").

ISO 15312 defines a bearing's reference speed n_r as the speed at which,
under its reference conditions (stationary ring at 70 C, 20 C ambient,
radial load 0.05 C0, oil of 12 mm^2/s in a bath up to the middle of the
lowest ball), the friction heat equals the reference heat flow

    Phi_r = q_r A_r,   A_r = pi B (D + d),
    q_r = 0.016 W/mm^2 (A_r <= 50 000 mm^2), 0.016 (A_r / 50 000)^-0.34 above.

So every catalogue row is a published friction heat Phi_r at a known speed,
load and viscosity. Each heat model thermobear offers is evaluated there
with [`thermobear.thermal.isothermal_heat`][thermobear.isothermal_heat]; each candidate calibrates
at most one input on the set's calibration bearings, the candidate with the
lowest AIC (chi^2 + 2 k) on them is chosen, and every other bearing is held
out."""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .._types import Lubrication
from ..bearing import Bearing
from ..errors import ConfigError
from .catalogue import inch_ball_mm
from .result import SetResult

if TYPE_CHECKING:
    import polars


#: The calibrated scale of the catalogue's oil-bath drag (its V_M at the ISO
#: reference level over the model's default): a validation parameter, applied
#: to the model's drag by the evaluator (``_Evaluator.heat``).
BATH_DRAG_SCALE = "bath_drag_scale"
#: Oil-supply keywords a candidate may set (dropped for the heat without drag).
SUPPLY_KEYS = ("oil_level_mm",)


def reference_heat_flow_w(bore_mm: float, outer_diameter_mm: float, width_mm: float) -> float:
    """ISO 15312 reference heat flow Phi_r = q_r A_r [W] of a radial bearing
    (module doc)."""
    a_r = math.pi * width_mm * (bore_mm + outer_diameter_mm)
    q_r = 0.016 if a_r <= 50_000.0 else 0.016 * (a_r / 50_000.0) ** -0.34
    return q_r * a_r


def catalogue_deep_groove(row: dict) -> Bearing:
    """A deep-groove bearing from boundary dimensions with the set's assumed
    internal geometry (the set's ``[geometry]``): ball the standard inch ball
    nearest 0.3 (D - d), round(0.55 pi dm / D_w) balls, f_i = 0.515,
    f_o = 0.525, the middle of the normal clearance range."""
    d, big_d = float(row["bore_mm"]), float(row["outer_diameter_mm"])
    dm = 0.5 * (d + big_d)
    dw = inch_ball_mm(d, big_d)
    lo, hi = row["normal_clearance_um"]
    return Bearing.deep_groove(
        ball_count=int(round(0.55 * math.pi * dm / dw)),
        ball_diameter_mm=dw,
        pitch_diameter_mm=dm,
        inner_conformity=0.515,
        outer_conformity=0.525,
        diametral_clearance_mm=0.5e-3 * (float(lo) + float(hi)),
        bore_mm=d,
        outer_diameter_mm=big_d,
        width_mm=float(row["width_mm"]),
        name=str(row["name"]),
    )


@dataclass(frozen=True)
class HeatCandidate:
    """One heat-model setting: fixed options and at most one calibrated
    option ``parameter`` within ``bounds``."""

    name: str
    options: dict
    parameter: str = ""
    bounds: tuple = (0.0, 0.0)
    description: str = ""
    iso_oil_level: bool = False  # oil_level_mm: the ISO 15312 level, mid lowest ball

    def options_for(self, bearing: Bearing) -> dict:
        """The options of this candidate for one ``bearing``: with
        ``iso_oil_level``, ``oil_level_mm`` = half its ball diameter (oil up to
        the middle of the lowest ball, measured from its lowest point)."""
        if not self.iso_oil_level:
            return dict(self.options)
        return {**self.options, "oil_level_mm": 0.5 * bearing.geometry["ball_diameter_mm"]}

    @property
    def k(self) -> int:
        return 1 if self.parameter else 0


def heat_candidates(lubrication: Lubrication) -> list[HeatCandidate]:
    """The baseline (Palmgren with the lubrication method's f0 and ball
    drag) and the alternatives an engineer would try."""
    from ..thermal import lubrication_defaults

    lub = lubrication_defaults(lubrication, "deep_groove")
    f0b, xb = lub["f0_bounds"], (0.0, lub["oil_fraction_bounds"][1])
    base = {"lubrication": lubrication}
    return [
        HeatCandidate("baseline", base, description="Palmgren, the method's f0 and drag"),
        HeatCandidate(
            "palmgren_f0",
            {**base, "churning_oil_fraction": 0.0},
            "lubrication_factor_f0",
            f0b,
            "Palmgren without ball drag, f0 calibrated",
        ),
        HeatCandidate(
            "palmgren_drag",
            base,
            "churning_oil_fraction",
            xb,
            "Palmgren with the method's f0, ball-drag oil fraction calibrated",
        ),
        HeatCandidate(
            "skf",
            {**base, "heat_model": "skf", "churning_oil_fraction": 0.0},
            description="SKF-style four-term moment, no ball drag",
        ),
        HeatCandidate(
            "skf_drag",
            {**base, "heat_model": "skf"},
            "churning_oil_fraction",
            xb,
            "SKF-style four-term moment, ball-drag oil fraction calibrated",
        ),
        HeatCandidate(
            "skf_bath",
            {**base, "heat_model": "skf"},
            description="SKF-style moment with the catalogue's oil-bath drag V_M dm^5 n^2 "
            "at the ISO level, V_M as shipped",
            iso_oil_level=True,
        ),
        HeatCandidate(
            "skf_bath_fit",
            {**base, "heat_model": "skf"},
            BATH_DRAG_SCALE,
            (0.0, 5.0),
            "SKF-style moment with the oil-bath drag, its V_M scale calibrated",
            iso_oil_level=True,
        ),
    ]


def reference_points(data: dict) -> polars.DataFrame:
    """One row per bearing: ``bearing``, ``pitch_diameter_mm``, ``speed_rpm`` (the reference
    speed), ``radial_n`` (the reference load), ``quantity``
    (``reference_heat_w``), ``value`` (Phi_r), ``sigma``, ``label``."""
    import polars as pl

    rel = float(data["sigma"]["relative"])
    frac = float(data["conditions"]["radial_load_fraction_of_c0"])
    rows = []
    for b in data["bearings"]:
        phi = reference_heat_flow_w(b["bore_mm"], b["outer_diameter_mm"], b["width_mm"])
        rows.append(
            {
                "bearing": b["name"],
                "pitch_diameter_mm": 0.5 * (float(b["bore_mm"]) + float(b["outer_diameter_mm"])),
                "speed_rpm": float(b["reference_speed_rpm"]),
                "radial_n": frac * 1e3 * float(b["static_load_rating_kn"]),
                "quantity": "reference_heat_w",
                "value": phi,
                "sigma": rel * phi,
                "label": f"{b['name']}:reference_heat_w",
            }
        )
    return pl.DataFrame(rows)


def oil_temperature_for(lubricant: str, viscosity_cst: float) -> float:
    """The temperature [C] at which the ``lubricant`` preset has
    ``viscosity_cst`` (the reference conditions prescribe the viscosity)."""
    from scipy.optimize import brentq

    from ..thermal import isothermal_heat

    probe = Bearing.preset("6208")

    def gap(t: float) -> float:
        h = isothermal_heat(probe, 1000.0, 0.0, 100.0, oil_temperature_c=t, lubricant=lubricant)
        return h.viscosity_cst - viscosity_cst

    return float(brentq(gap, 20.0, 140.0, xtol=1e-6))


class _Evaluator:
    """Model heat of every bearing of a set for a candidate setting (cached)."""

    def __init__(self, data: dict, pts: polars.DataFrame):
        cond = data["conditions"]
        self.lubricant = str(cond["oil"])
        self.oil_c = oil_temperature_for(self.lubricant, float(cond["viscosity_cst"]))
        self.bearings = {b["name"]: catalogue_deep_groove(b) for b in data["bearings"]}
        self.pts = pts
        self._cache: dict = {}

    def _total(self, bearing: str, p: dict, options: dict) -> float:
        from ..thermal import isothermal_heat

        key = (bearing, tuple(sorted(options.items())))
        if key not in self._cache:
            self._cache[key] = isothermal_heat(
                self.bearings[bearing], p["speed_rpm"], 0.0, p["radial_n"],
                oil_temperature_c=self.oil_c, lubricant=self.lubricant, **options,
            ).total_heat_w  # fmt: skip
        return self._cache[key]

    def heat(self, cand: HeatCandidate, value: float | None, rows: np.ndarray) -> np.ndarray:
        """Model heat [W] of the ``rows`` for ``cand`` with its parameter at
        ``value``. The parameter ``BATH_DRAG_SCALE`` is no model keyword: it
        scales the candidate's oil-bath drag, the heat with the drag minus the
        heat with none (the drag is linear in the catalogue's V_M)."""
        if cand.parameter and value is None:
            raise ConfigError(
                f"invalid value = None: the candidate {cand.name} calibrates {cand.parameter}"
            )
        scale = cand.parameter == BATH_DRAG_SCALE
        v = 0.0 if value is None else float(value)
        extra = {cand.parameter: v} if cand.parameter and not scale else {}
        out = np.empty(len(rows))
        for j, i in enumerate(rows):
            p = self.pts.row(int(i), named=True)
            opts = {**cand.options_for(self.bearings[p["bearing"]]), **extra}
            total = self._total(p["bearing"], p, opts)
            if scale:
                dry = {k: v for k, v in opts.items() if k not in SUPPLY_KEYS}
                bare = self._total(p["bearing"], p, {**dry, "churning_oil_fraction": 0.0})
                total = bare + v * (total - bare)
            out[j] = total
        return out


def _fit(ev: _Evaluator, cand: HeatCandidate, cal: np.ndarray) -> tuple[float | None, float]:
    """The candidate's calibrated value (None without a parameter) and its
    chi^2 on the calibration rows."""
    from scipy.optimize import minimize_scalar

    rows = np.flatnonzero(cal)
    y, s = ev.pts["value"].to_numpy()[rows], ev.pts["sigma"].to_numpy()[rows]

    def chi2(v: float | None) -> float:
        return float(np.sum(((ev.heat(cand, v, rows) - y) / s) ** 2))

    if not cand.parameter:
        return None, chi2(None)
    lo, hi = cand.bounds
    r = minimize_scalar(chi2, bounds=(lo, hi), method="bounded", options={"xatol": 1e-6})
    return float(r.x), chi2(float(r.x))


def _candidate_rows(
    cal_ev: _Evaluator, ev: _Evaluator, cands: list, cal: np.ndarray, held: np.ndarray
) -> list[dict]:
    """Fit every candidate on the calibration rows ``cal`` of ``cal_ev`` (this set's
    evaluator, or the calibration set's) and score it on the rows ``held`` of ``ev``."""
    y, s = ev.pts["value"].to_numpy(), ev.pts["sigma"].to_numpy()
    dm = ev.pts["pitch_diameter_mm"].to_numpy()[held]
    every = np.arange(len(y))
    rows = []
    for c in cands:
        v, chi2 = _fit(cal_ev, c, cal)
        z = (ev.heat(c, v, every) - y) / s
        h = z[held]
        span = c.bounds[1] - c.bounds[0]
        at_bound = bool(c.parameter) and min(abs(v - b) for b in c.bounds) <= 1e-3 * span
        rows.append(
            {
                "candidate": c.name,
                "description": c.description,
                "parameter": c.parameter or "-",
                "value": float("nan") if v is None else v,
                "chi2_calibration": chi2,
                "aic": chi2 + 2.0 * c.k,
                "at_bound": at_bound,
                "heldout_rms_sigma": float(np.sqrt(np.mean(h**2))),
                "heldout_max_sigma": float(np.abs(h).max()),
                "heldout_size_correlation": float(np.corrcoef(dm, h)[0, 1]),
                "_value": v,
                "_cand": c,
            }
        )
    return rows


def _calibration_side(
    data: dict, ev: _Evaluator, cal_data: dict | None
) -> tuple[_Evaluator, np.ndarray, np.ndarray, str]:
    """Where the candidates are calibrated: on ``[calibration] calibrate_on`` of
    this set (the other bearings held out), or, with ``calibration_set``, on
    those bearings of that shipped set (every bearing of this set held out: a
    reference the model was not tuned to). Returns the calibration evaluator,
    its calibration rows, this set's held-out rows and the hold-out statement.
    ``cal_data``: the set named by ``calibration_set``, loaded by the caller."""
    cal_spec = data["calibration"]
    names = ", ".join(cal_spec["calibrate_on"])
    other = cal_spec.get("calibration_set")
    if not other:
        cal = np.isin(ev.pts["bearing"].to_numpy(), cal_spec["calibrate_on"])
        text = f"candidates calibrated on {names}; held out: the other {int((~cal).sum())} bearings"
        return ev, cal, ~cal, text
    if cal_data is None or cal_data.get("name") != other:
        raise ConfigError(f"invalid calibration_set = {other!r}: its data were not given")
    cal_ev = _Evaluator(cal_data, reference_points(cal_data))
    cal = np.isin(cal_ev.pts["bearing"].to_numpy(), cal_spec["calibrate_on"])
    if not cal.any():
        raise ConfigError(f"invalid calibrate_on = {cal_spec['calibrate_on']!r}: not in {other}")
    held = np.ones(ev.pts.height, dtype=bool)
    text = (
        f"candidates calibrated on {names} of {other}; no value calibrated on this set: "
        f"all {ev.pts.height} bearings held out"
    )
    return cal_ev, cal, held, text


def run_reference_speed(data: dict, cal_data: dict | None = None) -> SetResult:
    """Validate a reference-speed set (module doc): the baseline, every
    candidate calibrated on ``[calibration] calibrate_on`` (of this set, or of
    the set named by ``calibration_set``, whose data ``cal_data`` the caller
    loads), the one with the lowest AIC there
    (a candidate stuck at a bound is no choice) checked on the held-out
    bearings."""
    import polars as pl

    t0 = time.perf_counter()
    pts = reference_points(data)
    ev = _Evaluator(data, pts)
    cal_ev, cal, held, holdout = _calibration_side(data, ev, cal_data)
    cands = heat_candidates(data["conditions"]["lubrication"])
    rows = _candidate_rows(cal_ev, ev, cands, cal, held)
    free = [r for r in rows if not r["at_bound"]] or rows
    best = min(free, key=lambda r: r["aic"])
    every = np.arange(pts.height)
    frame = pts.with_columns(
        pl.Series("model_before", ev.heat(cands[0], None, every)),
        pl.Series("model_after", ev.heat(best["_cand"], best["_value"], every)),
        pl.Series("heldout", held),
    )
    table = pl.DataFrame([{k: v for k, v in r.items() if not k.startswith("_")} for r in rows])
    c = best["_cand"]
    calibrated = (
        [{"name": c.parameter, "value": best["_value"], "lower": c.bounds[0],
          "upper": c.bounds[1], "unit": "1"}] if c.parameter else []
    )  # fmt: skip
    res = SetResult(
        data["name"],
        data["title"],
        data["source"]["citation"],
        frame,
        _verdict(frame, best, ev.oil_c, data["calibration"].get("calibration_set", "")),
        calibrated,
        holdout=holdout,
        tables={"heat-model candidates": table},
    )
    res.notes += _notes(frame)
    if not res.passes:
        res.missing = _missing(frame, data)
    res.seconds = time.perf_counter() - t0
    return res


def _ratio_range(frame: polars.DataFrame, col: str) -> str:
    r = (frame[col] / frame["value"]).to_numpy()
    return f"{r.min():.2f}-{r.max():.2f} x"


def _verdict(frame: polars.DataFrame, best: dict, oil_c: float, other: str = "") -> str:
    v = best["_value"]
    where = f" of {other}" if other else ""
    par = f" with {best['parameter']} = {v:.3g}" if v is not None else ""
    before, after = _ratio_range(frame, "model_before"), _ratio_range(frame, "model_after")
    return (
        f"baseline (Palmgren, oil-bath f0 and bath drag) gives {before} the catalogue heat; "
        f"the lowest-AIC candidate on the calibration bearings{where} is "
        f"'{best['candidate']}'{par} "
        f"({best['description']}): {after} (ISO VG 32 at {oil_c:.1f} C = 12 mm^2/s)"
    )


def _notes(frame: polars.DataFrame) -> list[str]:
    return [
        "Catalogue data (the maker's reference speeds, computed with the maker's own friction "
        "model under the ISO 15312 reference conditions), not a measurement of one bearing.",
        "The reference heat flow density q_r and surface A_r are ISO 15312's; they were read "
        "from a public implementation of the standard, not from the standard itself.",
        "tb.diagnose is not run on this set: its bearing model predicts the coupled thermal "
        "state, while the reference conditions fix the temperature; the heat-model candidates "
        "are screened here instead (same rule: calibrate, compare, hold out).",
    ]


def size_correlation(frame: polars.DataFrame) -> float:
    """Correlation of the held-out residual (``model_after - value``) / sigma with the
    pitch diameter (d + D)/2 of the bearings: near -1 when the calibrated model's
    error falls steadily with bearing size. ``frame``: a reference-speed
    result's ``points``."""
    held = frame.filter(frame["heldout"])
    z = ((held["model_after"] - held["value"]) / held["sigma"]).to_numpy()
    return float(np.corrcoef(held["pitch_diameter_mm"].to_numpy(), z)[0, 1])


def _missing(frame: polars.DataFrame, data: dict) -> str:
    held = frame.filter(frame["heldout"])
    z = ((held["model_after"] - held["value"]) / held["sigma"]).to_numpy()
    bad = np.abs(z) > 2.0
    if not bad.any():
        return "a calibrated value lies outside its bounds"
    r = size_correlation(frame)
    trend = (
        f"; the residual {'falls' if r < 0 else 'grows'} with bearing size (correlation {r:.2f} "
        "with the pitch diameter), so the missing term scales with size unlike the candidates'"
        if abs(r) > 0.7
        else f"; all {'above' if z[bad].min() > 0 else 'below'} it with no size trend (correlation "
        f"{r:.2f}): an offset of the whole set, as from a coefficient that differs for its "
        "bearings"
        if (z[bad] > 0).all() or (z[bad] < 0).all()
        else ""
    )
    names = ", ".join(held.filter(bad)["bearing"].to_list())
    return (
        f"{int(bad.sum())} of {held.height} held-out bearings lie {np.abs(z[bad]).min():.1f}-"
        f"{np.abs(z[bad]).max():.1f} sigma from the catalogue heat ({names}){trend}"
    )

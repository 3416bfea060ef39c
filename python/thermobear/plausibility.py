"""Plausibility limits: where real machines stop, and where the model does.

Two tiers (every limit, with its source, is on the docs page "Limits"):

* past what real machines do, a
  [`PlausibilityWarning`][thermobear.PlausibilityWarning] and the result is
  still returned: a speed factor n dm past what the lubrication method
  supports, a maximum Hertz contact pressure past the material's static
  limit (4,200 MPa for bearing steel, ISO 76), a misalignment past a few
  milliradians. These limits can be tightened or widened:
  [`set_limits`][thermobear.set_limits] for the rest of the program, or
  [`limits`][thermobear.limits] as a context manager for a block;
* where the model stops being valid, a
  [`ConfigError`][thermobear.ConfigError] naming the inputs: a contact
  ellipse reaching past the groove (its edge beyond 90 degrees from the
  radial plane), an inner-ring tilt that moves the groove at the balls by
  more than the distance between the curvature centres (``A = (f_i + f_o -
  1) D``). These are geometry, not settings.

The limits are held per thread and per asyncio task (a ``ContextVar``).
"""

from __future__ import annotations

import contextlib
import dataclasses
import math
import warnings
from contextvars import ContextVar
from dataclasses import dataclass
from typing import Any, Iterator, NoReturn, Optional

from ._limits import _outside_stacklevel
from .errors import ConfigError, PlausibilityWarning


@dataclass(frozen=True)
class Limits:
    """The limits of the warning tier (see the module text and the docs
    page "Limits" for each source)."""

    #: Maximum Hertz contact pressure at any ball [MPa]: ISO 76's static
    #: limit for ball bearings of through-hardened bearing steel.
    max_contact_pressure_mpa: float = 4200.0
    #: Inner-ring tilt against the outer ring [rad] (about 10 arc minutes).
    max_misalignment_rad: float = 3.0e-3
    #: Speed factor n dm (rpm times pitch diameter in mm) per lubrication.
    max_ndm_grease_mm_rpm: float = 1.0e6
    #: Oil bath: the highest n dm of SKF's own oil-bath reference speeds (ISO
    #: 15312 conditions; SKF General Catalogue 6000, 60/62/63-series deep-groove
    #: ball bearings), 1.206e6 for a 6000 at 67,000 rpm on its 18 mm pitch
    #: diameter, rounded up (the shipped validation sets hold these rows).
    max_ndm_oil_bath_mm_rpm: float = 1.21e6
    max_ndm_oil_mist_mm_rpm: float = 1.5e6
    max_ndm_oil_air_mm_rpm: float = 2.5e6
    max_ndm_jet_mm_rpm: float = 3.5e6

    def __post_init__(self) -> None:
        top = max(
            self.max_ndm_grease_mm_rpm,
            self.max_ndm_oil_bath_mm_rpm,
            self.max_ndm_oil_mist_mm_rpm,
            self.max_ndm_oil_air_mm_rpm,
            self.max_ndm_jet_mm_rpm,
        )
        object.__setattr__(self, "_highest_ndm_mm_rpm", top)  # frozen: set once here

    def max_ndm_mm_rpm(self, lubrication: Optional[str]) -> float:
        """The n dm limit of a lubrication method; with none given, that of
        the method that supports the highest speeds (jet)."""
        if lubrication is None:
            return float(self.__dict__["_highest_ndm_mm_rpm"])
        return float(getattr(self, f"max_ndm_{lubrication.replace('-', '_')}_mm_rpm"))


#: The limits in force (``Limits`` is frozen: the default is never mutated).
_CURRENT: ContextVar[Limits] = ContextVar("thermobear_limits", default=Limits())  # noqa: B039


def get_limits() -> Limits:
    """The limits in force (the defaults, unless changed)."""
    return _CURRENT.get()


def _changed(**changes: Any) -> Limits:
    from . import _validate

    names = [f.name for f in dataclasses.fields(Limits)]
    for k, v in changes.items():
        if k not in names:
            raise ConfigError(
                f"invalid {k} = {v!r}: not a limit (limits: {', '.join(names)})"
                + _validate.did_you_mean(k, names)
            )
        _validate.real(k, v, 0.0, open_lo=True)
    return dataclasses.replace(_CURRENT.get(), **{k: float(v) for k, v in changes.items()})


def set_limits(**changes: float) -> Limits:
    """Change limits of the warning tier for the rest of the program (this
    thread or task), e.g. ``set_limits(max_contact_pressure_mpa=3000)``;
    returns the limits that were in force before. ``set_limits()`` with no
    argument restores the defaults."""
    before = _CURRENT.get()
    _CURRENT.set(_changed(**changes) if changes else Limits())
    return before


@contextlib.contextmanager
def limits(**changes: float) -> Iterator[Limits]:
    """Change limits for a ``with`` block only:
    ``with tb.limits(max_ndm_grease_mm_rpm=1.2e6): ...``."""
    token = _CURRENT.set(_changed(**changes))
    try:
        yield _CURRENT.get()
    finally:
        _CURRENT.reset(token)


def warn(message: str) -> None:
    """A [`PlausibilityWarning`][thermobear.PlausibilityWarning] at the user's line."""
    warnings.warn(message, PlausibilityWarning, stacklevel=_outside_stacklevel())


def _inputs(loads: dict[str, Any]) -> str:
    return ", ".join(
        f"{k} = {v:g}" if isinstance(v, float) else f"{k} = {v}" for k, v in loads.items()
    )


def check_speed(
    speed_rpm: float, pitch_diameter_mm: float, lubrication: Optional[str] = None
) -> None:
    """Warn when ``speed_rpm`` times the pitch diameter passes the n dm the
    ``lubrication`` supports (the highest of all methods when None)."""
    ndm = abs(speed_rpm) * pitch_diameter_mm
    top = _CURRENT.get().max_ndm_mm_rpm(lubrication)
    if ndm > top:
        how = f"{lubrication} lubrication" if lubrication else "any lubrication method"
        warn(
            f"speed_rpm = {speed_rpm:g} gives n dm = {ndm:.3g} mm rpm, past the {top:.3g} "
            f"that {how} supports (limits: docs page Limits)"
        )


def check_speeds(speeds_rpm: Any, pitch_diameter_mm: float, lubrication: Optional[str]) -> None:
    """[`check_speed`][thermobear.plausibility.check_speed] for the fastest of many speeds."""
    import numpy as np

    arr = np.asarray(speeds_rpm, dtype=float)
    if arr.size:
        check_speed(float(np.max(np.abs(arr))), pitch_diameter_mm, lubrication)


def check_misalignment(misalignment_rad: Optional[float], geometry: dict[str, float]) -> None:
    """Warn past the misalignment limit; refuse a tilt past the groove."""
    if misalignment_rad is None:
        return
    tilt = abs(misalignment_rad)
    if tilt > groove_tilt_rad(geometry):
        raise ConfigError(
            f"invalid misalignment_rad = {misalignment_rad:g}: must not exceed "
            f"{groove_tilt_rad(geometry):.3g} rad, the tilt that moves the inner groove at the "
            "balls by the distance between the groove curvature centres (past the groove)"
        )
    if tilt > _CURRENT.get().max_misalignment_rad:
        warn(
            f"misalignment_rad = {misalignment_rad:g} is past the "
            f"{_CURRENT.get().max_misalignment_rad:g} rad that ball bearings tolerate"
        )


def groove_tilt_rad(geometry: dict[str, float]) -> float:
    """The tilt at which the groove at the balls moves by ``A = (f_i + f_o
    - 1) D``, the distance between the curvature centres: beyond it the
    contact runs off the groove."""
    a = geometry["inner_conformity"] + geometry["outer_conformity"] - 1.0
    return a * geometry["ball_diameter_mm"] / (0.5 * geometry["pitch_diameter_mm"])


#: Per raceway: the name, the per-ball columns, the conformity key.
_RACES = tuple(
    (r, f"{r}_load_n", f"{r}_contact_angle_deg", f"{r}_semi_major_mm", f"{r}_conformity")
    for r in ("inner", "outer")
)


def check_contacts(bearing: Any, balls: dict[str, Any], inputs: dict[str, Any]) -> None:
    """The contact checks on a solved state (``balls``: the raw per-ball
    columns): refuse an ellipse past the groove, warn past the pressure
    limit. ``bearing``: a [`Bearing`][thermobear.Bearing]; ``inputs``: the
    loads named in the messages."""
    geo = _geometry(bearing)
    limit_pa = _CURRENT.get().max_contact_pressure_mpa * 1e6
    worst = (0.0, "")
    for race, load_col, angle_col, axis_col, conformity in _RACES:
        loads = balls[load_col]
        if not len(loads):
            continue
        i = int(loads.argmax())
        q = loads.item(i)
        if not q > 0.0:
            continue
        angle = abs(balls[angle_col].item(i)) * _RAD
        a_mm = balls[axis_col].item(i)
        edge = angle + a_mm / (geo[conformity] * geo["ball_diameter_mm"])
        if edge >= 0.5 * math.pi:
            _past_the_groove(inputs, race, edge, angle, a_mm)
        # p0 a^2 / Q = 3 kappa / (2 pi) (kappa = a / b): bounded per raceway, exact near the limit
        factor = bearing.__dict__.get(_FACTOR_KEYS[race]) or _pressure_factor(bearing, race)
        if factor * q / (a_mm * a_mm * 1e-6) > limit_pa:
            p = float(bearing._b.contact(race, angle / _RAD, q, True)["max_pressure_pa"])
            worst = max(worst, (p, race))
    if worst[0] > limit_pa:
        warn(
            f"{_inputs(inputs)}: the maximum Hertz contact pressure ({worst[1]} raceway) is "
            f"{worst[0] / 1e6:.0f} MPa, past the {limit_pa / 1e6:.0f} MPa static limit "
            "(ISO 76 for bearing steel; set_limits(max_contact_pressure_mpa=...) for another)"
        )


_RAD = math.pi / 180.0


def _past_the_groove(
    inputs: dict[str, Any], race: str, edge: float, angle: float, a_mm: float
) -> NoReturn:
    raise ConfigError(
        f"invalid {_inputs(inputs)}: the contact ellipse on the {race} raceway reaches "
        f"{math.degrees(edge):.0f} deg from the radial plane (contact angle "
        f"{math.degrees(angle):.1f} deg, semi-major axis {a_mm:.3g} mm), past the groove; "
        "the Hertz contact model does not hold there"
    )


_FACTOR_KEYS = {"inner": "_tb_pressure_factor_inner", "outer": "_tb_pressure_factor_outer"}


def _pressure_factor(bearing: Any, race: str) -> float:
    """An upper bound of p0 a^2 / Q = 3 kappa / (2 pi) on a raceway over
    every contact angle (the largest of 0 to 89 degrees in 1-degree steps,
    plus 2 %), kept on the bearing after the first call: the pressure check
    then needs the exact Hertz solution only near its limit."""
    key = _FACTOR_KEYS[race]
    c: Optional[float] = bearing.__dict__.get(key)
    if c is None:
        ratios = []
        for deg in range(90):
            h = bearing._b.contact(race, float(deg), 1000.0, True)
            ratios.append(h["max_pressure_pa"] * h["semi_major_m"] ** 2 / 1000.0)
        c = bearing.__dict__[key] = 1.02 * max(ratios)
    return c


#: Margin on the bound of the semi-major axis: covers the Hertz
#: approximations the solver may use against the exact solution.
_AXIS_MARGIN = 1.05


def _axis_factor(bearing: Any, race: str) -> float:
    """An upper bound of a / Q^(1/3) [mm N^-1/3] on a raceway over every
    contact angle (Hertz: the semi-major axis a grows as the cube root of
    the ball load Q at a given angle; the largest of 0 to 89 degrees in
    1-degree steps, plus 5 %), kept on the bearing after the first call."""
    key = f"_tb_axis_factor_{race}"
    c: Optional[float] = bearing.__dict__.get(key)
    if c is None:
        axes = [
            bearing._b.contact(race, float(deg), 1000.0, True)["semi_major_m"] for deg in range(90)
        ]
        c = bearing.__dict__[key] = _AXIS_MARGIN * max(axes) * 1e3 / 1000.0 ** (1.0 / 3.0)
    return c


def _rows_near_the_groove(bearing: Any, cols: dict[str, Any]) -> Any:
    """The rows of a batch (``cols``: the native columns, per raceway the
    largest ball load and the extreme contact angles) whose contact MAY
    reach past the groove: the largest angle plus the semi-major axis of the
    largest load (an upper bound of every ball's ellipse edge) at 90 degrees
    or more. A row that fails none is past the groove at no ball."""
    import numpy as np

    geo = _geometry(bearing)
    near = np.zeros(len(cols["inner_load_max_n"]), dtype=bool)
    for race in ("inner", "outer"):
        q = np.asarray(cols[f"{race}_load_max_n"], dtype=float)
        lo = np.abs(cols[f"{race}_contact_angle_min_deg"])
        angle = np.maximum(np.abs(cols[f"{race}_contact_angle_max_deg"]), lo) * _RAD
        a_mm = _axis_factor(bearing, race) * np.cbrt(np.maximum(q, 0.0))
        near |= (
            angle + a_mm / (geo[f"{race}_conformity"] * geo["ball_diameter_mm"]) >= 0.5 * math.pi
        )
    return np.flatnonzero(near)


def rows_past_the_groove(
    bearing: Any, cols: dict[str, Any], points: dict[str, Any], options: dict[str, Any]
) -> dict[int, str]:
    """The rows of a batch of solves whose contact reaches past the groove,
    with the error [`Bearing.solve`][thermobear.Bearing.solve] gives for each.
    ``cols``: the native columns; ``points``: per-row ``axial_n``,
    ``radial_n``, ``moment_n_m``, ``speed_rpm``; ``options``: the solve's
    keywords. A vectorised bound picks the rows that may be past it (none in
    ordinary use); each is solved again alone (bit-identical to its batch
    row) and checked exactly as ``solve`` checks it."""
    out: dict[int, str] = {}
    for i in _rows_near_the_groove(bearing, cols):
        point = {k: float(a[i]) for k, a in points.items()}
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", PlausibilityWarning)
                bearing.solve(**point, **options)
        except ConfigError as e:
            out[int(i)] = str(e)
    return out


def _geometry(bearing: Any) -> dict[str, float]:
    """A [`Bearing`][thermobear.Bearing]'s geometry (mm), kept on it after the first call."""
    geo: Optional[dict[str, float]] = bearing.__dict__.get("_tb_geometry")
    if geo is None:
        geo = dict(bearing._b.geometry())
        bearing.__dict__["_tb_geometry"] = geo
    return geo


def check_solution(
    bearing: Any,
    raw: dict[str, Any],
    inputs: dict[str, Any],
    misalignment_rad: Optional[float],
    lubrication: Optional[str] = None,
) -> None:
    """All checks on one solved state ``raw`` of a [`Bearing`][thermobear.Bearing]."""
    geo = _geometry(bearing)
    check_speed(float(raw["speed_rpm"]), geo["pitch_diameter_mm"], lubrication)
    if misalignment_rad is None:  # free tilt: check the tilt the moment gave
        d = raw["displacement"]
        check_misalignment(math.hypot(float(d[3]), float(d[4])), geo)
    check_contacts(bearing, raw["balls"], inputs)


__all__ = [
    "Limits",
    "check_contacts",
    "check_misalignment",
    "check_solution",
    "check_speed",
    "check_speeds",
    "get_limits",
    "groove_tilt_rad",
    "rows_past_the_groove",
    "limits",
    "set_limits",
    "warn",
]

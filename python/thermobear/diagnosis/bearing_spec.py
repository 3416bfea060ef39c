"""The model spec of one bearing ([`BearingModelSpec`][thermobear.BearingModelSpec]) and the
baseline of a system description (``model_from_toml``)."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any, Optional, Sequence, Union

import numpy as np

from .._validate import did_you_mean
from ..errors import ConfigError, ThermobearError
from ..thermal.oil_supply import SUPPLY_WITHOUT_KEYWORDS
from .candidates import Candidate, _candidate_list, load_level_candidates
from .measurements import QUANTITIES
from .protocol import ModelSpec, register_kind
from .registry import _THERMAL_DEFAULTS, LOAD_SCALE_OPTIONS, supply_given
from .relative import with_changes
from .unknown_heat import UNKNOWN_HEAT_OPTIONS, has_unknown_heat

if TYPE_CHECKING:
    import polars


class BearingModelSpec(ModelSpec):
    """The baseline model of one bearing: [`Bearing`][thermobear.Bearing],
    ``effects`` (names; None = all) and the keyword options of
    [`thermobear.thermal_state`][thermobear.thermal_state] (``lubricant``,
    ``lubrication_factor_f0``, ``spin_friction_coefficient``, ``oil_air_temperature_c``,
    ``ambient_temperature_c``, ``housing_material``, ``raceway_control``,
    ``extra_heat_w``, ``housing_conductance_scale``, ``churning_oil_fraction``,
    ``heat_model``, ``lubrication``, ``sliding_friction_ehl``,
    ``replenishment_krs`` and the oil-supply keywords such as
    ``oil_flow_cm3_per_min``, ``oil_flow_scale``,
    ``cavity_fraction_speed_exponent``; with a supply the drag follows it
    and ``churning_oil_fraction`` is left unset) and the load scales ``axial_load_scale``,
    ``radial_load_scale`` (default 1; per level ``axial_load_scale@<N>``)
    applied to the stated loads of the measured conditions.
    Evaluates every quantity of ``QUANTITIES`` at given conditions; each
    configuration is solved once per set of conditions (cached).

    The protocol [`diagnose`][thermobear.diagnose] uses (a spec of another machine, such as
    [`thermobear.SpindleModelSpec`][thermobear.SpindleModelSpec], provides the same): ``quantities``
    (the quantity registry), ``candidate_list(quantities)``,
    ``predict(conditions)``, ``with_setting(add_effects, **options)``,
    ``options``, ``effects``."""

    #: The quantities this model predicts (see ``QUANTITIES``).
    quantities = QUANTITIES

    def __init__(self, bearing: Any, effects: Optional[Sequence[str]] = None, **options: Any):
        from .. import _native
        from ..bearing import Bearing

        if not isinstance(bearing, Bearing):
            raise ConfigError(f"invalid bearing = {bearing!r}: give a thermobear.Bearing")
        known = [n for n, *_ in _native.effects()]
        eff = list(known) if effects is None else [str(e) for e in effects]
        for e in eff:
            if e not in known:
                raise ConfigError(f"invalid effect = {e!r}: known: {', '.join(known)}")
        _check_option_names(options)
        self.bearing = bearing
        self.effects = tuple(sorted(eff))
        self.options = {**_THERMAL_DEFAULTS, **_lubrication_options(bearing, options), **options}
        if supply_given(options) and "churning_oil_fraction" not in options:
            self.options["churning_oil_fraction"] = None  # the drag follows the supply
        _check_supply(self.options)
        _check_numbers(options)
        self._cache: dict = {}

    @classmethod
    def of_model(cls, bearing: Any) -> "BearingModelSpec":
        """The spec of a [`Bearing`][thermobear.Bearing] as
        [`thermobear.thermal_state`][thermobear.thermal_state] runs it by default: every effect
        on, the default options."""
        return cls(bearing)

    def with_setting(self, add_effects: Sequence[str] = (), **options: Any) -> "BearingModelSpec":
        """A copy with effects added and options replaced (shares the cache)."""
        new = object.__new__(BearingModelSpec)
        new.bearing = self.bearing
        new.effects = tuple(sorted(set(self.effects) | set(add_effects)))
        _check_option_names(options)
        new.options = {**self.options, **options}
        _check_supply(new.options)
        _check_numbers(options)
        new._cache = self._cache
        return new

    def loads(self, axial_n: float, radial_n: float) -> tuple[float, float]:
        """The loads the model applies for stated ``axial_n``, ``radial_n``
        [N]: times the load scales (``axial_load_scale``,
        ``radial_load_scale``) and the scale of the level
        (``axial_load_scale@<level>``, ``radial_load_scale@<level>``)."""
        o = self.options
        fa = (
            axial_n
            * float(o["axial_load_scale"])
            * float(o.get(f"axial_load_scale@{axial_n:g}", 1.0))
        )
        fr = (
            radial_n
            * float(o["radial_load_scale"])
            * float(o.get(f"radial_load_scale@{radial_n:g}", 1.0))
        )
        return fa, fr

    def thermal_options(self) -> dict:
        """The options as [`thermobear.thermal_state`][thermobear.thermal_state] keywords (the
        load scales removed, unset SKF inputs left to their defaults; the
        unknown heat law only when it is not zero)."""
        law = has_unknown_heat(self.options)
        return {
            k: v
            for k, v in self.options.items()
            if k not in LOAD_SCALE_OPTIONS
            and (law or k not in UNKNOWN_HEAT_OPTIONS)
            and "@" not in k
            and v is not None
        }

    def level_candidates(
        self,
        conditions: polars.DataFrame,
        min_levels: int = 2,
    ) -> list[Candidate]:
        """One load-scale candidate per axial and per radial load level of
        ``conditions`` (``min_levels`` or more levels each)."""
        allq = tuple(QUANTITIES)
        ax, ra = conditions["axial_n"].to_list(), conditions["radial_n"].to_list()
        return load_level_candidates(
            "axial_load_scale", ax, allq, "axial load", min_levels
        ) + load_level_candidates("radial_load_scale", ra, allq, "radial load", min_levels)

    def predict(self, conditions: polars.DataFrame) -> dict[str, np.ndarray]:
        """Every supported quantity at each row of ``conditions``
        (``speed_rpm``, ``axial_n``, ``radial_n``): name -> array."""
        sp = conditions["speed_rpm"].to_numpy()
        ax = conditions["axial_n"].to_numpy()
        ra = conditions["radial_n"].to_numpy()
        out = {q: np.empty(len(sp)) for q in QUANTITIES}
        topts = self.thermal_options()
        tkey = (self.effects, tuple(sorted((k, str(v)) for k, v in topts.items())))
        for a, r in sorted(set(zip(ax.tolist(), ra.tolist(), strict=False))):
            rows = np.flatnonzero((ax == a) & (ra == r))
            speeds = np.unique(sp[rows])
            fa, fr = self.loads(a, r)
            key = (tkey, self._unknown_key(), fa, fr, tuple(speeds.tolist()))
            if key not in self._cache:
                try:
                    df = self._curve(speeds, fa, fr, topts)
                except ThermobearError as e:  # a failing configuration fails every time
                    self._cache[key] = e
                    raise
                self._cache[key] = {
                    q: df[c].to_numpy() * s for q, (c, s, *_rest) in QUANTITIES.items()
                }
            res = self._cache[key]
            if isinstance(res, ThermobearError):
                raise res
            idx = np.searchsorted(speeds, sp[rows])
            for q in QUANTITIES:
                out[q][rows] = res[q][idx]
        return with_changes(out, conditions, self.predict)  # relative quantities

    def _unknown_key(self) -> tuple:
        return tuple(self.options.get(k) for k in UNKNOWN_HEAT_OPTIONS)

    def _curve(self, speeds: np.ndarray, fa: float, fr: float, topts: dict) -> polars.DataFrame:
        """The thermal stiffness curve at ``speeds`` (with an unknown heat
        law in ``topts``, each speed with its own extra heat: the thermal
        entry points take the law)."""
        from ..thermal import thermal_stiffness_curve

        return thermal_stiffness_curve(
            self.bearing, speeds, fa, fr, effects=list(self.effects), **topts
        )

    def candidate_list(self, quantities: Sequence[str] = ()) -> list[Candidate]:
        """The candidates against this baseline, with a sensor-offset decoy
        per measured quantity in ``quantities``."""
        return _candidate_list(self, quantities)

    def __repr__(self) -> str:
        return f"BearingModelSpec({self.bearing!r}, effects={list(self.effects)})"


def _check_option_names(options: dict) -> None:
    from .registry import current_option_names

    current_option_names(options)
    for k in options:
        level = k.split("@", 1)
        if k in _THERMAL_DEFAULTS or k in UNKNOWN_HEAT_OPTIONS:
            continue
        if len(level) == 2 and level[0] in LOAD_SCALE_OPTIONS:
            continue
        raise ConfigError(
            f"invalid option = {k!r}: known: {', '.join(sorted(_THERMAL_DEFAULTS))}"
            + did_you_mean(k, [*_THERMAL_DEFAULTS, *UNKNOWN_HEAT_OPTIONS])
        )


def _check_numbers(options: dict) -> None:
    """The load scales (global and per level: finite, >= 0) and the unknown
    heat law (finite) are numbers; a wrong one is named."""
    from .. import _validate as val

    for k, v in options.items():
        if k in LOAD_SCALE_OPTIONS or k.split("@", 1)[0] in LOAD_SCALE_OPTIONS:
            val.real(k, v, 0.0)
        elif k in UNKNOWN_HEAT_OPTIONS and v is not None:
            val.real(k, v)


def _check_supply(options: dict) -> None:
    """A fixed drag fraction is the override of an oil supply: both at once
    are refused, naming the fixed fraction (as ``thermal_state`` does)."""
    x = options.get("churning_oil_fraction")
    if x is not None and supply_given(options):
        raise ConfigError(
            f"invalid churning_oil_fraction = {x!r}: a fixed cavity oil fraction overrides "
            "the oil supply given; give one or the other"
        )


def _lubrication_options(bearing: Any, options: dict) -> dict:
    """With a ``lubrication`` method among ``options``, the f0 and drag
    oil fraction it sets (docs/concepts/physics.md §9) where not given:
    none (unset) when the drag follows an oil supply -- supply keywords
    given, or an oil bath (``SUPPLY_WITHOUT_KEYWORDS``) -- so that the spec
    runs ``thermal_state``'s own drag."""
    from .. import _native

    lub = options.get("lubrication")
    if lub is None:
        return {}
    d = _native.lubrication_defaults(str(lub), bearing.bearing_type.replace("-", "_"))
    out: dict[str, Optional[float]] = {"lubrication_factor_f0": float(d["lubrication_factor_f0"])}
    if supply_given(options) or str(lub) in SUPPLY_WITHOUT_KEYWORDS:
        out["churning_oil_fraction"] = None  # the drag follows the supply, as in thermal_state
    else:
        out["churning_oil_fraction"] = float(d["oil_volume_fraction"])
    return out


def model_from_toml(path_or_text: Union[str, Path]) -> tuple[BearingModelSpec, dict]:
    """The baseline [`BearingModelSpec`][thermobear.BearingModelSpec] of a system description
    ([bearing], [model] effects, raceway_control, extra_heat_w,
    housing_conductance_scale, churning_oil_fraction, lubrication_factor_f0, heat_model,
    lubrication and the [model.oil_supply] keys; the other thermal options take their
    [`thermobear.thermal_state`][thermobear.thermal_state] defaults) and its [operating]
    table (loads for measurements that give none)."""
    from ..bearing import Bearing
    from ..config import load_config, read_toml

    text = load_config(path_or_text)
    cfg = read_toml(text)
    mdl = cfg.get("model", {})
    opts = {}
    if "raceway_control" in mdl:
        opts["raceway_control"] = mdl["raceway_control"]
    for key in (
        "extra_heat_w",
        "housing_conductance_scale",
        "churning_oil_fraction",
        "lubrication_factor_f0",
    ):
        if key in mdl:
            opts[key] = float(mdl[key])
    for key in ("heat_model", "lubrication"):
        if key in mdl:
            opts[key] = str(mdl[key])
    opts.update(mdl.get("oil_supply", {}))
    spec = BearingModelSpec(Bearing.from_toml(text), effects=mdl.get("effects"), **opts)
    return spec, cfg.get("operating", {})


def _register() -> None:
    from ..bearing import Bearing

    register_kind("bearing", Bearing, BearingModelSpec, QUANTITIES)


_register()

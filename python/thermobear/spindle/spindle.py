"""The [`Spindle`][thermobear.Spindle]: its presets, options, assumptions and coupled
thermal steady state; the table rows of a solved state."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Sequence

import numpy as np

from .. import _native, plausibility
from .. import _validate as val
from .._deprecation import renamed_kwargs, warn_renamed
from .._names import spindle_node, temperature_column
from .._types import PreloadKind
from ..thermal.heat_law import HEAT_LAW_OPTIONS, pop_heat_law
from ..thermal.oil_supply import SUPPLY_OPTIONS
from .parts import Cooling, Housing, Lubrication, Motor, Preload, Shaft, ToolLoad

#: Spring rate implied by seed B Fig. 17: 6.45 N / 17.92 um.
SEED_B_SPRING_RATE_N_PER_UM = 6.45 / 17.92


class Spindle:
    """A motorized spindle. Build with [`preset`][thermobear.Spindle.preset], from its parts
    (``Spindle(shaft=Shaft(...), front=BearingSet("7009C-hybrid"), ...)``, every part
    left out takes the ``seed-ceramic-spindle`` values) or from a description file with
    [`from_toml`][thermobear.Spindle.from_toml]; change settings with
    [`with_options`][thermobear.Spindle.with_options] (returns a new spindle)."""

    def __init__(
        self,
        native: Any = None,
        *,
        name: Optional[str] = None,
        shaft: Optional[Shaft] = None,
        front: Any = None,
        rear: Any = None,
        preload: Optional[Preload] = None,
        housing: Optional[Housing] = None,
        motor: Optional[Motor] = None,
        cooling: Optional[Cooling] = None,
        lubrication: Optional[Lubrication] = None,
        tool: Optional[ToolLoad] = None,
        effects: Optional[Sequence[str]] = None,
    ) -> None:
        parts = (name, shaft, front, rear, preload, housing, motor, cooling, lubrication, tool)
        if native is not None and any(p is not None for p in (*parts, effects)):
            raise val.fail("native", native, "None when the parts are given")
        if native is None:
            from .description import build_native

            native = build_native(
                name, front, rear, effects, shaft=shaft, preload=preload, housing=housing,
                motor=motor, cooling=cooling, lubrication=lubrication, tool=tool,
            )  # fmt: skip
            _check_preset_name(native)
        self._native = native

    @staticmethod
    def from_toml(source: str | Path) -> "Spindle":
        """A spindle from a ``[spindle]`` description: a file path, TOML text or
        the name of a preset (its shipped file). An error names the file,
        the line and the key."""
        from ..config import located_config_errors
        from .description import parse_description, read_description

        path, text = read_description(source)
        with located_config_errors(path, text):
            return Spindle(**parse_description(text))

    def to_toml(self) -> str:
        """The ``[spindle]`` description file of this spindle (every value
        written; ``from_toml`` of it gives this spindle to the last bit)."""
        from .description import to_toml

        return to_toml(self._native)

    @property
    def parts(self) -> dict[str, Any]:
        """The description of this spindle: the keywords of ``Spindle(...)``
        (``name``, ``shaft``, ``front``, ``rear``, ``preload`` ...); a
        bearing that is no preset (balls scaled by a calibration) comes back
        as a [`Bearing`][thermobear.Bearing], which ``Spindle(...)`` takes
        (a description file, ``to_toml``, names presets only)."""
        from .description import describe

        return describe(self._native, named=False)

    @staticmethod
    def preset(name: str) -> "Spindle":
        """``seed-ceramic-spindle`` (hybrid), ``seed-steel-spindle``,
        ``seed-full-ceramic-spindle``."""
        return Spindle(_native.Spindle.preset(name))

    @staticmethod
    def preset_names() -> list[str]:
        return list(_native.Spindle.preset_names())

    @renamed_kwargs(spin_friction="spin_friction_coefficient")
    def with_options(
        self,
        *,
        preload_n: Optional[float] = None,
        preload_kind: Optional[PreloadKind] = None,
        spring_rate_n_per_um: Optional[float] = None,
        radial_load_n: Optional[float] = None,
        effects: Optional[Sequence[str]] = None,
        spin_friction_coefficient: Optional[float] = None,
        **heat: Any,
    ) -> "Spindle":
        """A copy with other settings; ``preload_kind`` is ``"rigid"`` or
        ``"spring"`` (a spring keeps ``spring_rate_n_per_um``, default seed
        B's 0.36 N/um). Heat-model keywords (docs/concepts/physics.md §9;
        None keeps the current value): ``heat_model`` ("palmgren" or "skf"),
        ``lubrication`` ("grease", "oil-air", "oil-mist", "jet", "oil-bath":
        its defaults fill ``lubrication_factor_f0`` and
        ``churning_oil_fraction`` when they are not given),
        ``lubrication_factor_f0``, ``load_friction_scale`` (Palmgren's
        load-friction factor f1 times this, default 1; the "palmgren" heat
        model only), ``extra_heat_w`` (an extra heat at the front bearing
        set [W], half on each front bearing, split like rolling heat;
        default 0) and an unknown heat source's speed law added to it,
        ``max(0, a x + b x^2)`` with ``x = n / n_ref``
        (``unknown_heat_linear_w`` a, ``unknown_heat_quadratic_w`` b [W],
        ``unknown_heat_reference_rpm`` n_ref; a diagnosis' unknown member),
        ``churning_oil_fraction`` (ball-drag oil
        volume fraction, 0..1), ``skf_series``, ``sliding_friction_ehl``,
        ``replenishment_krs``, ``seal_moment_n_m`` (as for
        [`thermobear.thermal_state`][thermobear.thermal_state]). ``spin_friction_coefficient``:
        mu_s of the spin moment (default 0.05, the same as a single
        bearing's)."""
        from ..bearing.ball_bearing import _effects_arg

        return Spindle(
            self._native.with_options(
                preload_n=val.optional_real("preload_n", preload_n, 0.0),
                preload_kind=None
                if preload_kind is None
                else val.choice("preload_kind", preload_kind, ("rigid", "spring")),
                spring_rate_n_per_um=val.optional_real(
                    "spring_rate_n_per_um", spring_rate_n_per_um, 0.0, open_lo=True
                ),
                radial_load_n=val.optional_real("radial_load_n", radial_load_n),
                effects=_effects_arg(effects),
                spin_friction=val.optional_real(
                    "spin_friction_coefficient", spin_friction_coefficient, 0.0
                ),
                heat=_heat_args(heat),
            )
        )

    @property
    def name(self) -> str:
        return self._native.name

    @property
    def preload_n(self) -> float:
        return self._native.preload_n

    @property
    def preload_kind(self) -> str:
        return self._native.preload_kind

    @property
    def spring_rate_n_per_um(self) -> Optional[float]:
        return self._native.spring_rate_n_per_um

    @property
    def radial_load_n(self) -> float:
        return self._native.radial_load_n

    @property
    def node_names(self) -> list[str]:
        """The thermal network's nodes (``front_outer_ring``, ``rotor`` ...);
        each is the ``<node>_temperature_c`` column of the results."""
        return [spindle_node(n) for n in self._native.node_names]

    @property
    def assumptions(self) -> dict[str, Any]:
        """Every assumed number and modelling choice."""
        a = dict(self._native.assumptions())
        if "spin_friction" in a:
            a["spin_friction_coefficient"] = a.pop("spin_friction")
        return a

    def __repr__(self) -> str:
        return (
            f"Spindle({self.name!r}, preload {self.preload_n:g} N {self.preload_kind}, "
            f"radial load {self.radial_load_n:g} N)"
        )

    def thermal_state(
        self,
        speed_rpm: float,
        preload_n: Optional[float] = None,
        radial_n: Optional[float] = None,
        preload_kind: Optional[PreloadKind] = None,
        effects: Optional[Sequence[str]] = None,
        axial_n: Optional[float] = None,
        spin_friction_coefficient: Optional[float] = None,
        **unused: Any,
    ) -> Any:
        """Coupled steady state at one speed as a one-row DataFrame: node
        temperatures (``<node>_temperature_c``), heat, preload, axial growth, radial
        thermal displacement, front-bearing contact angles and loads,
        the front pair's stiffness (``k_xx_n_per_m``, ``k_zz_n_per_m``: entries
        of the full tangent stiffness), the radial load each pair carries
        (``<pair>_pair_radial_x_n``: nose load side, ``_y_n``: the static
        unbalanced magnetic pull ``magnetic_pull_n``, which acts with the
        ``unbalanced_magnetic_pull`` effect on), convergence report."""
        import polars as pl

        from ..errors import ConfigError, ConvergenceError

        if axial_n not in (None, 0.0):
            raise ConfigError(
                f"invalid axial_n = {axial_n}: a spindle's axial load is its preload; "
                "give preload_n"
            )
        if "spin_friction" in unused:
            warn_renamed("spin_friction", "spin_friction_coefficient", stacklevel=3)
            spin_friction_coefficient = unused.pop("spin_friction")
        heat = {k: unused.pop(k) for k in list(unused) if k in SPINDLE_HEAT_OPTIONS}
        if unused:
            raise ConfigError(
                f"invalid argument = {sorted(unused)[0]}: a spindle takes speed_rpm, "
                "preload_n, radial_n, preload_kind, effects and the heat-model options"
                + val.did_you_mean(sorted(unused)[0], ["speed_rpm", "preload_n", "radial_n",
                                   "preload_kind", "effects", *SPINDLE_HEAT_OPTIONS])
            )  # fmt: skip
        sp = self
        given = (preload_n, radial_n, preload_kind, effects, spin_friction_coefficient)
        if any(v is not None for v in (*given, *heat.values())):
            sp = self.with_options(
                preload_n=preload_n,
                radial_load_n=radial_n,
                preload_kind=preload_kind,
                effects=effects,
                spin_friction_coefficient=spin_friction_coefficient,
                **heat,
            )
        speed = sp._speed(speed_rpm)
        try:
            d = sp._native.steady_state(speed)
        except ConvergenceError as e:
            val.name_inputs(e, {"speed_rpm": speed, "preload_n": sp.preload_n})
            raise
        return pl.DataFrame([_state_row(d, sp)])

    _thermal_state = thermal_state

    def thermal_state_many(
        self,
        points: Any,
        *,
        progress: Any = None,
        **options: Any,
    ) -> Any:
        """[`thermal_state`][thermobear.Spindle.thermal_state] at many operating points: ``points``
        a polars DataFrame (or a mapping of columns) with ``speed_rpm`` and
        optional ``preload_n``, ``radial_n`` (absent: the spindle's own);
        other columns are carried through. ``options`` (``preload_kind``,
        ``effects``, the heat-model keywords) as in
        [`thermal_state`][thermobear.Spindle.thermal_state],
        shared by every point; ``progress(done, total)`` after each point.

        Returns the input columns followed by the
        [`thermal_state`][thermobear.Spindle.thermal_state]
        columns, then ``ok``, ``error_kind``, ``error``: a point that fails
        (a runaway, no convergence) is a row with its error and null
        outputs; nothing is raised for it (as
        [`thermobear.thermal_state_many`][thermobear.thermal_state_many] for a bearing)."""
        from ..bearing.batch import join_inputs, operating_frame
        from ..errors import ConfigError, ThermobearError

        frame = operating_frame(points, _INPUTS)
        if "speed_rpm" not in frame.columns:
            raise ConfigError(
                f"invalid points = frame with columns {frame.columns}: needs speed_rpm"
            )
        rows: list[Optional[dict[str, Any]]] = []
        errors: list[tuple[bool, Optional[str], Optional[str]]] = []
        for i, p in enumerate(frame.iter_rows(named=True)):
            preload, radial = p.get("preload_n"), p.get("radial_n")
            try:
                row = self.thermal_state(
                    p["speed_rpm"],
                    preload_n=preload,
                    radial_n=radial,
                    **options,
                ).row(0, named=True)
                rows.append(row)
                errors.append((True, None, None))
            except ConfigError:
                raise  # a bad option or input fails the call, not a point
            except ThermobearError as e:
                rows.append(None)
                errors.append((False, type(e).__name__, str(e)))
            if progress is not None:
                progress(i + 1, frame.height)
        out = _rows_frame(rows, errors)
        # the operating inputs come back as the points gave them
        return join_inputs(frame, out.drop([c for c in frame.columns if c in _INPUTS]))

    _thermal_state_many = thermal_state_many

    # -- the seam to the rotor model (thermobear.rotor) ---------------------
    @property
    def rotor_preset_name(self) -> str:
        """The rotor model of this spindle for [`thermobear.campbell`][thermobear.campbell],
        [`thermobear.vibration`][thermobear.vibration] and
        [`thermobear.spectrum`][thermobear.spectrum]."""
        from ..errors import ConfigError

        name = self.name
        if name not in ("seed-ceramic-spindle", "seed-steel-spindle"):
            raise ConfigError(
                f"invalid spindle = {name!r}: the seed rotor model has hybrid and steel "
                "rows only; this spindle's own rotor is rotor_layout"
            )
        return name

    @property
    def rotor_layout(self) -> Optional[dict[str, Any]]:
        """The rotor of this spindle laid out from its own shaft, bearing and
        motor dimensions (see ``thermobear.spindle.rotor_layout``), or None for
        the two seed presets and their variants (``with_options``,
        ``with_dimensions``), which keep the seed rotor
        (``src/rotor/presets.rs``). A described spindle may carry a preset's
        name only with that preset's shaft, bearings and motor."""
        from .rotor_layout import rotor_layout

        if self.name in _SEED_ROTORS:  # the preset, or a variant of it (with_dimensions)
            return None
        return rotor_layout(self._native)

    def raceway_offsets(self, speed_rpm: float) -> dict[str, tuple[float, float]]:
        """Thermal groove-centre offsets ``(radial_m, axial_m)`` of the front
        and rear rows at the coupled steady state of ``speed_rpm`` (the values
        the coupled bearing solve uses, A-38). Makes ``coupled=True`` work in
        the rotor functions."""
        d = self._native.steady_state(self._speed(speed_rpm))
        (front_r, front_a), (rear_r, rear_a) = (
            d["front_raceway_offsets_m"],
            d["rear_raceway_offsets_m"],
        )
        return {"front": (float(front_r), float(front_a)), "rear": (float(rear_r), float(rear_a))}

    def convection_coefficients(
        self, speeds_rpm: Sequence[float], temperature_difference_k: float = 10.0
    ) -> Any:
        """Film coefficient of every convection link of the thermal network
        against speed (seed B Fig. 2): a long DataFrame ``speed_rpm``,
        ``link``, ``film_coefficient_w_per_m2_k``. Natural convection depends
        on the temperature difference across the link, taken as
        ``temperature_difference_k``; forced convection on speed only."""
        import polars as pl

        speeds = list(val.reals("speeds_rpm", speeds_rpm, 0.0))
        dt_k = val.real("temperature_difference_k", temperature_difference_k)
        names, h = self._native.convection_coefficients(speeds, dt_k)
        h = np.asarray(h, dtype=float).reshape(len(speeds), len(names))
        return pl.DataFrame(
            {
                "speed_rpm": np.repeat(speeds, len(names)),
                "link": list(names) * len(speeds),
                "film_coefficient_w_per_m2_k": h.ravel(),
            }
        )

    def _speed(self, speed_rpm: Any) -> float:
        """``speed_rpm`` checked, and warned past the n dm that the
        spindle's lubrication supports (its front bearing's pitch diameter)."""
        speed = val.real("speed_rpm", speed_rpm, 0.0)
        ndm = self.__dict__.get("_ndm")
        if ndm is None:
            import json

            geometry = json.loads(self._native.config_json())["params"]["front_bearing"]["geometry"]
            pitch = geometry["pitch_diameter_m"] * 1e3
            ndm = self.__dict__["_ndm"] = (pitch, self.assumptions.get("lubrication"))
        plausibility.check_speed(speed, *ndm)
        return speed

    def isothermal(self, speed_rpm: float) -> Any:
        """Front pair without thermal effects at speed (one-row DataFrame)."""
        import polars as pl

        speed = self._speed(speed_rpm)
        front, _ = self._native.isothermal(speed)
        row = {"speed_rpm": speed}
        row.update(_pair_row(front))
        return pl.DataFrame([row])


#: The largest extra heat at the front bearing set [W] (the core's limit:
#: ten times the seed spindle's bearing heat at 18,000 rpm).
MAX_EXTRA_HEAT_W = 1e4

#: Heat-model keywords of ``Spindle.with_options``.
SPINDLE_HEAT_OPTIONS = (
    "heat_model",
    "lubrication",
    "lubrication_factor_f0",
    "load_friction_scale",
    "extra_heat_w",
    *HEAT_LAW_OPTIONS,
    "churning_oil_fraction",
    "skf_series",
    "sliding_friction_ehl",
    "replenishment_krs",
    "seal_moment_n_m",
    *SUPPLY_OPTIONS,
)


def _heat_args(heat: dict[str, Any]) -> Optional[dict[str, Any]]:
    """The heat keywords as the native dict (None: nothing given)."""
    from ..errors import ConfigError
    from ..thermal.oil_supply import supply_dict
    from ..thermal.state import seal_moment_option

    heat = seal_moment_option(heat)
    for k in heat:
        if k not in SPINDLE_HEAT_OPTIONS:
            raise ConfigError(
                f"invalid argument = {k!r}: known: {', '.join(SPINDLE_HEAT_OPTIONS)}"
                + val.did_you_mean(k, SPINDLE_HEAT_OPTIONS)
            )
    if all(v is None for v in heat.values()):
        return None
    out = {k: heat.get(k) for k in SPINDLE_HEAT_OPTIONS}
    for k in ("lubrication_factor_f0", "load_friction_scale", "churning_oil_fraction",
              "sliding_friction_ehl", "replenishment_krs", "seal_moment_n_m"):  # fmt: skip
        out[k] = val.optional_real(k, out[k], 0.0)
    out["extra_heat_w"] = val.optional_real("extra_heat_w", out["extra_heat_w"], 0.0,
                                            MAX_EXTRA_HEAT_W)  # fmt: skip
    law = pop_heat_law({k: out[k] for k in HEAT_LAW_OPTIONS})  # checked: a reference speed
    for k in HEAT_LAW_OPTIONS:
        out[k] = law.get(k)
    for k in ("heat_model", "lubrication", "skf_series"):
        out[k] = None if out[k] is None else val.text(k, out[k])
    out["oil_supply"] = supply_dict(heat)
    for k in SUPPLY_OPTIONS:
        out.pop(k)
    return out


def _pair_row(p: dict[str, Any]) -> dict[str, Any]:
    k = np.asarray(p["stiffness_matrix"])
    return {
        "operating_preload_n": p["preload_n"],
        "spring_compression_um": p["spring_compression_m"] * 1e6,
        "radial_displacement_um": float(np.asarray(p["displacement"])[0]) * 1e6,
        "inner_contact_angle_deg": float(np.mean(p["inner_contact_angle_deg"])),
        "outer_contact_angle_deg": float(np.mean(p["outer_contact_angle_deg"])),
        "inner_load_max_n": float(np.max(p["inner_load_n"])),
        "outer_load_max_n": float(np.max(p["outer_load_n"])),
        "k_xx_n_per_m": float(k[0, 0]),
        "k_zz_n_per_m": float(k[2, 2]),
    }


def _state_row(d: dict[str, Any], sp: Spindle) -> dict[str, Any]:
    row: dict[str, Any] = {
        "speed_rpm": d["speed_rpm"],
        "preload_n": sp.preload_n,
        "preload_kind": sp.preload_kind,
    }
    for name, t in zip(d["node_names"], d["temperatures_c"], strict=False):
        row[temperature_column(spindle_node(name))] = t
    row.update(_pair_row(d["front"]))
    row["rear_operating_preload_n"] = d["rear"]["preload_n"]
    row["front_bearing_heat_w"] = d["bearing_heat_w"][0]
    row["front_spin_heat_w"] = d["spin_heat_w"][0]
    row["bearing_heat_w"] = float(sum(d["bearing_heat_w"]))
    row["bearing_drag_heat_w"] = float(sum(d["drag_heat_w"]))
    row["motor_losses_w"] = d["motor_losses_w"]
    row["magnetic_pull_n"] = d["magnetic_pull_n"]
    for pair in ("front", "rear"):
        fx, fy = d[pair]["radial_load_n"]
        row[f"{pair}_pair_radial_x_n"] = fx
        row[f"{pair}_pair_radial_y_n"] = fy
    row["total_heat_w"] = d["total_heat_w"]
    row["boundary_flow_w"] = d["boundary_flow_w"]
    row["axial_growth_um"] = d["axial_growth_m"] * 1e6
    row["thermal_radial_displacement_um"] = d["front_radial_thermal_displacement_m"] * 1e6
    row["ball_growth_um"] = d["front_ball_growth_m"] * 1e6
    row.update(_offset_columns(d))
    row["iterations"] = d["iterations"]
    row["temperature_change_k"] = d["temperature_change_k"]
    return row


def _offset_columns(d: dict[str, Any]) -> dict[str, float]:
    """Thermal displacements of both rows [um]: radial and axial groove-centre
    offsets (positive = more interference), the groove-centre growths and
    the ball growth (seed B Fig. 8)."""
    row: dict[str, float] = {}
    for pair in ("front", "rear"):
        radial, axial = d[f"{pair}_raceway_offsets_m"]
        if pair == "rear":
            row["rear_thermal_radial_displacement_um"] = radial * 1e6
        row[f"{pair}_axial_thermal_displacement_um"] = axial * 1e6
        u_ic, u_oc = d.get(f"{pair}_groove_centres_m", (float("nan"), float("nan")))
        row[f"{pair}_inner_groove_centre_um"] = u_ic * 1e6
        row[f"{pair}_outer_groove_centre_um"] = u_oc * 1e6
    row["rear_ball_growth_um"] = d.get("rear_ball_growth_m", float("nan")) * 1e6
    return row


def _check(spindle: Any) -> Spindle:
    from ..errors import ConfigError

    if not isinstance(spindle, Spindle):
        raise ConfigError(f"invalid spindle = {type(spindle).__name__}: need a thermobear.Spindle")
    return spindle


#: Operating columns of ``Spindle.thermal_state_many`` points.
_INPUTS = ("speed_rpm", "preload_n", "radial_n")


def _rows_frame(rows: list[Any], errors: list[Any]) -> Any:
    """The state rows of a batch (None: a failed point, its outputs null),
    then ``ok``, ``error_kind``, ``error``."""
    import polars as pl

    keys = next((list(r) for r in rows if r is not None), [])
    data = {k: [None if r is None else r[k] for r in rows] for k in keys}
    report = {
        "ok": pl.Series("ok", [e[0] for e in errors], dtype=pl.Boolean),
        "error_kind": pl.Series("error_kind", [e[1] for e in errors], dtype=pl.String),
        "error": pl.Series("error", [e[2] for e in errors], dtype=pl.String),
    }
    return pl.DataFrame({**data, **report}, strict=False)


#: The presets whose rotor is the seed rotor (``src/rotor/presets.rs``).
_SEED_ROTORS = ("seed-ceramic-spindle", "seed-steel-spindle")


def _check_preset_name(native: Any) -> None:
    """A described spindle named like a preset has the preset's shaft,
    bearings and motor (the rotor model goes by that name); else a
    ConfigError asking for a name of its own."""
    from .description import describe

    name = str(native.name)
    if name not in _native.Spindle.preset_names():
        return
    mine = describe(native, named=False)
    theirs = describe(_native.Spindle.preset(name), named=False)
    differ = [k for k in ("shaft", "front", "rear", "motor") if mine.get(k) != theirs.get(k)]
    if differ:
        raise val.fail(
            "name", name,
            f"a name of your own: {name!r} is a preset's, and this spindle's "
            f"{', '.join(differ)} differ from it",
        )  # fmt: skip

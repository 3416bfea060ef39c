"""Human labels of the package's quantities for axes and legends: the
quantity in words and its unit in symbols ("speed [rpm]", "torque [N m]",
"ball temperature [°C]"), derived from the glossary (``thermobear.glossary``)
so that no figure shows a column name such as ``radial_stiffness_n_per_m``."""

from __future__ import annotations

from ..glossary import GLOSSARY, SUFFIX_UNITS, UNIT_SUFFIXES

__all__ = ["axis_label", "human_name", "unit_text"]

#: How a glossary unit reads on a figure.
_UNIT_TEXT = {
    "um": "µm",
    "C": "°C",
    "deg": "°",
    "mm^2/s": "mm²/s",
    "N/um": "N/µm",
    "1": "",
}

#: Short figure names where the glossary's description is long or reads
#: poorly on an axis.
_SHORT = {
    "speed_rpm": "speed",
    "speeds_rpm": "speed",
    "torque_n_m": "torque",
    "torques_n_m": "torque",
    "axial_n": "axial load",
    "radial_n": "radial load",
    "preload_n": "preload",
    "time_s": "time",
    "frequency_hz": "frequency",
    "heat_w": "heat",
    "k_xx_n_per_m": "radial stiffness $k_{xx}$",
    "k_yy_n_per_m": "radial stiffness $k_{yy}$",
    "k_zz_n_per_m": "axial stiffness $k_{zz}$",
    "k_xx_isothermal_n_per_m": "isothermal radial stiffness $k_{xx}$",
    "radial_stiffness_n_per_m": "radial stiffness",
    "axial_stiffness_n_per_m": "axial stiffness",
    "radial_stiffness_seed_n_per_m": "radial stiffness (seed formula)",
    "axial_stiffness_seed_n_per_m": "axial stiffness (seed formula)",
    "mesh_stiffness_n_per_m": "mesh stiffness",
    "mesh_stiffness_mean_n_per_m": "mean mesh stiffness",
    "dte_um": "dynamic transmission error",
    "dte": "dynamic transmission error",
    "te_amplitude_um": "transmission error amplitude",
    "velocity_rms_mm_s": "vibration velocity (RMS)",
    "axial_growth_um": "axial thermal growth",
    "mechanical_radial_displacement_um": "mechanical radial displacement",
    "thermal_radial_displacement_um": "thermal radial displacement",
    "radial_thermal_offset_um": "radial thermal offset $u_{Tr}$",
    "axial_thermal_offset_um": "axial thermal offset $u_{Ta}$",
    "centrifugal_expansion_um": "centrifugal ring expansion",
    "ball_growth_um": "ball diameter growth",
}

#: Longest description taken from the glossary as is.
_MAX_DESCRIPTION = 40


def split_unit(name: str) -> tuple[str, str]:
    """A name's stem and unit suffix (``"speed_rpm"`` -> ``("speed",
    "_rpm")``; no suffix: ``(name, "")``)."""
    for s in UNIT_SUFFIXES:
        if name.endswith(s) and len(name) > len(s):
            return name[: -len(s)], s
    return name, ""


def human_name(name: str) -> str:
    """The quantity of a column or glossary name in words, without its
    unit: ``"speed_rpm"`` -> ``"speed"``, ``"ball_temperature_c"`` ->
    ``"ball temperature"``, ``"k_xx_n_per_m"`` -> "radial stiffness
    $k_{xx}$" (mathtext). A text without an underscore is returned as is."""
    if name in _SHORT:
        return _SHORT[name]
    if "_" not in name:
        return name
    if name.endswith("_temperature_c"):  # a node: "front outer ring temperature"
        return name.removesuffix("_c").replace("_", " ")
    entry = GLOSSARY.get(name)
    if entry is not None and len(entry.description) <= _MAX_DESCRIPTION:
        return entry.description
    stem, _ = split_unit(name)
    if stem.startswith("k_") and stem.count("_") == 1:
        return f"$k_{{{stem[2:]}}}$"
    return stem.replace("_", " ")


def unit_text(unit: str) -> str:
    """A glossary unit as a figure shows it (``"um"`` -> ``"µm"``, ``"C"`` ->
    ``"°C"``, ``"deg"`` -> ``"°"``, ``"1"`` -> ``""``)."""
    return _UNIT_TEXT.get(unit, unit)


def name_unit(name: str) -> str:
    """The unit of a name (glossary unit, else its suffix's), as a figure
    shows it; ``""`` for a name without one."""
    entry = GLOSSARY.get(name)
    if entry is not None:
        return unit_text(entry.unit)
    return unit_text(SUFFIX_UNITS.get(split_unit(name)[1], "1"))


def axis_label(name: str, unit: str | None = None) -> str:
    """An axis label of a column or glossary name: the quantity in words
    and its unit in brackets, e.g. ``axis_label("speed_rpm")`` -> "speed
    [rpm]", ``axis_label("torque_n_m")`` -> "torque [N m]",
    ``axis_label("k_xx_n_per_m", "N/µm")`` -> "radial stiffness $k_{xx}$
    [N/µm]". ``unit``: the unit the figure shows when it differs from the
    name's (a stiffness drawn in N/µm); ``""`` for none."""
    shown = name_unit(name) if unit is None else unit_text(unit)
    text = human_name(name)
    return f"{text} [{shown}]" if shown else text

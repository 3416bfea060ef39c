"""The one name of each quantity (see ``thermobear.glossary``) and the
maps from the names the native core reports, or older releases used, to it.

The native extension keeps some older keys (``"Ts"``, ``"front_outer"``,
``k_rxrx_nm_per_rad`` ...); every frame and property of the Python package
goes through these maps so that users only see the names of the glossary.
"""

from __future__ import annotations

from typing import Any

#: Node of the single-bearing network: long name -> symbol of the physics
#: docs (seed A Fig. 7).
BEARING_NODES: dict[str, str] = {
    "shaft": "Ts",
    "inner_contact": "Tci",
    "inner_ring": "Ti",
    "ball": "Tb",
    "outer_ring": "To",
    "outer_contact": "Tco",
    "housing": "Th",
    "oil_air": "Tog",
    "ambient": "Ta",
}

#: Symbol -> long name.
BEARING_SYMBOLS: dict[str, str] = {v: k for k, v in BEARING_NODES.items()}

#: Spindle network node as the native core names it -> its name here.
SPINDLE_NODES: dict[str, str] = {
    "shaft_front": "front_shaft",
    "rotor": "rotor",
    "shaft_rear": "rear_shaft",
    "stator": "stator",
    "front_inner": "front_inner_ring",
    "front_balls": "front_ball",
    "front_outer": "front_outer_ring",
    "rear_inner": "rear_inner_ring",
    "rear_balls": "rear_ball",
    "rear_outer": "rear_outer_ring",
    "housing_front": "front_housing",
    "sleeve": "sleeve",
    "housing_rear": "rear_housing",
    "water": "cooling_water",
    "ambient": "ambient",
    "oil_air": "oil_air",
}


def spindle_node(native: str) -> str:
    """The glossary name of a spindle node (unknown names pass through)."""
    return SPINDLE_NODES.get(native, native)


def temperature_column(node: str) -> str:
    """``<node>_temperature_c``."""
    return f"{node}_temperature_c"


#: Columns of the native stiffness frames -> (glossary name, factor).
NATIVE_COLUMNS: dict[str, tuple[str, float]] = {
    "radial_stiffness_n_per_m": ("radial_stiffness_seed_n_per_m", 1.0),
    "axial_stiffness_n_per_m": ("axial_stiffness_seed_n_per_m", 1.0),
    "k_rxrx_nm_per_rad": ("k_rxrx_n_m_per_rad", 1.0),
    "k_ryry_nm_per_rad": ("k_ryry_n_m_per_rad", 1.0),
    "radial_displacement_mm": ("radial_displacement_um", 1000.0),
    "axial_displacement_mm": ("axial_displacement_um", 1000.0),
    "churning_w": ("churning_heat_w", 1.0),
}


def renamed_columns(cols: dict[str, Any]) -> dict[str, Any]:
    """A native column mapping with the glossary names (values converted to
    the new unit where it changed). Order kept."""
    import numpy as np

    out: dict[str, Any] = {}
    for k, v in cols.items():
        new, factor = NATIVE_COLUMNS.get(k, (k, 1.0))
        if new in cols and new != k:
            continue  # the native side already gives the new name
        arr = np.asarray(v)
        out[new] = arr * factor if factor != 1.0 and arr.dtype.kind == "f" else arr
    return out


#: Old names of frame columns and result properties -> new names (for the
#: changelog and the deprecation messages).
RENAMED_COLUMNS: dict[str, str] = {
    **{k: v for k, (v, _f) in NATIVE_COLUMNS.items()},
    **{f"{k}_c": temperature_column(v) for k, v in SPINDLE_NODES.items()},
}

#: Columns of the native spindle grid -> glossary names (the stiffness there
#: is the front pair's k_xx, an entry of the full tangent stiffness).
SPINDLE_GRID_COLUMNS: dict[str, str] = {
    **{f"{k}_c": temperature_column(v) for k, v in SPINDLE_NODES.items()},
    "radial_stiffness_n_per_m": "k_xx_n_per_m",
    "radial_stiffness_isothermal_n_per_m": "k_xx_isothermal_n_per_m",
}


def renamed_spindle_columns(cols: dict[str, Any]) -> dict[str, Any]:
    """A native spindle column mapping with the glossary names."""
    return {SPINDLE_GRID_COLUMNS.get(k, k): v for k, v in cols.items()}

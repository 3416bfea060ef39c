"""Materials of rings, balls and housings: presets and custom ones."""

from __future__ import annotations

from typing import Any, Optional

from .. import _native

_MATERIAL_FIELDS = (
    "youngs_modulus_gpa",
    "poisson_ratio",
    "density_kg_m3",
    "thermal_expansion_per_k",
    "conductivity_w_mk",
    "specific_heat_j_kgk",
)


class Material:
    """An isotropic solid. ``Material("my-steel", base="52100",
    youngs_modulus_gpa=200)`` starts from a preset and overrides any
    property; without ``base`` every property must be given.

    Properties: ``youngs_modulus_gpa``, ``poisson_ratio``, ``density_kg_m3``,
    ``thermal_expansion_per_k``, ``conductivity_w_mk``, ``specific_heat_j_kgk``.
    """

    def __init__(self, name: str, base: Optional[str] = None, **properties: float) -> None:
        from .._validate import did_you_mean
        from ..errors import ConfigError

        unknown = set(properties) - set(_MATERIAL_FIELDS)
        if unknown:
            raise ConfigError(
                f"invalid material property = {sorted(unknown)[0]}: unknown; known: "
                + ", ".join(_MATERIAL_FIELDS)
                + did_you_mean(sorted(unknown)[0], _MATERIAL_FIELDS)
            )
        values: dict[str, Any] = {}
        if base is not None:
            b = _native.Material.preset(base)
            values = {f: getattr(b, f) for f in _MATERIAL_FIELDS}
        values.update(properties)
        missing = [f for f in _MATERIAL_FIELDS if f not in values]
        if missing:
            raise ConfigError(
                f"invalid {missing[0]} = missing: give it or a `base` preset to start from"
            )
        for k, v in values.items():
            if not isinstance(v, (int, float)) or isinstance(v, bool):
                raise ConfigError(f"invalid {k} = {v!r}: must be a number")
        self._m = _native.Material(str(name), **{k: float(v) for k, v in values.items()})

    @classmethod
    def preset(cls, name: str) -> "Material":
        """``"52100"`` (bearing steel), ``"Si3N4"``, ``"shaft-steel"``,
        ``"cast-iron"``, ``"aluminium"``."""
        obj = cls.__new__(cls)
        obj._m = _native.Material.preset(name)
        return obj

    @staticmethod
    def preset_names() -> list[str]:
        return list(_native.Material.preset_names())

    def replace(self, **properties: float) -> "Material":
        """A copy with some properties changed (and optionally ``name``)."""
        name = properties.pop("name", self.name)
        vals = {f: getattr(self, f) for f in _MATERIAL_FIELDS}
        vals.update(properties)
        return Material(name, **vals)

    def __getattr__(self, item: str) -> Any:
        if item in _MATERIAL_FIELDS or item == "name":
            return getattr(self._m, item)
        raise AttributeError(item)

    def to_dict(self) -> dict[str, Any]:
        return {"name": self.name, **{f: getattr(self, f) for f in _MATERIAL_FIELDS}}

    def __repr__(self) -> str:
        return repr(self._m)


def _native_material(m: Any) -> Any:
    if m is None:
        return None
    if isinstance(m, str):
        return _native.Material.preset(m)
    if isinstance(m, Material):
        return m._m
    if isinstance(m, _native.Material):
        return m
    from ..errors import ConfigError

    raise ConfigError(f"invalid material = {m!r}: give a Material or a preset name")

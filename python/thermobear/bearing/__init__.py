"""Ball bearings: materials, geometry, the static and high-speed
quasi-static solve and the bearing stiffness matrix (crate: ``src/bearing``,
bindings ``src/python/bearing.rs``).

Stiffness against speed is [`thermobear.thermal.stiffness_curve`][thermobear.stiffness_curve]
(its thermal mode needs the thermal network, one layer up)."""

from .. import config as _config
from .ball_bearing import Bearing, BearingSolution
from .material import Material

# a system description's [bearing] preset takes catalogue designations too
_config.set_catalogue_lookup(lambda name: Bearing.preset(name)._b)

__all__ = ["Bearing", "BearingSolution", "Material"]

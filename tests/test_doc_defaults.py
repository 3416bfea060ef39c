"""Every default the physics docs (docs/concepts/*.md) quote is read from the
code here, so the two cannot drift apart.

Each entry of ``QUOTES`` names a page, a pattern that finds the quoted number
in its text (first group: the number), and where the code holds it: a Python
value of the package, or a pattern in a Rust source file. The test fails if
the quote is gone from the page, if the code no longer holds the value, or if
the two differ.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Callable

import pytest

import thermobear as tb
from thermobear import _native

ROOT = Path(__file__).resolve().parents[1]
PAGES = ROOT / "docs" / "concepts"


def _number(text: str) -> float:
    return float(text.replace(",", "").replace(" ", ""))


def _find(text: str, pattern: str, where: str) -> float:
    m = re.search(pattern, text, flags=re.S)
    assert m is not None, f"{where}: no match for {pattern!r}"
    return _number(m.group(1))


def rust(path: str, pattern: str, scale: float = 1.0) -> Callable[[], float]:
    """The number of ``pattern`` (first group) in the Rust file ``src/path``."""

    def read() -> float:
        return scale * _find((ROOT / "src" / path).read_text(), pattern, f"src/{path}")

    return read


def geometry(name: str, key: str) -> Callable[[], float]:
    return lambda: float(tb.Bearing.preset(name).geometry[key])


def lubrication(method: str, kind: str, key: str, scale: float = 1.0) -> Callable[[], float]:
    def read() -> float:
        v = tb.lubrication_defaults(method, kind)[key]
        return scale * float(v)

    return read


def gear(key: str) -> Callable[[], float]:
    return lambda: float(_native.gear_defaults()[key])


def _spring_rate() -> float:
    """Seed B's spring rate in N/µm, rounded to the two digits the docs quote."""
    force = rust("spindle/coupled.rs", r"SEED_B_SPRING_RATE_N_PER_M: f64 = ([\d.]+) / [\d.]+e-6")()
    travel = rust("spindle/coupled.rs", r"SEED_B_SPRING_RATE_N_PER_M: f64 = [\d.]+ / ([\d.]+)e-6")()
    return round(force / travel, 2)


PHYSICS, SPINDLE = "physics.md", "spindle-rotor.md"
DG, AC = "deep-groove", "angular-contact"

# (page, pattern of the quoted number, the code's value)
QUOTES: list[tuple[str, str, Callable[[], float]]] = [
    # §4 Palmgren load moment constants (src/thermal/heat.rs).
    (
        PHYSICS,
        r"with \\\(z = ([\d.]+)\\\), \\\(y = [\d.]+\\\) for deep-groove",
        rust("thermal/heat.rs", r"DeepGroove => LoadFrictionConstants \{ z: ([\d.]+)"),
    ),
    (
        PHYSICS,
        r"\\\(y = ([\d.]+)\\\) for deep-groove",
        rust("thermal/heat.rs", r"DeepGroove => LoadFrictionConstants \{ z: [\d.]+, y: ([\d.]+)"),
    ),
    (
        PHYSICS,
        r"deep-groove and \\\(z = ([\d.]+)\\\),",
        rust("thermal/heat.rs", r"AngularContact => LoadFrictionConstants \{ z: ([\d.]+)"),
    ),
    (
        PHYSICS,
        r"deep-groove and \\\(z = [\d.]+\\\),\s*\\\(y = ([\d.]+)\\\) for angular",
        rust(
            "thermal/heat.rs", r"AngularContact => LoadFrictionConstants \{ z: [\d.]+, y: ([\d.]+)"
        ),
    ),
    # §4 spin friction coefficient default.
    (
        PHYSICS,
        r"default is\s*\\\(\\mu_s = ([\d.]+)\\\)",
        rust("spindle/coupled.rs", r"pub const DEFAULT_SPIN_FRICTION_COEFFICIENT: f64 = ([\d.]+);"),
    ),
    # §4 the oil supply temperatures of the one oil-temperature rule.
    (
        PHYSICS,
        r"the oil-air supply, ([\d.]+) °C in seed A",
        rust("thermal/presets.rs", r"oil_air_temperature_c: ([\d.]+),\s*ambient_temperature_c: 26"),
    ),
    (
        PHYSICS,
        r"°C in seed A,\s*([\d.]+) °C in the seed B spindle",
        rust(
            "thermal/presets.rs",
            r"ambient_temperature_c: [\d.]+,\s*oil_air_temperature_c: ([\d.]+),",
        ),
    ),
    # §5 seed A's boundary temperatures.
    (
        PHYSICS,
        r"\(fixed at ([\d.]+) °C\)",
        rust("thermal/presets.rs", r"oil_air_temperature_c: ([\d.]+),\s*ambient_temperature_c: 26"),
    ),
    (
        PHYSICS,
        r"ambient air \\\(T_a\\\) \(([\d.]+) °C\)",
        rust(
            "thermal/presets.rs",
            r"oil_air_temperature_c: 28\.0,\s*ambient_temperature_c: ([\d.]+),",
        ),
    ),
    (
        PHYSICS,
        r"h_\{og\} = ([\d.]+)\\,k_",
        rust("thermal/network.rs", r"pub const POHLHAUSEN_LOCAL: f64 = ([\d.]+);"),
    ),
    # §8 seed A data notes.
    (
        PHYSICS,
        r"\| ([\d.]+)e-6 1/K \(AISI 52100",
        rust("materials.rs", r"fn steel_52100.*?thermal_expansion_per_k: ([\d.]+)e-6"),
    ),
    (
        PHYSICS,
        r"\| ([\d,]+) MPa \(206 GPa\)",
        rust("materials.rs", r"fn shaft_steel.*?youngs_modulus_pa: ([\d.]+)e9", 1e3),
    ),
    (
        PHYSICS,
        r"= ([\d]+) kg/m³ \|",
        rust("materials.rs", r"fn shaft_steel.*?density_kg_m3: ([\d.]+),"),
    ),
    (
        PHYSICS,
        r"\| ([\d.]+), the laminar flat-plate value",
        rust("thermal/network.rs", r"pub const POHLHAUSEN_LOCAL: f64 = ([\d.]+);"),
    ),
    (
        PHYSICS,
        r"units: ([\d.]+) W/\(m² K\^1\.25\)",
        rust("thermal/network.rs", r"pub const SEED_A_NATURAL_W_M2_K125: f64 = ([\d.]+);"),
    ),
    (
        PHYSICS,
        r"housing diameter ([\d.]+) × OD",
        rust(
            "thermal/presets.rs",
            r"housing_diameter_m: ([\d.]+) \* bearing\.geometry\.outer_diameter_m",
        ),
    ),
    (
        PHYSICS,
        r"shaft node ([\d.]+) mm beside the seat",
        rust("thermal/presets.rs", r"shaft_length_m: ([\d.]+),", 1e3),
    ),
    (
        PHYSICS,
        r"housing boss ([\d.]+) mm",
        rust("thermal/presets.rs", r"housing_length_m: ([\d.]+),\s*housing: Material", 1e3),
    ),
    (PHYSICS, r"shaft diameter = bore ([\d.]+) mm", geometry("6208", "bore_mm")),
    (PHYSICS, r"\| 6208 width \| not given \| ([\d.]+) mm", geometry("6208", "width_mm")),
    (PHYSICS, r"half backlash \\\(b\\\) = ([\d.]+) µm", gear("half_backlash_um")),
    (PHYSICS, r"damping ratio \\\(\\zeta_m\\\) = ([\d.]+), in contact", gear("mesh_damping_ratio")),
    (PHYSICS, r"\| damping ratio ([\d.]+) on each body", gear("bearing_damping_ratio")),
    (PHYSICS, r"first mesh harmonic, amplitude ([\d.]+) µm", gear("te_amplitude_um")),
    (PHYSICS, r"\| ([\d.]+) in parallel per gear body", gear("bearings_per_shaft")),
    # §8 seed B data notes: bearing presets.
    (PHYSICS, r"7008: (\d+) × 68 × 15 mm", geometry("7008C", "bore_mm")),
    (PHYSICS, r"7008: 40 × (\d+) × 15 mm", geometry("7008C", "outer_diameter_mm")),
    (PHYSICS, r"7008: 40 × 68 × (\d+) mm", geometry("7008C", "width_mm")),
    (PHYSICS, r"7009: (\d+) × 75 × 16 mm", geometry("7009C", "bore_mm")),
    (PHYSICS, r"7009: 45 × (\d+) × 16 mm", geometry("7009C", "outer_diameter_mm")),
    (PHYSICS, r"7009: 45 × 75 × (\d+) mm", geometry("7009C", "width_mm")),
    (
        PHYSICS,
        r"\\\(\\alpha_0 = (\d+)\^\\circ\\\), pitch",
        geometry("7009C", "free_contact_angle_deg"),
    ),
    (PHYSICS, r"5/16 in = ([\d.]+) mm \(7008C\)", geometry("7008C", "ball_diameter_mm")),
    (PHYSICS, r"11/32 in = ([\d.]+) mm \(7009C\)", geometry("7009C", "ball_diameter_mm")),
    (PHYSICS, r"(\d+) balls, \\\(f_i", geometry("7009C", "ball_count")),
    (PHYSICS, r"\\\(f_i = ([\d.]+)\\\)", geometry("7009C", "inner_conformity")),
    (PHYSICS, r"\\\(f_o = ([\d.]+)\\\) \|", geometry("7009C", "outer_conformity")),
    (PHYSICS, r"6\.45 N / 17\.92 µm ≈ ([\d.]+) N/µm", _spring_rate),
    (
        PHYSICS,
        r"k_s = 6\.45\\,\\text\{N\} / 17\.92\\,\\mu\\text\{m\} \\approx ([\d.]+)\\\)",
        _spring_rate,
    ),
    (
        PHYSICS,
        r"placeholder rows of ([\d.e]+) N/m radial",
        rust("rotor/presets.rs", r"front_radial_stiffness_n_per_m: ([\d.e]+),"),
    ),
    (
        PHYSICS,
        r"N/m radial, ([\d.e]+) N/m axial",
        rust("rotor/presets.rs", r"axial_stiffness_n_per_m: ([\d.e]+),"),
    ),
    (
        PHYSICS,
        r"N/m axial, (\d+) % modal damping",
        rust("rotor/presets.rs", r"modal_damping_ratio: ([\d.]+),", 100.0),
    ),
    (
        PHYSICS,
        r"\\\(B_0\\\) = ([\d.]+) T RMS",
        rust("rotor/presets.rs", r"flux_density_t: ([\d.]+),"),
    ),
    (
        PHYSICS,
        r"static eccentricity (\d+) % of the",
        rust("rotor/presets.rs", r"static_eccentricity_m: ([\d.]+) \* AIR_GAP_M", 100.0),
    ),
    (
        PHYSICS,
        r"% of the ([\d.]+) mm gap",
        rust("rotor/presets.rs", r"pub const AIR_GAP_M: f64 = ([\d.e-]+);", 1e3),
    ),
    # §9 SKF-style model.
    (
        PHYSICS,
        r"\\mu_\{bl\} = ([\d.]+)\\\)",
        rust("thermal/friction.rs", r"pub const SKF_MU_BOUNDARY: f64 = ([\d.]+);"),
    ),
    (
        PHYSICS,
        r"takes ([\d.]+) for its \"e-drive ATF\" preset",
        rust("thermal/friction.rs", r"contains\(\"transmission\"\) \{\s*([\d.]+)"),
    ),
    (
        PHYSICS,
        r"preset and\s*([\d.]+) for the ISO VG grades",
        rust("thermal/friction.rs", r"contains\(\"ester\"\) \{\s*[\d.]+\s*\} else \{\s*([\d.]+)"),
    ),
    (
        PHYSICS,
        r"\\mu_\{EHL\}\\\) = [\d.]+ for mineral oils, ([\d.]+) synthetic",
        rust("thermal/friction.rs", r"contains\(\"ester\"\) \{\s*([\d.]+)"),
    ),
    (
        PHYSICS,
        r"\\\(K_z = ([\d.]+)\\\)\s*deep-groove",
        rust("thermal/friction.rs", r"kz: ([\d.]+),"),
    ),
    (
        PHYSICS,
        r"deep-groove, \\\(([\d.]+)\\\) single-row angular-contact",
        rust("thermal/friction.rs", r"kz: 3\.1,.*?kz: ([\d.]+),"),
    ),
    # spindle-rotor.md.
    (
        SPINDLE,
        r"a (\d+) % modal damping ratio",
        rust("rotor/presets.rs", r"modal_damping_ratio: ([\d.]+),", 100.0),
    ),
    (
        SPINDLE,
        r"shrinks the increment by less than a factor (\d+)",
        lambda: 1.0 / rust("rotor/transient.rs", r"pub const SLOW_CONTRACTION: f64 = ([\d.]+);")(),
    ),
]

# §9 lubrication method table: every cell against tb.lubrication_defaults.
_METHODS = {
    "grease": "grease",
    "oil mist": "oil-mist",
    "oil-air": "oil-air",
    "jet": "jet",
    "oil bath": "oil-bath",
}


@pytest.mark.parametrize(("page", "pattern", "code"), QUOTES, ids=[q[1][:40] for q in QUOTES])
def test_quoted_default_is_the_code_default(
    page: str, pattern: str, code: Callable[[], float]
) -> None:
    quoted = _find((PAGES / page).read_text(), pattern, page)
    value = code()
    assert quoted == pytest.approx(value, rel=1e-12), (
        f"{page}: {pattern!r} quotes {quoted}, code has {value}"
    )


@pytest.mark.parametrize("row", sorted(_METHODS))
def test_lubrication_table_is_the_code_default(row: str) -> None:
    text = (PAGES / PHYSICS).read_text()
    num = r"([\d.e-]+)"
    pattern = (
        rf"\n\| {row} \| {num}(?: \(([\d.]+)-([\d.]+)\))? \| {num} \| {num}(?: %)? "
        rf"\(([\d.]+)-([\d.]+) %\) \| {num} \|"
    )
    m = re.search(pattern, text)
    assert m is not None, f"lubrication table row {row!r} not found"
    f0_dg, lo, hi, f0_ac, x, x_lo, x_hi, krs = m.groups()
    method = _METHODS[row]
    dg = tb.lubrication_defaults(method, DG)
    ac = tb.lubrication_defaults(method, AC)
    assert float(f0_dg) == pytest.approx(dg["lubrication_factor_f0"], rel=1e-12)
    assert float(f0_ac) == pytest.approx(ac["lubrication_factor_f0"], rel=1e-12)
    if lo is not None:
        assert (float(lo), float(hi)) == pytest.approx(dg["f0_bounds"], rel=1e-12)
    assert float(x) / 100 == pytest.approx(dg["oil_volume_fraction"], rel=1e-12)
    assert (float(x_lo) / 100, float(x_hi) / 100) == pytest.approx(
        dg["oil_fraction_bounds"], rel=1e-12
    )
    assert float(krs) == pytest.approx(dg["replenishment_krs"], rel=1e-12)


def test_every_default_sentence_is_covered() -> None:
    """A page that says thermobear's default is a number must have it in QUOTES:
    each "default is/of/rate ... <number>" sentence is matched by one pattern."""
    found = 0
    for page in (PHYSICS, SPINDLE):
        text = (PAGES / page).read_text()
        patterns = [p for pg, p, _ in QUOTES if pg == page]
        for m in re.finditer(r"(?:thermobear's )?default (?:is|of|spring rate)[^.]*?\d", text):
            start = m.start()
            window = text[start : start + 300]
            assert any(re.search(p, window, flags=re.S) for p in patterns), (
                f"{page}: quoted default not checked: {window[:120]!r}"
            )
            found += 1
    assert found >= 2  # the spin friction coefficient and the spring rate at least

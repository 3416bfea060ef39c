"""Bearings by designation: a standard designation such as ``"6208-2RS1"``,
``"7014CE/HCP4A"`` or ``"HCB7009C-T-P4S"`` read into its series, bore, contact
angle, ball material and clearance group, and the geometry it stands for.

What is read
    * the series: deep groove 618, 619, 60, 62, 63; angular contact 718, 719
      (also written 79, as NSK and NTN do), 70, 72, 73;
    * the bore code: two digits (00 = 10 mm, 01 = 12, 02 = 15, 03 = 17,
      04 and up = 5 x code), one digit for the small 60/62/63 bores
      (608: 8 mm), or ``/d`` (618/8, 62/22: d in mm);
    * the contact angle of an angular-contact bearing, the letters right
      after the bore code (a ``-`` or space between is allowed; NTN's
      ULTAGE ``U`` before them is skipped): C = 15 deg, AC, AD, A5 or E
      (FAG) = 25 deg, A = 30 deg, B = 40 deg. Without them the 72 and 73
      series are 40 deg, as makers sell them; a 70, 718 or 719 bearing must
      name its angle;
    * the balls: ``HC`` before the series (FAG style, ``HCB7014C``) or
      ``/HC`` in the suffix (SKF style, ``7014 CD/HCP4A``, ``6208/HC5C3``)
      or a trailing ``-hybrid``: Si3N4 balls on steel rings; a trailing
      ``-ceramic``: Si3N4 rings and balls;
    * the radial clearance group of a deep-groove bearing: C2, C3, C4 or
      C5 in the suffix (default: the normal group CN).

What is ignored (and kept in ``Designation.ignored``)
    the spindle-bearing prefix ``B`` (FAG), the design letter after the
    angle (SKF's E, D, B), cage (TN9, M, T, TY), precision class (P4, P4A,
    P4S, UP, ABEC), seals and shields (2RS1, 2Z, ZZ, DDU, LLU), snap rings
    (N, NR), arrangement and preload (DB, DGA, UL). A seal changes the
    friction, which the model does not take from the name.

The boundary dimensions come from ``data/iso15_boundary_dimensions.toml``
(ISO 15, as the SKF General Catalogue prints them; sources in its header).
The internal geometry is published where thermobear has it (the presets'
bearings, ``KNOWN_INTERNAL``); otherwise it is estimated with the rule the
project's validation sets use (``estimate_internal``), and every value says
which (``provenance``)."""

from __future__ import annotations

import math
import re
import tomllib
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from typing import Any, Optional

from .. import _validate as v

DEEP = "deep-groove"
ANGULAR = "angular-contact"

#: Series -> (bearing type, ISO 15 dimension series).
SERIES: dict[str, tuple[str, str]] = {
    "618": (DEEP, "18"),
    "619": (DEEP, "19"),
    "60": (DEEP, "10"),
    "62": (DEEP, "02"),
    "63": (DEEP, "03"),
    "718": (ANGULAR, "18"),
    "719": (ANGULAR, "19"),
    "70": (ANGULAR, "10"),
    "72": (ANGULAR, "02"),
    "73": (ANGULAR, "03"),
}
#: Other spellings of a series (NSK and NTN write the 719 series as 79).
SERIES_ALIASES = {"79": "719"}
#: Contact-angle letters after the bore code -> free contact angle [deg].
ANGLE_CODES: dict[str, float] = {
    "AC": 25.0,
    "AD": 25.0,
    "A5": 25.0,
    "A": 30.0,
    "B": 40.0,
    "C": 15.0,
    "E": 25.0,
}
#: The angle of a series sold without an angle letter [deg].
DEFAULT_ANGLE_DEG = {"72": 40.0, "73": 40.0}
#: The clearance groups a deep-groove designation may name.
CLEARANCE_GROUPS = ("C2", "CN", "C3", "C4", "C5")
#: Suffixes read straight after a deep-groove bore code without a separator
#: (NSK and NTN style: 6208ZZ, 6208DDU, 6208LLU, 6208C3).
_DEEP_SUFFIX_START = re.compile(r"^(2?Z|2?RS|2?RZ|LL|DD|VV|NR|N|E|T|M|J|Y|C[2-5N]|P[0-6])")

_INCH_MM = 25.4
_ISO15 = "catalogue ISO 15: SKF General Catalogue 6000 (2006), deep groove tables pp. 301-314"
_CLEARANCE = "catalogue: SKF General Catalogue 6000 (2006) table 4 (ISO 5753-1 groups)"
_SEED_A = "published: seed A Table 1 (Liu et al., Sensors 2021, 21, 309)"
_SEED_B = (
    "estimated: thermobear's {name} preset (seed B's bearing; internal geometry not "
    "published, assumed as the preset states)"
)
_INTERNAL = ("ball_count", "ball_diameter_mm", "pitch_diameter_mm")
_CONFORMITY = ("inner_conformity", "outer_conformity")

#: Internal geometry thermobear knows for a series and bore code: the
#: presets' numbers as their sources give them, with the provenance of
#: each. ``Bearing.preset`` of any designation of these sizes takes them.
KNOWN_INTERNAL: dict[tuple[str, str], dict[str, Any]] = {
    ("62", "08"): {
        "ball_count": 9,
        "ball_diameter_mm": 12.0,
        "pitch_diameter_mm": 60.0,
        "inner_conformity": 0.52,
        "outer_conformity": 0.53,
        "diametral_clearance_mm": 0.04,
        "source": _SEED_A,
    },
    ("70", "08"): {
        "ball_count": 16,
        "ball_diameter_mm": 7.938,
        "pitch_diameter_mm": 54.0,
        "inner_conformity": 0.52,
        "outer_conformity": 0.53,
        "source": _SEED_B.format(name="7008C"),
    },
    ("70", "09"): {
        "ball_count": 16,
        "ball_diameter_mm": 8.731,
        "pitch_diameter_mm": 60.0,
        "inner_conformity": 0.52,
        "outer_conformity": 0.53,
        "source": _SEED_B.format(name="7009C"),
    },
}

#: The estimation rule for the internal geometry of a catalogue size (the
#: rule of thermobear's validation sets): per bearing type, the fraction of
#: the pitch circumference the balls fill and the groove conformities.
ESTIMATION_RULE: dict[str, dict[str, float]] = {
    DEEP: {"fill": 0.55, "inner_conformity": 0.515, "outer_conformity": 0.525},
    ANGULAR: {"fill": 0.75, "inner_conformity": 0.52, "outer_conformity": 0.53},
}
_RULE_TEXT = {
    "pitch_diameter_mm": "estimated: (d + D)/2",
    "ball_diameter_mm": "estimated: the standard inch ball (1/32 in steps) nearest 0.3 (D - d)",
    "ball_count": "estimated: round({fill} pi d_m / D_w), balls filling {pct} % of the pitch "
    "circle",
    "inner_conformity": "estimated: f_i = {inner_conformity} (typical {kind} groove)",
    "outer_conformity": "estimated: f_o = {outer_conformity} (typical {kind} groove)",
}


@dataclass(frozen=True)
class Designation:
    """A bearing designation read into what thermobear uses of it."""

    text: str
    series: str
    bore_code: str
    bearing_type: str
    free_contact_angle_deg: Optional[float]
    angle_source: str
    material_class: str
    material_source: str
    clearance_group: str
    ignored: str

    @property
    def canonical(self) -> str:
        """The short form: series, bore code, angle letter and material
        (``"7014C-hybrid"``, ``"6208"``)."""
        letter = ""
        if self.bearing_type == ANGULAR:
            angle = self.free_contact_angle_deg
            letter = {15.0: "C", 25.0: "AC", 30.0: "A", 40.0: "B"}[float(angle or 0.0)]
        tail = "" if self.material_class == "steel" else f"-{self.material_class}"
        return f"{self.series}{self.bore_code}{letter}{tail}"


# -- the ISO 15 tables -------------------------------------------------------


@lru_cache(maxsize=1)
def _tables() -> dict[str, Any]:
    path = resources.files("thermobear.bearing").joinpath("data/iso15_boundary_dimensions.toml")
    return tomllib.loads(path.read_text(encoding="utf-8"))


def bore_codes(series: str) -> list[str]:
    """The bore codes of ``series`` in the table, small bores first. An
    angular-contact series takes the two-digit codes only."""
    kind, dims = SERIES[series]
    codes = [str(r[0]) for r in _tables()["series"][dims]["rows"]]
    return [c for c in codes if kind == DEEP or (len(c) == 2 and c.isdigit())]


def boundary_dimensions(series: str, bore_code: str) -> tuple[float, float, float]:
    """(d, D, B) in mm of ``series`` and ``bore_code`` from the ISO 15 table."""
    dims = SERIES[series][1]
    for code, d, big_d, b in _tables()["series"][dims]["rows"]:
        if code == bore_code and bore_code in bore_codes(series):
            return float(d), float(big_d), float(b)
    raise KeyError((series, bore_code))


def bore_of_code(bore_code: str) -> float:
    """The bore [mm] a bore code stands for (module doc)."""
    if bore_code.startswith("/"):
        return float(bore_code[1:])
    if len(bore_code) == 1:
        return float(bore_code)
    return float({0: 10, 1: 12, 2: 15, 3: 17}.get(int(bore_code), 5 * int(bore_code)))


def clearance_um(bore_mm: float, group: str = "CN") -> tuple[float, float]:
    """The (min, max) radial internal clearance [um] of a deep-groove
    bearing of ``bore_mm`` in ``group`` (C2, CN, C3, C4, C5)."""
    i = CLEARANCE_GROUPS.index(group)
    for row in _tables()["clearance"]["rows"]:
        if row[0] < bore_mm <= row[1]:
            lo, hi = float(row[2 + 2 * i]), float(row[3 + 2 * i])
            if math.isnan(lo):
                break
            return lo, hi
    raise v.fail("clearance group", group, f"a group the table gives for a {bore_mm:g} mm bore")


# -- reading a designation ---------------------------------------------------

_SERIES_PATTERN = "|".join(sorted([*SERIES, *SERIES_ALIASES], key=len, reverse=True))
_CORE = re.compile(
    rf"^(?P<hc>HC)?[- ]?(?P<spindle>B(?=[- ]?7))?[- ]?(?P<series>{_SERIES_PATTERN})"
    r"(?P<bore>/\d+|\d{2}|\d)(?P<rest>.*)$"
)
_MATERIAL_WORD = re.compile(r"[-_ ]?(HYBRID|CERAMIC)$")
_ANGLE = re.compile(r"^[- ]?(?:U(?=AC|AD|A|B|C|E))?(AC|AD|A5|A|B|C|E)")
_CLEARANCE_TOKEN = re.compile(r"(?<!H)C[2-5N](?!\d)")
_SEPARATORS = "-/ ."


def _fail(text: str, accepted: str, hint: str = "") -> Exception:
    e = v.fail("name", text, accepted)
    e.args = (f"{e}{hint}", *e.args[1:])
    return e


def _material(core: re.Match[str], rest: str, word: Optional[str]) -> tuple[str, str]:
    """(material class, how the designation says it)."""
    hybrid = []
    if core["hc"]:
        hybrid.append("HC prefix")
    if "/HC" in rest:
        hybrid.append("/HC suffix")
    if word == "HYBRID":
        hybrid.append("-hybrid")
    if word == "CERAMIC":
        if hybrid:
            raise _fail(core.string, "one ball material: the HC marks and -ceramic disagree")
        return "ceramic", "designation: -ceramic (Si3N4 rings and balls)"
    if hybrid:
        return "hybrid", f"designation: {' and '.join(hybrid)} (Si3N4 balls, steel rings)"
    return "steel", "default: bearing steel 52100 rings and balls (no HC mark)"


def _angle(text: str, series: str, bore: str, rest: str) -> tuple[float, str, str]:
    """(free contact angle [deg], how it was read, the rest after it)."""
    m = _ANGLE.match(rest)
    if m:
        code = m.group(1)
        return (
            ANGLE_CODES[code],
            f"designation: {code} = {ANGLE_CODES[code]:g} deg",
            rest[m.end() :],
        )
    if rest and rest[0] not in _SEPARATORS:
        hint = f"; did you mean {series}{bore}C?"
        raise _fail(text, _angle_letters(series), hint)
    if series in DEFAULT_ANGLE_DEG:
        deg = DEFAULT_ANGLE_DEG[series]
        return deg, f"default: {deg:g} deg, the {series} series without an angle letter", rest
    raise _fail(text, _angle_letters(series), f"; did you mean {series}{bore}C?")


def _misspelt_material(text: str, rest: str) -> None:
    """A trailing word close to ``hybrid`` or ``ceramic`` is a misspelling."""
    last = re.split(r"[- /]", rest)[-1]
    near = v.close_name(last, ("HYBRID", "CERAMIC")) if len(last) > 3 else None
    if near is not None:
        fixed = text.strip()[: len(text.strip()) - len(last)] + near.lower()
        hint = v.did_you_mean(text, _preset_names()) or f"; did you mean {fixed}?"
        raise _fail(text, "a designation ending in -hybrid or -ceramic, if any", hint)


def _angle_letters(series: str) -> str:
    return (
        f"a {series}-series designation with its contact angle after the bore code: "
        "C (15 deg), AC (25 deg), A (30 deg) or B (40 deg)"
    )


def _clearance(rest: str) -> str:
    groups = _CLEARANCE_TOKEN.findall(rest)
    return str(groups[-1]) if groups else ""


def _core(text: str) -> tuple[re.Match[str], Optional[str], str]:
    """The designation matched, its material word and the series it names."""
    upper = text.strip().upper()
    word = _MATERIAL_WORD.search(upper)
    body = upper[: word.start()] if word else upper
    core = _CORE.match(body)
    if core is None:
        raise _fail(text, f"a bearing preset or designation ({family_list()})", _hint(text))
    series = SERIES_ALIASES.get(core["series"], core["series"])
    return core, (word.group(1) if word else None), series


def parse_designation(text: str) -> Designation:
    """Read a designation (module doc); a ConfigError, with a guess when
    one is close, for a string that is not one."""
    if not isinstance(text, str) or not text.strip():
        raise v.fail("name", text, "a bearing preset name or designation (a non-empty string)")
    core, word, series = _core(text)
    bore, rest = core["bore"], core["rest"]
    _misspelt_material(text, rest)
    if bore not in bore_codes(series):
        codes = bore_codes(series)
        hint = v.did_you_mean(text, _preset_names()) or _hint(text)
        raise _fail(
            text, f"a {series}-series bore code in the table ({codes[0]}-{codes[-1]})", hint
        )
    kind = SERIES[series][0]
    material, material_source = _material(core, rest, word)
    angle: Optional[float] = None
    angle_source, group = "", ""
    if kind == ANGULAR:
        angle, angle_source, rest = _angle(text, series, bore, rest)
    else:
        if rest and rest[0] not in _SEPARATORS and not _DEEP_SUFFIX_START.match(rest):
            raise _fail(text, "a deep-groove designation", f"; did you mean {series}{bore}?")
        group = _clearance(rest)
    ignored = re.sub(r"/HC\d?", "/", rest, count=1) if material == "hybrid" else rest
    if group:
        ignored = ignored.replace(group, "", 1)
    if core["spindle"]:
        ignored = f"B (prefix) {ignored}"
    return Designation(
        text=text.strip(),
        series=series,
        bore_code=bore,
        bearing_type=kind,
        free_contact_angle_deg=angle,
        angle_source=angle_source,
        material_class=material,
        material_source=material_source,
        clearance_group=group or "CN",
        ignored=ignored.strip(_SEPARATORS),
    )


# -- guesses for a designation that is not one ------------------------------

_TYPOS = str.maketrans("OIL", "011")
_LEAD = re.compile(r"^(HC)?([- ]?B)?([- ]?)([0-9OIL/]+)(.*)$")


def _preset_names() -> list[str]:
    from .. import _native

    return list(_native.Bearing.preset_names())


def known_names() -> list[str]:
    """One short designation per size (angular contact with C), for guesses."""
    out = []
    for series, (kind, _) in SERIES.items():
        letter = "C" if kind == ANGULAR else ""
        out += [f"{series}{code}{letter}" for code in bore_codes(series)]
    return out


def _hint(text: str) -> str:
    """``"; did you mean X?"`` for a near miss: a letter O, I or L typed
    for a digit, else the closest preset name or designation."""
    m = _LEAD.match(text.strip().upper())
    if m and m.group(4).translate(_TYPOS) != m.group(4):
        fixed = "".join(m.groups(""))[: m.start(4)] + m.group(4).translate(_TYPOS) + m.group(5)
        try:
            parse_designation(fixed)
        except Exception:  # noqa: BLE001 - no guess then
            pass
        else:
            return f"; did you mean {fixed}?"
    return v.did_you_mean(text, _preset_names()) or v.did_you_mean(text, known_names())


def family_list() -> str:
    """The series read, for messages."""
    deep = ", ".join(s for s, (k, _) in SERIES.items() if k == DEEP)
    angular = ", ".join(s for s, (k, _) in SERIES.items() if k == ANGULAR)
    return f"deep groove {deep}; angular contact {angular} with C, AC or B"


def families() -> list[dict[str, str]]:
    """One row per series: type, bore range, the angle letters read and the
    ball-material marks (for ``thermobear presets --bearings``)."""
    rows = []
    for series, (kind, dims) in SERIES.items():
        codes = bore_codes(series)
        first, last = boundary_dimensions(series, codes[0]), boundary_dimensions(series, codes[-1])
        if kind == ANGULAR:
            default = DEFAULT_ANGLE_DEG.get(series)
            angles = "C 15, AC/AD/A5/E 25, A 30, B 40 deg" + (
                f" (none: {default:g} deg)" if default else " (required)"
            )
        else:
            angles = "-"
        alias = [a for a, s in SERIES_ALIASES.items() if s == series]
        rows.append(
            {
                "series": series + (f" (also {alias[0]})" if alias else ""),
                "type": kind,
                "iso_dimension_series": dims,
                "bore_codes": f"{codes[0]}-{codes[-1]}",
                "bore_range": f"{first[0]:g}-{last[0]:g} mm",
                "angles": angles,
            }
        )
    return rows


# -- the geometry of a designation -------------------------------------------


def inch_ball_mm(bore_mm: float, outer_diameter_mm: float) -> float:
    """The estimated ball [mm]: the standard inch ball (1/32 in steps)
    nearest 0.3 (D - d), at least one step."""
    step = _INCH_MM / 32.0
    return max(1, round(0.3 * (outer_diameter_mm - bore_mm) / step)) * step


def estimate_internal(
    bearing_type: str, bore_mm: float, outer_diameter_mm: float
) -> dict[str, Any]:
    """The estimated internal geometry of a catalogue size (``ESTIMATION_RULE``):
    pitch diameter (d + D)/2, ball ``inch_ball_mm``, round(fill pi d_m / D_w)
    balls, the type's conformities."""
    rule = ESTIMATION_RULE[bearing_type]
    dm = 0.5 * (bore_mm + outer_diameter_mm)
    dw = inch_ball_mm(bore_mm, outer_diameter_mm)
    return {
        "ball_count": int(round(rule["fill"] * math.pi * dm / dw)),
        "ball_diameter_mm": dw,
        "pitch_diameter_mm": dm,
        "inner_conformity": rule["inner_conformity"],
        "outer_conformity": rule["outer_conformity"],
    }


def _estimated_provenance(bearing_type: str) -> dict[str, str]:
    rule = ESTIMATION_RULE[bearing_type]
    words = {**rule, "pct": f"{100 * rule['fill']:g}", "kind": bearing_type.replace("-", " ")}
    return {k: _RULE_TEXT[k].format(**words) for k in (*_INTERNAL, *_CONFORMITY)}


def catalogue_geometry(des: Designation) -> tuple[dict[str, Any], dict[str, str]]:
    """The constructor keywords of ``des`` (``Bearing.deep_groove`` or
    ``Bearing.angular_contact``) and the provenance of every value."""
    d, big_d, b = boundary_dimensions(des.series, des.bore_code)
    kw: dict[str, Any] = {"bore_mm": d, "outer_diameter_mm": big_d, "width_mm": b}
    dims = SERIES[des.series][1]
    twins = " and ".join(s for s, (_, ds) in SERIES.items() if ds == dims)
    prov = dict.fromkeys(kw, f"{_ISO15}, dimension series {dims} ({twins})")
    known = KNOWN_INTERNAL.get((des.series, des.bore_code))
    if known is not None:
        fields = (*_INTERNAL, *_CONFORMITY)
        kw.update({k: known[k] for k in fields})
        prov.update(dict.fromkeys(fields, str(known["source"])))
    else:
        kw.update(estimate_internal(des.bearing_type, d, big_d))
        prov.update(_estimated_provenance(des.bearing_type))
    if des.bearing_type == DEEP:
        named = des.clearance_group != "CN" or "CN" in des.text.upper()
        if known is not None and "diametral_clearance_mm" in known and not named:
            kw["diametral_clearance_mm"] = known["diametral_clearance_mm"]
            prov["diametral_clearance_mm"] = str(known["source"])
        else:
            lo, hi = clearance_um(d, des.clearance_group)
            kw["diametral_clearance_mm"] = 0.5e-3 * (lo + hi)
            prov["diametral_clearance_mm"] = (
                f"{_CLEARANCE}: middle of group {des.clearance_group}, {lo:g}-{hi:g} um"
            )
    else:
        kw["free_contact_angle_deg"] = des.free_contact_angle_deg
        prov["free_contact_angle_deg"] = des.angle_source
    si3n4 = "Si3N4"
    kw["ball_material"] = None if des.material_class == "steel" else si3n4
    kw["ring_material"] = si3n4 if des.material_class == "ceramic" else None
    prov["ball_material"] = prov["ring_material"] = des.material_source
    return kw, prov


def preset_provenance(name: str, bearing_type: str) -> dict[str, str]:
    """The provenance of a built-in preset (``"6208"``, ``"7009C-hybrid"``)."""
    des = parse_designation(name)
    _, prov = catalogue_geometry(des)
    if bearing_type == ANGULAR:
        prov["free_contact_angle_deg"] = des.angle_source
    return prov


def summary_lines(
    name: str,
    bearing_type: str,
    material_class: str,
    geometry: dict[str, float],
    provenance: dict[str, str],
) -> list[str]:
    """The lines of ``Bearing.summary``."""
    g = geometry
    lines = [
        f"bearing {name}: {bearing_type}, {material_class}",
        f"  bore {g['bore_mm']:g} mm, outside {g['outer_diameter_mm']:g} mm, "
        f"width {g['width_mm']:g} mm",
        f"  {int(g['ball_count'])} balls of {g['ball_diameter_mm']:.4g} mm on a "
        f"{g['pitch_diameter_mm']:.4g} mm pitch circle, f_i {g['inner_conformity']:g}, "
        f"f_o {g['outer_conformity']:g}",
        f"  free contact angle {g['free_contact_angle_deg']:.4g} deg"
        + (
            f", diametral clearance {1000.0 * g['diametral_clearance_mm']:.3g} um"
            if bearing_type == DEEP
            else ""
        ),
    ]
    if not provenance:
        return [*lines, "  dimensions as given to the constructor"]
    estimated = sorted(k for k, p in provenance.items() if p.startswith("estimated"))
    if estimated:
        lines.append(
            "  note: estimated, not published: "
            + ", ".join(estimated)
            + " (see provenance for the rule)"
        )
    sources = sorted({p for k, p in provenance.items() if k in ("bore_mm", *_INTERNAL)})
    lines += [f"  source: {s}" for s in sources if not s.startswith("estimated")]
    return lines


def bearing_family_lines() -> list[str]:
    """The text of ``thermobear presets --bearings``: the presets, then one
    line per series (bore codes and range, angle letters), then the marks
    read and ignored."""
    from .. import _native

    rows = families()
    width = max(len(r["series"]) for r in rows)
    lines = [
        "bearing presets: " + ", ".join(_native.Bearing.preset_names()),
        "bearings by designation (ISO 15 boundary dimensions; internal geometry published "
        "for the presets' sizes, else estimated):",
    ]
    for r in rows:
        lines.append(
            f"  {r['series']:<{width}}  {r['type']:<15}  bore codes {r['bore_codes']:<8} "
            f"({r['bore_range']}), dimension series {r['iso_dimension_series']}"
            + ("" if r["angles"] == "-" else f"; angle {r['angles']}")
        )
    lines += [
        "  balls: HC prefix, /HC suffix or -hybrid = Si3N4 balls; -ceramic = Si3N4 rings and balls",
        "  deep-groove clearance: C2, C3, C4, C5 (default CN)",
        "  ignored: B prefix, design letters, cage, precision class (P4 ...), seals "
        "(2RS1, 2Z ...), snap rings, arrangement",
    ]
    return lines

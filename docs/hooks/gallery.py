"""MkDocs hook: the gallery of the seed studies, built from ``thermobear demo``.

Where the figures come from, first match wins:

1. the folder named by the environment variable ``THERMOBEAR_DEMO_OUT``;
2. ``thermobear-out/`` at the repository root (the default output folder of
   ``thermobear demo``), if it exists;
3. a fresh ``python -m thermobear demo --quick`` into a temporary folder, run
   with the interpreter that runs MkDocs (``sys.executable``), so the
   thermobear installed beside MkDocs is the one used.

Every PNG found is added to the site under ``gallery/img/`` (none is committed
to the repository) and the gallery pages are generated: one overview page
and one page per group of studies, each figure with a caption saying what it
shows, which seed study it belongs to and which figure of the paper it
corresponds to where there is one. A figure the table below does not know
still appears, with a caption built from its file name.
"""

from __future__ import annotations

import logging
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from mkdocs.exceptions import PluginError
from mkdocs.structure.files import File

log = logging.getLogger("mkdocs.hooks.gallery")

SEED_A = (
    "Seed A (Liu, Liu & Hu, *Sensors* 2021, 21, 309: deep-groove 6208 bearings "
    "of an electric-drive helical gear pair)"
)
SEED_B = (
    "Seed B (*Dynamic and thermal coupling model of a ceramic motorized "
    "spindle*: 7009C front / 7008C rear hybrid pairs)"
)

#: Gallery pages: (file stem, title, intro, study folders in order).
PAGES: list[tuple[str, str, str, list[str]]] = [
    (
        "seed-a-bearing",
        "Seed A: bearing, heat and stiffness",
        f"{SEED_A}. The 6208 bearing alone and in its thermal network: ball "
        "loads, heat, node temperatures, thermal deformation and the three "
        "stiffness cases the gear study is run with.",
        ["seed_a_bearing", "seed_a_thermal"],
    ),
    (
        "seed-a-gear",
        "Seed A: gear dynamics",
        f"{SEED_A}. Bifurcation diagrams of the 8-DOF helical pair for the "
        "three bearing-stiffness cases, accelerating and decelerating, and "
        "regime maps over torque and speed. Seed A gives no backlash, damping, "
        "transmission error or mesh stiffness: the documented defaults of "
        "[Physics §8](../concepts/physics.md#8-data-notes) are used, so the "
        "structure of the diagrams is comparable with the paper, not the digits.",
        ["seed_a_gear"],
    ),
    (
        "seed-b-spindle",
        "Seed B: bearings and spindle",
        f"{SEED_B}. Single 7009C bearings under preload, then the coupled "
        "spindle: transient and steady temperatures, thermal displacement, "
        "contact angles, loads, stiffness, optimal and compensation preload. "
        "Seed B's spindle and bearing tables are missing from the text, so the "
        "geometry is the stated catalogue-based assumption "
        "([Physics §8](../concepts/physics.md#8-data-notes)).",
        ["seed_b_bearing", "seed_b_spindle"],
    ),
    (
        "seed-b-vibration",
        "Seed B: rotor vibration",
        f"{SEED_B}. The spindle rotor on its solved bearings: Campbell "
        "diagram, shaft-end vibration velocity against speed and the velocity "
        "spectrum at 12,000 rpm.",
        ["seed_b_vibration"],
    ),
    (
        "diagnosis",
        "Diagnosis studies",
        "The model-against-measurement workflow "
        "([concepts](../concepts/diagnosis.md), [how-to](../how-to/diagnose.md)) "
        "on a synthetic case with a hidden effect and on seed B's own quoted "
        "measurements.",
        ["diagnose_synthetic", "diagnose_seed_b"],
    ),
    (
        "rig-to-prediction",
        "From rig to prediction",
        "The end-to-end study of the [how-to](../how-to/rig-to-prediction.md): "
        "seed A's 6208 measured on a rig with a hidden effect, diagnosed and "
        "calibrated, its thermal stiffness with the 95 % band and the gear's "
        "regime boundaries with their intervals; seed B's spindle calibrated on "
        "its measured temperatures against the values the paper reports.",
        ["rig_to_prediction"],
    ),
]

_CASE = {
    "constant": "constant bearing stiffness (the zero-speed value at every speed)",
    "speed": "speed-dependent bearing stiffness without thermal effects",
    "thermal": "speed-dependent bearing stiffness with thermal deformation",
}
_DIRECTION = {"up": "accelerating (speed swept up)", "down": "decelerating (speed swept down)"}

#: (pattern on the file stem, caption). Captions may use the named groups.
CAPTIONS: list[tuple[str, str]] = [
    (
        r"seed_a_ball_loads",
        "Seed A: inner and outer contact load of every ball of the 6208 around "
        "the bearing at the 100 N m load case (Fa = 2680.9 N including the 300 N "
        "preload, Fr = 1189.9 N) and 16,000 rpm. The outer loads exceed the inner "
        "ones by the centrifugal force. Supports the statics of seed A "
        "section 2.1-2.2 (its Fig. 4 shows the ball loading).",
    ),
    (
        r"seed_a_(?P<dir>radial|axial)_stiffness",
        "Seed A: {dir} stiffness of the 6208 against speed, constant (zero-speed) "
        "stiffness against the speed-dependent quasi-static one without thermal "
        "effects (two of the three cases of seed A Fig. 11).",
    ),
    (
        r"seed_a_contact_angles",
        "Seed A: inner and outer contact angles of the 6208 against speed: "
        "the centrifugal force raises the outer load and lowers the outer "
        "contact angle (the mechanism seed A gives for Fig. 11).",
    ),
    (
        r"seed_a_fig6a_heat_no_load",
        "Seed A Fig. 6a: friction heat of the 6208 against speed for several "
        "axial preloads, no external load.",
    ),
    (
        r"seed_a_fig6b_heat_loaded",
        "Seed A Fig. 6b: friction heat against speed and preload at the 100 N m "
        "load case (Fa = 2380.9 N, Fr = 1189.9 N from the gear forces).",
    ),
    (
        r"seed_a_fig8a_temperatures_vs_speed",
        "Seed A Fig. 8a: temperatures of the thermal-network nodes (shaft, inner "
        "ring, balls, outer ring, housing) against speed, 300 N preload, no load.",
    ),
    (
        r"seed_a_fig8b_temperatures_vs_axial_load",
        "Seed A Fig. 8b: node temperatures at 6500 rpm against the axial load "
        "(0 to 2380.9 N) with Fr = 1189.9 N.",
    ),
    (
        r"seed_a_fig8c_temperatures_vs_radial_load",
        "Seed A Fig. 8c: node temperatures at 6500 rpm against the radial load "
        "(0 to 1189.9 N) with Fa = 2380.9 N.",
    ),
    (
        r"seed_a_deformations_vs_speed",
        "Seed A, detail of Fig. 10: the thermal parts of the 6208's deformation "
        "against speed at the 100 N m case (radial and axial groove-centre "
        "offsets, ball growth) beside the centrifugal ring expansion.",
    ),
    (
        r"seed_a_fig10_deformations",
        "Seed A Fig. 10: (a) axial and (b) radial deformation of the 6208 against "
        "speed at the 100 N m case (300 N preload): the part under load, the "
        "centrifugal and thermal parts and the combined deformation u_a-all, "
        "u_r-all. The axial thermal part is small against the load part; the "
        "radial one is of the size of the load part.",
    ),
    (
        r"seed_a_fig13_mesh_stiffness",
        "Seed A Fig. 13: time-varying mesh stiffness of the first gear pair: "
        "the stiffness of each tooth pair as it approaches, passes the pitch "
        "point and recesses (tooth pairs 1 to 11, one mesh period apart) and "
        "their parallel sum, potential-energy tooth model.",
    ),
    (
        r"seed_a_fig11_(?P<dir>radial|axial)_stiffness_three_cases",
        "Seed A Fig. 11: {dir} stiffness of the 6208 against speed for the three "
        "cases (constant, speed-dependent without thermal effects, thermally "
        "coupled), 100 N m, 6500 to 16,500 rpm.",
    ),
    (
        r"seed_a_fig1[45][abc]_bifurcation_100_n_m_(?P<case>constant|speed|thermal)_(?P<d>up|down)",
        "Seed A Fig. {fig}: bifurcation diagram of the helical pair's dynamic "
        "transmission error (Poincare section once per mesh period) against "
        "speed at the paper's 100 N m, {case_text}, {d_text}.",
    ),
    (
        r"bifurcation_light_(?P<case>constant|speed|thermal)_(?P<d>up|down)",
        "Seed A model at a light, strongly excited point (20 N m, transmission "
        "error 10 um) where the teeth separate: bifurcation diagram, "
        "{case_text}, {d_text}. Companion of seed A Fig. {fig}, not in the paper.",
    ),
    (
        r"regime_map_te(?P<te>[0-9.]+)um",
        "Seed A gear pair: motion regime (period-1, period-n, quasi-periodic, "
        "chaotic; impacts) over input torque and speed, transmission-error "
        "amplitude {te} um, constant bearing stiffness. Not in the paper: a map "
        "of where the drive runs smoothly.",
    ),
    (
        r"seed_b_radial_stiffness",
        "Seed B: radial stiffness of a single 7009C hybrid bearing against speed "
        "at 300, 400 and 500 N preload, without thermal effects (compare the "
        "uncoupled panel, Fig. 12a).",
    ),
    (
        r"seed_b_contact_angles",
        "Seed B: inner and outer contact angles of a single 7009C hybrid "
        "bearing against speed, 300 N preload, without thermal effects "
        "(compare Fig. 13a).",
    ),
    (
        r"seed_b_fig02_convection_coefficients",
        "Seed B Fig. 2: film coefficients of the spindle network's convection "
        "boundaries against speed (bearing oil-air films, rotor-stator air gap, "
        "shaft end in air; natural convection of the housing and the water "
        "jacket, constant, beside them). Table 1 is their values at 12,000 rpm.",
    ),
    (
        r"seed_b_fig03_temperature_field",
        "Seed B Fig. 3: node temperatures of the spindle network at 12,000 rpm, "
        "400 N, drawn on a schematic half cross-section; each region is one "
        "lumped node at one temperature, not a finite-element field.",
    ),
    (
        r"seed_b_fig04_transient",
        "Seed B Fig. 4: transient temperatures of the balls, inner and outer "
        "rings of the front (solid) and rear (dashed) bearings from ambient at "
        "12,000 rpm, 400 N spring preload (seed B: near-steady after about 21 min).",
    ),
    (
        r"seed_b_fig05_temperatures_vs_speed",
        "Seed B Fig. 5: steady temperatures of balls, inner and outer rings of "
        "the front (solid) and rear (dashed) bearings against speed, 400 N.",
    ),
    (
        r"seed_b_fig06_ball_temperature_vs_preload",
        "Seed B Fig. 6: ball temperature of the front and rear bearings against "
        "preload, one colour per speed.",
    ),
    (
        r"seed_b_fig08_thermal_displacement",
        "Seed B Fig. 8: (a) radial thermal displacement and (b) axial groove-centre "
        "offset of the front and rear bearings against speed, Si3N4 against steel "
        "balls (seed B: 8.2 against 16.68 um radial at 18,000 rpm).",
    ),
    (
        r"seed_b_fig12_radial_stiffness",
        "Seed B Fig. 12: radial stiffness of the front pair against speed at 300, "
        "400 and 500 N, (a) uncoupled and (b) with thermal displacement.",
    ),
    (
        r"seed_b_fig13_contact_angles",
        "Seed B Fig. 13: (a) inner and outer contact angles of the front bearing "
        "against speed by preload, uncoupled; (b) at 400 N, uncoupled against "
        "thermally coupled.",
    ),
    (
        r"seed_b_fig14_contact_loads",
        "Seed B Fig. 14: largest contact loads of the front bearing against "
        "speed: (a) by preload, uncoupled; (b) 400 N, uncoupled against coupled; "
        "(c) outer and (d) inner ring by preload, coupled and uncoupled.",
    ),
    (
        r"seed_b_fig15_radial_displacement",
        "Seed B Fig. 15: (a) radial thermal displacement of the front bearing "
        "against speed by preload; (b) radial displacement under the assumed "
        "working load without thermal displacement against preload at 12,000 rpm.",
    ),
    (
        r"seed_b_fig16_optimal_preload",
        "Seed B Fig. 16: total radial displacement (load plus thermal) "
        "against preload at 12,000, 15,000 and 18,000 rpm under an assumed "
        "working load at the nose; the minimum is the optimal preload.",
    ),
    (
        r"seed_b_fig17_compensation",
        "Seed B Fig. 17: compensation preload, the extra spring force from the "
        "spindle's axial thermal growth, at 12,000, 15,000 and 18,000 rpm "
        "(seed B: 17.92/26.40/35.38 um give 6.45/9.50/12.74 N).",
    ),
    (
        r"seed_b_fig19_outer_ring_vs_measurement",
        "Seed B Fig. 19: outer-ring temperatures of the front and rear bearings, "
        "(a) against time at 12,000 rpm and (b) against speed, simulated, with "
        "the two measured values seed B quotes (33.7 and 30.1 C).",
    ),
    (
        r"seed_b_campbell",
        "Seed B spindle: Campbell diagram (whirl frequencies of the lowest modes "
        "against speed, forward and backward) on bearing rows from the bearing "
        "solver at 400 N preload. Not a figure of the paper.",
    ),
    (
        r"seed_b_fig21_vibration_vs_speed",
        "Seed B Fig. 21 counterpart: RMS shaft-end vibration velocity against "
        "speed, ceramic and steel spindles, uncoupled and thermally coupled, for "
        "an ISO 21940 G2.5 residual unbalance (seed B does not state its "
        "excitation, so the levels are not comparable, only the trends).",
    ),
    (
        r"seed_b_fig20_spectrum_12000rpm",
        "Seed B Fig. 20 counterpart: velocity spectrum at the tool nose at "
        "12,000 rpm from a time response with nonlinear ball forces (1X at "
        "200 Hz): (a) under the unbalance alone; (b) with the unbalanced "
        "magnetic pull of an eccentric rotor on, the cause seed B gives for "
        "its measured spectrum's excess at 1X and scatter near 2X (the "
        "measured spectrum itself is not given as numbers).",
    ),
    (
        r"diagnose_fit_(?P<q>.+)",
        "Synthetic diagnosis (7008C, 300 N, hidden ball drag in the oil-air "
        "mixture): measured {q} against the baseline model and the model with "
        "the accepted candidate.",
    ),
    (
        r"diagnose_residuals",
        "Synthetic diagnosis: residuals over sigma against speed per quantity, "
        "before and after the accepted candidate.",
    ),
    (
        r"diagnose_seed_b_fit_(?P<i>\d+)",
        "Seed B's quoted measurements (outer-ring temperatures at 12,000 rpm, "
        "shaft-end vibration at 18,000 rpm) against the spindle model without "
        "thermal displacement: measured against model, quantity {i1}.",
    ),
    (
        r"diagnose_seed_b_residuals",
        "Seed B's quoted measurements: residuals over sigma of the model "
        "without thermal displacement.",
    ),
    (
        r"diagnose_seed_b_synthetic_fit",
        "Seed B spindle, synthetic: data from the model with thermal "
        "displacement diagnosed from the model without it; measured axial "
        "growth against the model before and after.",
    ),
    (
        r"diagnose_seed_b_synthetic_residuals",
        "Seed B spindle, synthetic: residuals over sigma before and after the accepted candidate.",
    ),
    (
        r"diagnose_seed_b_temperatures",
        "Seed B Fig. 19b counterpart: front and rear outer-ring temperatures "
        "against speed, model with and without thermal displacement, with seed "
        "B's measured values.",
    ),
    (
        r"diagnose_seed_b_vibration",
        "Seed B Fig. 21 counterpart: shaft-end velocity RMS against speed, model "
        "with and without thermal displacement, seed B's measurement and its two "
        "simulated values at 18,000 rpm.",
    ),
    (
        r"rig_to_prediction_rig_(?P<q>To|axial)",
        "From rig to prediction, seed A: the rig's measured {q} points with one-sigma "
        "bars against the calibrated model with its 95 % band, measured speeds shaded, "
        "extrapolated to 16,500 rpm.",
    ),
    (
        r"rig_to_prediction_stiffness",
        "From rig to prediction, seed A: the thermal radial stiffness k_xx of the "
        "calibrated 6208 over seed A's speed range with its 95 % band and the truth "
        "the rig data were made with; the band widens toward the top speed.",
    ),
    (
        r"rig_to_prediction_bifurcation",
        "From rig to prediction, seed A: bifurcation diagram of the seed gear pair "
        "(20 N m, TE 10 um, run-down) on the calibrated bearings, the regime "
        "boundaries crossed by at least half the samples shaded with their 95 % "
        "intervals.",
    ),
    (
        r"rig_to_prediction_regimes",
        "From rig to prediction, seed A: probability of each gear regime against "
        "speed under the calibrated bearing's uncertainty.",
    ),
    (
        r"rig_to_prediction_seed_b_(?P<q>To|growth)",
        "From rig to prediction, seed B: the spindle calibrated on its two measured "
        "outer-ring temperatures; predicted {q} against speed with the 95 % band and "
        "the value seed B reports.",
    ),
]


def caption_for(stem: str, folder: str) -> str:
    """The caption of one figure (its file stem, its study folder)."""
    for pattern, text in CAPTIONS:
        m = re.fullmatch(pattern, stem)
        if m is None:
            continue
        g = m.groupdict()
        extra = {}
        if "case" in g:
            extra["case_text"] = _CASE[g["case"]]
        if "d" in g:
            extra["d_text"] = _DIRECTION[g["d"]]
            letter = {"constant": "a", "speed": "b", "thermal": "c"}[g["case"]]
            extra["fig"] = ("14" if g["d"] == "up" else "15") + letter
        if "i" in g:
            extra["i1"] = str(int(g["i"]) + 1)
        return text.format(**g, **extra)
    words = stem.replace("_", " ")
    return f"Figure `{stem}.png` written by the demo study `{folder}` ({words})."


_demo_dir: Path | None = None
_temp_dir: str | None = None


def _run_quick_demo() -> Path:
    global _temp_dir
    _temp_dir = tempfile.mkdtemp(prefix="thermobear-docs-demo-")
    out = Path(_temp_dir) / "out"
    cmd = [sys.executable, "-m", "thermobear", "demo", "--quick", "--out", str(out)]
    log.info("gallery: no demo output found, running %s", " ".join(cmd))
    try:
        res = subprocess.run(cmd, cwd=_temp_dir, capture_output=True, text=True, check=False)
    except OSError as e:
        raise PluginError(f"gallery: could not run {' '.join(cmd)}: {e}") from e
    if res.returncode != 0:
        raise PluginError(
            f"gallery: '{' '.join(cmd)}' failed with exit code {res.returncode}:\n"
            f"{res.stdout[-2000:]}\n{res.stderr[-4000:]}"
        )
    return out


def _find_demo_dir(config) -> Path:
    env = os.environ.get("THERMOBEAR_DEMO_OUT")
    if env:
        p = Path(env).expanduser().resolve()
        if not p.is_dir():
            raise PluginError(f"gallery: THERMOBEAR_DEMO_OUT={env} is not a folder")
        return p
    root = Path(config.config_file_path).resolve().parent
    default = root / "thermobear-out"
    if default.is_dir():
        return default
    return _run_quick_demo()


def _figures(demo: Path) -> dict[str, list[Path]]:
    """PNGs by study folder (top-level PNGs under "")."""
    found: dict[str, list[Path]] = {}
    for png in sorted(demo.rglob("*.png")):
        rel = png.relative_to(demo)
        folder = rel.parts[0] if len(rel.parts) > 1 else ""
        found.setdefault(folder, []).append(png)
    return found


def _pages(found: dict[str, list[Path]]) -> list[tuple[str, str, str, list[str]]]:
    """The pages to write: the known ones with figures, then one per unknown folder."""
    pages = [p for p in PAGES if any(found.get(f) for f in p[3])]
    known = {f for p in PAGES for f in p[3]}
    for folder in sorted(set(found) - known):
        name = folder or "other"
        title = "Other figures" if not folder else f"Study {folder}"
        intro = f"Figures of the demo study `{folder}`." if folder else "Further figures."
        pages.append((re.sub(r"[^a-z0-9]+", "-", name.lower()).strip("-"), title, intro, [folder]))
    return pages


def on_config(config):
    global _demo_dir
    if _demo_dir is None:
        _demo_dir = _find_demo_dir(config)
    found = _figures(_demo_dir)
    if not found:
        raise PluginError(f"gallery: no PNG figures in {_demo_dir}")
    # Replace the "Gallery" entry of the nav by the generated pages.
    section = [{"Overview": "gallery/index.md"}] + [
        {title: f"gallery/{stem}.md"} for stem, title, _, _ in _pages(found)
    ]
    nav = config.nav or []
    for i, entry in enumerate(nav):
        if isinstance(entry, dict) and "Gallery" in entry:
            nav[i] = {"Gallery": section}
    return config


def _page_text(title: str, intro: str, folders: list[str], found, images) -> str:
    lines = [f"# {title}", "", intro, ""]
    for folder in folders:
        for png in found.get(folder, []):
            rel = images[png]
            cap = caption_for(png.stem, folder)
            lines += [
                f"## {png.stem.replace('_', ' ')}",
                "",
                f"![{png.stem}]({rel})",
                "",
                f"*{cap}*",
                "",
            ]
    return "\n".join(lines)


def on_files(files, config):
    assert _demo_dir is not None
    found = _figures(_demo_dir)
    images: dict[Path, str] = {}
    for folder, pngs in found.items():
        for png in pngs:
            uri = "gallery/img/" + (f"{folder}/" if folder else "") + png.name
            files.append(File.generated(config, uri, abs_src_path=str(png)))
            images[png] = uri.removeprefix("gallery/")
    pages = _pages(found)
    n = sum(len(v) for v in found.values())
    index = [
        "# Gallery",
        "",
        "Figures of the seed studies as `thermobear demo` draws them "
        f"({n} figures, from the demo output this site was built with; "
        "`thermobear demo --quick` draws coarser sweeps). "
        "Regenerate them with `thermobear demo` and rebuild the site; "
        "each figure's data is written beside it as parquet and CSV.",
        "",
        "| page | figures |",
        "| --- | --- |",
    ]
    for stem, title, intro, folders in pages:
        k = sum(len(found.get(f, [])) for f in folders)
        index.append(f"| [{title}]({stem}.md) | {k} |")
        files.append(
            File.generated(
                config,
                f"gallery/{stem}.md",
                content=_page_text(title, intro, folders, found, images),
            )
        )
    index += [
        "",
        "Where a caption names a figure of a paper, the paper is seed A "
        "(Liu, Liu & Hu, *Sensors* 2021, 21, 309, CC BY 4.0) or seed B "
        "(*Dynamic and thermal coupling model of a ceramic motorized spindle*); "
        "see [Physics](../concepts/physics.md) for the models and "
        "[§8](../concepts/physics.md#8-data-notes) for the data the papers "
        "leave out.",
        "",
    ]
    files.append(File.generated(config, "gallery/index.md", content="\n".join(index)))
    return files


def on_shutdown():
    global _temp_dir, _demo_dir
    if _temp_dir is not None:
        shutil.rmtree(_temp_dir, ignore_errors=True)
        _temp_dir = None
        _demo_dir = None

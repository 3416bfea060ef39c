"""Fit of V_M, the coefficient of the SKF oil-bath drag moment
M_drag = V_M K_ball dm^5 n^2, at the reference oil level (the middle of the
lowest ball), on the SKF 62-series reference-speed set.

The catalogue gives V_M only as a diagram against H/dm, which could not be
read; so V_M is fitted here. At a reference speed the catalogue bearing's
friction heat equals the ISO 15312 reference heat flow Phi_r; the SKF-style
rolling and sliding moments of thermobear are evaluated there
(``heat_model="skf"``, oil bath, ISO VG 32 at 12 mm^2/s) without drag, and
with the bath drag at V_M = the value in the code; the drag is linear in
V_M, so the weighted least-squares V_M on the set's calibration bearings is
closed-form. The held-out bearings are scored with it. Run:
``python validation/bath_drag_fit.py`` (writes validation/bath_drag_fit.md).
"""

from __future__ import annotations

import pathlib
import tomllib

import numpy as np

import thermobear as tb
from thermobear.validation import reference_speed as rs

HERE = pathlib.Path(__file__).parent
DATA = HERE.parent / "python" / "thermobear" / "validation" / "data" / "skf_reference_speed_62.toml"
VM_IN_CODE = 4.28e-6  # SKF_BATH_DRAG_VM_REFERENCE when this fit was run


def main() -> None:
    data = tomllib.loads(DATA.read_text())
    pts = rs.reference_points(data)
    oil_c = rs.oil_temperature_for(data["conditions"]["oil"], data["conditions"]["viscosity_cst"])
    bearings = {b["name"]: rs.catalogue_deep_groove(b) for b in data["bearings"]}
    base, drag = [], []
    for p in pts.iter_rows(named=True):
        kw = dict(oil_temperature_c=oil_c, lubricant=data["conditions"]["oil"], heat_model="skf")
        b = bearings[p["bearing"]]
        h0 = tb.isothermal_heat(b, p["speed_rpm"], 0.0, p["radial_n"], lubrication="oil-bath",
                                churning_oil_fraction=0.0, **kw)  # fmt: skip
        h1 = tb.isothermal_heat(b, p["speed_rpm"], 0.0, p["radial_n"], lubrication="oil-bath", **kw)
        base.append(h0.total_heat_w)
        drag.append(h1.raw["drag_heat_w"] / VM_IN_CODE)
    y, s = pts["value"].to_numpy(), pts["sigma"].to_numpy()
    base, drag = np.array(base), np.array(drag)
    cal = np.isin(pts["bearing"].to_numpy(), data["calibration"]["calibrate_on"])
    w = 1.0 / s[cal] ** 2
    vm = float(np.sum(w * drag[cal] * (y[cal] - base[cal])) / np.sum(w * drag[cal] ** 2))
    model = base + vm * drag
    z = (model - y) / s
    lines = [
        "# V_M of the SKF oil-bath drag, fitted on the SKF 62-series reference-speed set",
        "",
        "Written by `python validation/bath_drag_fit.py` (see its docstring for the method).",
        "The catalogue's V_M diagram could not be read; this fit stands in for it.",
        "",
        f"Fitted on: {', '.join(data['calibration']['calibrate_on'])}",
        f"**V_M (reference level, oil to the middle of the lowest ball) = {vm:.4g}**",
        "",
        "| bearing | n_ref rpm | Phi_r W | SKF moments W | bath drag W | model / Phi_r | z "
        "| held out |",
        "| --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for i, p in enumerate(pts.iter_rows(named=True)):
        lines.append(
            f"| {p['bearing']} | {p['speed_rpm']:.0f} | {y[i]:.1f} | {base[i]:.1f} | "
            f"{vm * drag[i]:.1f} | {model[i] / y[i]:.2f} | {z[i]:+.2f} | "
            f"{'' if cal[i] else 'yes'} |"
        )
    held = z[~cal]
    lines += [
        "",
        f"Held-out bearings: rms z = {np.sqrt(np.mean(held**2)):.2f}, max |z| = "
        f"{np.abs(held).max():.2f} ({int((np.abs(held) > 2).sum())} of {held.size} "
        "beyond 2 sigma); "
        f"model/catalogue {np.min(model[~cal] / y[~cal]):.2f}-{np.max(model[~cal] / y[~cal]):.2f}.",
    ]
    (HERE / "bath_drag_fit.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()

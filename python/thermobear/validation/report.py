"""The validation report: one markdown file with a section per set and a
figure per set (published value vs model before/after calibration, in units
of the point's sigma)."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from .result import SetResult

if TYPE_CHECKING:
    import polars


def _figure(r: SetResult, out: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    import numpy as np

    p = r.points
    z0 = (p["model_before"] - p["value"]).to_numpy() / p["sigma"].to_numpy()
    z1 = (p["model_after"] - p["value"]).to_numpy() / p["sigma"].to_numpy()
    x = np.arange(p.height)
    fig, ax = plt.subplots(figsize=(7.5, 3.2 + 0.15 * min(p.height, 80)))
    ax.barh(x - 0.2, np.clip(z0, -50, 50), 0.4, label="baseline")
    ax.barh(x + 0.2, np.clip(z1, -50, 50), 0.4, label="after calibration")
    held = p["heldout"].to_numpy()
    every = max(1, p.height // 80)  # at most about 80 labels on a large set
    ax.set_yticks(
        x[::every],
        [f"{lab}{' (held out)' if h else ''}" for lab, h in zip(p["label"], held, strict=True)][
            ::every
        ],
        fontsize=8 if every == 1 else 5,
    )
    ax.axvspan(-2, 2, color="0.9", zorder=0, label="within 2 sigma")
    ax.set_xlabel("(model - published) / sigma (clipped at +-50)")
    ax.set_title(r.name)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = out / f"{r.name}.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def _md_table(df: polars.DataFrame) -> list[str]:
    cols = df.columns
    lines = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    for row in df.iter_rows():
        cells = [f"{v:.4g}" if isinstance(v, float) else str(v).replace("|", "/") for v in row]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def _section(r: SetResult, fig: Path) -> list[str]:
    status = "PASS" if r.passes else "NOT PASSED"
    lines = [f"## {r.name}: {r.title}", "", f"Source: {r.source}", ""]
    lines += [f"**Status: {status}** ({r.seconds:.1f} s). {r.holdout}.", ""]
    lines += [f"- baseline: worst point {r.baseline_max_sigma:.3g} sigma"]
    lines += [f"- verdict: {r.verdict}"]
    for c in r.calibrated:
        lines.append(
            f"- calibrated {c['name']} = {c['value']:.4g} {c['unit']} "
            f"(bounds {c['lower']:.4g}..{c['upper']:.4g})"
        )
    lines += [
        f"- held-out error, calibrated without the held-out points: worst "
        f"{r.heldout_max_sigma_after:.3g} sigma"
    ]
    lines += [f"  - under {k}: {v:.3g} sigma" for k, v in r.heldout_by_explanation.items()]
    if r.missing:
        lines += [f"- what is missing: {r.missing}"]
    lines += ["", f"![{r.name}]({fig.name})", ""]
    names = ("label", "origin", "value", "sigma", "model_before", "model_after", "heldout")
    cols = [c for c in names if c in r.points.columns]
    lines += _md_table(r.points.select(cols)) + [""]
    for name, t in r.tables.items():
        if t is not None and t.height:
            lines += [f"### {name}", ""] + _md_table(t) + [""]
    for n in r.notes:
        lines += ["```" if "\n" in n else "", n, "```" if "\n" in n else "", ""]
    return lines


def write_report(results: list[SetResult], out: Path) -> list[Path]:
    """``validation.md`` and one PNG per set in ``out``; returns the paths."""
    out.mkdir(parents=True, exist_ok=True)
    files, lines = [], ["# thermobear validation against published data", ""]
    lines += ["| set | status | baseline worst (sigma) | held-out after (sigma) | verdict |"]
    lines += ["|---|---|---|---|---|"]
    for r in results:
        lines.append(
            f"| {r.name} | {'PASS' if r.passes else 'NOT PASSED'} | "
            f"{r.baseline_max_sigma:.3g} | {r.heldout_max_sigma_after:.3g} | "
            + r.verdict.replace("|", "/")
            + " |"
        )
    lines.append("")
    for r in results:
        fig = _figure(r, out)
        files.append(fig)
        lines += _section(r, fig)
    md = out / "validation.md"
    md.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return [md] + files

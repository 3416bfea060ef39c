"""Step 5 of :func:`thermobear.diagnose`: the verdict in words."""

from __future__ import annotations


def _unit(u: str) -> str:
    return "" if u == "1" else f" {u}"


def _verdict_part(a: dict) -> str:
    """One accepted candidate in words, by its role."""
    u = _unit(a["unit"])
    if a["lower_95"] is None:
        interval = ""
    else:
        interval = f"95 % [{a['lower_95']:.4g}, {a['upper_95']:.4g}]"
    if a["role"] == "measurement":
        return f"measurement-side {a['name']} = {a['value']:.4g}{u} ({interval})"
    if a["role"] == "calibration":
        return (
            f"miscalibrated baseline parameter {a['name']}: {a['parameter']} = "
            f"{a['value']:.4g}{u} (baseline {a['null']:.4g}{u}; {interval})"
            if interval
            else f"miscalibrated baseline setting {a['name']}"
        )
    return f"missing effect {a['name']}" + (
        f" ({a['parameter']} = {a['value']:.4g}{u}, {interval})" if interval else ""
    )


def verdict_text(accepted: list, tie: list, p_final: float) -> str:
    """The verdict: the accepted candidates in words (:func:`_verdict_part`)
    and a tie set; without either, "structured residual not explained by
    any known effect" when the final training residual fails the chi^2 test
    at 1 % (``p_final`` < 0.01), else "no missing effect supported"."""
    parts = [_verdict_part(a) for a in accepted]
    if tie:
        parts.append("tie: " + " | ".join(tie) + " (the data cannot tell them apart)")
    if parts:
        return "; ".join(parts)
    if p_final < 0.01:
        return "structured residual not explained by any known effect"
    return "no missing effect supported"

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


def unresolved_text(records: list, gain: float, ctrl) -> str:
    """The verdict when the generic control explains the data as well as
    the candidates the rounds would accept (``records``, delta-BIC ``gain``
    together)."""
    names = " + ".join(a["name"] for a in records)
    return (
        f"unresolved: the data cannot tell a known effect ({names}, delta-BIC {gain:.1f}) "
        f"from an unknown smooth one ({ctrl.label}, delta-BIC {ctrl.delta_bic:.1f})"
    )


def verdict_text(accepted: list, tie: list, p_final: float, unresolved=None, outliers=None) -> str:
    """The verdict: the accepted candidates in words (:func:`_verdict_part`)
    and a tie set, or the unresolved comparison with the generic control
    (:func:`unresolved_text`); without any, "structured residual not
    explained by any known effect" when the final residual fails the chi^2
    test at 1 % (``p_final`` < 0.01), else "no missing effect supported".
    Outliers left out (``outliers``: their table) close the verdict."""
    parts = [_verdict_part(a) for a in accepted]
    if unresolved is not None:
        parts.append(unresolved_text(*unresolved))
    if tie:
        names = [n if n != "generic_control" else "an unknown smooth effect" for n in tie]
        parts.append("tie: " + " | ".join(names) + " (the data cannot tell them apart)")
    if not parts:
        parts.append(
            "structured residual not explained by any known effect"
            if p_final < 0.01
            else "no missing effect supported"
        )
    if outliers is not None and outliers.height:
        from .outliers import outlier_words

        parts.append(outlier_words(outliers))
    return "; ".join(parts)

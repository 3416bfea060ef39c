"""Step 5 of [`thermobear.diagnose`][thermobear.diagnose]: the verdict in words."""

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


def unresolved_text(records: list, gain: float, ctrl, chi2_named=None, k_named=None) -> str:
    """The verdict when the generic control explains the data as well as
    the candidates the rounds would accept (``records``, delta-BIC ``gain``
    together; chi^2 ``chi2_named`` with ``k_named`` parameters; records
    marked ``alternative``: other candidates that explain the data as well,
    listed after "or")."""
    names = " + ".join(a["name"] for a in records if not a.get("alternative"))
    others = [a["name"] for a in records if a.get("alternative")]
    fit_n = "" if chi2_named is None else f", chi^2 {chi2_named:.1f} with {k_named} parameter(s)"
    fit_c = "" if chi2_named is None else f", chi^2 {ctrl.chi2:.1f} with {ctrl.n_parameters}"
    alt = "".join(f"; or {n}" for n in others)
    return (
        f"unresolved: the data cannot tell a known effect ({names}, delta-BIC {gain:.1f}"
        f"{fit_n}{alt}) from an unknown smooth one ({ctrl.label}, delta-BIC "
        f"{ctrl.delta_bic:.1f}{fit_c})"
    )


def verdict_text(
    accepted: list, tie: list, p_final: float, unresolved=None, outliers=None, unexplained: str = ""
) -> str:
    """The verdict: the accepted candidates in words (``_verdict_part``)
    and a tie set, or the unresolved comparison with the generic control
    (``unresolved_text``); without any, "structured residual not
    explained by any known effect" when the final residual fails the chi^2
    test at 1 % (``p_final`` < 0.01), else "no missing effect supported".
    ``unexplained``: the words of a best named fit still far above noise
    (``thermobear.diagnosis.plausible_data.unexplained_words``: "not
    explained by any known effect", its chi^2 and the likely causes),
    after what was found, or after "structured residual" when nothing was.
    Outliers left out (``outliers``: their table) close the verdict."""
    parts = [_verdict_part(a) for a in accepted]
    if unresolved is not None:
        parts.append(unresolved_text(*unresolved))
    if tie:
        names = [n if n != "generic_control" else "an unknown smooth effect" for n in tie]
        parts.append("tie: " + " | ".join(names) + " (the data cannot tell them apart)")
    if parts and unexplained:
        parts.append(unexplained)
    if not parts:
        parts.append(
            f"structured residual {unexplained}"
            if unexplained
            else "structured residual not explained by any known effect"
            if p_final < 0.01
            else "no missing effect supported"
        )
    if outliers is not None and outliers.height:
        from .outliers import outlier_words

        parts.append(outlier_words(outliers))
    return "; ".join(parts)

"""The generic control of the screening: an unknown smooth effect per
measured quantity, ``a x + b x^2`` with ``x`` the speed over the highest
measured speed (zero at standstill, like every speed-driven effect; two
parameters per quantity). It is never a verdict of its own: when it explains
the data as well as the best named candidate (``matching_control``),
the data cannot tell the known effect from an unknown one, and the verdict
says so instead of naming it.

Beside the per-quantity terms, a *carrier* control: an additive input of
the model (``CARRIERS``, e.g. the extra heat at the bearing) given a
free smooth speed law ``h(x) = a x + b x^2``, acting through the model's
own sensitivity of every row to that input (linearised at the setting:
``dm_i = S_i h(x_i)``) -- an unknown heat source, seen by every quantity
the way heat is, with two parameters for all of them.

The rules (``matching_control``): the per-quantity control matches by
BIC (only parsimony can favour a named effect over two free parameters per
quantity); a carrier matches unless the named set's chi^2 is lower than
its own by more than ``CARRIER_LEAD`` (the fit decides, not BIC's
charge for the carrier's one extra parameter)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Parameters of the generic term of one quantity (and of a carrier's law).
GENERIC_PARAMETERS = 2

#: How far below the named candidates' delta-BIC the control may stay and
#: still match them: 0 -- it must explain the data at least as well after
#: BIC's charge for its extra parameters. (A named effect the control nests,
#: e.g. a probe runout ~ speed on one quantity, is then called unresolved
#: only when noise gives the control's extra parameter more than ln n of
#: chi^2: about 4 % of data sets for n ~ 50.)
CONTROL_MARGIN = 0.0

#: Additive model inputs that carry the carrier control (see the module
#: docstring): candidate names; a model whose candidates have none of them
#: has only the per-quantity control.
CARRIERS = ("extra_heat_w",)

#: The lead in chi^2 a named set needs over a carrier control to be told
#: from an unknown source (``matching_control``): the 95 % quantile of
#: chi^2 with one degree of freedom. Were the unknown source the truth,
#: the named set's chi^2 lead over it would have mean about -D^2 - 1 and
#: standard deviation about sqrt(4 D^2 + 2) (D: the distance of the two
#: fits in sigma; the carrier fits one noise direction more); it exceeds
#: 3.84 in at most about 2 % of data sets, whatever D and however the
#: named direction leans out of the carrier's (largest at small D).
CARRIER_LEAD = 3.841


@dataclass(frozen=True)
class GenericControl:
    """The generic control fitted to a residual: the quantities whose term
    lowers BIC (``quantities``), its total delta-BIC against the setting
    (the sum over those quantities), its parameter count, chi^2 after it
    and its prediction shift (value units) of every row."""

    quantities: tuple[str, ...]
    delta_bic: float
    n_parameters: int
    chi2: float
    shift: np.ndarray
    label: str = ""
    carrier: str = ""


def generic_control(data, pred: np.ndarray, carriers=None) -> GenericControl:
    """The better of the per-quantity control (``quantity_control``)
    and each carrier control (``carrier_control``; ``carriers``: name ->
    d prediction / d input of every row)."""
    best = quantity_control(data, pred)
    for name, slope in (carriers or {}).items():
        c = carrier_control(data, pred, name, slope)
        if c.delta_bic > best.delta_bic:
            best = c
    return best


def _speed_fraction(data) -> np.ndarray:
    sp = data.cond["speed_rpm"].to_numpy()
    top = float(sp.max()) if sp.max() > 0 else 1.0
    return sp / top


def quantity_control(data, pred: np.ndarray) -> GenericControl:
    """The generic smooth term fitted by linear least squares, quantity by
    quantity, to the residual of ``pred``; a quantity's term is kept when it
    lowers BIC (delta chi^2 > 2 ln n). The quantities act on disjoint rows,
    so the best combination is the union of the terms each worth keeping."""
    x = _speed_fraction(data)
    r = data.residual(pred)
    n = data.n
    shift = np.zeros(n)
    kept, dbic = [], 0.0
    for q in sorted(set(data.quantity.tolist())):
        rows = data.quantity == q
        if rows.sum() <= GENERIC_PARAMETERS:
            continue
        a = np.column_stack([x[rows], x[rows] ** 2]) / data.s[rows, None]
        coef, *_ = np.linalg.lstsq(a, r[rows], rcond=None)
        gain = float(r[rows] @ r[rows] - np.sum((r[rows] - a @ coef) ** 2))
        d = gain - GENERIC_PARAMETERS * np.log(n)
        if d > 0.0:
            kept.append(q)
            dbic += d
            shift[rows] = np.column_stack([x[rows], x[rows] ** 2]) @ coef
    chi2 = float(np.sum((r - shift / data.s) ** 2))
    label = "a generic term in speed on " + ", ".join(kept)
    return GenericControl(tuple(kept), dbic, GENERIC_PARAMETERS * len(kept), chi2, shift, label)


def carrier_control(data, pred: np.ndarray, name: str, slope: np.ndarray) -> GenericControl:
    """The carrier control of input ``name``: its smooth speed law fitted by
    linear least squares to the residual of ``pred`` through the rows'
    sensitivities ``slope``."""
    x = _speed_fraction(data)
    r = data.residual(pred)
    cols = np.column_stack([slope * x, slope * x**2])
    a = cols / data.s[:, None]
    coef, *_ = np.linalg.lstsq(a, r, rcond=None)
    chi2 = float(np.sum((r - a @ coef) ** 2))
    dbic = float(r @ r) - chi2 - GENERIC_PARAMETERS * np.log(data.n)
    quantities = tuple(sorted({q for q, g in zip(data.quantity, slope, strict=True) if g != 0}))
    label = f"an unknown source like {name} with its own smooth speed law"
    return GenericControl(quantities, dbic, GENERIC_PARAMETERS, chi2, cols @ coef, label, name)


def control_row(ctrl: GenericControl, chi_base: float) -> dict:
    """The control's row in the screening table (never passes: it is not a
    verdict)."""
    return {
        "candidate": "generic_control",
        "kind": "control",
        "side": "model",
        "value": float(len(ctrl.quantities)),
        "lower_95": None,
        "upper_95": None,
        "null": 0.0,
        "at_bound": False,
        "chi2": ctrl.chi2,
        "n_parameters": ctrl.n_parameters,
        "delta_bic": ctrl.delta_bic,
        "delta_aicc": None,
        "cv_chi2_before": chi_base,
        "cv_chi2_after": None,
        "cv_folds": None,
        "heldout_chi2_before": None,
        "heldout_chi2_after": None,
        "passes": False,
    }


def control_matches(ctrl: GenericControl, best: dict, margin: float) -> bool:
    """Whether the generic control explains the data as well as the best
    named candidate: its delta-BIC no more than ``margin`` below."""
    return ctrl.delta_bic > 0.0 and ctrl.delta_bic >= best["delta_bic"] - margin


def carrier_lead_needed(k_named: int) -> float:
    """The chi^2 lead a named set of ``k_named`` parameters needs over a
    carrier control (two parameters): ``CARRIER_LEAD``, plus one per
    parameter the named set has beyond the carrier's (each fits about one
    unit of chi^2 of noise)."""
    return CARRIER_LEAD + max(0, k_named - GENERIC_PARAMETERS)


def explains_as_well(ctrl: GenericControl, row: dict) -> bool:
    """Whether a named candidate (its screening row, against the same
    setting as ``ctrl``) explains the data about as well as the control
    that matched the accepted set: it passes the screening, does not sit at
    a bound, and the control's lead over it is within
    ``CARRIER_LEAD`` -- in chi^2 for a carrier control, in delta-BIC
    for the per-quantity control (its many parameters charged). Such
    candidates are listed beside the accepted ones in an "unresolved"
    verdict: the data cannot tell any of them from the unknown source."""
    if not row.get("passes") or row.get("at_bound"):
        return False
    if ctrl.label.startswith("a generic term"):
        return ctrl.delta_bic - row["delta_bic"] <= CARRIER_LEAD
    return row["chi2"] - ctrl.chi2 <= CARRIER_LEAD


def matching_control(data, pred0, chi2_named, k_named, carriers=None, margin=0.0):
    """The control that explains the data as well as a named set of
    ``k_named`` parameters whose fit from the setting ``pred0`` reaches
    ``chi2_named``, or None. Two rules, one per kind of control:

    * the per-quantity control (``quantity_control``; two parameters
      per quantity, flexible enough to absorb any smooth named effect one
      quantity at a time, so only parsimony can favour the named set):
      its delta-BIC no more than ``margin`` below the named set's;
    * a carrier control (``carrier_control``; an unknown source with
      its own speed law, nesting nearly every named term of the same kind
      whose speed law is smooth, one parameter more): the named set's
      chi^2 no lower than the carrier's by more than
      ``carrier_lead_needed`` -- the parameter the carrier pays in BIC
      is not counted in the named set's favour: the fit itself must be
      better by more than noise allows (or BIC as above).

    A control that does not itself lower BIC against the setting matches
    nothing."""
    n = data.n
    gain = float(np.sum(data.residual(pred0) ** 2)) - chi2_named - k_named * np.log(n)
    best = {"delta_bic": gain}
    pq = quantity_control(data, pred0)
    if control_matches(pq, best, margin):
        return pq
    for name, slope in (carriers or {}).items():
        c = carrier_control(data, pred0, name, slope)
        lead = c.chi2 - chi2_named
        if c.delta_bic > 0.0 and (
            control_matches(c, best, margin) or lead <= carrier_lead_needed(k_named)
        ):
            return c
    return None

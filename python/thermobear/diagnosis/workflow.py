"""Model-vs-measurement discrepancy workflow: find where the model
misses measured data, name the missing effect the data support, show the gap
shrink -- and refuse to name one the data cannot support.

Pipeline of [`diagnose`][thermobear.diagnose] (each step a function of its own module in
this package):

1. residual audit per quantity and speed band (mean residual/sigma, chi^2)
   and the residual's shape per quantity: polynomial bases in speed (none,
   offset, slope, growth = quadratic) and a local feature (offset + one
   point) compared by AIC = chi^2 + 2 k (Gaussian errors, known sigma);
2. identifiability: each candidate's fingerprint (its prediction change over
   sigma on the measured points, finite difference at the null value),
   pairwise cosine similarity, look-alike pairs (|cos| > 0.95) and the
   quantity/speed (on a speed grid over all supported quantities) where
   the two best-matched fingerprints differ most;
3. screening: each candidate added alone to the setting and calibrated
   within its bounds on all points, scored by BIC = chi^2 + k ln n (n: all
   points, k = 1 per candidate) and AICc, by the cross-validated chi^2
   (folds of operating cells: a speed at a load in a run), and, reported
   apart, by the extrapolation check (calibrated without the held-out
   points -- highest speeds or given runs -- and scored on them);
4. acceptance: delta-BIC >= 10 against the setting, the cross-validated
   chi^2 improved, the 95 % profile interval (chi^2 rise 3.84 phi, phi =
   max(1, reduced chi^2)) inside the bounds and excluding the null value,
   no rival in a tie (``thermobear.diagnosis.ties``: within delta-BIC 2, or a lead noise
   could produce; a rival at its bound is none). Accepted effects join the
   setting and the screening repeats while the residual fails the chi^2
   test at 1 %. Then the generic controls (``thermobear.diagnosis.control``) are compared
   with what was accepted (per-quantity control: by BIC; carrier control:
   the named set must fit better by more than 3.84 in chi^2), and the
   outlier audit (``thermobear.diagnosis.outliers``) runs on the best fit: flagged points
   are left out and the search runs again;
5. a verdict that says what each accepted candidate is: a missing effect
   (a registry switch or a term the baseline leaves out), a miscalibrated
   baseline input (f0, spin friction coefficient, cooling and ambient
   temperatures, housing material), or a measurement-side sensor offset;
   a tie set; "unresolved" (a known effect the data cannot tell from an
   unknown smooth one); "no missing effect supported"; or "structured
   residual not explained by any known effect" -- and the outliers left out;
6. the held-out gap before/after per quantity and speed band.

Model specs: [`BearingModelSpec`][thermobear.BearingModelSpec] (one bearing, quantities
``QUANTITIES``) and [`thermobear.SpindleModelSpec`][thermobear.SpindleModelSpec] (the seed B
spindle with its rotor) follow one protocol -- ``quantities``,
``candidate_list(quantities)``, ``predict(conditions)``,
``with_setting(add_effects, **options)``, ``options``, ``effects`` -- and
[`diagnose`][thermobear.diagnose] runs the same statistics on either.

Speed: every model configuration (effects + options + parameter value) is
evaluated once on the measured conditions and cached in the
[`BearingModelSpec`][thermobear.BearingModelSpec]; a parameter candidate is evaluated on a fixed
grid of values over its bounds and calibrated on a cubic interpolant of the
predictions, so re-diagnosing new noise on the same conditions costs no
model run.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Mapping, Optional, Sequence, Union

import numpy as np

from .. import _validate as val
from .acceptance import accepted_record, joint_refit, select
from .audit import audit
from .calibrated import diagnosis_model
from .candidates import Candidate, candidate_pool, split_evaluable
from .control import (
    CARRIERS,
    CONTROL_MARGIN,
    GenericControl,
    control_row,
    explains_as_well,
    generic_control,
    matching_control,
)
from .explain import (
    calibrated_without_heldout,
    explained_gap,
    explained_points,
    explained_predictions,
)
from .identifiability import identifiability
from .measurements import MeasuredData, prepare_measurements
from .outliers import flag_outliers, outlier_table
from .plausible_data import unexplained_words
from .protocol import ModelSpec, as_spec
from .result import Diagnosis
from .screening import candidate_curves, screen, screening_table
from .setting import _predict, _Setting
from .statistics import _chi2, noise_p_value
from .ties import significant_rivals, tie_gap, tie_table
from .verdict import verdict_text

if TYPE_CHECKING:
    import polars as pl

__all__ = ["diagnose"]

#: Passes of the outlier audit (flag, refit without, audit the refit once more).
_OUTLIER_PASSES = 2


@dataclass(frozen=True)
class _Rules:
    """The decision thresholds and switches of [`diagnose`][thermobear.diagnose]."""

    max_rounds: int
    delta_bic_min: float
    tie_delta_bic: float
    lookalike_cosine: float
    suggest: bool
    envelope: Optional[dict] = None
    control: bool = True


@dataclass
class _Search:
    """The state of the screening rounds: the setting reached (baseline plus
    accepted candidates), its prediction, the candidates left, and what the
    rounds found."""

    model: ModelSpec
    data: MeasuredData
    base_options: dict
    pool: list
    pred: np.ndarray
    st: _Setting = field(default_factory=_Setting)
    accepted: list = field(default_factory=list)
    accepted_cands: list = field(default_factory=list)
    tie: list = field(default_factory=list)
    ties: Any = None
    tie_gap: Any = None
    unresolved: Optional[tuple[list, float, GenericControl, float, int]] = None
    withdrawn: list = field(default_factory=list)
    tie_control: Optional[GenericControl] = None
    carriers: dict = field(default_factory=dict)
    screening: list = field(default_factory=list)
    fingerprints: Any = None
    lookalikes: Any = None
    not_evaluable: list = field(default_factory=list)
    notes: list = field(default_factory=list)


def diagnose(
    model: ModelSpec,
    measured: Any,
    candidates: Optional[Sequence[str]] = None,
    holdout: Union[str, float, Sequence[str], None] = "highest_speeds",
    *,
    max_rounds: int = 3,
    delta_bic_min: float = 10.0,
    tie_delta_bic: float = 2.0,
    lookalike_cosine: float = 0.95,
    suggest: bool = True,
    envelope: Optional[dict] = None,
    outliers: bool = True,
    control: bool = True,
) -> Diagnosis:
    """Diagnose the gap between ``model`` (the baseline: a
    [`BearingModelSpec`][thermobear.BearingModelSpec] or
    [`SpindleModelSpec`][thermobear.SpindleModelSpec], or
    a [`Bearing`][thermobear.Bearing] or [`Spindle`][thermobear.Spindle] taken as
    configured, every effect it has on) and ``measured`` (anything
    [`load_measurements`][thermobear.load_measurements] reads, with that model's quantities).
    ``candidates``: names from [`candidates`][thermobear.diagnosis.candidates.candidates] (default:
    all of them, with a sensor-offset decoy per measured quantity and, when the
    data hold two or more load levels, a load-scale candidate per level:
    ``axial_load_scale@<N>`` / ``radial_load_scale@<N>`` on a bearing,
    ``preload_scale@<N>`` on a spindle); ``holdout``:
    the points of the extrapolation check -- ``"highest_speeds"`` (the top
    quarter of the distinct speeds), a fraction of the distinct speeds, run
    label(s), or None; ``envelope``: the operating range where an extra
    measurement can be made (``{"speed_rpm": (lo, hi), "axial_n": (lo,
    hi)}``; default: the measured range); ``outliers``: run the robust
    outlier audit (``thermobear.diagnosis.outliers``); ``control``: compare the best named
    candidate with the generic smooth control (``thermobear.diagnosis.control``). See the
    module docstring for the statistics; returns a [`Diagnosis`][thermobear.Diagnosis]."""
    model = as_spec(model)
    rules = _checked_rules(
        max_rounds, delta_bic_min, tie_delta_bic, lookalike_cosine, suggest, envelope, control
    )
    candidates = val.optional_names("candidates", candidates, one=True)
    outliers = val.flag("outliers", outliers)
    full = prepare_measurements(measured, model.quantities, holdout)
    # with no names given, data at two or more load levels also screen one
    # load-scale candidate per level (a load cell or preload off at one level)
    pool = candidate_pool(
        model, full.quantity, candidates, full.cond if candidates is None else None
    )
    pool, outside = split_evaluable(pool)
    # the spec already carries the baseline effects and options; a setting adds to them
    pred0 = _predict(model, _Setting(), full.cond, full.quantity)
    baseline_audit = audit(full.df, full.residual(pred0))
    keep = np.ones(full.n, dtype=bool)
    z = np.zeros(full.n)
    for _ in range(_OUTLIER_PASSES):
        s = _search(model, full.subset(keep), pool, outside, rules)
        if not outliers:
            break
        flagged, zz = flag_outliers(s.data.df, s.data.residual(s.pred))
        if not flagged.any():
            break
        idx = np.flatnonzero(keep)
        z[idx[flagged]] = zz[flagged]
        keep[idx[flagged]] = False
    else:
        s = _search(model, full.subset(keep), pool, outside, rules)
    return _conclude(s, full, keep, z, pred0, baseline_audit)


def _checked_rules(
    max_rounds: Any,
    delta_bic_min: Any,
    tie_delta_bic: Any,
    lookalike_cosine: Any,
    suggest: Any,
    envelope: Any,
    control: Any,
) -> _Rules:
    """The decision rules of [`diagnose`][thermobear.diagnose], each argument checked."""
    return _Rules(
        val.whole("max_rounds", max_rounds, 0),
        val.real("delta_bic_min", delta_bic_min, 0.0),
        val.real("tie_delta_bic", tie_delta_bic, 0.0),
        val.real("lookalike_cosine", lookalike_cosine, 0.0, 1.0),
        val.flag("suggest", suggest),
        _checked_envelope(envelope),
        val.flag("control", control),
    )


def _checked_envelope(envelope: Any) -> Optional[dict]:
    """``envelope`` checked: None, or a dict of ``speed_rpm`` -> (low, high)
    and load columns -> their values (finite, >= 0)."""
    if envelope is None:
        return None
    if not isinstance(envelope, Mapping):
        raise val.fail("envelope", envelope, "None or a dict name -> (low, high)")
    out: dict[str, Any] = {}
    for k, v in envelope.items():
        name = f"envelope[{k!r}]"
        out[val.text("envelope key", k)] = (
            val.pair(name, v, 0.0) if k == "speed_rpm" else tuple(val.reals(name, v, 0.0))
        )
    return out


def _search(
    model: ModelSpec,
    data: MeasuredData,
    pool: Sequence[Candidate],
    outside: Sequence[str],
    rules: _Rules,
) -> _Search:
    """The screening rounds on ``data``: while the residual is above noise,
    screen, accept the best passing candidate, stop at a tie or when the
    generic control explains the data as well."""
    pred = _predict(model, _Setting(), data.cond, data.quantity)
    s = _Search(model, data, dict(model.options), list(pool), pred, not_evaluable=list(outside))
    if outside:
        s.notes.append("not in the single-bearing model: " + ", ".join(outside))
    for rnd in range(rules.max_rounds):
        if not _screening_round(s, rnd, rules):
            break
    if rules.control and s.accepted:
        _control_check(s, pred, CONTROL_MARGIN)
    return s


def _control_check(s: _Search, pred0: np.ndarray, margin: float) -> None:
    """The generic control against what the rounds accepted: when a generic
    term fitted to the baseline's residual explains the data as well as
    the accepted candidates together (``matching_control``: the
    per-quantity control by BIC, no more than ``margin`` below; a carrier
    control by the chi^2 lead), the data cannot tell them from an unknown
    effect: they are withdrawn from ``accepted`` and reported as
    unresolved."""
    d = s.data
    k = len(s.accepted)
    chi_named = _chi2(d.residual(s.pred))
    ctrl = matching_control(d, pred0, chi_named, k, s.carriers, margin)
    if ctrl is not None:
        gain = _chi2(d.residual(pred0)) - chi_named - k * np.log(d.n)
        records = list(s.accepted) + _also_unresolved(s, ctrl)
        s.unresolved = (records, gain, ctrl, chi_named, k)
        # withdrawn: no longer the setting; kept as the named explanation
        s.withdrawn = list(s.accepted_cands)
        s.accepted, s.accepted_cands = [], []


def _also_unresolved(s: _Search, ctrl: GenericControl) -> list:
    """The first round's other named candidates that explain the data as
    well as the control (``explains_as_well``): listed as unresolved
    beside the accepted ones, so that the verdict names every known
    candidate the data cannot tell from the unknown source."""
    if not s.screening or s.screening[0].is_empty():
        return []
    taken = {a["name"] for a in s.accepted}
    by_name = {c.name: c for c in s.pool}
    out = []
    for row in s.screening[0].iter_rows(named=True):
        name = row["candidate"]
        if name in taken or name not in by_name or not explains_as_well(ctrl, row):
            continue
        out.append(accepted_record(by_name[name], row, 0) | {"alternative": True})
    return out


def _screening_round(s: _Search, rnd: int, rules: _Rules) -> bool:
    """One round: stop when the residual is already noise (after the first
    round), evaluate the candidates, fingerprint them (first round), screen
    (with the generic control), and accept the best passing candidate unless
    a rival ties it or the control matches it. Returns whether another round
    may follow."""
    d = s.data
    r = d.residual(s.pred)
    chi_base = _chi2(r)
    chi_held = _chi2(r[d.held]) if d.held.any() else 0.0
    if rnd > 0 and noise_p_value(chi_base, d.n) > 0.01:
        return False
    curves, dropped, notes = candidate_curves(s.model, s.st, s.pool, d, s.base_options)
    s.not_evaluable += dropped
    s.notes += notes
    s.pool = [c for c in s.pool if c.name in curves]
    if s.fingerprints is None:  # identifiability: around the baseline
        s.fingerprints, s.lookalikes = identifiability(
            s.model, s.st, curves, d, s.base_options, rules.lookalike_cosine, rules.suggest,
            rules.envelope,
        )  # fmt: skip
    k_acc = len(s.accepted_cands)
    rows, fits = screen(curves, d, chi_base, chi_held, rules.delta_bic_min, k_acc)
    if rnd == 0:  # the carriers' sensitivities around the baseline
        s.carriers = {n: curves[n].slope() for n in CARRIERS if n in curves}
    ctrl = generic_control(d, s.pred, s.carriers) if rules.control else None
    table_rows = rows + ([control_row(ctrl, chi_base)] if ctrl is not None else [])
    s.screening.append(screening_table(table_rows, rnd))
    best, rivals = select(rows, rules.tie_delta_bic)
    if best is None:
        return False
    rivals += significant_rivals(rows, fits, best, d, set(rivals))
    if rivals:
        s.tie = [best["candidate"]] + rivals
        if ctrl is not None and matching_control(
            d, s.pred, best["chi2"], 1, s.carriers, CONTROL_MARGIN
        ):
            s.tie.append("generic_control")
            s.tie_control = ctrl
        named = [m for m in s.tie if m in fits]
        s.ties = tie_table(named, rows, fits, curves, s, rules.envelope, rules.suggest)
        s.tie_gap = tie_gap(named, fits, s)
        return False
    _accept(s, curves[best["candidate"]].cand, best, fits[best["candidate"]], rnd)
    return True


def _accept(s: _Search, c: Candidate, best: dict, fit: dict, rnd: int) -> None:
    """Add an accepted candidate to the setting; re-calibrate the accepted
    parameters together (``joint_refit``)."""
    d = s.data
    s.accepted.append(accepted_record(c, best, rnd))
    s.st = s.st.apply(c, best["value"], s.base_options)
    s.pred = fit["pred"]
    s.pool = [p for p in s.pool if p.name != c.name]
    s.accepted_cands.append(c)
    everything = np.ones(d.n, dtype=bool)
    joint = joint_refit(
        s.model, s.accepted_cands, s.accepted, d.cond, d.quantity, d.y, d.s, everything,
        s.base_options,
    )  # fmt: skip
    if joint is not None:
        s.st, s.pred = joint


def _conclude(
    s: _Search,
    full: MeasuredData,
    keep: np.ndarray,
    z: np.ndarray,
    pred0: np.ndarray,
    baseline_audit: pl.DataFrame,
) -> Diagnosis:
    """The verdict, the held-out gap before/after and the measured points
    (outliers included, flagged) with both predictions."""
    import polars as pl

    d = s.data
    # under "unresolved" the withdrawn candidates are no longer the setting
    st = _Setting() if s.unresolved is not None else s.st
    pred1 = _predict(s.model, st, full.cond, full.quantity)
    r1 = d.residual(s.pred)
    p_final = noise_p_value(_chi2(r1), d.n)
    out_table = outlier_table(full.df, ~keep, z, pred1)
    unexplained = unexplained_words(d, s.pred, s.screening, s.model.quantities)
    verdict = verdict_text(s.accepted, s.tie, p_final, s.unresolved, out_table, unexplained)
    _final_notes(s, full, p_final)
    pred_x = calibrated_without_heldout(s, s.accepted_cands, full) if full.held.any() else pred1
    preds = explained_predictions(s)
    gap = explained_gap(s, pred0[keep], preds)
    points = full.df.with_columns(
        pl.Series("model_before", pred0),
        pl.Series("model_after", pred1),
        pl.Series("model_extrapolated", pred_x),
        pl.Series("heldout", full.held),
        pl.Series("outlier", ~keep),
    )
    model = diagnosis_model(s, verdict)
    verdict = with_weights(verdict, model)
    return Diagnosis(
        baseline_audit, s.fingerprints, s.lookalikes, s.screening, s.accepted, s.tie,
        verdict, gap, points, sorted(set(s.not_evaluable)), s.notes, ties=s.ties,
        tie_gap=s.tie_gap, outliers=out_table, explained=explained_points(s, preds),
        unresolved=[] if s.unresolved is None else s.unresolved[0],
        _model=model,
    )  # fmt: skip


def with_weights(verdict: str, model: Any) -> str:
    """The verdict with the weights of a tie's or an "unresolved"
    verdict's explanations in words (``weights_words``), also in the
    model's provenance."""
    from .weights import weights_words

    words = weights_words(model)
    if not words:
        return verdict
    verdict = f"{verdict}; {words}"
    model.provenance["verdict"] = verdict
    for m in model.members:
        m.provenance["verdict"] = verdict
    return verdict


def _final_notes(s: _Search, full: MeasuredData, p_final: float) -> None:
    from .measurements import STATIC_QUANTITIES
    from .plausible_data import one_speed_note

    single = one_speed_note(full.df, STATIC_QUANTITIES)
    if single:
        s.notes.append(single)
    weak = [a["name"] for a in s.accepted if a.get("identified") is False]
    if weak:
        s.notes.append("calibrated together, not identified by these data: " + ", ".join(weak))
    if s.accepted and p_final < 0.01:
        s.notes.append(f"residual after the accepted effects still above noise (p = {p_final:.2g})")
    if not full.held.any():
        s.notes.append("no held-out points: the gap table uses all points")
    if not full.sigma_given:
        s.notes.append(
            "no sigma column: typical uncertainties assumed; intervals widened by the reduced "
            "chi^2 of the fit when it exceeds 1"
        )

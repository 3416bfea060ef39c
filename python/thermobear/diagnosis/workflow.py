"""Model-vs-measurement discrepancy workflow (issue 6): find where the model
misses measured data, name the missing effect the data support, show the gap
shrink -- and refuse to name one the data cannot support.

Pipeline of :func:`diagnose` (each step a function of its own module in
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
3. screening: each candidate added alone to the baseline and calibrated
   within its bounds on the training points, scored by BIC = chi^2 + k ln n
   and by chi^2 on held-out points (highest speeds or given runs);
4. acceptance: delta-BIC >= 10 against the baseline, held-out chi^2
   improved, the 95 % profile interval (chi^2 rise 3.84) inside the bounds
   and excluding the null value, no rival within delta-BIC 2 (else a tie
   set). Accepted effects join the baseline and the screening repeats while
   the reduced chi^2 of the training residual fails the chi^2 test at 1 %;
5. a verdict that says what each accepted candidate is: a missing effect
   (a registry switch or a term the baseline leaves out), a miscalibrated
   baseline input (f0, spin friction coefficient, cooling and ambient
   temperatures, housing material), or a measurement-side sensor offset;
   a tie set; "no missing effect supported"; or "structured residual not
   explained by any known effect";
6. the held-out gap before/after per quantity and speed band.

Model specs: :class:`BearingModelSpec` (one bearing, quantities
:data:`QUANTITIES`) and :class:`thermobear.SpindleModelSpec` (the seed B
spindle with its rotor) follow one protocol -- ``quantities``,
``candidate_list(quantities)``, ``predict(conditions)``,
``with_setting(add_effects, **options)``, ``options``, ``effects`` -- and
:func:`diagnose` runs the same statistics on either.

Speed: every model configuration (effects + options + parameter value) is
evaluated once on the measured conditions and cached in the
:class:`BearingModelSpec`; a parameter candidate is evaluated on a fixed grid
of values over its bounds and calibrated on a cubic interpolant of the
predictions, so re-diagnosing new noise on the same conditions costs no
model run.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Optional, Sequence, Union

import numpy as np

from .acceptance import accepted_record, joint_refit, select
from .audit import audit, gap_table
from .candidates import Candidate, candidate_pool, split_evaluable
from .identifiability import identifiability
from .measurements import MeasuredData, prepare_measurements
from .protocol import ModelSpec, check_spec
from .result import Diagnosis
from .screening import candidate_curves, screen, screening_table
from .setting import _predict, _Setting
from .statistics import _chi2, noise_p_value
from .verdict import verdict_text

__all__ = ["diagnose"]


@dataclass(frozen=True)
class _Rules:
    """The decision thresholds of :func:`diagnose`."""

    max_rounds: int
    delta_bic_min: float
    tie_delta_bic: float
    lookalike_cosine: float
    suggest: bool


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
) -> Diagnosis:
    """Diagnose the gap between ``model`` (a :class:`BearingModelSpec`,
    the baseline) and ``measured`` (anything :func:`load_measurements`
    reads). ``candidates``: names from :func:`candidates` (default: all of
    them, with a sensor-offset decoy per measured quantity); ``holdout``:
    ``"highest_speeds"`` (the top quarter of the distinct speeds), a fraction
    of the distinct speeds, run label(s), or None. See the module docstring
    for the statistics; returns a :class:`Diagnosis`.

    The steps: the measurements (:func:`prepare_measurements`), the
    candidate pool (:func:`candidate_pool`), the baseline's residual audit
    (:func:`audit`), screening rounds (:func:`_screening_round`: curves,
    identifiability, screening, acceptance) while the residual is above
    noise, then the verdict and the held-out gap (:func:`_conclude`)."""
    check_spec(model)
    rules = _Rules(max_rounds, delta_bic_min, tie_delta_bic, lookalike_cosine, suggest)
    data = prepare_measurements(measured, model.quantities, holdout)
    pool = candidate_pool(model, data.quantity, candidates)
    # the spec already carries the baseline effects and options; a setting adds to them
    pred0 = _predict(model, _Setting(), data.cond, data.quantity)
    baseline_audit = audit(data.df, data.residual(pred0))
    pool, outside = split_evaluable(pool)
    search = _Search(model, data, dict(model.options), pool, pred0, not_evaluable=outside)
    if outside:
        search.notes.append("not in the single-bearing model: " + ", ".join(outside))
    for rnd in range(rules.max_rounds):
        if not _screening_round(search, rnd, rules):
            break
    return _conclude(search, pred0, baseline_audit)


def _screening_round(s: _Search, rnd: int, rules: _Rules) -> bool:
    """One round: stop when the residual is already noise (after the first
    round), evaluate the candidates, fingerprint them (first round), screen,
    and accept the best passing candidate unless a rival ties it. Returns
    whether another round may follow."""
    d = s.data
    r = d.residual(s.pred)
    chi_base = _chi2(r[d.train])
    chi_held = _chi2(r[d.held]) if d.held.any() else 0.0
    if rnd > 0 and noise_p_value(chi_base, d.n_train) > 0.01:
        return False
    curves, dropped, notes = candidate_curves(s.model, s.st, s.pool, d, s.base_options)
    s.not_evaluable += dropped
    s.notes += notes
    s.pool = [c for c in s.pool if c.name in curves]
    if s.fingerprints is None:  # identifiability: around the baseline
        s.fingerprints, s.lookalikes = identifiability(
            s.model, s.st, curves, d, s.base_options, rules.lookalike_cosine, rules.suggest
        )
    rows, fits = screen(curves, d, chi_base, chi_held, rules.delta_bic_min)
    s.screening.append(screening_table(rows, rnd))
    best, rivals = select(rows, rules.tie_delta_bic)
    if best is None:
        return False
    if rivals:
        s.tie = [best["candidate"]] + rivals
        return False
    _accept(s, curves[best["candidate"]].cand, best, fits[best["candidate"]], rnd)
    return True


def _accept(s: _Search, c: Candidate, best: dict, fit: dict, rnd: int) -> None:
    """Add an accepted candidate to the setting; re-calibrate the accepted
    parameters together (:func:`joint_refit`)."""
    d = s.data
    s.accepted.append(accepted_record(c, best, rnd))
    s.st = s.st.apply(c, best["value"], s.base_options)
    s.pred = fit["pred"]
    s.pool = [p for p in s.pool if p.name != c.name]
    s.accepted_cands.append(c)
    joint = joint_refit(
        s.model, s.accepted_cands, s.accepted, d.cond, d.quantity, d.y, d.s, d.train, s.base_options
    )
    if joint is not None:
        s.st, s.pred = joint


def _conclude(s: _Search, pred0: np.ndarray, baseline_audit: Any) -> Diagnosis:
    """The verdict, the held-out gap before/after and the measured points
    with both predictions."""
    import polars as pl

    d = s.data
    r0, r1 = d.residual(pred0), d.residual(s.pred)
    p_final = noise_p_value(_chi2(r1[d.train]), d.n_train)
    verdict = verdict_text(s.accepted, s.tie, p_final)
    if s.accepted and p_final < 0.01:
        s.notes.append(f"residual after the accepted effects still above noise (p = {p_final:.2g})")
    gap = gap_table(d.df, r0, r1, d.held if d.held.any() else np.ones(len(d.y), dtype=bool))
    if not d.held.any():
        s.notes.append("no held-out points: the gap table uses all points")
    points = d.df.with_columns(
        pl.Series("model_before", pred0),
        pl.Series("model_after", s.pred),
        pl.Series("heldout", d.held),
    )
    return Diagnosis(
        baseline_audit,
        s.fingerprints,
        s.lookalikes,
        s.screening,
        s.accepted,
        s.tie,
        verdict,
        gap,
        points,
        sorted(set(s.not_evaluable)),
        s.notes,
    )

"""Calibration against bounds: the choice among the values of categorical
inputs (a housing material, a reading of a misprinted coefficient, a
level of a network coefficient) scored by claims that are bounds or
approximate relations rather than measured values with a sigma.

A claim is met when ours lies within its bound (``comparison`` ``">="``
or ``"<="`` against ``value`` widened by ``tolerance_abs``, or ``"="``
within ``tolerance_abs`` of ``value``); otherwise it falls short by the
distance past the bound, counted in the claim's reading ``precision`` (the
smallest change the source could show). An option's score is the number
of claims it meets and, between options meeting as many, the total
number of precisions by which it misses the others. Two options that meet
the same claims and miss each of the others by amounts within one
precision of each other are not told apart by the claims (a difference
below the reading looseness is no evidence): the choice among the options
tied so with the best one follows a stated order of preference (the
source's own value first, then the baseline's).

Only the claims given to ``score_option`` enter the choice: held-out
(checked) claims are scored afterwards, never before.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Iterable, Mapping, Sequence

from ..errors import ConfigError

if TYPE_CHECKING:
    import polars

COMPARISONS = ("=", "<=", ">=")


@dataclass(frozen=True)
class Claim:
    """One bound: ``id``, ``comparison`` ("=", "<=", ">="), ``value``,
    ``tolerance_abs`` (in the value's unit) and ``precision`` (the reading
    looseness, > 0, in the value's unit)."""

    id: str
    comparison: str
    value: float
    tolerance_abs: float
    precision: float

    def __post_init__(self) -> None:
        if self.comparison not in COMPARISONS:
            raise ConfigError(
                f"invalid comparison = {self.comparison!r} ({self.id}): one of {COMPARISONS}"
            )
        if not (self.precision > 0.0 and math.isfinite(self.precision)):
            raise ConfigError(f"invalid precision = {self.precision!r} ({self.id}): must be > 0")
        if not self.tolerance_abs >= 0.0:
            raise ConfigError(
                f"invalid tolerance_abs = {self.tolerance_abs!r} ({self.id}): must be >= 0"
            )


def shortfall(claim: Claim, ours: float) -> float:
    """How far ``ours`` lies past the claim's bound, in its unit (0 when it
    is met; infinite when ours is not a finite number)."""
    if not math.isfinite(ours):
        return math.inf
    if claim.comparison == ">=":
        return max(0.0, claim.value - claim.tolerance_abs - ours)
    if claim.comparison == "<=":
        return max(0.0, ours - claim.value - claim.tolerance_abs)
    return max(0.0, abs(ours - claim.value) - claim.tolerance_abs)


@dataclass(frozen=True)
class OptionScore:
    """An option scored by the claims: ``label``, ``met`` (ids of the claims
    it meets), ``missed`` (id -> shortfall in the claim's precisions) and
    ``shortfall_precisions`` (their sum)."""

    label: str
    met: frozenset
    missed: Mapping[str, float]
    shortfall_precisions: float

    @property
    def count(self) -> int:
        """The number of claims met."""
        return len(self.met)

    def key(self) -> tuple[int, float]:
        """The ranking key: more claims met, then a smaller shortfall."""
        return (self.count, -self.shortfall_precisions)

    def same_as(self, other: OptionScore) -> bool:
        """Whether the claims cannot tell the two apart: the same claims met,
        and every claim missed missed by both to within one precision."""
        return self.met == other.met and all(
            abs(v - other.missed[k]) < 1.0 for k, v in self.missed.items()
        )


def score_option(label: str, claims: Iterable[Claim], ours: Mapping[str, float]) -> OptionScore:
    """The score of one option: ``ours`` (claim id -> our value under the
    option) against each of ``claims``."""
    met, missed = set(), {}
    for c in claims:
        if c.id not in ours:
            raise ConfigError(f"invalid ours: no value for claim {c.id!r} ({label})")
        s = shortfall(c, float(ours[c.id]))
        if s == 0.0:
            met.add(c.id)
        else:
            missed[c.id] = s / c.precision
    return OptionScore(label, frozenset(met), missed, float(sum(missed.values())))


def best_group(scores: Sequence[OptionScore]) -> list[OptionScore]:
    """The options the claims cannot tell from the best-ranked one
    (``OptionScore.key``; ``OptionScore.same_as``), the best first."""
    if not scores:
        raise ConfigError("invalid scores = []: give at least one option")
    top = max(scores, key=lambda s: s.key())
    return [top] + [s for s in scores if s is not top and s.same_as(top)]


def choose(scores: Sequence[OptionScore], preference: Sequence[str]) -> OptionScore:
    """The chosen option: of ``best_group`` the first in ``preference``
    (every label must be in it)."""
    rank = {lab: i for i, lab in enumerate(preference)}
    missing = [s.label for s in scores if s.label not in rank]
    if missing:
        raise ConfigError(f"invalid preference: option {missing[0]!r} is not in it")
    return min(best_group(scores), key=lambda s: rank[s.label])


def score_table(scores: Sequence[OptionScore], chosen: OptionScore) -> polars.DataFrame:
    """One row per option: ``option``, ``claims_met``, ``shortfall_precisions``,
    ``missed`` (the ids of the claims it misses, comma-joined), ``tied``
    (the claims cannot tell it from the best) and ``chosen``."""
    import polars as pl

    tied = {s.label for s in best_group(scores)}
    return pl.DataFrame(
        {
            "option": [s.label for s in scores],
            "claims_met": [s.count for s in scores],
            "shortfall_precisions": [s.shortfall_precisions for s in scores],
            "missed": [", ".join(sorted(s.missed)) for s in scores],
            "tied": [s.label in tied for s in scores],
            "chosen": [s.label == chosen.label for s in scores],
        }
    )

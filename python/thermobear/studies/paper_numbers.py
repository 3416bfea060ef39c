"""The seed papers' quoted numbers as data, and the number-by-number
reproduction table.

Every number a seed paper quotes as a result is one row of
``papers/seed_a_quotes.csv`` or ``papers/seed_b_quotes.csv`` (the columns
of ``QUOTE_COLUMNS``): its figure (``item``), the quantity (a glossary
name), the condition it holds at, the paper's value and unit, how it was
read (``read``, with its reading ``precision`` in the value's unit: half a
unit of the last digit printed), the ``tolerance`` within which ours counts
as agreeing (absolute in the unit, or ``"25%"`` relative) and its ``role``:
``"fitted"`` (used to pin an input the paper leaves out) or ``"checked"``
(held out: predicted by the model calibrated on the fitted rows only).

``relation`` says what the number is: ``"value"`` (the quantity at the
condition), ``"difference"`` / ``"ratio"`` (the condition minus / over the
``reference``, e.g. ``"preload_n=300"`` or
``"quantity=front_inner_ring_temperature_c"``), ``"model_error"`` /
``"model_error_percent"`` (the paper's own model against a measurement it
names in ``reference``; ours is our model against the same measurement).
``comparison`` is ``"="`` or a bound (``"<="``, ``">="``).

An evaluator (one per model: ``EVALUATORS``) takes a seed's rows and
returns, for each row it handles, ``ours`` (NaN when ours cannot be
compared: the paper gives no measured curve, say), ``lower`` and ``upper``
(the 95 % band of ours, NaN when none) and ``basis`` (what ours is, in a
few words). ``number_table`` joins quotes and evaluations and adds
``error`` (ours - paper), ``tolerance_abs``, ``within`` (null when not
comparable) and ``covered`` (the band holds the paper's value).
"""

from __future__ import annotations

import math
from contextlib import contextmanager
from contextvars import ContextVar
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Iterator, Optional, Sequence

from ..errors import ConfigError

if TYPE_CHECKING:
    import polars

#: The columns of a quotes file, in order.
QUOTE_COLUMNS: tuple[str, ...] = (
    "id",
    "seed",
    "item",
    "quantity",
    "speed_rpm",
    "preload_n",
    "torque_n_m",
    "stiffness",
    "direction",
    "variant",
    "coupling",
    "harmonic",
    "relation",
    "reference",
    "comparison",
    "value",
    "unit",
    "read",
    "precision",
    "tolerance",
    "role",
    "note",
)

#: Numeric columns of a quotes file (the rest are text).
_NUMERIC = ("speed_rpm", "preload_n", "torque_n_m", "harmonic", "value", "precision")

RELATIONS = ("value", "difference", "ratio", "model_error", "model_error_percent")
COMPARISONS = ("=", "<=", ">=")
ROLES = ("fitted", "checked")
SEEDS = ("A", "B")
#: "number": a number the text quotes; "claim": a trend or ordering it
#: states in words (counted apart from the numbers).
KINDS = ("number", "claim")

#: The columns an evaluator returns, beside ``id``.
EVALUATION_COLUMNS: tuple[str, ...] = ("ours", "lower", "upper", "basis")

#: Evaluators by seed: ``"module:function"`` inside ``thermobear.studies``,
#: each ``function(quotes, quick) -> DataFrame`` (``id`` and
#: ``EVALUATION_COLUMNS``) for the rows it handles.
EVALUATORS: dict[str, list[str]] = {
    "A": ["reproduce_seed_a_gear:evaluate", "reproduce_seed_a_thermal:evaluate"],
    "B": ["reproduce_seed_b:evaluate"],
}


#: A folder of refitted paper models (``thermobear demo --refit``) that
#: takes precedence over the shipped ones while set (``refitted``).
_REFIT_DIR: ContextVar[Optional[Path]] = ContextVar("refit_dir", default=None)


def papers_file(name: str) -> Any:
    """A file of the papers' data: the refitted one while ``refitted`` is
    in force and it exists there, else the one shipped in
    ``thermobear.studies.papers``."""
    d = _REFIT_DIR.get()
    if d is not None and (d / name).is_file():
        return d / name
    return resources.files("thermobear.studies.papers").joinpath(name)


@contextmanager
def refitted(folder: Path) -> Iterator[Path]:
    """Within the block, the papers' model files are read from ``folder``
    first (where the refits write them)."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    token = _REFIT_DIR.set(folder)
    try:
        yield folder
    finally:
        _REFIT_DIR.reset(token)


def quotes(seed: Optional[str] = None, kind: Optional[str] = "number") -> polars.DataFrame:
    """The quoted numbers (``kind="number"``, ``papers/seed_<s>_quotes.csv``)
    or the claims in words (``"claim"``, ``papers/seed_<s>_claims.csv``:
    a trend or an ordering the text states without a number, written as a
    bound or an approximate ratio) of seed ``"A"``, ``"B"`` or both (None),
    or both kinds (``kind=None``); a ``kind`` column says which. Checked:
    known columns, relation, comparison, role, a positive precision, a
    parseable tolerance, unique ids."""
    import polars as pl

    seeds = SEEDS if seed is None else (seed,)
    kinds = KINDS if kind is None else (kind,)
    frames = []
    for s in seeds:
        if s not in SEEDS:
            raise ConfigError(f"invalid seed = {s!r}: 'A' or 'B'")
        for k in kinds:
            if k not in KINDS:
                raise ConfigError(f"invalid kind = {k!r}: one of {KINDS}")
            name = f"seed_{s.lower()}_{'quotes' if k == 'number' else 'claims'}.csv"
            path = resources.files("thermobear.studies.papers").joinpath(name)
            if not path.is_file():
                continue
            with path.open("rb") as f:
                df = pl.read_csv(f, comment_prefix="#", infer_schema=False)
            frames.append(_checked(df, name).with_columns(pl.lit(k).alias("kind")))
    if not frames:
        raise ConfigError(f"invalid seed/kind = {seed!r}/{kind!r}: no such file")
    out = pl.concat(frames)
    dup = out["id"].is_duplicated()
    if dup.any():
        raise ConfigError(f"invalid quotes: duplicate id {out.filter(dup)['id'][0]!r}")
    return out


def _checked(df: Any, name: str) -> Any:
    import polars as pl

    if tuple(df.columns) != QUOTE_COLUMNS:
        raise ConfigError(f"invalid quotes file {name}: columns {df.columns}, need {QUOTE_COLUMNS}")
    df = df.with_columns(
        [pl.col(c).str.strip_chars().cast(pl.Float64) for c in _NUMERIC]
        + [pl.col(c).fill_null("") for c in QUOTE_COLUMNS if c not in _NUMERIC]
    )
    for col, allowed in (("relation", RELATIONS), ("comparison", COMPARISONS), ("role", ROLES)):
        bad = df.filter(~pl.col(col).is_in(list(allowed)))
        if bad.height:
            raise ConfigError(
                f"invalid {col} = {bad[col][0]!r} ({name}, {bad['id'][0]}): one of {allowed}"
            )
    for r in df.iter_rows(named=True):
        if not (r["precision"] is not None and r["precision"] > 0):
            raise ConfigError(f"invalid precision = {r['precision']!r} ({name}, {r['id']})")
        tolerance_abs(r["tolerance"], r["value"])
    return df


def tolerance_abs(tolerance: str, value: float) -> float:
    """A row's tolerance in the value's unit: ``"25%"`` is a quarter of
    ``|value|``, a number is itself."""
    t = str(tolerance).strip()
    try:
        if t.endswith("%"):
            return abs(float(value)) * float(t[:-1]) / 100.0
        return float(t)
    except ValueError:
        raise ConfigError(f"invalid tolerance = {tolerance!r}: a number or a percentage") from None


def sigma_of(precision: float) -> float:
    """The measurement sigma of a quoted number: its reading precision
    (half a unit of the last digit printed), as the issue of the reading
    is a rounding."""
    return float(precision)


def evaluate(seed: str, quick: bool = False, rows: Any = None) -> polars.DataFrame:
    """Every row of ``seed`` (or of ``rows``, a quotes frame; default both
    kinds) evaluated by the registered evaluators; each row at most once."""
    import importlib

    import polars as pl

    q = quotes(seed, kind=None) if rows is None else rows
    parts = []
    for spec in EVALUATORS[seed]:
        module, name = spec.split(":")
        fn: Callable[..., Any] = getattr(importlib.import_module(f"{__package__}.{module}"), name)
        got = fn(q, quick)
        parts.append(got.select(["id", *EVALUATION_COLUMNS]))
    if not parts:
        return pl.DataFrame(
            {"id": [], "ours": [], "lower": [], "upper": [], "basis": []},
            schema={"id": pl.Utf8, "ours": pl.Float64, "lower": pl.Float64,
                    "upper": pl.Float64, "basis": pl.Utf8},
        )  # fmt: skip
    ev = pl.concat(parts)
    dup = ev["id"].is_duplicated()
    if dup.any():
        raise ConfigError(f"evaluation: row {ev.filter(dup)['id'][0]!r} evaluated twice")
    return ev


def number_table(q: Any, ev: Any) -> polars.DataFrame:
    """Quotes joined with their evaluation: ``ours``, ``lower``, ``upper``,
    ``basis``, ``error`` (ours - paper), ``tolerance_abs``, ``within``
    (ours agrees within the tolerance, or meets the bound; null when ours is
    not comparable) and ``covered`` (the band holds the paper's value; null
    without a band). A row no evaluator handled is not comparable."""
    import polars as pl

    t = q.join(ev, on="id", how="left")
    rows = []
    for r in t.iter_rows(named=True):
        tol = tolerance_abs(r["tolerance"], r["value"])
        ours = r["ours"]
        ok = ours is not None and math.isfinite(ours)
        err = (ours - r["value"]) if ok else None
        if not ok:
            within = None
        elif r["relation"].startswith("model_error"):
            within = abs(ours) <= _model_error_tolerance(r)
        elif r["comparison"] == "<=":
            within = ours <= r["value"] + tol
        elif r["comparison"] == ">=":
            within = ours >= r["value"] - tol
        else:
            within = abs(ours - r["value"]) <= tol
        lo, hi = r["lower"], r["upper"]
        band = lo is not None and hi is not None and math.isfinite(lo) and math.isfinite(hi)
        covered = (lo <= r["value"] <= hi) if band and r["comparison"] == "=" else None
        rows.append({"id": r["id"], "error": err, "tolerance_abs": tol, "within": within,
                     "covered": covered})  # fmt: skip
    extra = pl.DataFrame(
        rows,
        schema={"id": pl.Utf8, "error": pl.Float64, "tolerance_abs": pl.Float64,
                "within": pl.Boolean, "covered": pl.Boolean},
    )  # fmt: skip
    return t.join(extra, on="id", how="left")


def _model_error_tolerance(r: dict) -> float:
    """Our model's error against a measurement agrees when it is within
    the tolerance of the measured quantity: the row's tolerance, in the
    measured quantity's unit (a percentage row: that tolerance relative to
    the measurement, in per cent)."""
    tol = str(r["tolerance"]).strip()
    if r["relation"] == "model_error_percent" and not tol.endswith("%"):
        measured = _reference_number(r["reference"])
        return 100.0 * float(tol) / abs(measured) if measured else float("inf")
    if tol.endswith("%"):
        return float(tol[:-1]) if r["relation"] == "model_error_percent" else float("inf")
    return float(tol)


def _reference_number(ref: str) -> Optional[float]:
    if "=" not in ref:
        return None
    try:
        return float(ref.split("=", 1)[1])
    except ValueError:
        return None


def counts(table: Any, seed: str, kind: str = "number") -> dict[str, tuple[int, int]]:
    """Per role (and ``"all"``): (rows within tolerance, comparable rows)
    of ``seed`` and ``kind``, ``"not comparable"``: (0, rows ours cannot be
    compared with) and ``"checked in band"``: (checked rows whose band
    holds the paper's value, checked rows with a band)."""
    import polars as pl

    t = table.filter(pl.col("seed") == seed)
    if "kind" in t.columns:
        t = t.filter(pl.col("kind") == kind)
    out: dict[str, tuple[int, int]] = {}
    for role in ("fitted", "checked", "all"):
        s = t if role == "all" else t.filter(pl.col("role") == role)
        comparable = s.filter(pl.col("within").is_not_null())
        out[role] = (int(comparable["within"].sum()), comparable.height)
    out["not comparable"] = (0, t.filter(pl.col("within").is_null()).height)
    covered = t.filter(pl.col("role") == "checked", pl.col("covered").is_not_null())
    out["checked in band"] = (int(covered["covered"].sum()), covered.height)
    return out


def summary(table: Any, seeds: Sequence[str] = SEEDS) -> str:
    """``"seed A: 30 of 45 numbers within tolerance (fitted 20/25, checked
    10/20; checked inside their band 12/20); ..."``."""
    parts = []
    for s in seeds:
        c = counts(table, s)
        n, m = c["all"]
        text = (
            f"seed {s}: {n} of {m} numbers within tolerance (fitted {c['fitted'][0]}/"
            f"{c['fitted'][1]}, checked {c['checked'][0]}/{c['checked'][1]}"
        )
        if c["checked in band"][1]:
            text += f"; checked inside their 95 % band {c['checked in band'][0]}/" + str(
                c["checked in band"][1]
            )
        text += ")"
        if c["not comparable"][1]:
            text += f", {c['not comparable'][1]} not comparable"
        parts.append(text)
    return "; ".join(parts)


def item_status(table: Any) -> polars.DataFrame:
    """Per seed and item (figure): numbers, within, and a status that
    follows from them: "reproduced" (every comparable number within
    tolerance), "partly reproduced" (some), "differs" (none) or "not
    comparable" (no number ours can be compared with)."""
    import polars as pl

    g = table.group_by(["seed", "item"], maintain_order=True).agg(
        pl.len().alias("numbers"),
        pl.col("within").is_not_null().sum().alias("comparable"),
        pl.col("within").fill_null(False).sum().alias("within_tolerance"),
    )
    return g.with_columns(
        pl.when(pl.col("comparable") == 0)
        .then(pl.lit("not comparable"))
        .when(pl.col("within_tolerance") == pl.col("comparable"))
        .then(pl.lit("reproduced"))
        .when(pl.col("within_tolerance") > 0)
        .then(pl.lit("partly reproduced"))
        .otherwise(pl.lit("differs"))
        .alias("status")
    )


def condition_text(r: dict) -> str:
    """A row's condition in words: speed, preload, torque, sweep
    direction, stiffness case, variant, coupling, harmonic, and the
    reference of a difference or ratio."""
    parts = []
    if r.get("speed_rpm") is not None and not r["quantity"].endswith("_speed_rpm"):
        parts.append(f"{r['speed_rpm']:g} rpm")
    if r.get("preload_n") is not None:
        parts.append(f"{r['preload_n']:g} N preload")
    if r.get("torque_n_m") is not None:
        parts.append(f"{r['torque_n_m']:g} N m")
    for k, label in (("direction", "sweep"), ("stiffness", "stiffness")):
        if r.get(k):
            parts.append(f"{label} {r[k]}")
    for k in ("variant", "coupling"):
        if r.get(k):
            parts.append(str(r[k]))
    if r.get("harmonic") is not None:
        parts.append(f"{r['harmonic']:g}X")
    if r.get("relation") in ("difference", "ratio"):
        word = "minus" if r["relation"] == "difference" else "over"
        parts.append(f"{word} {r['reference']}")
    return ", ".join(parts)


def measurement_rows(q: Any, role: Optional[str] = "fitted") -> polars.DataFrame:
    """The rows of ``role`` ("fitted", "checked" or None for both) that a
    calibration can use as measurements: plain values with ``=`` (the
    differences, ratios, bounds and model errors stay in the table)."""
    import polars as pl

    sel = q.filter(pl.col("relation") == "value", pl.col("comparison") == "=")
    return sel if role is None else sel.filter(pl.col("role") == role)

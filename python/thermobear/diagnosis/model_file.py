"""The checks of a saved calibrated model: what
[`CalibratedModel.load`][thermobear.CalibratedModel.load] and
[`from_json`][thermobear.CalibratedModel.from_json] run before anything is
built from a file.

The file must be UTF-8 JSON of at most ``MAX_DEPTH`` levels; then every
field is checked by name (``covariance[0][1]``, ``members[1].weight``,
``steps[0].candidate.lower``, ...), each failure a
[`ConfigError`][thermobear.ConfigError] that names it:

* every field present with its type, no unknown field;
* one value, one profile interval and one covariance row and column per
  calibrated name (a step without a ``fixed`` value), the names unique;
* every number finite (a profile bound may be NaN: not computed), a
  value inside its candidate's bounds;
* the covariance symmetric and positive semi-definite (to
  ``COVARIANCE_TOLERANCE`` of the variances plus ``ROUNDING`` of the
  largest), no standard deviation past ``MAX_STD_PER_SCALE`` times its
  value's bound span (or its magnitude, at least 1, without bounds), no
  negative variance; an infinite variance marks a value the data do not
  identify and is allowed on the diagonal only, its row and column zero
  and the value bounded (a band then takes the uniform variance over the
  bounds);
* the machine's options finite, the load and preload scales numbers; a
  bearing's saved geometry through its constructor's checks
  (``check_machine``);
* the members checked the same way, their weights in [0, 1] and summing
  to 1 when they carry weights;
* the discrepancy term's kernel known, its speeds, residuals and sigmas of
  one length, the sigmas and the length scale positive, the amplitude
  positive and within the fit's bounds, the speed power in
  [0, ``MAX_SPEED_POWER``];
* a gear model's calibrated bearing model (its ``bearings`` option)
  checked the same way.

A file carries its ``format`` and ``version``; a version newer than this
thermobear reads is refused by name.
"""

from __future__ import annotations

import dataclasses
import json
import math
import os
from pathlib import Path
from typing import Any, Optional

import numpy as np

from .._validate import choice, did_you_mean, fail, names, real, reals, text, whole
from ..errors import ConfigError

#: The ``format`` and ``version`` of a saved calibrated model: a file of
#: another format is refused, one of a newer version too.
FILE_FORMAT = "thermobear-calibrated-model"
FILE_VERSION = 1

#: The deepest nesting of JSON arrays and objects a model file may hold
#: (saved models reach about 6).
MAX_DEPTH = 40

#: The deepest nesting of models in models (members, a gear model's
#: calibrated bearings).
MAX_NESTED_MODELS = 4

#: Relative tolerance of the covariance's symmetry and positive
#: semi-definiteness: of each covariance, of each variance.
COVARIANCE_TOLERANCE = 1e-8

#: Rounding allowed in the covariance's symmetry and eigenvalues, as a
#: fraction of its largest variance.
ROUNDING = 1e-12

#: The largest standard deviation of a calibrated value, in units of its
#: bounds' span (its magnitude, at least 1, without bounds): past it a
#: number says nothing and spreads a band over everything.
MAX_STD_PER_SCALE = 1e6

#: Relative tolerance of a value at its bound (of the bound span).
BOUND_TOLERANCE = 1e-9

#: Tolerance of the members' weights summing to 1.
WEIGHT_TOLERANCE = 1e-6

_KINDS = ("calibration", "named", "tie", "unresolved", "nothing")
_MODEL_KEYS = ("kind", "label", "base", "steps", "values", "covariance", "profile", "members",
               "provenance", "discrepancy")  # fmt: skip
_OPTIONAL_KEYS = ("weight",)
_FILE_KEYS = ("format", "version")
_BASE_KEYS = ("machine", "state", "effects", "options")
_STEP_KEYS = ("name", "fixed", "candidate")
_GP_KEYS = ("kernel", "speed_scale_rpm", "terms")
_TERM_KEYS = ("amplitude", "length_scale", "speed_power", "speeds_rpm", "residuals", "sigmas")
_TERM_OPTIONAL = ("log_marginal_likelihood",)
_PROVENANCE_TEXT = ("data_hash", "verdict", "date", "thermobear_version")


def read_text(path: Any) -> str:
    """The text of the file at ``path``; a missing file, a directory, an
    unreadable file or one that is not UTF-8 text raise a ``ConfigError``
    naming the path."""
    if not isinstance(path, (str, os.PathLike)):
        raise fail("path", path, f"a file path (a str or a Path), not a {type(path).__name__}")
    try:
        p = Path(path)
        if p.is_dir():
            raise ConfigError(
                f"invalid path = {str(p)!r}: a directory, not a calibrated model file"
            )
        data = p.read_bytes()
    except FileNotFoundError:
        raise ConfigError(f"invalid path = {str(path)!r}: no such file") from None
    except (OSError, ValueError) as e:
        why = getattr(e, "strerror", None) or str(e)
        raise ConfigError(f"invalid path = {str(path)!r}: cannot be read ({why})") from None
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as e:
        raise ConfigError(
            f"invalid path = {str(path)!r}: not a calibrated model file (not UTF-8 text: "
            f"byte {e.start} is {data[e.start : e.start + 1]!r})"
        ) from None


def parse(source: Any) -> Any:
    """The JSON of ``source`` (a saved model's text), at most ``MAX_DEPTH``
    levels deep."""
    if not isinstance(source, str):
        raise fail("text", source, f"the JSON text of a saved calibrated model (a str), not a "
                                   f"{type(source).__name__}")  # fmt: skip
    try:
        d = json.loads(source)
    except RecursionError:
        raise ConfigError(
            f"invalid calibrated model = JSON nested too deeply: at most {MAX_DEPTH} levels"
        ) from None
    except ValueError as e:  # json.JSONDecodeError, an integer of too many digits
        raise ConfigError(f"invalid calibrated model = not JSON: {e}") from None
    depth = _depth(d)
    if depth > MAX_DEPTH:
        raise ConfigError(
            f"invalid calibrated model = JSON {depth} levels deep: at most {MAX_DEPTH} levels"
        )
    return d


def _depth(value: Any) -> int:
    """The nesting depth of a parsed JSON value (without recursion)."""
    deepest, stack = 0, [(value, 1)]
    while stack:
        v, level = stack.pop()
        if isinstance(v, dict):
            v = list(v.values())
        if isinstance(v, list):
            deepest = max(deepest, level)
            if level <= MAX_DEPTH:
                stack.extend((x, level + 1) for x in v)
    return deepest


def check_model(d: Any, where: str = "", level: int = 0, header: bool = False) -> None:
    """Check a saved model's fields (the dict of its JSON; with
    ``header``, ``format`` and ``version`` allowed among them); ``where``
    prefixes the field names (``members[1].``)."""
    if level > MAX_NESTED_MODELS:
        raise ConfigError(
            f"invalid {where.rstrip('.')}: models nested more than {MAX_NESTED_MODELS} deep"
        )
    _mapping(where.rstrip(".") or "calibrated model", d)
    known = _MODEL_KEYS + _OPTIONAL_KEYS + (_FILE_KEYS if header else ())
    _keys(where, d, _MODEL_KEYS, known)
    choice(where + "kind", d["kind"], _KINDS)
    text(where + "label", d["label"])
    _check_base(d["base"], where + "base.", level)
    steps = _list(where + "steps", d["steps"])
    cands = []
    for i, s in enumerate(steps):
        at = f"{where}steps[{i}]"
        _mapping(at, s)
        _keys(at + ".", s, _STEP_KEYS, _STEP_KEYS)
        text(at + ".name", s["name"])
        cand = (
            None if s["candidate"] is None else _check_candidate(at + ".candidate", s["candidate"])
        )
        if s["fixed"] is None:
            cands.append((s["name"], cand))
        else:
            _in_bounds(at + ".fixed", real(at + ".fixed", s["fixed"]), cand)
    free = [n for n, _ in cands]
    for i, n in enumerate(free):
        if n in free[:i]:
            raise fail(f"{where}steps", n, "steps of distinct calibrated names (a name repeats)")
    p = len(free)
    shown = ", ".join(free) or "none"
    values = _list(where + "values", d["values"])
    if len(values) != p:
        raise fail(where + "values", values, f"{p} number(s), one per calibrated name ({shown})")
    vals = [real(f"{where}values[{i}]", v) for i, v in enumerate(values)]
    for i, (v, (_, cand)) in enumerate(zip(vals, cands, strict=True)):
        _in_bounds(f"{where}values[{i}]", v, cand)
    _check_profile(where + "profile", d["profile"], p, shown)
    _check_covariance(where + "covariance", d["covariance"], vals, cands, shown)
    members = _list(where + "members", d["members"])
    for i, m in enumerate(members):
        check_model(m, f"{where}members[{i}].", level + 1)
    _check_weights(where, d, members)
    _check_provenance(where + "provenance", d["provenance"])
    if d["discrepancy"] is not None:
        _check_discrepancy(where + "discrepancy", d["discrepancy"])


# -- the parts -----------------------------------------------------------------------


def _mapping(name: str, value: Any) -> dict:
    if not isinstance(value, dict):
        raise fail(name, value, f"a JSON object, not a {_json_type(value)}")
    return value


def _list(name: str, value: Any) -> list:
    if not isinstance(value, list):
        raise fail(name, value, f"a JSON array, not a {_json_type(value)}")
    return value


def _json_type(value: Any) -> str:
    if value is None:
        return "null"
    return {bool: "boolean", int: "number", float: "number", str: "string", list: "array",
            dict: "object"}.get(type(value), type(value).__name__)  # fmt: skip


def _keys(where: str, d: dict, required: tuple, known: tuple) -> None:
    """Every ``required`` key present, none outside ``known``."""
    for k in required:
        if k not in d:
            raise ConfigError(f"invalid {where}{k}: missing (a saved calibrated model holds it)")
    for k in d:
        if k not in known:
            raise ConfigError(
                f"invalid {where}{k}: not a field of a saved calibrated model (fields: "
                f"{', '.join(known)}){did_you_mean(k, known)}"
            )


def _finite_json(name: str, value: Any) -> None:
    """Every number in ``value`` (a JSON value) finite."""
    stack = [(name, value)]
    while stack:
        at, v = stack.pop()
        if isinstance(v, float) and not math.isfinite(v):
            raise fail(at, v, "a finite number")
        if isinstance(v, dict):
            stack.extend((f"{at}.{k}", x) for k, x in v.items())
        elif isinstance(v, list):
            stack.extend((f"{at}[{i}]", x) for i, x in enumerate(v))


def _check_base(b: Any, where: str, level: int) -> None:
    from .protocol import MODEL_KINDS
    from .registry import LOAD_SCALE_OPTIONS

    _mapping(where.rstrip("."), b)
    _keys(where, b, _BASE_KEYS, _BASE_KEYS)
    choice(where + "machine", b["machine"], tuple(MODEL_KINDS))
    _mapping(where + "state", b["state"])
    names(where + "effects", b["effects"])
    opts = _mapping(where + "options", b["options"])
    _finite_json(where + "options", opts)
    for k, v in opts.items():  # the options a downstream call reads as numbers
        if k in LOAD_SCALE_OPTIONS or "@" in k or k.startswith("preload_scale"):
            real(f"{where}options.{k}", v, 0.0)
        elif k == "unbalance_grade" and b["machine"] == "spindle":
            real(f"{where}options.{k}", v, 0.0)
    bearings = opts.get("bearings") if b["machine"] == "gear" else None
    if isinstance(bearings, str) and bearings.lstrip().startswith("{"):
        inner = where + "options.bearings"
        try:
            d = parse(bearings)
        except ConfigError as e:
            raise ConfigError(f"invalid {inner}: {e}") from None
        check_file(d, inner + ".", level + 1)


def check_file(d: Any, where: str = "", level: int = 0) -> None:
    """Check a saved model's JSON as a whole: its ``format`` and
    ``version`` (see ``check_header``), then its fields."""
    check_header(d, where)
    check_model(d, where, level, header=True)


def check_header(d: Any, where: str = "") -> None:
    """The ``format`` is a calibrated model's; the ``version`` one this
    thermobear reads (a newer one is refused by name)."""
    if isinstance(d, dict) and "format" not in d:
        raise ConfigError(
            f"invalid {where}format: missing (a saved calibrated model holds it, "
            f"{FILE_FORMAT!r}): not a saved calibrated model"
        )
    if not isinstance(d, dict) or d.get("format") != FILE_FORMAT:
        fmt = d.get("format") if isinstance(d, dict) else d
        raise fail(where + "format", fmt, f"{FILE_FORMAT!r}: not a saved calibrated model")
    if "version" not in d:
        raise ConfigError(f"invalid {where}version: missing (a saved calibrated model holds it)")
    v = whole(where + "version", d["version"], 1, None)
    if v > FILE_VERSION:
        raise ConfigError(
            f"invalid {where}version = {v}: written by a newer thermobear (this one reads "
            f"version {FILE_VERSION}); update thermobear to load it"
        )
    if v != FILE_VERSION:
        raise fail(where + "version", v, f"{FILE_VERSION}")


def _check_candidate(where: str, c: Any) -> Any:
    """A candidate record: its fields and types; returns it."""
    from .candidates import Candidate

    _mapping(where, c)
    fields = dataclasses.fields(Candidate)
    required = tuple(f.name for f in fields if f.default is dataclasses.MISSING)
    _keys(where + ".", c, required, tuple(f.name for f in fields))
    for f in fields:
        if f.name not in c:
            continue
        at, v = f"{where}.{f.name}", c[f.name]
        if f.name in ("lower", "upper", "null"):
            real(at, v)
        elif f.name == "affects":
            names(at, v)
        elif f.name in ("offset", "relative"):
            if not isinstance(v, bool):
                raise fail(at, v, "true or false")
        else:
            text(at, v)
    choice(where + ".kind", c["kind"], ("switch", "parameter"))
    choice(where + ".side", c["side"], ("model", "measurement"))
    if "role" in c:
        choice(where + ".role", c["role"], ("effect", "calibration", "measurement"))
    if c["lower"] > c["upper"]:
        raise fail(where + ".upper", c["upper"], f">= its lower bound {c['lower']:g}")
    return c


def _in_bounds(name: str, v: float, cand: Optional[dict]) -> None:
    if cand is None:
        return
    lo, hi = float(cand["lower"]), float(cand["upper"])
    tol = BOUND_TOLERANCE * max(hi - lo, abs(lo), abs(hi), 1e-300)
    if not (lo - tol <= v <= hi + tol):
        raise fail(name, v, f"inside its bounds [{lo:g}, {hi:g}] ({cand['name']})")


def _check_profile(where: str, profile: Any, p: int, shown: str) -> None:
    rows = _list(where, profile)
    if len(rows) != p:
        raise fail(where, rows, f"{p} pair(s), one per calibrated name ({shown})")
    for i, r in enumerate(rows):
        at = f"{where}[{i}]"
        if not isinstance(r, list) or len(r) != 2:
            raise fail(at, r, "a pair [lower, upper]")
        for k, x in enumerate(r):
            if isinstance(x, float) and math.isnan(x):
                continue  # not computed
            real(f"{at}[{k}]", x)
        a, b = float(r[0]), float(r[1])
        if a > b:
            raise fail(f"{at}[1]", b, f">= the lower end {a:g}")


def _check_covariance(where: str, cov: Any, vals: list, cands: list, shown: str) -> None:
    p = len(vals)
    rows = _list(where, cov)
    if len(rows) != p or any(not isinstance(r, list) or len(r) != p for r in rows):
        raise fail(where, cov, f"a {p} x {p} matrix, one row and column per calibrated name "
                               f"({shown})")  # fmt: skip
    c = np.empty((p, p))
    for i, r in enumerate(rows):
        for j, x in enumerate(r):
            at = f"{where}[{i}][{j}]"
            if i == j and x == math.inf:
                c[i, j] = x
                continue
            c[i, j] = real(at, x)
    if p == 0:
        return
    diag = np.diag(c).copy()
    unknown = np.isinf(diag)
    for j in np.flatnonzero(unknown).tolist():
        name, cand = cands[j]
        span = float(cand["upper"]) - float(cand["lower"]) if cand is not None else math.inf
        others = np.delete(np.concatenate([c[j], c[:, j]]), [j, p + j])
        if not math.isfinite(span) or np.any(others != 0.0):
            raise fail(
                f"{where}[{j}][{j}]", math.inf,
                "a finite number (an infinite variance marks a value the data do not identify: "
                f"its row and column zero and the value bounded; {name} is not)",
            )  # fmt: skip
    keep = np.flatnonzero(~unknown)
    if keep.size == 0:
        return
    s = c[np.ix_(keep, keep)]
    d = np.diag(s)
    top = float(d.max()) if d.size else 0.0
    for k, j in enumerate(keep.tolist()):
        if d[k] < -COVARIANCE_TOLERANCE * top:
            raise fail(f"{where}[{j}][{j}]", float(d[k]), "a variance >= 0")
        name, cand = cands[j]
        span = float(cand["upper"]) - float(cand["lower"]) if cand is not None else math.nan
        bounded = math.isfinite(span) and span > 0.0
        scale = span if bounded else max(abs(vals[j]), 1.0)
        if math.sqrt(max(d[k], 0.0)) > MAX_STD_PER_SCALE * scale:
            what = f"the span {scale:g} of its bounds" if bounded else f"its value's size {scale:g}"
            raise fail(
                f"{where}[{j}][{j}]", float(d[k]),
                f"a variance of at most {(MAX_STD_PER_SCALE * scale) ** 2:g} (a standard "
                f"deviation of at most {MAX_STD_PER_SCALE:g} times {what}, {name})",
            )  # fmt: skip
    # symmetric and positive semi-definite, to COVARIANCE_TOLERANCE of the
    # variances plus rounding (ROUNDING of the largest variance)
    root = np.sqrt(np.clip(d, 0.0, None))
    slack = ROUNDING * max(top, 0.0)
    gap = np.abs(s - s.T) - (COVARIANCE_TOLERANCE * np.outer(root, root) + slack)
    if np.any(gap > 0.0):
        a, b = np.unravel_index(int(np.argmax(gap)), gap.shape)
        i, j = keep[a], keep[b]
        raise fail(f"{where}[{i}][{j}]", float(c[i, j]),
                   f"equal to {where}[{j}][{i}] = {float(c[j, i]):g} (a covariance is "
                   "symmetric)")  # fmt: skip
    jitter = np.diag(COVARIANCE_TOLERANCE * np.clip(d, 0.0, None) + slack)
    try:
        least = float(np.linalg.eigvalsh(0.5 * (s + s.T) + jitter).min())
    except np.linalg.LinAlgError:
        least = -math.inf
    if not least >= 0.0:
        raise fail(where, c.tolist(), "positive semi-definite (a negative eigenvalue: a "
                                      "variance of some combination below 0)")  # fmt: skip


def _check_weights(where: str, d: dict, members: list) -> None:
    if "weight" in d and d["weight"] is not None:
        real(where + "weight", d["weight"], 0.0, 1.0)
    weights = [m.get("weight") for m in members]
    given = [w for w in weights if w is not None]
    if not given:
        return
    if len(given) != len(weights):
        i = weights.index(None)
        raise ConfigError(
            f"invalid {where}members[{i}].weight: missing (the other members carry weights: "
            "every member or none)"
        )
    total = math.fsum(float(w) for w in given)
    if abs(total - 1.0) > WEIGHT_TOLERANCE:
        raise fail(f"{where}members[*].weight", given, f"weights summing to 1 (sum {total:.6g})")


def _check_provenance(where: str, prov: Any) -> None:
    _mapping(where, prov)
    if "data_sets" in prov:
        names(where + ".data_sets", prov["data_sets"])
    if "n_points" in prov:
        whole(where + ".n_points", prov["n_points"], 0, None)
    for k in _PROVENANCE_TEXT:
        if k in prov:
            text(f"{where}.{k}", prov[k])


def _check_discrepancy(where: str, disc: Any) -> None:
    from .discrepancy import KERNELS, MAX_LENGTH_SCALE, MAX_SPEED_POWER, hyperparameter_bounds

    _mapping(where, disc)
    for k in ("label", "physics"):
        if k in disc:
            text(f"{where}.{k}", disc[k])
    if "quantities" in disc:
        names(where + ".quantities", disc["quantities"])
    if "n_parameters" in disc:
        whole(where + ".n_parameters", disc["n_parameters"], 0, None)
    if "chi2" in disc:
        real(where + ".chi2", disc["chi2"], 0.0)
    if "delta_bic" in disc:
        real(where + ".delta_bic", disc["delta_bic"])
    gp = disc.get("gaussian_process")
    if gp is None:
        return
    at = where + ".gaussian_process"
    _mapping(at, gp)
    if not gp:
        return
    _keys(at + ".", gp, _GP_KEYS, _GP_KEYS)
    choice(at + ".kernel", gp["kernel"], KERNELS)
    top = real(at + ".speed_scale_rpm", gp["speed_scale_rpm"], 0.0, open_lo=True)
    for q, term in _mapping(at + ".terms", gp["terms"]).items():
        t = f"{at}.terms.{q}"
        _mapping(t, term)
        _keys(t + ".", term, _TERM_KEYS, _TERM_KEYS + _TERM_OPTIONAL)
        sp = reals(t + ".speeds_rpm", term["speeds_rpm"], 0.0)
        res = reals(t + ".residuals", term["residuals"])
        sig = reals(t + ".sigmas", term["sigmas"])
        if not sp.size == res.size == sig.size:
            raise fail(t + ".residuals", term["residuals"],
                       f"{sp.size} number(s), one per speed (and as many sigmas)")  # fmt: skip
        for i, x in enumerate(sig):
            if not x > 0.0:
                raise fail(f"{t}.sigmas[{i}]", float(x), "a finite number > 0")
        (_, a_hi), _, _ = hyperparameter_bounds(sp / top, res, sig)
        slack = 1.0 + 1e-6
        real(t + ".amplitude", term["amplitude"], 0.0, a_hi * slack, open_lo=True)
        real(t + ".length_scale", term["length_scale"], 0.0, MAX_LENGTH_SCALE * slack,
             open_lo=True)  # fmt: skip
        real(t + ".speed_power", term["speed_power"], 0.0, MAX_SPEED_POWER)
        if "log_marginal_likelihood" in term:
            real(t + ".log_marginal_likelihood", term["log_marginal_likelihood"])


def check_machine(machine: str, native: Any, where: str = "") -> None:
    """A restored bearing's geometry through the checks of the bearing
    constructors (``Bearing.deep_groove``, ``Bearing.angular_contact``):
    the saved state is rebuilt without them, so a tampered dimension (a
    pitch diameter of 0) would otherwise pass. The rebuilt bearing is
    discarded; the restored one is kept (bit-identical results)."""
    import warnings

    from ..bearing import Bearing

    if machine != "bearing":
        return
    b = Bearing(native)
    g = b.geometry
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            common: dict[str, Any] = dict(
                ball_count=whole("ball_count", g["ball_count"], 1),
                ball_diameter_mm=g["ball_diameter_mm"], pitch_diameter_mm=g["pitch_diameter_mm"],
                inner_conformity=g["inner_conformity"], outer_conformity=g["outer_conformity"],
                bore_mm=g["bore_mm"], outer_diameter_mm=g["outer_diameter_mm"],
                width_mm=g["width_mm"], ring_material=b.ring_material,
                ball_material=b.ball_material, name=b.name,
            )  # fmt: skip
            if b.bearing_type == "deep-groove":
                Bearing.deep_groove(**common, diametral_clearance_mm=g["diametral_clearance_mm"])
            else:
                Bearing.angular_contact(
                    **common, free_contact_angle_deg=g["free_contact_angle_deg"]
                )
    except ConfigError as e:
        raise ConfigError(f"invalid {where}base.state: the saved bearing: {e}") from None

"""A calibrated model as an object: [`CalibratedModel`][thermobear.CalibratedModel] -- the
model spec with the accepted settings, the estimate of each calibrated
value with its linearised covariance and profile interval, one member per
explanation for a tie or an "unresolved" verdict, and its provenance.

It stands for its bearing or spindle in every downstream call
(``thermobear.thermal_state``, ``stiffness_curve``, ``transient``,
``vibration``, ``GearSystem(bearings=...)``) through the hook
``_thermobear_model_()`` (see ``thermobear._model_hook`` for the rules),
pickles, and saves to and loads from JSON.

Covariance: ``phi (J^T J)^-1``, J the Jacobian of the weighted residuals
(residual / sigma) against the calibrated values at the estimate, phi =
max(1, chi^2 / (n - p)) the stretch the profile intervals use."""

from __future__ import annotations

import dataclasses
import datetime
import hashlib
import json
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal, Mapping, Optional, Sequence, Union

import numpy as np

from ..errors import ConfigError
from .candidates import Candidate
from .model_file import FILE_FORMAT, FILE_VERSION  # the saved form's format and version
from .protocol import ModelSpec
from .setting import _Setting

if TYPE_CHECKING:
    import polars

ModelKind = Literal["calibration", "named", "tie", "unresolved", "nothing"]

_INTERVAL_COLUMNS = ("name", "value", "lower_95", "upper_95", "std", "lower", "upper")


@dataclasses.dataclass(frozen=True)
class _Step:
    """One candidate applied to the baseline, in order: calibrated (its
    value among ``CalibratedModel.values``) or held ``fixed`` (a switch
    on, an earlier round's value). ``cand`` None: a value of another data
    set that does not act on this model."""

    name: str
    cand: Optional[Candidate]
    fixed: Optional[float] = None


class CalibratedModel:
    """A calibrated model (``Calibration.model``, ``Diagnosis.model``).

    ``kind``: "calibration" (of [`calibrate`][thermobear.calibrate]), "named"
    (the candidates a diagnosis accepted), "tie", "unresolved" (then
    ``members`` holds one model per explanation, the generic smooth control
    among them, labelled so) or "nothing" (the baseline); ``label``;
    ``spec``: the model spec at the estimate; ``names``, ``values``: the
    calibrated values (``name`` or ``name@set``); ``covariance`` (p x p,
    linearised); ``intervals``: ``name``, ``value``, ``lower_95``,
    ``upper_95`` (profile likelihood), ``std`` (square root of the
    covariance's diagonal), ``lower``, ``upper`` (bounds); ``members``;
    ``provenance``: ``data_sets``, ``data_hash`` (SHA-256 of the measured
    tables), ``n_points``, ``verdict``, ``date`` (ISO 8601),
    ``thermobear_version``; ``discrepancy``: for the generic-control
    member, what the unknown smooth term is and, under
    ``"gaussian_process"``, its model-discrepancy term -- a Gaussian
    process in speed per measured quantity fitted to the residuals on the
    training points (``thermobear.diagnosis.discrepancy``), which
    [`predict`][thermobear.predict.band.predict] adds to the baseline with
    its band (else None).

    Sensor offsets and gains are measurement-side: they are among the
    calibrated values but do not change the spec or any downstream
    prediction."""

    def __init__(
        self,
        kind: ModelKind,
        label: str,
        base: ModelSpec,
        steps: Sequence[_Step],
        values: Any,
        covariance: Any,
        profile: Optional[Sequence[tuple[float, float]]] = None,
        members: Sequence[CalibratedModel] = (),
        provenance: Optional[dict] = None,
        discrepancy: Optional[dict] = None,
    ) -> None:
        self.kind: ModelKind = kind
        self.label = str(label)
        self._base = base
        self._steps = tuple(steps)
        self.names: tuple[str, ...] = tuple(s.name for s in self._steps if s.fixed is None)
        self.values = np.asarray(values, dtype=float).reshape(len(self.names))
        p = len(self.names)
        self.covariance = np.asarray(covariance, dtype=float).reshape(p, p)
        self._profile = [tuple(map(float, b)) for b in (profile or [(np.nan, np.nan)] * p)]
        self.members: tuple[CalibratedModel, ...] = tuple(members)
        self.provenance: dict = dict(provenance or {})
        self.discrepancy = discrepancy
        #: A member's weight in the mixture of its tie or "unresolved"
        #: model (pseudo-BMA+ weight of its cross-validated predictive densities,
        #: ``thermobear.diagnosis.weights``); None: not weighed.
        self.weight: Optional[float] = None
        self.spec: ModelSpec = self.spec_at(self.values)

    @property
    def intervals(self) -> polars.DataFrame:
        """One row per calibrated value (see the class docstring)."""
        import polars as pl

        free = [s for s in self._steps if s.fixed is None]
        std = np.sqrt(np.clip(np.diag(self.covariance), 0.0, None))
        rows = [
            (s.name, float(v), a, b, float(e), *_bounds(s.cand))
            for s, v, (a, b), e in zip(free, self.values, self._profile, std, strict=True)
        ]
        schema = dict.fromkeys(_INTERVAL_COLUMNS, pl.Float64) | {"name": pl.Utf8}
        return pl.DataFrame(rows, schema=schema, orient="row")

    def _setting(self, values: Any) -> _Setting:
        """The setting of ``values`` (in ``names`` order), offsets included."""
        vals = iter(np.asarray(values, dtype=float).tolist())
        st, opts = _Setting(), dict(self._base.options)
        for s in self._steps:
            v = s.fixed if s.fixed is not None else next(vals)
            if s.cand is not None:
                st = st.apply(s.cand, float(v), opts)
        return st

    def spec_at(self, values: Union[Mapping[str, float], Any]) -> ModelSpec:
        """The spec with ``values`` applied as the calibration applied them:
        an array in ``names`` order, or a mapping name -> value (the names
        left out keep their estimates)."""
        if isinstance(values, Mapping):
            v = self.values.copy()
            for k, x in values.items():
                if k not in self.names:
                    raise ConfigError(f"invalid name = {k!r}: calibrated: {', '.join(self.names)}")
                v[self.names.index(k)] = float(x)
        else:
            v = np.asarray(values, dtype=float).ravel()
            if v.size != len(self.names):
                raise ConfigError(
                    f"invalid values = {v.tolist()}: give {len(self.names)} value(s), one per "
                    f"name ({', '.join(self.names)})"
                )
        st = self._setting(v)
        return self._base.with_setting(st.effects, **dict(st.options))

    def model(self) -> tuple[Any, dict]:
        """``(machine, options)`` for downstream calls: the
        [`Bearing`][thermobear.Bearing] and the keywords of
        [`thermal_state`][thermobear.thermal_state] (``effects`` and the
        thermal options) with the load scales; or the
        [`Spindle`][thermobear.Spindle] configured at its stated preload
        (scaled) with ``effects``, ``unbalance_grade`` and the preload
        scales; or the [`GearPair`][thermobear.GearPair] with its calibrated
        [`GearSystem`][thermobear.GearSystem] inputs (and, under
        ``"_defaults"``, the stiffness case, torque and bearings a call may
        change)."""
        return machine_options(self.spec)

    _thermobear_model_ = model

    def save(self, path: Union[str, Path]) -> Path:
        """Write the model to ``path`` as JSON (the machine in its exact
        serialised form, the baseline's effects and options, the applied
        candidates, the estimates, covariance, intervals, members,
        provenance); returns the path."""
        out = Path(path)
        out.write_text(self.to_json() + "\n")
        return out

    def to_json(self) -> str:
        """The saved form as JSON text (what [`save`][thermobear.CalibratedModel.save]
        writes; the same model gives the same text)."""
        return json.dumps({"format": FILE_FORMAT, "version": FILE_VERSION, **_to_dict(self)})

    @classmethod
    def from_json(cls, text: str) -> CalibratedModel:
        """The model of a saved form's JSON text (see
        [`to_json`][thermobear.CalibratedModel.to_json]), every field
        checked first (``thermobear.diagnosis.model_file``): a
        [`ConfigError`][thermobear.ConfigError] names the first bad one."""
        from .model_file import check_file, parse

        d = parse(text)
        check_file(d)
        try:
            return _from_dict(d)
        except (ValueError, TypeError, KeyError, OverflowError) as e:  # past the checks
            raise ConfigError(f"invalid calibrated model = its fields do not fit: {e}") from None

    @classmethod
    def load(cls, path: Union[str, Path]) -> CalibratedModel:
        """Read a model written by [`save`][thermobear.CalibratedModel.save],
        every field checked first: a missing, unreadable or damaged file
        raises a [`ConfigError`][thermobear.ConfigError] naming the path
        and the field."""
        from .model_file import read_text

        source = read_text(path)
        try:
            return cls.from_json(source)
        except ConfigError as e:
            raise ConfigError(f"{e} (in {str(path)!r})") from None

    def summary(self) -> str:
        """The model in a few lines: kind and label, each calibrated value
        with its standard deviation and 95 % interval, the members, the
        provenance."""
        lines = [f"calibrated model ({self.kind}): {self.label}"]
        for r in self.intervals.iter_rows(named=True):
            lines.append(
                f"  {r['name']} = {r['value']:.4g} +/- {r['std']:.3g}  95 % "
                f"[{r['lower_95']:.4g}, {r['upper_95']:.4g}]"
            )
        lines += [
            f"  member: {m.label}" + ("" if m.weight is None else f" (weight {m.weight:.2f})")
            for m in self.members
        ]
        p = self.provenance
        if p:
            lines.append(
                f"  data: {', '.join(map(str, p.get('data_sets', [])))} "
                f"({p.get('n_points', '?')} points, sha256 {str(p.get('data_hash', ''))[:12]}); "
                f"{p.get('date', '')}, thermobear {p.get('thermobear_version', '')}"
            )
            if p.get("verdict"):
                lines.append(f"  verdict: {p['verdict']}")
        return "\n".join(lines)

    def __eq__(self, other: object) -> bool:
        """Equal when the saved forms are (machine, settings, values to the
        last bit, members, provenance)."""
        if not isinstance(other, CalibratedModel):
            return NotImplemented
        return json.dumps(_to_dict(self)) == json.dumps(_to_dict(other))

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        vals = ", ".join(f"{n}={v:.4g}" for n, v in zip(self.names, self.values, strict=True))
        more = f"; {len(self.members)} members" if self.members else ""
        return f"CalibratedModel({self.kind}: {self.label!r}; {vals or 'no values'}{more})"


def _bounds(c: Optional[Candidate]) -> tuple[float, float]:
    return (float("nan"), float("nan")) if c is None else (float(c.lower), float(c.upper))


def machine_options(spec: Any) -> tuple[Any, dict]:
    """``(machine, options)`` of a bearing, spindle or gear spec (see
    ``CalibratedModel.model``)."""
    from .registry import LOAD_SCALE_OPTIONS

    if hasattr(spec, "bearing") and hasattr(spec, "thermal_options"):
        opts: dict[str, Any] = {"effects": list(spec.effects), **spec.thermal_options()}
        for k, v in spec.options.items():
            if k in LOAD_SCALE_OPTIONS or "@" in k:
                opts[k] = float(v)
        return spec.bearing, opts
    if hasattr(spec, "configured"):
        o = spec.options
        unbalance = spec.unbalance() if hasattr(spec, "unbalance") else {}
        opts = {"effects": list(spec.effects), "unbalance_grade": float(o["unbalance_grade"])}
        if unbalance.get("unbalance_g_mm") is not None:  # declared: the rotor's g mm
            opts = {"effects": list(spec.effects), "unbalance_g_mm": unbalance["unbalance_g_mm"]}
        opts |= {k: float(v) for k, v in o.items() if k.startswith("preload_scale")}
        return spec.configured(spec.spindle.preload_n), opts
    if hasattr(spec, "gear") and hasattr(spec, "system_options"):
        # the pair's calibrated inputs; the stiffness case, the torque and the
        # bearings are defaults a call may change (conditions, not inputs)
        opts = spec.system_options()
        opts.pop("torque_n_m", None)
        defaults = {"stiffness": spec.options["stiffness"], "bearings": spec.bearing_model()}
        if spec.options["torque_n_m"] is not None:
            defaults["torque_n_m"] = float(spec.options["torque_n_m"])
        return spec.gear, {**opts, GEAR_DEFAULTS_KEY: defaults}
    raise ConfigError(f"invalid spec = {spec!r}: a bearing or spindle model spec has no machine")


def linear_covariance(jac: Any, phi: float) -> np.ndarray:
    """``phi (J^T J)^-1`` (pseudo-inverse: a direction no data point moves
    gets no variance from the data)."""
    j = np.asarray(jac, dtype=float)
    return float(phi) * np.linalg.pinv(j.T @ j)


def provenance(labels: Sequence[str], tables: Sequence[Any], verdict: str = "") -> dict:
    """The provenance record: data-set labels, the SHA-256 of the measured
    tables (CSV text), the number of points, the verdict, the date (UTC,
    ISO 8601) and the thermobear version."""
    from .. import _native

    h = hashlib.sha256()
    for t in tables:
        h.update(t.write_csv().encode())
    return {
        "data_sets": [str(x) for x in labels],
        "data_hash": h.hexdigest(),
        "n_points": int(sum(t.height for t in tables)),
        "verdict": str(verdict),
        "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "thermobear_version": str(_native.__version__),
    }


def fd_covariance(base: ModelSpec, steps: Sequence[_Step], values: Any, data: Any) -> np.ndarray:
    """The linearised covariance of ``values`` from a finite-difference
    Jacobian of ``data``'s weighted residuals (``weighted_jacobian``)."""
    r0, jac = weighted_jacobian(base, steps, values, data)
    phi = max(1.0, float(r0 @ r0) / max(len(r0) - len(np.atleast_1d(values)), 1))
    return linear_covariance(jac, phi)


def weighted_jacobian(
    base: ModelSpec, steps: Sequence[_Step], values: Any, data: Any
) -> tuple[np.ndarray, np.ndarray]:
    """``data``'s weighted residuals (residual / sigma) at ``values`` and
    their finite-difference Jacobian against the free steps (a step of
    1e-4 of each value's bound span, inward at a bound)."""
    from .setting import _predict

    probe = CalibratedModel("named", "", base, steps, values, np.zeros((len(values),) * 2))
    free = [s.cand for s in steps if s.fixed is None]

    def resid(v: np.ndarray) -> np.ndarray:
        return data.residual(_predict(base, probe._setting(v), data.cond, data.quantity))

    v0 = np.asarray(values, dtype=float)
    r0 = resid(v0)
    jac = np.zeros((len(r0), len(v0)))
    for j, c in enumerate(free):
        lo, hi = _bounds(c)
        h = 1e-4 * (hi - lo) if np.isfinite(hi - lo) and hi > lo else 1e-6 * max(abs(v0[j]), 1.0)
        h = -h if v0[j] + h > hi else h
        v = v0.copy()
        v[j] += h
        jac[:, j] = (resid(v) - r0) / h
    return r0, jac


def _plain(v: Any) -> Any:
    if isinstance(v, (np.floating, np.integer)):
        return v.item()
    if isinstance(v, (tuple, list)):
        return [_plain(x) for x in v]
    if isinstance(v, dict):
        return {k: _plain(x) for k, x in v.items()}
    return v


#: The key under which a calibrated gear model's options carry the
#: settings a call may change (stiffness case, torque, bearings).
GEAR_DEFAULTS_KEY = "_defaults"


def _machine_state(spec: Any) -> dict:
    if hasattr(spec, "gear") and hasattr(spec, "system_options"):
        return {"machine": "gear", "state": spec.gear._g.__reduce__()[1][0]}
    if hasattr(spec, "bearing"):
        return {"machine": "bearing", "state": spec.bearing._b.__reduce__()[1][0]}
    return {"machine": "spindle", "state": spec.spindle._native.__reduce__()[1][0]}


def _to_dict(m: CalibratedModel) -> dict:
    steps = [
        {"name": s.name, "fixed": s.fixed,
         "candidate": None if s.cand is None else _plain(dataclasses.asdict(s.cand))}
        for s in m._steps
    ]  # fmt: skip
    base = m._base
    return {
        "kind": m.kind,
        "label": m.label,
        "base": {
            **_machine_state(base),
            "effects": list(base.effects),
            "options": {k: _plain(v) for k, v in base.options.items()},
        },
        "steps": steps,
        "values": m.values.tolist(),
        "covariance": m.covariance.tolist(),
        "profile": [list(b) for b in m._profile],
        "members": [_to_dict(x) for x in m.members],
        "provenance": m.provenance,
        "discrepancy": m.discrepancy,
        **({} if m.weight is None else {"weight": float(m.weight)}),
    }


def _base_from(d: dict, where: str = "") -> ModelSpec:
    from .. import _native
    from .model_file import check_machine
    from .protocol import MODEL_KINDS

    if d["machine"] not in MODEL_KINDS:
        raise ConfigError(f"invalid machine = {d['machine']!r}: known: {', '.join(MODEL_KINDS)}")
    model_class, spec_class, _ = MODEL_KINDS[d["machine"]]
    try:
        native = _native._restore(d["state"])
    except ConfigError as e:
        raise ConfigError(f"invalid {where}base.state: {e}") from None
    check_machine(d["machine"], native, where)
    build: Any = spec_class  # a registered spec: (machine, effects=..., **options)
    try:
        return build(model_class(native), effects=d["effects"], **d["options"])
    except ConfigError as e:
        raise ConfigError(f"invalid {where}base.effects or base.options: {e}") from None


def _from_dict(d: dict, where: str = "") -> CalibratedModel:
    steps = []
    for s in d["steps"]:
        c = s["candidate"]
        cand = None if c is None else Candidate(**{**c, "affects": tuple(c["affects"])})
        steps.append(_Step(s["name"], cand, s["fixed"]))
    m = CalibratedModel(
        d["kind"], d["label"], _base_from(d["base"], where), steps, d["values"], d["covariance"],
        [tuple(b) for b in d["profile"]],
        [_from_dict(x, f"{where}members[{i}].") for i, x in enumerate(d["members"])],
        d["provenance"], d["discrepancy"],
    )  # fmt: skip
    w = d.get("weight")
    m.weight = None if w is None else float(w)
    return m


def calibration_models(prob: Any, theta: Any, jac: Any, intervals: Any, phi: float) -> list:
    """One [`CalibratedModel`][thermobear.CalibratedModel] per data set of a
    joint calibration (``prob``: its problem, ``theta``, ``jac`` at the
    optimum, the profile ``intervals``, the stretch ``phi``): every
    calibrated value in the names (``name`` or ``name@set``), those of
    other sets not acting on the set's spec."""
    cov = linear_covariance(jac, phi)
    labels = [label for label, _, _ in prob.sets]
    prov = provenance(labels, [d.df for d in prob.data], "joint calibration")
    out = []
    for i, (label, spec, _) in enumerate(prob.sets):
        steps = [
            _Step(s.name if s.label == "all" else f"{s.name}@{s.label}", s.cands.get(i))
            for s in prob.slots
        ]
        tag = ", ".join(st.name for st in steps)
        out.append(
            CalibratedModel(
                "calibration",
                f"{tag} on {label}",
                spec,
                steps,
                theta,
                cov,
                intervals,
                provenance=prov,
            )  # fmt: skip
        )
    return out


def _steps_of(records: Sequence[dict], cands: Mapping[str, Candidate], free: bool) -> list:
    """Steps of accepted records in order: parameters calibrated (``free``)
    or fixed at their values; switches fixed on."""
    return [
        _Step(r["name"], cands[r["name"]],
              None if free and cands[r["name"]].kind == "parameter"
              else (1.0 if cands[r["name"]].kind == "switch" else float(r["value"])))
        for r in records
    ]  # fmt: skip


def _f(x: Any) -> float:
    return float("nan") if x is None else float(x)


def _member(
    kind: ModelKind, label: str, base: Any, steps: list, records: Sequence[dict], data: Any,
    prov: dict, discrepancy: Optional[dict] = None,
) -> CalibratedModel:  # fmt: skip
    """A model of the calibrated ``steps``; values and profile intervals
    from ``records`` (one per free step, in order), covariance from the
    data's Jacobian."""
    values = [float(r["value"]) for r in records]
    profile = [(_f(r["lower_95"]), _f(r["upper_95"])) for r in records]
    cov = fd_covariance(base, steps, values, data) if values else np.zeros((0, 0))
    return CalibratedModel(
        kind, label, base, steps, values, cov, profile, provenance=prov, discrepancy=discrepancy
    )


def _with_members(kind: ModelKind, label: str, members: list, prov: dict) -> CalibratedModel:
    m0 = members[0]
    return CalibratedModel(
        kind, label, m0._base, m0._steps, m0.values, m0.covariance, m0._profile, members, prov,
        m0.discrepancy,
    )  # fmt: skip


def _candidates(s: Any, names: Sequence[str]) -> dict:
    """The candidates of a diagnosis' search by name (those the search
    withdrew from its pool rebuilt from the model)."""
    from .candidates import candidate_pool

    by_name = {c.name: c for c in [*s.accepted_cands, *s.pool]}
    missing = [n for n in dict.fromkeys(names) if n not in by_name]
    if missing:
        by_name |= {c.name: c for c in candidate_pool(s.model, s.data.quantity, missing, None)}
    return by_name


def diagnosis_model(s: Any, verdict: str) -> CalibratedModel:
    """The calibrated model of a diagnosis' search ``s`` (its spec, data,
    accepted records, tie and unresolved state) with the ``verdict``."""
    d = s.data
    prov = provenance(["measured"], [d.df], verdict)
    if s.unresolved is not None:
        return _unresolved_model(s, prov)
    if s.tie:
        return _tie_model(s, prov)
    cands = _candidates(s, [r["name"] for r in s.accepted])
    steps = _steps_of(s.accepted, cands, True)
    free = [r for r in s.accepted if cands[r["name"]].kind == "parameter"]
    label = " + ".join(r["name"] for r in s.accepted) or "baseline"
    return _member("named" if s.accepted else "nothing", label, s.model, steps, free, d, prov)


def with_discrepancy(desc: dict, base: Any, steps: Sequence[_Step], data: Any) -> dict:
    """The description ``desc`` of the unknown smooth term with its
    model-discrepancy term under ``"gaussian_process"``: a Gaussian
    process in speed per measured quantity (``fit_discrepancy``) fitted
    to the residuals of ``base`` with the fixed ``steps`` on the training
    points of ``data`` (all of them when none is held out), the
    measurement sigmas as noise."""
    from .discrepancy import fit_discrepancy
    from .setting import _predict

    probe = CalibratedModel("named", "", base, steps, [], np.zeros((0, 0)))
    pred = _predict(base, probe._setting([]), data.cond, data.quantity)
    train = data.train if data.held.any() else np.ones(data.n, dtype=bool)
    speeds = data.cond["speed_rpm"].to_numpy()[train]
    gp = fit_discrepancy(speeds, data.quantity[train], (data.y - pred)[train], data.s[train])
    return {**desc, "gaussian_process": gp}


def _unresolved_model(s: Any, prov: dict) -> CalibratedModel:
    """Members: the named set, each alternative alone, the generic control
    (the baseline with the discrepancy term: ``with_discrepancy``)."""
    records, _, ctrl, _, _ = s.unresolved
    cands = _candidates(s, [r["name"] for r in records])
    named = [r for r in records if not r.get("alternative")]
    members = []
    groups = [("named: ", named)] + [("alternative: ", [r]) for r in records
                                     if r.get("alternative")]  # fmt: skip
    for tag, group in groups:
        free = [r for r in group if cands[r["name"]].kind == "parameter"]
        label = tag + " + ".join(r["name"] for r in group)
        members.append(
            _member("named", label, s.model, _steps_of(group, cands, True), free, s.data, prov)
        )
    disc = {"label": ctrl.label, "quantities": list(ctrl.quantities),
            "n_parameters": int(ctrl.n_parameters), "chi2": float(ctrl.chi2),
            "delta_bic": float(ctrl.delta_bic)}  # fmt: skip
    members.append(_unknown_member("generic_control: ", s, [], disc, prov))
    return _weighed("unresolved", "unresolved: " + members[0].label, members, s.data, prov)


def _unknown_member(
    tag: str, s: Any, fixed: list, desc: dict, prov: dict
) -> CalibratedModel:  # fmt: skip
    """The member of an unknown effect on top of the ``fixed`` steps: on a
    bearing, an unknown heat source with its own speed law fitted to the
    data (``thermobear.diagnosis.unknown_heat``) and a Gaussian-process
    discrepancy for what it leaves; elsewhere the discrepancy alone."""
    from .unknown_heat import fit_unknown_heat, supports_unknown_heat

    if not supports_unknown_heat(s.model):
        disc = with_discrepancy(desc, s.model, fixed, s.data)
        return _member("named", f"{tag}{desc['label']}", s.model, fixed, [], s.data, prov, disc)
    probe = CalibratedModel("named", "", s.model, fixed, [], np.zeros((0, 0)))
    (lin, quad, rc), ref, coef, chi2 = fit_unknown_heat(s.model, probe._setting([]), s.data)
    steps = [*fixed, _Step(rc.name, rc, ref), _Step(lin.name, lin), _Step(quad.name, quad)]
    cov = fd_covariance(s.model, steps, coef, s.data)
    sd = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    records = [
        {"value": float(v), "lower_95": float(v - 1.96 * e), "upper_95": float(v + 1.96 * e)}
        for v, e in zip(coef, sd, strict=True)
    ]
    held = [_Step(st.name, st.cand, float(v)) for st, v in zip(
        [st for st in steps if st.fixed is None], coef, strict=True)]  # fmt: skip
    label = "an unknown heat source with its own speed law"
    desc = {**desc, "label": label, "physics": "unknown_heat_source", "chi2": chi2}
    disc = with_discrepancy(desc, s.model, [*[st for st in steps if st.fixed is not None], *held],
                            s.data)  # fmt: skip
    return _member("named", f"{tag}{label}", s.model, steps, records, s.data, prov, disc)


def _weighed(
    kind: ModelKind, label: str, members: list, data: Any, prov: dict
) -> CalibratedModel:  # fmt: skip
    """The model of ``members`` with each member's weight from its
    cross-validated predictive density (pseudo-BMA+:
    ``thermobear.diagnosis.weights``)."""
    from .weights import loo_log_density, pseudo_bma_weights

    lpd = []
    for m in members:
        r, jac = weighted_jacobian(m._base, m._steps, m.values, data)
        gp = (m.discrepancy or {}).get("gaussian_process")
        lpd.append(loo_log_density(r, jac, data, gp))
    for m, w in zip(members, pseudo_bma_weights(np.column_stack(lpd)), strict=True):
        m.weight = float(w)
    out = _with_members(kind, label, members, prov)
    out.weight = None
    return out


def _tie_model(s: Any, prov: dict) -> CalibratedModel:
    """Members: each tie member added alone to the setting the rounds
    reached (earlier accepted values held), the generic control when it
    ties too."""
    names = [n for n in s.tie if n != "generic_control"]
    cands = _candidates(s, [r["name"] for r in s.accepted] + names)
    fixed = _steps_of(s.accepted, cands, False)
    rows = {r["candidate"]: r for r in s.ties.iter_rows(named=True)} if s.ties is not None else {}
    members = []
    for i, n in enumerate(s.tie, start=1):
        if n == "generic_control":
            disc = {"label": "an unknown smooth effect", "quantities": [], "n_parameters": 0}
            members.append(_unknown_member(f"tie member {i}: generic_control: ", s, fixed,
                                           disc, prov))  # fmt: skip
            continue
        c, r = cands[n], rows.get(n, {"value": 1.0, "lower_95": None, "upper_95": None})
        step = _Step(n, c) if c.kind == "parameter" else _Step(n, c, 1.0)
        free = [r] if c.kind == "parameter" else []
        label = f"tie member {i}: {n}"
        members.append(_member("named", label, s.model, [*fixed, step], free, s.data, prov))
    return _weighed("tie", "tie: " + " | ".join(s.tie), members, s.data, prov)

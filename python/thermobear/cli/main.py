"""The ``thermobear`` command line."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path


def _cmd_demo(args: argparse.Namespace) -> int:
    from ..studies.demo import run_demo

    out = run_demo(Path(args.out), quick=args.quick)
    print(f"thermobear demo: results written to {out.resolve()}")
    return 0


def _cmd_solve(args: argparse.Namespace) -> int:
    from .solve import solve_config

    out = solve_config(Path(args.config), Path(args.out))
    print(f"thermobear solve: results written to {out.resolve()}")
    return 0


def _cmd_presets(args: argparse.Namespace) -> int:
    from ..bearing import Bearing, Material
    from ..config import seed_config_names
    from ..spindle import Spindle

    print("bearings: " + ", ".join(Bearing.preset_names()))
    print("spindles: " + ", ".join(Spindle.preset_names()))
    print("materials: " + ", ".join(Material.preset_names()))
    print("seed configurations: " + ", ".join(seed_config_names()))
    return 0


def _cmd_effects(args: argparse.Namespace) -> int:
    from ..diagnosis import effect_registry

    for r in effect_registry().iter_rows(named=True):
        bounds = (
            "on/off"
            if r["parameter"] == "on"
            else (f"{r['parameter']} {r['lower']:g}..{r['upper']:g} {r['unit']}")
        )
        print(f"{r['name']:34s} {r['kind']:6s} {r['models']:22s} {bounds:38s} {r['description']}")
    return 0


def _cmd_diagnose(args: argparse.Namespace) -> int:
    from .diagnose import diagnose_files

    out = Path(args.out) if args.out else None
    d, files = diagnose_files(
        Path(args.measured),
        Path(args.model) if args.model else None,
        out,
        spindle=args.spindle,
        without=args.without or (),
    )
    print(d.summary())
    if out is not None:
        print(f"thermobear diagnose: {len(files)} files written to {out.resolve()}")
    return 0


def _cmd_study(args: argparse.Namespace) -> int:
    from .study import run_study_file

    report = run_study_file(
        Path(args.grid),
        Path(args.out),
        scheduler=args.scheduler,
        progress=False if args.no_progress else None,
        overwrite=args.overwrite,
    )
    print(f"thermobear study: {report}")
    return 0


def _add_study(sub: argparse._SubParsersAction) -> None:
    st = sub.add_parser(
        "study", help="run a design study (grid in TOML) into parquet chunks; resumes"
    )
    st.add_argument("grid", help="path to the study's .toml ([study], [grid], [fixed])")
    st.add_argument("--out", required=True, help="results folder (manifest + chunks/*.parquet)")
    st.add_argument("--scheduler", default=None, help="Dask scheduler address (tcp://host:8786)")
    st.add_argument("--no-progress", action="store_true", help="no progress bar")
    st.add_argument(
        "--overwrite", action="store_true", help="replace the results of another grid in --out"
    )
    st.set_defaults(func=_cmd_study)


def _cmd_validate(args: argparse.Namespace) -> int:
    from .validate import validate_command

    return validate_command(Path(args.out), args.sets)


def main(argv: Sequence[str] | None = None) -> int:
    p = argparse.ArgumentParser(
        prog="thermobear",
        description="Thermally coupled bearing stiffness and drive dynamics.",
    )
    sub = p.add_subparsers(dest="command", required=True)
    d = sub.add_parser("demo", help="run the built-in seed studies and write tables and figures")
    d.add_argument("--out", default="thermobear-out", help="output folder (default: %(default)s)")
    d.add_argument("--quick", action="store_true", help="coarser sweeps (for tests)")
    d.set_defaults(func=_cmd_demo)
    s = sub.add_parser("solve", help="solve a system description (TOML)")
    s.add_argument("config", help="path to the .toml system description")
    s.add_argument("--out", default="thermobear-out", help="output folder (default: %(default)s)")
    s.set_defaults(func=_cmd_solve)
    sub.add_parser("presets", help="list built-in bearings, materials and seeds").set_defaults(
        func=_cmd_presets
    )
    sub.add_parser("effects", help="list the named physical effects").set_defaults(
        func=_cmd_effects
    )
    g = sub.add_parser("diagnose", help="name the effect missing between model and measurements")
    g.add_argument("measured", help="tidy measurement table (.csv or .parquet)")
    base = g.add_mutually_exclusive_group(required=True)
    base.add_argument("--model", help="system description (.toml) of a bearing baseline")
    base.add_argument(
        "--spindle", help="spindle preset of the baseline (thermobear presets lists them)"
    )
    g.add_argument(
        "--without",
        action="append",
        metavar="EFFECT",
        help="switch an effect off in the baseline (repeatable; thermobear effects lists them; "
        "'thermal_displacement' = the five thermal expansions of a spindle)",
    )
    g.add_argument("--out", default=None, help="folder for tables and figures")
    g.set_defaults(func=_cmd_diagnose)
    _add_study(sub)
    v = sub.add_parser("validate", help="model, diagnose and calibrate the published data sets")
    v.add_argument("sets", nargs="*", metavar="SET", help="set names (default: all)")
    v.add_argument(
        "--out", default="thermobear-validation", help="report folder (default: %(default)s)"
    )
    v.set_defaults(func=_cmd_validate)
    args = p.parse_args(argv)
    from ..errors import ThermobearError

    try:
        return int(args.func(args))
    except ThermobearError as e:
        print(f"thermobear: {type(e).__name__}: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("thermobear: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    raise SystemExit(main())

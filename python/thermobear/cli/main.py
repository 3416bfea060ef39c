"""The ``thermobear`` command line.

Exit status: 0 success; 1 a data, model or convergence error (any
[`ThermobearError`][thermobear.ThermobearError]: bad measurements, a bad system
description, a solver that did not converge), reported on one line of
stderr, ``thermobear: error: <file>:<line>: key <key>: <what>``, without a
traceback (``--debug`` shows it); 2 a usage error (argparse: an unknown
option, a missing or malformed argument); 130 interrupted (Ctrl-C); 141
(128 + SIGPIPE) when the reader of the output went away
(``thermobear effects | head -1``), quietly.
"""

from __future__ import annotations

import argparse
import os
import sys
import traceback
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Optional

#: Exit status of a successful run.
EXIT_OK = 0
#: Exit status of a data, model or convergence error (a ThermobearError).
EXIT_ERROR = 1
#: Exit status of a usage error (argparse's).
EXIT_USAGE = 2
#: Exit status after Ctrl-C (128 + SIGINT).
EXIT_INTERRUPTED = 130
#: Exit status when the reader of stdout closed the pipe (128 + SIGPIPE).
EXIT_BROKEN_PIPE = 141

EPILOG = """\
exit status:
  0    success
  1    data, model or convergence error (bad measurements, a bad system
       description, a solver that did not converge); one line on stderr,
       "thermobear: error: FILE:LINE: key KEY: ..." naming the file, the line
       and the key or column at fault (--debug adds the traceback)
  2    usage error (unknown option, missing or malformed argument, an option
       that does not fit the model given)
  130  interrupted (Ctrl-C)
  141  the reader of the output closed the pipe (e.g. "| head -1")
"""


def _cpu_count() -> int:
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


def _threads_arg(text: str) -> int:
    """``--threads``: a whole number of at least 1."""
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"invalid thread count: {text!r}") from None
    if n < 1:
        raise argparse.ArgumentTypeError(f"invalid thread count: {n} (at least 1)")
    return n


def _formats_arg(text: str) -> tuple[str, ...]:
    """``--format``: a comma list of figure formats (png, pdf, svg)."""
    from ..errors import ConfigError
    from ..studies.output import FIGURE_FORMATS, parse_formats

    try:
        return parse_formats(text)
    except ConfigError as e:
        from .._validate import did_you_mean

        bad = [f.strip().lower() for f in text.split(",") if f.strip()]
        near = next((t for t in (did_you_mean(b, FIGURE_FORMATS) for b in bad) if t), "")
        raise argparse.ArgumentTypeError(str(e) + near) from None


def _dpi_arg(text: str) -> float:
    """``--dpi``: dots per inch of a PNG figure (10 to 2400)."""
    from ..errors import ConfigError
    from ..studies.output import check_dpi

    try:
        return check_dpi(text)
    except ConfigError as e:
        raise argparse.ArgumentTypeError(str(e)) from None


def _names_arg(text: str) -> list[str]:
    """A comma-separated list of names (``NAME[,NAME...]``)."""
    names = [t.strip() for t in text.split(",") if t.strip()]
    if not names:
        raise argparse.ArgumentTypeError(f"invalid name list: {text!r}")
    return names


def _holdout_arg(text: str) -> Any:
    """``--holdout``: ``highest_speeds``, ``none``, a fraction of the
    distinct speeds in (0, 1), or ``run:LABEL[,LABEL...]`` (run labels);
    ``auto`` holds out the highest speeds when the data have three or more
    distinct speeds. The default is ``highest_speeds``, as in
    [`thermobear.diagnose`][thermobear.diagnose]."""
    t = text.strip()
    if t in ("auto", "highest_speeds"):
        return t
    if t.lower() == "none":
        return None
    if t.startswith("run:"):
        return _names_arg(t[4:])
    try:
        frac = float(t)
    except ValueError:
        from .._validate import did_you_mean

        near = did_you_mean(t, ("auto", "highest_speeds", "none"))
        raise argparse.ArgumentTypeError(
            f"invalid holdout: {text!r} (highest_speeds, none, a fraction, or run:LABEL,...)" + near
        ) from None
    if not 0.0 < frac < 1.0:
        raise argparse.ArgumentTypeError(f"invalid holdout: {text!r} (a fraction in (0, 1))")
    return frac


@contextmanager
def _thread_limit(threads: Optional[int]) -> Iterator[Optional[int]]:
    """Within the block, native parallel work uses at most ``threads``
    threads (capped at the cores, with a warning): ``RAYON_NUM_THREADS``
    for the pool a fresh process builds; the commands also pass the count
    to the functions that take ``threads``. Yields the count in force."""
    if threads is None:
        yield None
        return
    cores = _cpu_count()
    if threads > cores:
        print(
            f"thermobear: warning: --threads {threads} is above the {cores} cores; using {cores}",
            file=sys.stderr,
        )
        threads = cores
    old = os.environ.get("RAYON_NUM_THREADS")
    os.environ["RAYON_NUM_THREADS"] = str(threads)
    try:
        yield threads
    finally:
        if old is None:
            os.environ.pop("RAYON_NUM_THREADS", None)
        else:
            os.environ["RAYON_NUM_THREADS"] = old


def _cmd_demo(args: argparse.Namespace) -> int:
    from ..studies.demo import run_demo

    out = run_demo(
        Path(args.out), quick=args.quick, formats=args.format, dpi=args.dpi, refit=args.refit
    )
    print(f"thermobear demo: results written to {out.resolve()}")
    return EXIT_OK


def _cmd_solve(args: argparse.Namespace) -> int:
    from .solve import solve_config

    out = solve_config(Path(args.config), Path(args.out))
    print(f"thermobear solve: results written to {out.resolve()}")
    return EXIT_OK


def _cmd_presets(args: argparse.Namespace) -> int:
    from ..bearing import Bearing, Material
    from ..config import seed_config_names
    from ..spindle import Spindle

    if getattr(args, "bearings", False):
        from ..bearing.catalogue import bearing_family_lines

        print("\n".join(bearing_family_lines()))
        return EXIT_OK
    print("bearings: " + ", ".join(Bearing.preset_names()))
    print("bearings by designation: see thermobear presets --bearings")
    print("spindles: " + ", ".join(Spindle.preset_names()))
    print("materials: " + ", ".join(Material.preset_names()))
    print("seed configurations: " + ", ".join(seed_config_names()))
    return EXIT_OK


def _cmd_effects(args: argparse.Namespace) -> int:
    from ..diagnosis import effect_registry

    if args.parameters:
        from .calibrate import parameter_lines

        print("\n".join(parameter_lines(args.model, args.spindle)))
        return EXIT_OK
    if args.model is not None or args.spindle is not None:
        from .predict import UsageError

        raise UsageError("--model and --spindle go with --parameters")
    for r in effect_registry().iter_rows(named=True):
        bounds = (
            "on/off"
            if r["parameter"] == "on"
            else (f"{r['parameter']} {r['lower']:g}..{r['upper']:g} {r['unit']}")
        )
        print(f"{r['name']:34s} {r['kind']:6s} {r['models']:22s} {bounds:38s} {r['description']}")
    return EXIT_OK


def _cmd_diagnose(args: argparse.Namespace) -> int:
    from .diagnose import cli_summary, diagnose_files

    out = Path(args.out) if args.out else None
    d, files = diagnose_files(
        Path(args.measured),
        Path(args.model) if args.model else None,
        out,
        spindle=args.spindle,
        without=args.without or (),
        candidates=args.candidates,
        holdout=args.holdout,
    )
    print(cli_summary(d, verbose=args.verbose))
    if out is not None:
        print(f"thermobear diagnose: {len(files)} files written to {out.resolve()}")
    return EXIT_OK


def _cmd_calibrate(args: argparse.Namespace) -> int:
    from .calibrate import calibrate_files, calibration_summary

    out = Path(args.out)
    cal, files = calibrate_files(
        [Path(m) for m in args.measured],
        args.parameters,
        out,
        Path(args.model) if args.model else None,
        spindle=args.spindle,
        without=args.without or (),
        per_set=args.per_set or (),
    )
    print(calibration_summary(cal))
    print(f"thermobear calibrate: {len(files)} files written to {out.resolve()}")
    return EXIT_OK


def _cmd_predict(args: argparse.Namespace) -> int:
    from .predict import predict_files

    out = Path(args.out)
    _, files = predict_files(
        Path(args.model),
        args.what,
        args.speeds,
        out,
        loads_n=args.loads,
        preloads_n=args.preloads,
        level=args.level,
        member=args.member,
        band=args.band,
        formats=args.format,
        dpi=args.dpi,
    )
    print(f"thermobear predict: {len(files)} files written to {out.resolve()}")
    return EXIT_OK


def _cmd_study(args: argparse.Namespace) -> int:
    from .study import run_study_file

    report = run_study_file(
        Path(args.grid),
        Path(args.out),
        scheduler=args.scheduler,
        progress=False if args.no_progress else None,
        overwrite=args.overwrite,
        threads=args.threads,
        max_points=args.max_points,
        max_steps=args.max_steps,
    )
    print(f"thermobear study: {report}")
    return EXIT_OK


def _cmd_validate(args: argparse.Namespace) -> int:
    from .._validate import did_you_mean
    from ..errors import ConfigError
    from ..validation import set_names
    from .validate import validate_command

    known = set_names()
    for name in args.sets:
        if name not in known:
            raise ConfigError(
                f"invalid set = {name!r}: known: {', '.join(known)}{did_you_mean(name, known)}"
            )
    return validate_command(Path(args.out), args.sets)


def _add_baseline(p: argparse.ArgumentParser) -> None:
    """--model / --spindle (one of them) and --without."""
    base = p.add_mutually_exclusive_group(required=True)
    base.add_argument("--model", help="system description (.toml) of a bearing baseline")
    base.add_argument(
        "--spindle", help="spindle preset of the baseline (thermobear presets lists them)"
    )
    p.add_argument(
        "--without",
        action="extend",
        type=_names_arg,
        metavar="EFFECT[,EFFECT...]",
        help="switch effects off in the baseline (repeatable; thermobear effects lists them; "
        "'thermal_displacement' = the five thermal expansions of a spindle)",
    )


def _parents() -> tuple[argparse.ArgumentParser, argparse.ArgumentParser]:
    """The options every subcommand takes (``--debug``) and those of the
    subcommands that compute (also ``--threads``)."""
    debug = argparse.ArgumentParser(add_help=False)
    debug.add_argument(
        "--debug",
        action="store_true",
        default=argparse.SUPPRESS,
        help="show the traceback of an error",
    )
    compute = argparse.ArgumentParser(add_help=False, parents=[debug])
    compute.add_argument(
        "--threads",
        type=_threads_arg,
        default=None,
        metavar="N",
        help="at most N threads for the native parallel work (default: all cores; "
        "capped at the cores)",
    )
    return debug, compute


def _add_diagnose(g: argparse.ArgumentParser) -> None:
    g.add_argument("measured", help="tidy measurement table (.csv or .parquet)")
    _add_baseline(g)
    g.add_argument(
        "--candidates",
        action="extend",
        type=_names_arg,
        metavar="NAME[,NAME...]",
        help="screen only these candidates (repeatable; default: all of them, with a "
        "sensor-offset decoy per measured quantity and a load-scale candidate per load level)",
    )
    g.add_argument(
        "--holdout",
        type=_holdout_arg,
        default="highest_speeds",
        metavar="SPEC",
        help="points of the extrapolation check: highest_speeds (the top quarter of the "
        "distinct speeds), a fraction of the distinct speeds (0.25), run:LABEL[,LABEL...] "
        "(runs), none, or auto (highest_speeds with 3 or more distinct speeds, else none; "
        "default: highest_speeds, as the Python API)",
    )
    g.add_argument(
        "--out",
        default=None,
        help="folder for tables, figures and the calibrated model (calibrated_model.json)",
    )
    g.add_argument(
        "--verbose",
        action="store_true",
        help="print every look-alike pair, the gap table row by row and the notes",
    )


def _add_calibrate(c: argparse.ArgumentParser) -> None:
    c.add_argument(
        "measured", nargs="+", help="measurement tables (.csv or .parquet), one data set each"
    )
    _add_baseline(c)
    c.add_argument(
        "--parameters",
        action="extend",
        type=_names_arg,
        required=True,
        metavar="NAME[,NAME...]",
        help="the candidates to calibrate (1 to 4 parameters; see thermobear effects)",
    )
    c.add_argument(
        "--per-set",
        action="extend",
        type=_names_arg,
        metavar="NAME[,NAME...]",
        help="of --parameters, those with a value of their own per file (default: shared)",
    )
    c.add_argument(
        "--out",
        required=True,
        help="folder for calibration.json, calibration_summary.txt and the tables",
    )


def _add_study(st: argparse.ArgumentParser) -> None:
    st.add_argument("grid", help="path to the study's .toml ([study], [grid], [fixed])")
    st.add_argument("--out", required=True, help="results folder (manifest + chunks/*.parquet)")
    st.add_argument("--scheduler", default=None, help="Dask scheduler address (tcp://host:8786)")
    st.add_argument("--no-progress", action="store_true", help="no progress bar")
    st.add_argument(
        "--overwrite",
        action="store_true",
        help="start --out afresh, whatever it holds (another grid, damaged files)",
    )
    st.add_argument(
        "--max-points", type=int, default=None, metavar="N",
        help="the most points the grid may have (default: the file's max_points, or 1000000)",
    )  # fmt: skip
    st.add_argument(
        "--max-steps", type=int, default=None, metavar="N",
        help="the most time steps of a gear study (default: the file's max_steps, or 1e10)",
    )  # fmt: skip


def add_figure_options(p: argparse.ArgumentParser) -> None:
    """``--format`` and ``--dpi``, shared by the subcommands that draw."""
    p.add_argument(
        "--format", type=_formats_arg, default=("png",), metavar="FMT[,FMT...]",
        help="figure formats, a comma list of png, pdf, svg (default: png)",
    )  # fmt: skip
    p.add_argument(
        "--dpi", type=_dpi_arg, default=200.0, metavar="DPI",
        help="resolution of PNG figures in dots per inch (default: 200)",
    )  # fmt: skip


def _add_effects(e: argparse.ArgumentParser) -> None:
    e.add_argument(
        "--parameters",
        action="store_true",
        help="list instead every name thermobear calibrate --parameters accepts, per baseline",
    )
    only = e.add_mutually_exclusive_group()
    only.add_argument(
        "--model", default=None, help="with --parameters: only those of this system description"
    )
    only.add_argument(
        "--spindle", default=None, help="with --parameters: only those of this spindle preset"
    )


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of ``thermobear`` and its subcommands."""
    from .._native import __version__

    debug, compute = _parents()
    fmt = argparse.RawDescriptionHelpFormatter
    p = argparse.ArgumentParser(
        prog="thermobear",
        description="Thermally coupled bearing stiffness and drive dynamics.",
        epilog=EPILOG,
        formatter_class=fmt,
        parents=[debug],
    )
    p.add_argument("--version", action="version", version=f"thermobear {__version__}")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")

    def add(name: str, helptext: str, computes: bool, func: Any) -> argparse.ArgumentParser:
        s = sub.add_parser(
            name, help=helptext, description=helptext, epilog=EPILOG, formatter_class=fmt,
            parents=[compute if computes else debug],
        )  # fmt: skip
        s.set_defaults(func=func)
        return s

    d = add("demo", "run the built-in seed studies and write tables and figures", True, _cmd_demo)
    d.add_argument("--out", default="thermobear-out", help="output folder (default: %(default)s)")
    d.add_argument("--quick", action="store_true", help="coarser sweeps (for tests)")
    d.add_argument(
        "--refit", action="store_true",
        help="redo the calibrations that pin the seed papers' unstated inputs (minutes) "
        "into OUT/papers and use them",
    )  # fmt: skip
    add_figure_options(d)
    s = add("solve", "solve a system description (TOML)", True, _cmd_solve)
    s.add_argument("config", help="path to the .toml system description")
    s.add_argument("--out", default="thermobear-out", help="output folder (default: %(default)s)")
    pr = add("presets", "list built-in bearings, materials and seeds", False, _cmd_presets)
    pr.add_argument(
        "--bearings", action="store_true",
        help="list the bearing series read from a designation (6208-2RS1, 7014CE/HCP4A ...)",
    )  # fmt: skip
    _add_effects(add("effects", "list the named physical effects", False, _cmd_effects))
    _add_diagnose(
        add("diagnose", "name the effect missing between model and measurements", True,
            _cmd_diagnose)
    )  # fmt: skip
    _add_calibrate(
        add("calibrate", "calibrate named parameters of a baseline on measurements", True,
            _cmd_calibrate)
    )  # fmt: skip
    from .predict import add_arguments as _add_predict

    _add_predict(
        add("predict", "predict a calibrated model (.json) with its band: table and figures",
            True, _cmd_predict),
        add_figure_options,
    )  # fmt: skip
    _add_study(
        add("study", "run a design study (grid in TOML) into parquet chunks; resumes", True,
            _cmd_study)
    )  # fmt: skip
    v = add("validate", "model, diagnose and calibrate the published data sets", True,
            _cmd_validate)  # fmt: skip
    v.add_argument("sets", nargs="*", metavar="SET", help="set names (default: all)")
    v.add_argument(
        "--out", default="thermobear-validation", help="report folder (default: %(default)s)"
    )
    return p


def _one_line(error: BaseException) -> str:
    return " ".join(str(error).split()) or type(error).__name__


def _quiet_stdout() -> None:
    """After the reader closed the pipe: stdout to /dev/null, so that the
    flush at exit cannot fail again."""
    try:
        fd = sys.stdout.fileno()
    except (AttributeError, OSError, ValueError):
        return
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, fd)
    os.close(devnull)


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the command line on ``argv`` (default: ``sys.argv[1:]``) and
    return the exit status (see ``EPILOG``); ``--help`` and
    ``--version`` return 0, a usage error 2. A reader that stops early
    (``| head -c 1``, a closed pipe), at any point (help, output, error
    message), ends the run quietly with 141."""
    try:
        return _main(argv)
    except BrokenPipeError:
        _quiet_stdout()
        return EXIT_BROKEN_PIPE


def _main(argv: Optional[Sequence[str]]) -> int:
    from ..errors import ThermobearError
    from .predict import UsageError

    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:  # --help, --version (0) or a usage error (2)
        sys.stdout.flush()  # argparse ignores a closed pipe; the flush does not
        return e.code if isinstance(e.code, int) else EXIT_USAGE
    debug = getattr(args, "debug", False)
    try:
        with _thread_limit(getattr(args, "threads", None)) as threads:
            if hasattr(args, "threads"):
                args.threads = threads
            code = int(args.func(args))
        sys.stdout.flush()
        return code
    except BrokenPipeError:
        raise  # main: quietly
    except UsageError as e:  # an option that does not fit the input, found after parsing
        print(f"thermobear {args.command}: error: {_one_line(e)}", file=sys.stderr)
        return EXIT_USAGE
    except ThermobearError as e:
        if debug:
            traceback.print_exc()
        print(f"thermobear: error: {_one_line(e)}", file=sys.stderr)
        # a binary file given where a text file (TOML, JSON) goes: a usage error
        return EXIT_USAGE if getattr(e, "not_text", False) else EXIT_ERROR
    except UnicodeDecodeError as e:  # a binary file read past the checked readers
        if debug:
            traceback.print_exc()
        print(f"thermobear: error: a file given is not UTF-8 text ({e.reason})", file=sys.stderr)
        return EXIT_USAGE
    except OSError as e:  # an output folder that cannot be written, a file gone
        if debug:
            traceback.print_exc()
        where = f"{e.filename}: " if e.filename else ""
        print(f"thermobear: error: {where}{e.strerror or _one_line(e)}", file=sys.stderr)
        return EXIT_ERROR
    except KeyboardInterrupt:
        if debug:
            traceback.print_exc()
        print("thermobear: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED


if __name__ == "__main__":
    raise SystemExit(main())

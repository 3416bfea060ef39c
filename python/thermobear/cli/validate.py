"""``thermobear validate [--out DIR] [SET...]``: the published data sets
of [`thermobear.validation`][thermobear.validation] modelled, diagnosed and calibrated; the
report (``validation.md`` + one figure per set) written into DIR."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Sequence

from ..validation import set_names, validate


def validate_command(out: Path, sets: Sequence[str] = ()) -> int:
    """Run the sets (default: all), print one line per set, write the
    report; returns the exit code (0: ran, whatever the sets' status)."""
    t0 = time.perf_counter()
    results = validate(list(sets) or set_names(), out)
    for r in results:
        status = "PASS" if r.passes else "NOT PASSED"
        print(
            f"{r.name:20s} {status:10s} baseline worst {r.baseline_max_sigma:8.3g} sigma, "
            f"held-out after {r.heldout_max_sigma_after:8.3g} sigma  ({r.seconds:.1f} s)"
        )
        print(f"  verdict: {r.verdict}")
        if r.missing:
            print(f"  missing: {r.missing}")
    print(
        f"thermobear validate: {len(results)} sets in {time.perf_counter() - t0:.1f} s, "
        f"report in {(out / 'validation.md').resolve()}"
    )
    return 0

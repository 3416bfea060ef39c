"""The reproduction table's figures: one row per result figure and table of
the two seed studies, the paper's figure beside thermobear's counterpart
written by ``thermobear demo``, the paper's quoted numbers beside ours in
brief, the reason wherever they differ and the test that pins it. The
status of a figure whose numbers (or claims) are in the number table
follows from them (``reproduction_table.items``); the row's own status
stands for a figure or table with neither (a parameter table).

This module defines the row; the rows live in ``reproduction_seed_a`` and
``reproduction_seed_b`` (``ROWS``), and ``reproduction_table`` gathers
them: ``thermobear demo`` writes them as ``reproduction.csv`` and
``reproduction.parquet`` in its output folder, and the documentation's
reproduction page is generated from the same rows.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, get_args

Status = Literal[
    "reproduced",
    "partly reproduced",
    "trend reproduced, different magnitude",
    "differs",
    "not comparable",
]
Seed = Literal["A", "B"]

#: The statuses, best first.
STATUSES: tuple[str, ...] = get_args(Status)


@dataclass(frozen=True)
class Row:
    """One seed figure or table beside its thermobear counterpart.

    ``figure`` is the counterpart's file stem relative to the demo output
    folder (``"<study>/<stem>"``: a PNG for a figure, a CSV/parquet table for
    a table); ``quoted`` the paper's numbers or claims, ``ours``
    thermobear's; ``reason`` (required unless reproduced) an assumption, a
    typo in the paper or a physical argument; ``test`` the pytest node id
    that pins the row."""

    seed: Seed
    item: str
    paper: str
    figure: str
    quoted: str
    ours: str
    status: Status
    reason: str
    test: str

    def __post_init__(self) -> None:
        from ..errors import ConfigError

        if self.seed not in ("A", "B"):
            raise ConfigError(f"seed = {self.seed!r}: must be 'A' or 'B'")
        if self.status not in STATUSES:
            raise ConfigError(f"status = {self.status!r} ({self.item}): must be one of {STATUSES}")
        if self.status != "reproduced" and not self.reason.strip():
            raise ConfigError(f"reason = '' ({self.item}): required when status is {self.status!r}")
        for name in ("item", "paper", "figure", "quoted", "ours", "test"):
            if not getattr(self, name).strip():
                raise ConfigError(f"{name} = '' ({self.seed} {self.item}): must not be empty")

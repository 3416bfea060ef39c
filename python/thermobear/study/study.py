"""The [`Study`][thermobear.Study]: a grid of points of one kind, computed in chunks,
stored as parquet, resumed where it stopped."""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any, Callable, Mapping, Optional

from .. import _native
from .._limits import cap_threads
from .._types import StudyKind
from .._validate import whole
from ..errors import ConfigError, Interrupted
from . import engine as engines
from .grid import MAX_POINTS, MAX_STEPS, Grid, grid_hash
from .kinds import kind_of
from .store import FORMAT, Store

#: Points per chunk by kind: a chunk is about 0.1 .. 1 s of work on one core.
DEFAULT_CHUNK = {
    "bearing": 20000,
    "thermal": 500,
    "spindle": 8,
    "gear": 8,
    "prediction": 500,
    "regime_prediction": 64,
}


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}" + ("" if n == 1 else "s")


@dataclass
class RunReport:
    """What a run did: chunks computed now and reused from an earlier run."""

    points: int
    chunks: int
    computed: int = 0
    reused: int = 0
    failed_points: int = 0
    seconds: float = 0.0
    out: Optional[str] = None
    interrupted: bool = False

    def __str__(self) -> str:
        where = f"; results in {self.out}" if self.out else ""
        stop = " (interrupted)" if self.interrupted else ""
        return (
            f"{self.points} points in {_count(self.chunks, 'chunk')}: {self.computed} computed, "
            f"{self.reused} reused, {self.failed_points} failed points, "
            f"{self.seconds:.1f} s{stop}{where}"
        )

    def summary(self) -> str:
        """What the run did, in one line (as ``str``)."""
        return str(self)

    def __repr__(self) -> str:
        return (
            f"RunReport(points={self.points}, computed={self.computed}, reused={self.reused}, "
            f"failed_points={self.failed_points})"
        )


class Study:
    """A design study: points of one ``kind`` (``"bearing"``, ``"thermal"``,
    ``"spindle"``, ``"gear"``, ``"prediction"``; see
    [`thermobear.study.kinds_table`][thermobear.study.kinds_table] for each kind's inputs)
    over a ``grid`` (input name -> a list, array,
    ``range`` or a range ``{"start", "stop", "num"}`` /
    ``{"start", "stop", "step"}``; the Cartesian product, first dimension
    outermost) with the other inputs ``fixed`` (or at their defaults).

    [`run`][thermobear.Study.run] computes it in chunks of ``chunk_size`` points and returns
    one tidy polars DataFrame: ``point``, the inputs, the outputs (units in
    the names), ``ok``, ``error_kind``, ``error``.

    The grid's size is counted from the specs before any value is made
    (``repr`` states it): more than ``max_points`` points (default
    1,000,000), or for the ``gear`` kind more than ``max_steps`` time steps
    in all (default 10^10), is a ``ConfigError`` naming the largest
    dimension and the size; raise the cap with the keyword."""

    def __init__(
        self,
        kind: StudyKind,
        grid: Mapping[str, Any],
        fixed: Optional[Mapping[str, Any]] = None,
        *,
        chunk_size: Optional[int] = None,
        max_points: int = MAX_POINTS,
        max_steps: int = MAX_STEPS,
    ) -> None:
        self.max_points = whole("max_points", max_points, 1, None)
        self.max_steps = whole("max_steps", max_steps, 1, None)
        self.grid = Grid(
            kind_of(kind), grid, fixed, max_points=self.max_points, max_steps=self.max_steps
        )
        size = DEFAULT_CHUNK[kind] if chunk_size is None else chunk_size
        if isinstance(size, bool) or not isinstance(size, int) or size < 1:
            raise ConfigError(f"invalid chunk_size = {size!r}: must be a whole number >= 1")
        self.chunk_size = size
        self.report: Optional[RunReport] = None

    @property
    def kind(self) -> str:
        return self.grid.kind.name

    @property
    def n_points(self) -> int:
        return self.grid.n_points

    @property
    def n_chunks(self) -> int:
        return -(-self.n_points // self.chunk_size)

    def manifest(self) -> dict:
        """The study's description as stored next to its results."""
        spec = {"format": FORMAT, "version": _native.__version__, "chunk_size": self.chunk_size}
        spec.update(self.grid.spec())
        return {
            "grid_hash": grid_hash(spec),
            "study": spec,
            "n_points": self.n_points,
            "n_chunks": self.n_chunks,
        }

    @property
    def grid_hash(self) -> str:
        return self.manifest()["grid_hash"]

    def points(self) -> Any:
        """The input rows (``point`` and every input), without computing."""
        return self.grid.frame()

    def run(
        self,
        out: Any = None,
        *,
        engine: Any = None,
        progress: Optional[bool] = None,
        threads: Optional[int] = None,
        overwrite: bool = False,
        on_chunk: Optional[Callable[[int, Any], Any]] = None,
        collect: bool = True,
    ) -> Any:
        """Compute the study and return its DataFrame (point order).

        ``out``: a directory for the results (``manifest.json`` and
        ``chunks/chunk-NNNNNN.parquet``, each chunk written as it finishes);
        a second run with the same grid computes only the missing chunks,
        another grid is refused unless ``overwrite``. Without ``out`` the
        chunks stay in memory. A stored chunk is reused only when its check
        record (grid hash, index, point range, SHA-256) matches and its
        rows are the record's (its ``point`` column that range, its input
        columns this grid's values there); any other is recomputed with a
        warning naming its file. One run owns ``out`` at a time (an
        advisory lock on the folder, held even if its lock file is
        deleted): a second is refused with a ``ConfigError`` naming the
        first one's process. A folder that cannot be written is a
        ``ConfigError`` naming it. ``overwrite=True``
        starts ``out`` afresh whatever it holds (an unreadable manifest,
        stray or damaged chunks).

        ``engine``: None (this machine: rayon threads inside every chunk,
        ``threads`` of them, default all cores), a
        ``dask.distributed.Client`` or a scheduler address (one task per
        chunk on one worker thread; needs ``pip install "thermobear[dask]"``).

        ``threads`` above the available cores is capped to them with a
        ``ThreadsWarning``.

        ``progress``: a tqdm bar (None: only when stderr is a terminal or
        in a notebook). ``on_chunk(index, frame)`` after each stored chunk;
        if it returns False the run stops with ``thermobear.Interrupted``
        (the chunks stored so far are kept). Ctrl-C keeps the finished
        chunks; ``report`` says what was
        computed and reused (also after an interrupt). ``collect=False``
        (with ``out``) keeps no chunk in memory and returns None: read the
        results with ``polars.scan_parquet(out / "chunks" / "*.parquet")``."""
        if not collect and out is None:
            raise ConfigError("invalid collect = False: without out the results would be lost")
        store = Store(out, self.manifest(), overwrite, self.grid.frame) if out is not None else None
        try:
            return self._run(store, engine, progress, threads, on_chunk, collect)
        finally:
            if store is not None:
                store.close()

    def _run(
        self,
        store: Optional[Store],
        engine: Any,
        progress: Optional[bool],
        threads: Optional[int],
        on_chunk: Optional[Callable[[int, Any], Any]],
        collect: bool,
    ) -> Any:
        """[`run`][thermobear.Study.run] on an open (locked) store."""
        t0 = time.perf_counter()
        bounds = self._bounds
        done = store.done(bounds) if store is not None else set()
        todo = [i for i in range(self.n_chunks) if i not in done]
        report = RunReport(
            self.n_points,
            self.n_chunks,
            reused=len(done),
            out=None if store is None else str(store.root),
        )
        self.report = report
        report.failed_points = sum(store.failed(i) for i in done) if store is not None else 0
        memory: dict[int, Any] = {}
        initial = sum(self._chunk_len(i) for i in done)
        bar = engines.Progress(progress, self.n_points, initial, f"{self.kind} study")

        def on_done(index: int, frame: Any) -> None:
            if store is not None:
                store.write(index, frame, *bounds(index))
            if collect:
                memory[index] = frame
            report.computed += 1
            report.failed_points += int(frame.height - frame["ok"].sum())
            bar.update(frame.height)
            if on_chunk is not None and on_chunk(index, frame) is False:
                raise Interrupted(
                    f"stopped by on_chunk (it returned False) after chunk {index}: "
                    f"{report.computed} of {len(todo)} chunks computed"
                )

        threads = cap_threads(threads)
        try:
            self._execute(engine, todo, threads, on_done)
        except (KeyboardInterrupt, Interrupted):
            report.interrupted = True
            raise
        finally:
            bar.close()
            report.seconds = time.perf_counter() - t0
        return self._collect(store, memory) if collect else None

    def _bounds(self, index: int) -> tuple[int, int]:
        return engines.chunk_bounds(self.n_points, self.chunk_size, index)

    def _chunk_len(self, index: int) -> int:
        start, stop = self._bounds(index)
        return stop - start

    def _execute(
        self, engine: Any, todo: list[int], threads: Optional[int], on_done: engines.OnDone
    ) -> None:
        if engine is None or engine == "local":
            engines.run_local(self.grid, self.chunk_size, todo, threads, on_done)
            return
        client, owned = engines.dask_client(engine)
        try:
            if todo:
                engines.run_dask(client, self.grid, self.chunk_size, todo, on_done)
        finally:
            if owned:
                client.close()

    def _collect(self, store: Optional[Store], memory: dict) -> Any:
        import polars as pl

        # Chunks computed now are still in memory; only reused ones are read.
        frames = [
            memory[i] if i in memory else store.read_checked(i, *self._bounds(i))  # type: ignore[union-attr]
            for i in range(self.n_chunks)
        ]
        return pl.concat(frames, rechunk=False)

    def __reduce__(self) -> tuple:
        # The grid's values, not its kind (whose checks are closures).
        return (
            _rebuild,
            (
                self.kind,
                self.grid.dims,
                self.grid.fixed,
                self.chunk_size,
                self.max_points,
                self.max_steps,
            ),
        )

    def __len__(self) -> int:
        return self.n_points

    def __repr__(self) -> str:
        dims = ", ".join(f"{k}[{len(v)}]" for k, v in self.grid.dims.items())
        steps = ""
        if self.grid.n_steps is not None:
            more = " or more" if self.grid.steps_at_least else ""
            steps = f" ({self.grid.n_steps:,} time steps{more})"
        return (
            f"Study({self.kind!r}, {dims or 'one point'}: {self.n_points} points{steps}, "
            f"{_count(self.n_chunks, 'chunk')} of {self.chunk_size})"
        )

    def summary(self) -> str:
        """The study in one line, with its size (as ``repr``)."""
        return repr(self)


def _rebuild(
    kind: StudyKind,
    dims: dict,
    fixed: dict,
    chunk_size: int,
    max_points: int = MAX_POINTS,
    max_steps: int = MAX_STEPS,
) -> Study:
    """Unpickle a [`Study`][thermobear.Study] (through its validating constructor)."""
    return Study(
        kind, dims, fixed, chunk_size=chunk_size, max_points=max_points, max_steps=max_steps
    )

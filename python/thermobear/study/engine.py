"""Where the chunks of a study are computed: this machine (one chunk after
the other, rayon threads inside each native batch call) or a Dask cluster
(one task per chunk, results written by the caller as they arrive); the
progress bar for both."""

from __future__ import annotations

import sys
from concurrent.futures import Future, ThreadPoolExecutor, wait
from typing import Any, Callable, Iterable, Optional

from .._optional import optional_module
from ..errors import ConfigError
from .grid import Grid, grid_hash
from .kinds import kind_of

#: ``on_done(index, frame)`` for each finished chunk, in completion order.
OnDone = Callable[[int, Any], None]


def chunk_bounds(n_points: int, chunk_size: int, index: int) -> tuple[int, int]:
    start = index * chunk_size
    return start, min(start + chunk_size, n_points)


def compute(grid: Grid, chunk_size: int, index: int, threads: Optional[int]) -> Any:
    """One chunk: its input rows followed by the outputs (fixed schema)."""
    start, stop = chunk_bounds(grid.n_points, chunk_size, index)
    inputs = grid.frame(start, stop)
    return inputs.hstack(grid.kind.compute(inputs.drop("point"), threads))


#: Grids rebuilt in this (worker) process, by the hash of their description.
_GRIDS: dict[str, Grid] = {}


def compute_on_worker(spec: dict, chunk_size: int, index: int) -> Any:
    """The Dask task: rebuild the grid from its description (once per
    worker process), compute one chunk on one thread (a worker runs as many
    tasks as it has threads)."""
    key = grid_hash(spec)
    grid = _GRIDS.get(key)
    if grid is None:
        grid = Grid(kind_of(spec["kind"]), dict(spec["dims"]), spec["fixed"])
        _GRIDS.clear()  # keep one: a worker serves one study at a time
        _GRIDS[key] = grid
    return compute(grid, chunk_size, index, 1)


# -- progress ---------------------------------------------------------------------


def _interactive() -> bool:
    # A terminal, or a Jupyter kernel (whose stderr is not a TTY but shows
    # tqdm.auto's widget).
    return bool(getattr(sys.stderr, "isatty", lambda: False)()) or "ipykernel" in sys.modules


class Progress:
    """A tqdm bar over points (tqdm.auto: a widget in notebooks); silent
    when ``enabled`` is False, or None and stderr is not interactive."""

    def __init__(self, enabled: Optional[bool], total: int, initial: int, desc: str) -> None:
        self.bar = None
        if enabled is None:
            enabled = _interactive()
        if enabled:
            from tqdm.auto import tqdm

            self.bar = tqdm(total=total, initial=initial, unit="pt", desc=desc, smoothing=0.1)

    def update(self, n: int) -> None:
        if self.bar is not None:
            self.bar.update(n)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


# -- engines ----------------------------------------------------------------------


def run_local(
    grid: Grid, chunk_size: int, todo: Iterable[int], threads: Optional[int], on_done: OnDone
) -> None:
    """Chunk after chunk on this machine. A finished chunk is handed to
    ``on_done`` (stored) in a background thread while the next one
    computes; the ``on_done`` calls stay in order, one at a time, and an
    exception in one (an ``on_chunk`` hook's) stops the run at the next
    chunk. Ctrl-C (seen by the native batch call within 50 ms) stops it too;
    a chunk being stored at that moment is still kept."""
    with ThreadPoolExecutor(max_workers=1) as store:
        pending: Optional[Future] = None
        try:
            for index in todo:
                frame = compute(grid, chunk_size, index, threads)
                if pending is not None:
                    pending.result()
                pending = store.submit(on_done, index, frame)
            if pending is not None:
                pending.result()
        finally:
            if pending is not None:
                wait([pending])


def _distributed(engine: Any) -> Any:
    """The ``dask.distributed`` module, or a ConfigError saying what to install."""
    return optional_module(
        "dask.distributed", "dask", "engine", engine, "running a study on a Dask cluster"
    )


def dask_client(engine: Any) -> tuple[Any, bool]:
    """``(client, owned)`` for a ``dask.distributed.Client`` or a scheduler
    address (a client we open, and close, ourselves)."""
    distributed = _distributed(engine)
    if isinstance(engine, distributed.Client):
        return engine, False
    if isinstance(engine, str):
        try:
            return distributed.Client(engine, timeout="20s"), True
        except OSError as e:
            raise ConfigError(f"invalid scheduler = {engine!r}: cannot connect: {e}") from None
    raise ConfigError(
        f"invalid engine = {engine!r}: give None (this machine), a dask.distributed.Client "
        "or a scheduler address"
    )


def run_dask(client: Any, grid: Grid, chunk_size: int, todo: list[int], on_done: OnDone) -> None:
    """One task per chunk; results handed to ``on_done`` as they complete.
    Ctrl-C (or an error in ``on_done``) cancels what has not finished."""
    as_completed = _distributed(client).as_completed
    [spec] = client.scatter([grid.spec()], broadcast=True)  # sent once, not per task
    futures = {client.submit(compute_on_worker, spec, chunk_size, i, pure=False): i for i in todo}
    try:
        for fut in as_completed(futures):
            on_done(futures[fut], fut.result())
    finally:
        pending = [f for f in futures if not f.done()]
        if pending:
            client.cancel(pending)

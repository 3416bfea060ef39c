"""A study's results on disk: ``manifest.json`` (the study description and
its hash) and one parquet file per chunk under ``chunks/``
(``chunk-000000.parquet`` ...), each with its check record
(``chunk-000000.check.json``: the grid hash, the chunk index, its point
range and the SHA-256 of the parquet file).

Nothing is trusted by its name: a chunk is reused only when its record
matches this grid, this index and this range and the file's checksum
matches; any other chunk (swapped, truncated, zeroed, written by another
grid, or without a record) is recomputed with a warning naming its file.

A chunk whose file and record were both replaced (its checksum re-signed)
is caught by its rows: its ``point`` column must be exactly the record's
range and its input columns this grid's values at those points; a chunk
that fails is recomputed with a warning like any other.

One run owns a directory at a time: an advisory lock (``fcntl.flock`` on
the directory itself, which cannot be deleted or swapped while the run
holds it, and on ``.thermobear-study.lock``, which holds the owner's
process id, host and run id) refuses a second run with a ``ConfigError``
naming the first one's process, even when the lock file was deleted. A
folder that cannot be written is a ``ConfigError`` naming it. Files are
written to temporary files carrying the run's id and renamed into place; a
run removes only its own temporary files. ``overwrite=True`` starts the
directory afresh, whatever it holds."""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import socket
import time
import uuid
import warnings
from pathlib import Path
from typing import Any, Callable, Optional

from ..errors import ConfigError

try:  # POSIX; elsewhere the directory is not locked
    import fcntl
except ImportError:  # pragma: no cover - not on the platforms CI runs
    fcntl = None  # type: ignore[assignment]

MANIFEST = "manifest.json"
CHUNKS = "chunks"
LOCK = ".thermobear-study.lock"
FORMAT = 1


def chunk_name(index: int) -> str:
    return f"chunk-{index:06d}.parquet"


def record_name(index: int) -> str:
    return f"chunk-{index:06d}.check.json"


def file_sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _busy(root: Path, holder: Optional[str]) -> ConfigError:
    return ConfigError(
        f"invalid out = {str(root)!r}: another run is using it ({_holder(holder)}); "
        "wait for it to finish or stop it, or use another directory"
    )


def _read_holder(root: Path) -> Optional[str]:
    """The lock file's text, or None when it is gone."""
    try:
        with open(root / LOCK, "rb") as f:
            return f.read(4096).decode("utf-8", "replace")
    except FileNotFoundError:
        return None
    except OSError:
        return ""


class FolderLock:
    """An exclusive advisory lock on ``root`` for one run (released by
    ``release`` or when the process ends, however it ends).

    Two locks, both held for the run: one on the directory itself (its
    open descriptor: deleting or replacing the lock file does not free it)
    and one on the lock file (which names the owner), checked after
    locking to still be the file at that path. Where a directory cannot be
    locked (some network file systems) the lock file alone holds it."""

    def __init__(self, root: Path, run_id: str) -> None:
        self.fd: Optional[int] = None
        self.dir_fd: Optional[int] = None
        if fcntl is None:  # pragma: no cover
            return
        self.dir_fd = self._lock_dir(root)
        try:
            fd = self._lock_file(root)
        except BaseException:
            self.release()
            raise
        me = {"pid": os.getpid(), "host": socket.gethostname(), "run_id": run_id}
        me["started"] = time.strftime("%Y-%m-%dT%H:%M:%S%z")
        self.fd = fd
        os.ftruncate(fd, 0)
        os.pwrite(fd, json.dumps(me).encode(), 0)

    @staticmethod
    def _lock_dir(root: Path) -> Optional[int]:
        """The locked descriptor of the directory, or None where
        directories cannot be opened or locked."""
        try:
            fd = os.open(root, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
        except OSError:
            return None
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            raise _busy(root, _read_holder(root)) from None
        except OSError:  # no flock on a directory here
            os.close(fd)
            return None
        return fd

    @staticmethod
    def _lock_file(root: Path) -> int:
        """The locked descriptor of the lock file, checked after locking to
        be the file at its path (not one deleted or replaced meanwhile)."""
        path = root / LOCK
        for _ in range(10):
            fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                holder = os.pread(fd, 4096, 0).decode("utf-8", "replace")
                os.close(fd)
                raise _busy(root, holder) from None
            try:
                same = os.path.samestat(os.fstat(fd), os.stat(path))
            except FileNotFoundError:
                same = False
            if same:
                return fd
            os.close(fd)  # replaced while we locked it: lock the new one
        raise _busy(root, _read_holder(root))

    def release(self) -> None:
        for name in ("fd", "dir_fd"):
            fd = getattr(self, name)
            if fd is not None and fcntl is not None:
                setattr(self, name, None)
                try:
                    fcntl.flock(fd, fcntl.LOCK_UN)
                finally:
                    os.close(fd)


def _holder(text: Optional[str]) -> str:
    if text is None:
        return f"a process whose lock file {LOCK} was removed"
    try:
        h = json.loads(text)
        return (
            f"process {h['pid']} on host {h['host']}, run {h['run_id']}, "
            f"started {h.get('started', '?')}"
        )
    except (ValueError, KeyError, TypeError):
        return "a process that has not yet written its id"


class Store:
    """The output directory of one study (``manifest`` is what it holds),
    locked for this run until ``close``."""

    def __init__(
        self,
        out: Any,
        manifest: dict,
        overwrite: bool = False,
        expected: Optional[Callable[[int, int], Any]] = None,
    ) -> None:
        self.root = Path(out)
        self.manifest = manifest
        #: ``expected(start, stop)``: the input rows (``point`` and every
        #: input) the chunk of points ``start..stop`` must hold.
        self.expected = expected
        self.chunks = self.root / CHUNKS
        self.run_id = f"{os.getpid()}-{uuid.uuid4().hex[:8]}"
        try:
            self.root.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise ConfigError(f"invalid out = {str(self.root)!r}: {e}") from None
        try:
            self.lock = FolderLock(self.root, self.run_id)
        except OSError as e:
            raise self._unwritable(e) from None
        try:
            if overwrite:
                self._clear()
            else:
                self._check_existing()
            self.chunks.mkdir(parents=True, exist_ok=True)
            text = json.dumps(manifest, indent=1, sort_keys=True)
            self._atomic_write(self.root / MANIFEST, lambda p: p.write_text(text))
        except OSError as e:
            self.lock.release()
            raise self._unwritable(e) from None
        except BaseException:
            self.lock.release()
            raise

    def _unwritable(self, e: OSError) -> ConfigError:
        """The error of a folder this process cannot write to."""
        where = f" ({e.filename})" if e.filename and str(e.filename) != str(self.root) else ""
        return ConfigError(
            f"invalid out = {str(self.root)!r}: cannot write to this folder{where}: "
            f"{e.strerror or e}; give a folder this user may write to"
        )

    def close(self) -> None:
        """Release the directory (the lock) for another run."""
        self.lock.release()

    def _atomic_write(self, path: Path, write: Any) -> None:
        """``write(tmp_path)``, then rename over ``path``; the temporary
        file carries this run's id, and only this run removes it."""
        tmp = path.with_name(f".{path.name}.{self.run_id}.tmp")
        try:
            write(tmp)
            os.replace(tmp, path)
        finally:
            if tmp.exists():
                tmp.unlink()

    def _clear(self) -> None:
        """Remove what a study keeps here (manifest, chunks, temporary
        files), whatever state it is in; other files are left alone."""
        for path in [self.root / MANIFEST, self.chunks, *self.root.glob(f".{MANIFEST}.*.tmp")]:
            if path.is_dir() and not path.is_symlink():
                shutil.rmtree(path)
            elif path.exists() or path.is_symlink():
                path.unlink()

    def _check_existing(self) -> None:
        old = self._read_manifest()
        again = "; use another directory or overwrite=True (--overwrite) to start it afresh"
        if old is not None and old.get("grid_hash") != self.manifest["grid_hash"]:
            raise ConfigError(
                f"invalid out = {str(self.root)!r}: it holds the results of another grid "
                f"(hash {str(old.get('grid_hash'))[:12]}, this one "
                f"{self.manifest['grid_hash'][:12]}){again}"
            )
        if old is None and self.chunks.exists():
            if not self.chunks.is_dir() or any(self.chunks.iterdir()):
                raise ConfigError(
                    f"invalid out = {str(self.root)!r}: {CHUNKS}/ exists without {MANIFEST}{again}"
                )

    def _read_manifest(self) -> dict | None:
        path = self.root / MANIFEST
        if not path.exists():
            return None
        try:
            old = json.loads(path.read_text())
        except (OSError, ValueError) as e:
            raise ConfigError(
                f"invalid {path} = unreadable manifest ({e}); use overwrite=True "
                "(--overwrite) to start the directory afresh"
            ) from None
        if not isinstance(old, dict):
            raise ConfigError(
                f"invalid {path} = not a study manifest; use overwrite=True (--overwrite)"
            )
        return old

    def _record(self, index: int, start: int, stop: int) -> dict:
        return {
            "grid_hash": self.manifest["grid_hash"],
            "index": index,
            "start": start,
            "stop": stop,
            "file": chunk_name(index),
        }

    def problem(self, index: int, start: int, stop: int) -> Optional[str]:
        """Why the stored chunk ``index`` (points ``start..stop``) cannot be
        reused, or None when it passes every check."""
        try:
            rec = json.loads((self.chunks / record_name(index)).read_text())
        except FileNotFoundError:
            return f"it has no check record {record_name(index)}"
        except (OSError, ValueError) as e:
            return f"its check record is unreadable ({e})"
        if not isinstance(rec, dict):
            return "its check record is not a record"
        want = self._record(index, start, stop)
        wrong = [k for k in want if rec.get(k) != want[k]]
        if wrong:
            return "its record is for " + ", ".join(f"{k} = {rec.get(k)!r}" for k in wrong)
        if rec.get("sha256") != file_sha256(self.chunks / chunk_name(index)):
            return "its content checksum does not match (changed, truncated or replaced)"
        return self.rows_problem(index, start, stop)

    def rows_problem(self, index: int, start: int, stop: int) -> Optional[str]:
        """Why the rows of the stored chunk ``index`` are not the points
        ``start..stop`` of this grid (its ``point`` column exactly that
        range, its input columns this grid's values there), or None."""
        if self.expected is None:
            return None
        import polars as pl

        want = self.expected(start, stop)
        try:
            got = pl.read_parquet(self.chunks / chunk_name(index), columns=want.columns)
        except Exception as e:  # a missing column, an unreadable file
            return f"its input columns cannot be read ({e})"
        points = got["point"]
        if points.len() != stop - start or not points.equals(want["point"], check_dtypes=True):
            first = points.head(1).to_list()
            return (
                f"its point column ({points.len()} rows from {first[0] if first else None}) "
                f"is not the points {start}..{stop - 1} of its record"
            )
        wrong = [c for c in want.columns if not got[c].equals(want[c], check_dtypes=True)]
        if wrong:
            return (
                f"its {', '.join(wrong)} column{'s' if len(wrong) > 1 else ''} "
                f"{'do' if len(wrong) > 1 else 'does'} not hold this grid's values at "
                f"points {start}..{stop - 1}"
            )
        return None

    def done(self, bounds: Any) -> set[int]:
        """Indices of the stored chunks that pass their check
        (``bounds(index)`` gives a chunk's point range); a stored chunk
        that fails is reported with a warning and left to be recomputed."""
        found = set()
        for index in range(self.manifest["n_chunks"]):
            path = self.chunks / chunk_name(index)
            if not path.exists():
                continue
            why = self.problem(index, *bounds(index))
            if why is None:
                found.add(index)
            else:
                warnings.warn(
                    f"chunk file {path} fails its check: {why}; it is recomputed",
                    UserWarning,
                    stacklevel=3,
                )
        return found

    def write(self, index: int, frame: Any, start: int, stop: int) -> None:
        path = self.chunks / chunk_name(index)
        record = self._record(index, start, stop)

        def write_chunk(tmp: Path) -> None:
            frame.write_parquet(tmp)
            record["sha256"] = file_sha256(tmp)

        try:
            self._atomic_write(path, write_chunk)
            text = json.dumps(record, indent=1, sort_keys=True)
            self._atomic_write(self.chunks / record_name(index), lambda p: p.write_text(text))
        except PermissionError as e:
            raise self._unwritable(e) from None

    def read_checked(self, index: int, start: int, stop: int) -> Any:
        """The stored chunk ``index`` for merging, its rows checked again
        (a file changed since the check at the start of the run is a
        ConfigError naming it)."""
        why = self.rows_problem(index, start, stop)
        if why is not None:
            raise ConfigError(
                f"invalid chunk file {self.chunks / chunk_name(index)}: it changed during the "
                f"run ({why}); run the study again to recompute it"
            )
        return self.read(index)

    def read(self, index: int, columns: Optional[list[str]] = None) -> Any:
        import polars as pl

        path = self.chunks / chunk_name(index)
        try:
            return pl.read_parquet(path, columns=columns)
        except Exception as e:  # checked before: only a change since then
            raise ConfigError(f"invalid chunk file {path}: cannot be read ({e})") from None

    def failed(self, index: int) -> int:
        """Failed points of a stored chunk (reads its ``ok`` column only)."""
        ok = self.read(index, ["ok"])["ok"]
        return int(ok.len() - ok.sum())

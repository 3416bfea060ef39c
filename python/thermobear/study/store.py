"""A study's results on disk: ``manifest.json`` (the study description and
its hash) and one parquet file per chunk under ``chunks/``
(``chunk-000000.parquet`` ...), each written to a temporary file first and
renamed into place, so a file that exists is complete. A directory whose
manifest describes another grid is never mixed with this one."""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path
from typing import Any

from ..errors import ConfigError

MANIFEST = "manifest.json"
CHUNKS = "chunks"
FORMAT = 1


def chunk_name(index: int) -> str:
    return f"chunk-{index:06d}.parquet"


def _atomic_write(path: Path, write: Any) -> None:
    """``write(tmp_path)``, then rename over ``path`` (same directory)."""
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        write(tmp)
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()


class Store:
    """The output directory of one study (``manifest`` is what it holds)."""

    def __init__(self, out: Any, manifest: dict, overwrite: bool = False) -> None:
        self.root = Path(out)
        self.manifest = manifest
        self.chunks = self.root / CHUNKS
        old = self._read_manifest()
        if old is not None and old.get("grid_hash") != manifest["grid_hash"]:
            if not overwrite:
                raise ConfigError(
                    f"invalid out = {str(self.root)!r}: it holds the results of another grid "
                    f"(hash {str(old.get('grid_hash'))[:12]}, this one "
                    f"{manifest['grid_hash'][:12]}); use another directory or overwrite=True"
                )
            shutil.rmtree(self.chunks, ignore_errors=True)
        elif old is None and self.chunks.exists() and any(self.chunks.iterdir()):
            raise ConfigError(
                f"invalid out = {str(self.root)!r}: {CHUNKS}/ exists without {MANIFEST}; "
                "use another directory"
            )
        self.chunks.mkdir(parents=True, exist_ok=True)
        for stale in self.chunks.glob(".*.tmp"):
            stale.unlink()
        _atomic_write(
            self.root / MANIFEST,
            lambda p: p.write_text(json.dumps(manifest, indent=1, sort_keys=True)),
        )

    def _read_manifest(self) -> dict | None:
        path = self.root / MANIFEST
        if not path.exists():
            return None
        try:
            return json.loads(path.read_text())
        except (OSError, ValueError) as e:
            raise ConfigError(f"invalid {path} = unreadable manifest: {e}") from None

    def done(self) -> set[int]:
        """Indices of the chunks already on disk."""
        n = self.manifest["n_chunks"]
        found = set()
        for p in self.chunks.glob("chunk-*.parquet"):
            stem = p.name[len("chunk-") : -len(".parquet")]
            if stem.isdigit() and int(stem) < n:
                found.add(int(stem))
        return found

    def write(self, index: int, frame: Any) -> None:
        _atomic_write(self.chunks / chunk_name(index), lambda p: frame.write_parquet(p))

    def read(self, index: int) -> Any:
        import polars as pl

        return pl.read_parquet(self.chunks / chunk_name(index))

    def failed(self, index: int) -> int:
        """Failed points of a stored chunk (reads its ``ok`` column only)."""
        import polars as pl

        ok = pl.read_parquet(self.chunks / chunk_name(index), columns=["ok"])["ok"]
        return int(ok.len() - ok.sum())

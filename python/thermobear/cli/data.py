"""Measurement files of the command line: read (CSV lines starting with
``#`` are comments; or parquet), and a ``DataError`` about their content
re-raised naming the file, the line and the column at fault."""

from __future__ import annotations

import re
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Any, Optional

from ..errors import DataError

if TYPE_CHECKING:
    import polars

_ROW = re.compile(r"invalid (\w+) = (.+?) in row (\d+)")
_VALUE_FOR = re.compile(r"invalid value = (\S+) for (\S+?):")
_QUANTITY = re.compile(r"invalid quantity = '(.+?)'")
_NOT_NUMERIC = re.compile(r"invalid (\w+): not numeric")
_COLUMN_VALUE = re.compile(r"invalid (\w+) = ([^:]+):")
_MISSING = re.compile(r"missing column")

#: Advice of the Python API in a data error -> its command-line form (the
#: commands read a file; they have no ``duplicates`` option).
CLI_ADVICE = {
    'or load with duplicates="mean" to average them': "or average them in the file",
}


def cli_advice(message: str) -> str:
    """``message`` with the Python API's advice given as the command line's."""
    for python, cli in CLI_ADVICE.items():
        message = message.replace(python, cli)
    return message


def read_measurements(path: Path) -> polars.DataFrame:
    """The table of a measurement file (CSV, ``#`` comment lines, or
    parquet); a ``DataError`` naming the file when it cannot be read."""
    import polars as pl

    try:
        if path.suffix == ".parquet":
            return pl.read_parquet(path)
        return pl.read_csv(path, comment_prefix="#")
    except OSError as e:
        raise DataError(f"{path}: cannot read: {e.strerror or e}") from None
    except Exception as e:  # noqa: BLE001  (polars raises several types)
        first = " ".join(str(e).split())
        raise DataError(f"{path}: cannot read as a table: {first}") from None


def _raw_table(path: Path) -> Optional[polars.DataFrame]:
    """Every cell of the file as text (None when it cannot be read)."""
    import polars as pl

    try:
        if path.suffix == ".parquet":
            df = pl.read_parquet(path)
            return df.select(pl.all().cast(pl.Utf8))
        return pl.read_csv(path, comment_prefix="#", infer_schema=False)
    except Exception:  # noqa: BLE001
        return None


def _csv_lines(path: Path) -> tuple[Optional[int], list[int]]:
    """The line (from 1) of a CSV file's header and of each data row
    (comment lines skipped; a blank line is a row, as the reader makes it)."""
    try:
        lines = path.read_text().splitlines()
    except (OSError, UnicodeDecodeError):
        return None, []
    header, rows = None, []
    for n, line in enumerate(lines, start=1):
        if line.startswith("#"):
            continue
        if header is None:
            header = n
        else:
            rows.append(n)
    return header, rows


def _same(cell: Any, value: str) -> bool:
    if cell is None:
        return value in ("None", "nan", "null", "")
    try:
        return float(cell) == float(value)
    except ValueError:
        return str(cell).strip() == value.strip().strip("'\"")


def _not_number(cell: Any) -> bool:
    if cell is None:
        return False
    try:
        float(cell)
        return False
    except ValueError:
        return True


def _find_row(raw: polars.DataFrame, message: str) -> tuple[Optional[int], Optional[str]]:
    """The row (from 0) and the column of ``raw`` that a ``DataError``
    message concerns; None where they cannot be told."""

    def first(column: str, test: Any) -> tuple[Optional[int], Optional[str]]:
        if column not in raw.columns:
            return None, None
        for i, cell in enumerate(raw[column].to_list()):
            if test(i, cell):
                return i, column
        return None, column

    m = _ROW.search(message)
    if m is not None:
        return (
            (int(m.group(3)), m.group(1)) if m.group(1) in raw.columns else (int(m.group(3)), None)
        )
    m = _VALUE_FOR.search(message)
    if m is not None and "quantity" in raw.columns:
        qs = raw["quantity"].to_list()
        return first("value", lambda i, c: qs[i] == m.group(2) and _same(c, m.group(1)))
    m = _QUANTITY.search(message)
    if m is not None:
        return first("quantity", lambda i, c: c == m.group(1))
    m = _NOT_NUMERIC.search(message)
    if m is not None:
        return first(m.group(1), lambda i, c: _not_number(c))
    m = _COLUMN_VALUE.search(message)
    if m is not None:
        return first(m.group(1), lambda i, c: _same(c, m.group(2)))
    return None, None


def data_error_at(error: DataError, path: Path) -> DataError:
    """``error`` naming the file ``path`` and, where the message allows,
    the line (row, for parquet) and the column it concerns; the location
    is also on its ``path``, ``line`` (``row`` for parquet) and ``column``
    attributes."""
    if getattr(error, "path", None) is not None:
        return error
    message = cli_advice(" ".join(str(error).split()))
    line: Optional[int] = None
    row: Optional[int] = None
    column: Optional[str] = None
    raw = _raw_table(path)
    if raw is not None and not _MISSING.search(message):
        row, column = _find_row(raw, message)
    where = str(path)
    if path.suffix == ".parquet":
        if row is not None:
            where += f": row {row + 1}"
    else:
        header, rows = _csv_lines(path)
        line = header if _MISSING.search(message) else None
        if row is not None and 0 <= row < len(rows):
            line = rows[row]
        if line is not None:
            where += f":{line}"
    parts = [where] + ([f"column {column}"] if column is not None else []) + [message]
    out = type(error)(": ".join(parts))
    vars(out).update(path=str(path), line=line, row=row, column=column)
    return out


@contextmanager
def located_data_errors(path: Optional[Path]) -> Iterator[None]:
    """Re-raise a ``DataError`` raised inside the block naming the
    measurement file ``path`` (see ``data_error_at``); no location added
    when ``path`` is None. The Python API's advice is given as the command
    line's (``cli_advice``)."""
    try:
        yield
    except DataError as e:
        if path is None:
            text = str(e)
            if cli_advice(text) == text:
                raise
            raise type(e)(cli_advice(text)) from None
        raise data_error_at(e, path) from None

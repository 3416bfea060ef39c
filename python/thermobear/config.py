"""System descriptions (TOML). The Rust side parses and validates them and
rejects unknown keys by name; the built-in seed configurations ship inside
the package (``thermobear/configs/``)."""

from __future__ import annotations

import re
import tomllib
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from importlib import resources
from pathlib import Path
from typing import Any, Optional

import numpy as np

from . import _native

_CONFIG_PACKAGE = "thermobear.configs"


def seed_config_names() -> list[str]:
    """Names of the built-in seed configurations."""
    files = resources.files(_CONFIG_PACKAGE)
    return sorted(p.name[:-5] for p in files.iterdir() if p.name.endswith(".toml"))


def seed_config(name: str) -> str:
    """The TOML text of a built-in seed configuration."""
    from .errors import ConfigError

    if name not in seed_config_names():
        raise ConfigError(
            f"invalid config = {name}: unknown seed configuration; known: "
            + ", ".join(seed_config_names())
        )
    return resources.files(_CONFIG_PACKAGE).joinpath(name + ".toml").read_text()


def read_text_file(path: str | Path) -> str:
    """The text of the file at ``path`` (UTF-8). A file that cannot be read,
    or is not text (a binary file given as TOML or JSON), is a
    ``ConfigError`` naming the file, in one line; for a file that is not
    text its attribute ``not_text`` is True (the command line exits 2)."""
    from .errors import ConfigError

    p = Path(path)
    try:
        return p.read_text(encoding="utf-8")
    except OSError as e:
        err = ConfigError(f"{p}: cannot read: {e.strerror or e}")
    except UnicodeDecodeError as e:
        err = ConfigError(
            f"{p}: cannot read: not a UTF-8 text file (byte 0x{e.object[e.start]:02x} "
            f"at position {e.start})"
        )
        vars(err)["not_text"] = True
    vars(err).update(location=(str(err), None, None), path=str(p), line=None, key=None)
    raise err


#: Resolves a ``[bearing] preset`` name that is no built-in preset (a
#: catalogue designation) to a native bearing, or raises ConfigError; set
#: by the bearing catalogue (``set_catalogue_lookup``). None: the built-in
#: presets only.
_catalogue_lookup: Optional[Callable[[str], Any]] = None


def set_catalogue_lookup(lookup: Optional[Callable[[str], Any]]) -> None:
    """Install the resolver of catalogue designations (see
    ``catalogue_bearings``)."""
    global _catalogue_lookup
    _catalogue_lookup = lookup


def catalogue_bearings(text: str) -> Optional[dict[str, Any]]:
    """The bearing a description's ``[bearing] preset`` names when it is
    a catalogue designation rather than a built-in preset (``"7014C"``,
    ``"6310"``): ``{name as written: native bearing}``, for the native
    loader; None when the name is a built-in preset, is missing, or is no
    designation either (the native loader then names it with its line)."""
    try:
        name = tomllib.loads(text).get("bearing", {}).get("preset")
    except (tomllib.TOMLDecodeError, AttributeError):
        return None
    if not isinstance(name, str) or _catalogue_lookup is None:
        return None
    try:
        _native.Bearing.preset(name)
        return None
    except Exception:  # noqa: BLE001 -- not a built-in preset: try the catalogue
        pass
    from .errors import ConfigError

    try:
        return {name: _catalogue_lookup(name)}
    except ConfigError:
        return None


def load_config(path_or_text: str | Path) -> str:
    """Read a system description from a path (or take TOML text as is),
    check it on the Rust side and return the text. A ``ConfigError`` names
    the file (when read from one), the line and the key at fault. The
    ``[bearing] preset`` takes a built-in preset or a catalogue designation
    (as ``Bearing.preset`` does)."""
    text = str(path_or_text)
    p: Optional[Path] = None
    if "\n" not in text and "=" not in text:
        p = Path(text)
        text = read_text_file(p)
    try:
        with located_config_errors(p, text):
            tomllib.loads(text)
            _native.check_config(text, catalogue_bearings(text))
    except Exception as e:
        add_preset_hint(e, text)
        raise
    return text


def _preset_names(key: str) -> list[str]:
    """The preset names a key of a system description takes (none for a
    key that takes no preset)."""
    if key == "bearing.preset":
        return list(_native.Bearing.preset_names())
    if key in ("bearing.ring_material", "bearing.ball_material"):
        return list(_native.Material.preset_names())
    return []


def add_preset_hint(error: BaseException, text: str) -> None:
    """Add "; did you mean ...?" to a ``ConfigError`` about a misspelt
    preset name in the system description ``text`` (in place: its type and
    location attributes stay); other errors are left as they are."""
    from ._validate import did_you_mean

    key = getattr(error, "key", None)
    if not isinstance(key, str) or "did you mean" in str(error):
        return
    known = _preset_names(key)
    if not known:
        return
    try:
        value: Any = tomllib.loads(text)
        for part in key.split("."):
            value = value[part]
    except (tomllib.TOMLDecodeError, KeyError, TypeError):
        return
    hint = _designation_hint(value) if key == "bearing.preset" else ""
    hint = hint or did_you_mean(value, known)
    if hint:
        error.args = (f"{error}{hint}", *error.args[1:])
        loc = getattr(error, "location", None)
        if loc is not None:
            vars(error)["location"] = (f"{loc[0]}{hint}", *loc[1:])


def _designation_hint(name: Any) -> str:
    """Why ``name`` is no catalogue designation either (the catalogue's
    own reason, with its guess), or "" without a catalogue."""
    from .errors import ConfigError

    if not isinstance(name, str) or _catalogue_lookup is None:
        return ""
    try:
        _catalogue_lookup(name)
    except ConfigError as e:
        return "; nor a catalogue designation: " + str(e).split(": ", 1)[-1]
    return ""


def read_toml(text: str) -> dict:
    """The parsed TOML of a system description's text."""
    return tomllib.loads(text)


def sweep_speeds(cfg: dict, quick: bool = False) -> np.ndarray:
    """The speeds [rpm] of a parsed system description's ``[sweep]``:
    ``speeds_rpm``, or ``speed_count`` (default 51; at most 11 when
    ``quick``) from ``speed_start_rpm`` to ``speed_stop_rpm``."""
    sw = cfg.get("sweep", {})
    if "speeds_rpm" in sw:
        return np.asarray(sw["speeds_rpm"], dtype=float)
    n = int(sw.get("speed_count", 51))
    if quick:
        n = min(n, 11)
    return np.linspace(float(sw["speed_start_rpm"]), float(sw["speed_stop_rpm"]), n)


# ------------------------------------------------------------ error location
#
# A ConfigError raised while a TOML file is read or used is re-raised with
# the file, the line and the (dotted) key it concerns in front of the
# message: "system.toml:6: key bearing.ball_diameter_mm: must be ...". The
# line comes from the TOML parser when it gives one ("at line 6, column
# 1"); otherwise the key (or value) named by the message ("invalid
# ball_diameter_mm = -12: ...") is looked up in the file's text.

_AT_LINE = re.compile(r"at line (\d+), column (\d+)")
_INVALID = re.compile(r"invalid (?:key = )?['\"]?([A-Za-z_][\w.-]*)['\"]? = ['\"]?([^'\":]*)")
_NAMED_KEY = re.compile(r"invalid key = ['\"]?([A-Za-z_][\w.-]*)")
_KEY = re.compile(r"invalid (?:key = )?['\"]?([A-Za-z_][\w.-]*)")
_IN_TABLE = re.compile(r"in \[([\w.-]+)\]")
_HEADER = re.compile(r"^\s*\[\[?\s*([^\]]+?)\s*\]\]?\s*(?:#.*)?$")
_ENTRY = re.compile(
    r"^\s*((?:[A-Za-z0-9_-]+|\"[^\"]*\"|'[^']*')(?:\s*\.\s*(?:[A-Za-z0-9_-]+|\"[^\"]*\"|'[^']*'))*)\s*=(.*)$"
)


def _strip_comment(raw: str) -> str:
    """``raw`` up to a ``#`` that is not inside a quoted string."""
    quote = ""
    for i, ch in enumerate(raw):
        if quote:
            if ch == quote:
                quote = ""
        elif ch in "\"'":
            quote = ch
        elif ch == "#":
            return raw[:i]
    return raw


def _toml_entries(text: str) -> list[tuple[str, str, int, str]]:
    """(table, key, line, raw value) of every ``key = value`` line of TOML
    text and ("", table, line, "") of every table header; lines from 1, an
    array over several lines gathered into its raw value."""
    out: list[tuple[str, str, int, str]] = []
    table = ""
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        h = _HEADER.match(line)
        m = None if h else _ENTRY.match(line)
        if h:
            table = h.group(1).replace(" ", "").replace('"', "").replace("'", "")
            out.append(("", table, i + 1, ""))
        elif m:
            key = re.sub(r"\s*\.\s*", ".", m.group(1)).replace('"', "").replace("'", "")
            raw = _strip_comment(m.group(2)).strip()
            start = i
            while raw.startswith("[") and raw.count("[") > raw.count("]") and i + 1 < len(lines):
                i += 1
                raw += " " + _strip_comment(lines[i]).strip()
            out.append((table, key, start + 1, raw))
        i += 1
    return out


def _value_matches(raw: str, value: str) -> bool:
    value = value.strip()
    if not value or not raw:
        return False
    try:
        return float(raw) == float(value)
    except ValueError:
        pass
    if raw.strip("\"'") == value:
        return True
    return raw.startswith("[") and (f'"{value}"' in raw or f"'{value}'" in raw)


def locate_in_toml(text: str, message: str) -> tuple[Optional[int], Optional[str]]:
    """The line (from 1) and the dotted key (``table.key``) that a
    ``ConfigError`` message concerns in the TOML ``text``; None where they
    cannot be told."""
    entries = _toml_entries(text)

    def dotted(table: str, key: str) -> str:
        return f"{table}.{key}" if table else key

    at = _AT_LINE.search(message)
    if at is not None:
        line = int(at.group(1))
        for table, key, n, _ in entries:
            if n == line:
                return line, dotted(table, key)
        return line, None
    m = _NAMED_KEY.search(message) or _INVALID.search(message) or _KEY.search(message)
    if m is None:
        return None, None
    name = m.group(1)
    value = m.group(2) if m.re is _INVALID else ""
    t = _IN_TABLE.search(message)
    if t is not None:
        entries = [e for e in entries if e[0] == t.group(1) or (e[0] == "" and e[1] == t.group(1))]
    keyed = [e for e in entries if e[0] and (e[1] == name or e[1].endswith("." + name))]
    both = [e for e in keyed if _value_matches(e[3], value)]
    by_value = [e for e in entries if e[0] and _value_matches(e[3], value)]
    headers = [e for e in entries if not e[0] and e[1] == name]
    top = [e for e in entries if not e[0] and e[1] == name.split(".")[0]] if not t else []
    for found in (both, keyed, by_value, headers, top):
        if found:
            table, key, n, _ = found[0]
            return n, dotted(table, key)
    return None, None


def _clean_message(message: str) -> str:
    """A TOML parser's message on one line without its source excerpt."""
    caret = re.search(r"\|\s*\^+\s*(.*)$", message, re.S)
    if caret is not None and _AT_LINE.search(message):
        message = caret.group(1)
    message = re.sub(r"\s*\(at line \d+, column \d+\)", "", message)
    message = re.sub(r"^system description: ", "", message)
    return " ".join(message.split())


def config_error_at(
    error: BaseException, path: Optional[Path | str], text: Optional[str]
) -> BaseException:
    """``error`` (a ``ConfigError`` or a ``tomllib.TOMLDecodeError``) as a
    ``ConfigError`` that names the file ``path`` (when given), the line and
    the key in ``text``; the location is also on its ``path``, ``line`` and
    ``key`` attributes. An error that names its location already keeps it
    (a path is added when it had none)."""
    from .errors import ConfigError

    loc: Any = getattr(error, "location", None)
    if loc is not None:
        message, line, key = loc
        if getattr(error, "path", None) is not None or path is None:
            return error
    else:
        raw = str(error)
        message = _clean_message(raw)
        if isinstance(error, tomllib.TOMLDecodeError):
            message = "invalid TOML: " + message
        line, key = locate_in_toml(text, raw) if text is not None else (None, None)
        lineno = getattr(error, "lineno", None)  # tomllib gives it from Python 3.14
        if line is None and lineno is not None:
            line = int(lineno)
    where = []
    if path is not None:
        where.append(f"{path}:{line}" if line is not None else str(path))
    elif line is not None:
        where.append(f"line {line}")
    if key is not None:
        where.append(f"key {key}")
    cls = type(error) if isinstance(error, ConfigError) else ConfigError
    out = cls(": ".join(where + [message]))
    vars(out).update(
        location=(message, line, key),
        path=None if path is None else str(path),
        line=line,
        key=key,
    )
    return out


@contextmanager
def located_config_errors(path: Optional[Path | str], text: Optional[str] = None) -> Iterator[None]:
    """Re-raise a ``ConfigError`` or a TOML syntax error raised inside the
    block with the file ``path``, the line and the key it concerns (see
    ``config_error_at``); ``text``: the file's TOML (read from ``path``
    when not given)."""
    from .errors import ConfigError

    try:
        yield
    except (ConfigError, tomllib.TOMLDecodeError) as e:
        if text is None and path is not None:
            try:
                text = Path(path).read_text(encoding="utf-8")
            except (OSError, UnicodeDecodeError):
                text = None
        raise config_error_at(e, path, text) from None

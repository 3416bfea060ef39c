"""Every third-party module the package imports at run time is a declared
runtime dependency, so a fresh ``pip install .`` brings everything the
package needs (a regression once crashed ``thermobear demo`` for every new
user: scipy came only with the test extra).

The one exception: a module of an optional *feature* extra (an extra other
than the tooling ones, ``test``, ``docs``, ``bench``; e.g. ``dask`` for
studies on a cluster) may be imported where every import of it is guarded,
inside a ``try`` whose handler catches ``ImportError`` (so the package works
without it and says what to install)."""

from __future__ import annotations

import ast
import re
import sys
import tomllib
from importlib import metadata
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "python" / "thermobear"
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())


def _normalise(name: str) -> str:
    # PEP 503 name normalisation.
    return re.sub(r"[-_.]+", "-", name).lower()


def _requirement_name(req: str) -> str:
    return _normalise(re.split(r"[\s<>=!~;\[(]", req.strip(), maxsplit=1)[0])


def runtime_requirements() -> set[str]:
    return {_requirement_name(r) for r in PYPROJECT["project"]["dependencies"]}


def imported_top_level_modules(package: Path) -> dict[str, list[str]]:
    """Absolute imports anywhere in the package (module level and inside
    functions), as {top-level module: [file:line, ...]}."""
    found: dict[str, list[str]] = {}
    for path in sorted(package.rglob("*.py")):
        tree = ast.parse(path.read_text(), filename=str(path))
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                names = [node.module]
            else:
                continue
            for name in names:
                where = f"{path.relative_to(package.parent)}:{node.lineno}"
                found.setdefault(name.split(".")[0], []).append(where)
    return found


#: Extras for the project's own tooling; their packages may not be imported
#: by the package, guarded or not.
TOOLING_EXTRAS = ("test", "docs", "bench")


def feature_extra_requirements() -> dict[str, str]:
    """Distribution name -> the feature extra that declares it."""
    out = {}
    for extra, reqs in PYPROJECT["project"].get("optional-dependencies", {}).items():
        if extra not in TOOLING_EXTRAS:
            for r in reqs:
                out[_requirement_name(r)] = extra
    return out


def _catches_import_error(handler: ast.ExceptHandler) -> bool:
    names = []
    t = handler.type
    for node in t.elts if isinstance(t, ast.Tuple) else [t]:
        if isinstance(node, ast.Name):
            names.append(node.id)
    return bool({"ImportError", "ModuleNotFoundError"} & set(names))


def guarded_import_nodes(tree: ast.AST) -> set[int]:
    """ids of the import nodes inside the body of a ``try`` that catches
    ImportError (or ModuleNotFoundError)."""
    guarded: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Try) and any(_catches_import_error(h) for h in node.handlers):
            for stmt in node.body:
                for inner in ast.walk(stmt):
                    if isinstance(inner, (ast.Import, ast.ImportFrom)):
                        guarded.add(id(inner))
    return guarded


def guarded_only_modules(package: Path) -> set[str]:
    """Top-level modules every import of which is guarded (see above)."""
    guarded: dict[str, bool] = {}
    for path in sorted(package.rglob("*.py")):
        tree = ast.parse(path.read_text(), filename=str(path))
        inside = guarded_import_nodes(tree)
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                names = [node.module]
            else:
                continue
            for name in names:
                top = name.split(".")[0]
                guarded[top] = guarded.get(top, True) and id(node) in inside
    return {m for m, g in guarded.items() if g}


def third_party(modules: dict[str, list[str]]) -> dict[str, list[str]]:
    local = {"thermobear"}
    return {m: w for m, w in modules.items() if m not in sys.stdlib_module_names and m not in local}


def test_the_ast_walk_sees_lazy_imports(tmp_path):
    # A function-level import counts as much as a module-level one.
    (tmp_path / "m.py").write_text(
        "import os\nfrom . import x\n\n"
        "def f():\n    from scipy.stats import chi2\n    import yaml\n"
    )
    mods = third_party(imported_top_level_modules(tmp_path))
    assert set(mods) == {"scipy", "yaml"}


def undeclared_imports(package: Path) -> list[str]:
    declared = runtime_requirements()
    optional = feature_extra_requirements()
    guarded = guarded_only_modules(package)
    providers = metadata.packages_distributions()
    missing = []
    for module, where in sorted(third_party(imported_top_level_modules(package)).items()):
        # Import name -> distribution(s) from the installed metadata; a module
        # not installed here is taken to be its own distribution name.
        dists = {_normalise(d) for d in providers.get(module, [module])}
        if dists & declared:
            continue
        if module in guarded and dists & set(optional):
            continue  # an optional feature, imported only under a guard
        missing.append(f"{module} (distribution {sorted(dists)}) at {where[:3]}")
    return missing


def test_every_runtime_import_is_a_declared_dependency():
    missing = undeclared_imports(PACKAGE)
    assert not missing, "undeclared runtime imports:\n" + "\n".join(missing)


def test_optional_extra_imports_must_be_guarded(tmp_path):
    # dask is in the `dask` feature extra: fine under a guard, not without
    # one; a test-only package (hypothesis) is never fine.
    assert "dask" in feature_extra_requirements()
    (tmp_path / "ok.py").write_text(
        "def f():\n    try:\n        from dask.distributed import Client\n"
        "    except ImportError:\n        raise RuntimeError('pip install x[dask]')\n"
    )
    assert undeclared_imports(tmp_path) == []
    (tmp_path / "bare.py").write_text("def g():\n    import dask\n")
    assert [m.split()[0] for m in undeclared_imports(tmp_path)] == ["dask"]
    (tmp_path / "bare.py").unlink()
    (tmp_path / "tool.py").write_text(
        "try:\n    import hypothesis\nexcept ImportError:\n    hypothesis = None\n"
    )
    assert [m.split()[0] for m in undeclared_imports(tmp_path)] == ["hypothesis"]


def optional_module_calls(package: Path) -> list[tuple[str, str, str]]:
    """``(module, extra, where)`` of every ``optional_module("m", "extra", ...)``
    call in the package (the one place feature modules are imported by name)."""
    calls = []
    for path in sorted(package.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
            func = getattr(node, "func", None)
            name = getattr(func, "id", getattr(func, "attr", None))
            if isinstance(node, ast.Call) and name == "optional_module" and len(node.args) >= 2:
                module, extra = (ast.literal_eval(a) for a in node.args[:2])
                calls.append((module, extra, f"{path.name}:{node.lineno}"))
    return calls


def test_optional_modules_are_declared_in_their_extra():
    # A feature module asked for by name must come with the extra the
    # error message tells the user to install, and never with the plain install.
    extras = PYPROJECT["project"]["optional-dependencies"]
    providers = metadata.packages_distributions()
    calls = optional_module_calls(PACKAGE)
    assert ("dask.distributed", "dask") in {(m, e) for m, e, _ in calls}
    for module, extra, where in calls:
        top = module.split(".")[0]
        dists = {_normalise(d) for d in providers.get(top, [top])}
        declared = {_requirement_name(r) for r in extras.get(extra, [])}
        assert extra not in TOOLING_EXTRAS, f"{where}: {extra} is a tooling extra"
        assert dists & declared, f"{where}: {module} is not in the {extra!r} extra"
        assert not dists & runtime_requirements(), f"{where}: {module} is a runtime dependency"


def test_optional_module_names_the_extra_when_missing():
    from thermobear._optional import optional_module
    from thermobear.errors import ConfigError

    with pytest.raises(ConfigError, match=r'engine = .x.: .*pip install "thermobear\[dask\]"'):
        optional_module("thermobear_no_such_module", "dask", "engine", "x", "a test")


def test_installed_metadata_matches_pyproject():
    # The wheel's metadata is what pip installs from; it must say what
    # pyproject says (no marker-gated or extra-only runtime requirement).
    reqs = metadata.requires("thermobear") or []
    base = {_requirement_name(r) for r in reqs if "extra ==" not in r}
    assert base == runtime_requirements()


def test_source_parses_on_the_oldest_claimed_python():
    floor = PYPROJECT["project"]["requires-python"]
    m = re.fullmatch(r">=\s*3\.(\d+)", floor)
    assert m, f"requires-python {floor!r} is not a plain lower bound"
    minor = int(m.group(1))
    # The claimed floor is the interpreter CI runs (3.11); nothing may need newer syntax.
    assert sys.version_info >= (3, minor)
    for path in PACKAGE.rglob("*.py"):
        ast.parse(path.read_text(), filename=str(path), feature_version=(3, minor))

"""Every third-party module the package imports at run time is a declared
runtime dependency, so a fresh ``pip install .`` brings everything the
package needs (a regression once crashed ``thermobear demo`` for every new
user: scipy came only with the test extra)."""

from __future__ import annotations

import ast
import re
import sys
import tomllib
from importlib import metadata
from pathlib import Path

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


def test_every_runtime_import_is_a_declared_dependency():
    declared = runtime_requirements()
    providers = metadata.packages_distributions()
    missing = []
    for module, where in sorted(third_party(imported_top_level_modules(PACKAGE)).items()):
        # Import name -> distribution(s) from the installed metadata; a module
        # not installed here is taken to be its own distribution name.
        dists = {_normalise(d) for d in providers.get(module, [module])}
        if not dists & declared:
            missing.append(f"{module} (distribution {sorted(dists)}) at {where[:3]}")
    assert not missing, "undeclared runtime imports:\n" + "\n".join(missing)


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

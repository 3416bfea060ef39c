"""The package's layout: a layered import graph without cycles, small
functions, and a public namespace that is exactly ``__all__``.

The graph is read from the source with ``ast``: every import statement,
module level or inside a function, relative or absolute, counts. An edge
goes to the module imported (``from .x import y`` -> ``x``, or ``x.y`` when
``y`` is itself a module); importing a submodule does not count as an
import of its parent packages.
"""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "python" / "thermobear"

#: Bottom layer first. A module may import from its own layer or a lower
#: one; a module's layer is that of the longest prefix of its name listed.
LAYERS: list[tuple[str, ...]] = [
    (
        "thermobear._native",
        "thermobear.errors",
        "thermobear._optional",
        "thermobear._limits",
        "thermobear._validate",
        "thermobear._toml_text",
        "thermobear.plausibility",
        "thermobear._input_checks",
        "thermobear._types",
        "thermobear._deprecation",
        "thermobear._names",
        "thermobear._partial",
        "thermobear.glossary",
        "thermobear._model_hook",
        "thermobear.config",
    ),
    ("thermobear.bearing",),
    ("thermobear.thermal",),
    ("thermobear.gear", "thermobear.spindle", "thermobear.rotor"),
    ("thermobear.diagnosis",),
    ("thermobear.study",),
    ("thermobear.predict",),
    ("thermobear.plot",),
    ("thermobear.studies", "thermobear.validation"),
    ("thermobear.cli",),
    ("thermobear", "thermobear.__main__"),
]

MAX_FUNCTION_LINES = 80


def module_files(package: Path = PACKAGE) -> dict[str, Path]:
    """Dotted module name -> source file (``__init__.py`` for a package)."""
    root = package.parent
    out = {}
    for path in sorted(package.rglob("*.py")):
        parts = list(path.relative_to(root).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    if (package / "_native.pyi").exists():  # the extension module
        out.setdefault(f"{package.name}._native", package / "_native.pyi")
    return out


def _resolve(module: str, is_package: bool, node: ast.ImportFrom) -> str:
    if node.level == 0:
        return node.module or ""
    base = module.split(".")
    if not is_package:
        base = base[:-1]
    base = base[: len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def import_graph(package: Path = PACKAGE) -> dict[str, set[str]]:
    """Module -> the package's modules it imports (anywhere in its body)."""
    files = module_files(package)
    name = package.name
    graph: dict[str, set[str]] = {m: set() for m in files}
    for module, path in files.items():
        if path.suffix != ".py":
            continue
        is_package = path.name == "__init__.py"
        for node in ast.walk(ast.parse(path.read_text(), filename=str(path))):
            targets = []
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = _resolve(module, is_package, node)
                for a in node.names:
                    sub = f"{base}.{a.name}"
                    targets.append(sub if sub in files else base)
            for t in targets:
                if t != name and not t.startswith(name + "."):
                    continue
                while t not in files:  # `import thermobear.x.y` of a name in x
                    t = t.rsplit(".", 1)[0]
                if t != module:
                    graph[module].add(t)
    return graph


def find_cycle(graph: dict[str, set[str]]) -> list[str] | None:
    """One cycle of the graph as a list of modules (first = last), or None."""
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(m: str) -> list[str] | None:
        state[m] = 1
        stack.append(m)
        for n in sorted(graph.get(m, ())):
            if state.get(n) == 1:
                return stack[stack.index(n) :] + [n]
            if n not in state:
                found = visit(n)
                if found:
                    return found
        stack.pop()
        state[m] = 2
        return None

    for m in sorted(graph):
        if m not in state:
            found = visit(m)
            if found:
                return found
    return None


def layer_of(module: str) -> int:
    best, layer = -1, None
    for i, names in enumerate(LAYERS):
        for n in names:
            if (module == n or module.startswith(n + ".")) and len(n) > best:
                best, layer = len(n), i
    if layer is None:
        raise AssertionError(f"{module} is in no layer of LAYERS")
    return layer


def upward_imports(graph: dict[str, set[str]]) -> list[str]:
    return sorted(
        f"{m} (layer {layer_of(m)}) imports {t} (layer {layer_of(t)})"
        for m, targets in graph.items()
        for t in targets
        if layer_of(t) > layer_of(m)
    )


# -- the checks on this package ---------------------------------------------


def test_the_import_graph_sees_the_package():
    graph = import_graph()
    assert "thermobear.diagnosis.workflow" in graph
    # lazy (function-level) and relative imports are edges too
    assert "thermobear.studies.output" in graph["thermobear.studies.seed_a_gear"]
    assert "thermobear.diagnosis.screening" in graph["thermobear.diagnosis.workflow"]
    assert "thermobear._native" in graph["thermobear.bearing.ball_bearing"]


def test_no_import_cycles():
    cycle = find_cycle(import_graph())
    assert cycle is None, "import cycle: " + " -> ".join(cycle or [])


def test_every_module_is_in_a_layer():
    for m in import_graph():
        layer_of(m)


def test_no_import_from_a_lower_layer_to_a_higher_one():
    bad = upward_imports(import_graph())
    assert not bad, "imports against the layers:\n" + "\n".join(bad)


def test_functions_are_short():
    sizes = []
    for path in PACKAGE.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                n = node.end_lineno - node.lineno + 1
                sizes.append((n, f"{path.relative_to(PACKAGE)}:{node.lineno} {node.name}"))
    largest = max(sizes)
    assert largest[0] < MAX_FUNCTION_LINES, f"largest function: {largest}"


def test_nothing_points_at_private_notes():
    for path in PACKAGE.rglob("*"):
        if path.is_file() and path.suffix in (".py", ".pyi", ".toml", ".csv", ".md"):
            text = path.read_text()
            for s in ("../shared", "/work/shared", "PHYSICS.md"):
                assert s not in text, f"{path.relative_to(PACKAGE)} mentions {s}"


def test_public_namespace_is_all():
    """In a fresh interpreter: every public name of ``thermobear`` is in
    ``__all__`` (subpackages included, deliberately) and vice versa."""
    code = (
        "import thermobear as tb\n"
        "public = {n for n in dir(tb) if not n.startswith('_')}\n"
        "print(sorted(public - set(tb.__all__)), sorted(set(tb.__all__) - public),"
        " len(tb.__all__) == len(set(tb.__all__)))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[] [] True", out.stdout


def test_public_namespace_is_all_in_process():
    import thermobear as tb

    public = {n for n in dir(tb) if not n.startswith("_")}
    # loaded on demand (by other tests in this process): the studies, the command
    # line and the data package of the seed configurations (importlib.resources)
    assert public - {"studies", "cli", "configs"} == set(tb.__all__)
    for leak in ("Optional", "annotations", "TYPE_CHECKING"):
        assert leak not in dir(tb)


def test_readme_names_keep_working():
    import re

    import thermobear as tb

    readme = (PACKAGE.parents[1] / "README.md").read_text()
    names = set(re.findall(r"\btb\.([A-Za-z_]\w*)", readme))
    assert names
    missing = sorted(n for n in names if not hasattr(tb, n))
    assert not missing
    assert names <= set(tb.__all__)


# -- the checker itself -------------------------------------------------------


def _write(root: Path, files: dict[str, str]) -> Path:
    pkg = root / "pkg"
    for rel, text in files.items():
        p = pkg / rel
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(text)
    return pkg


def test_checker_finds_a_cycle_through_a_lazy_import(tmp_path):
    pkg = _write(
        tmp_path,
        {
            "__init__.py": "",
            "a.py": "from .b import f\n",
            "b.py": "def f():\n    from . import a\n",
        },
    )
    cycle = find_cycle(import_graph(pkg))
    assert cycle is not None and set(cycle) == {"pkg.a", "pkg.b"}


def test_checker_resolves_relative_and_absolute_imports(tmp_path):
    pkg = _write(
        tmp_path,
        {
            "__init__.py": "from .sub import x\n",
            "sub/__init__.py": "from .x import g\n",
            "sub/x.py": "import pkg.y\nfrom .. import z\ndef g():\n    from ..y import h\n",
            "y.py": "def h(): ...\n",
            "z.py": "",
        },
    )
    g = import_graph(pkg)
    assert g["pkg"] == {"pkg.sub.x"}  # `from .sub import x`: x is a module
    assert g["pkg.sub"] == {"pkg.sub.x"}
    assert g["pkg.sub.x"] == {"pkg.y", "pkg.z"}
    assert find_cycle(g) is None


def test_checker_flags_an_upward_import(monkeypatch):
    graph = {"thermobear.bearing.material": {"thermobear.plot.axes"}}
    graph["thermobear.plot.axes"] = set()
    bad = upward_imports(graph)
    assert len(bad) == 1 and "thermobear.plot.axes" in bad[0]


@pytest.mark.parametrize("module", ["thermobear.errors", "thermobear.diagnosis.workflow"])
def test_layers_are_ordered(module):
    assert layer_of(module) < layer_of("thermobear.studies.demo")


def test_bench_scripts_import_names_that_exist():
    """The Python benchmark scripts are not run by the tests (they time
    things), so check what they import from thermobear still exists."""
    import importlib

    benches = PACKAGE.parents[1] / "benches"
    checked = 0
    for path in sorted(benches.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("thermobear"):
                module = importlib.import_module(node.module)
                for alias in node.names:
                    assert hasattr(module, alias.name), f"{path.name}: {node.module}.{alias.name}"
                    checked += 1
    assert checked > 0

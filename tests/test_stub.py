"""The checked-in type stub lists exactly what the extension module exports."""

import re
from pathlib import Path

import thermobear._native as native


def test_native_stub_matches_the_module():
    root = Path(__file__).resolve().parents[1]
    pyi = (root / "python" / "thermobear" / "_native.pyi").read_text()
    stubbed = set(re.findall(r"^(?:def|class) (\w+)", pyi, re.M))
    exported = {x for x in dir(native) if not x.startswith("_")}
    assert exported - stubbed == set(), "exported but not in _native.pyi"
    assert stubbed - exported == set(), "in _native.pyi but not exported"


def test_native_stub_signatures_match_the_module():
    """Parameter names of every stubbed function and method equal the
    extension's own text signature (where it has one)."""
    import ast
    import inspect

    root = Path(__file__).resolve().parents[1]
    tree = ast.parse((root / "python" / "thermobear" / "_native.pyi").read_text())

    def params(fn: ast.FunctionDef) -> list[str]:
        a = fn.args
        names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]
        return [n for n in names if n not in ("self", "cls")]

    checked = 0
    for node in tree.body:
        items = []
        if isinstance(node, ast.FunctionDef):
            items.append((getattr(native, node.name), node))
        elif isinstance(node, ast.ClassDef):
            cls = getattr(native, node.name)
            for f in node.body:
                if isinstance(f, ast.FunctionDef) and not f.decorator_list:
                    items.append((getattr(cls, f.name, None), f))
        for obj, fn in items:
            if obj is None or fn.name.startswith("__"):
                continue
            try:
                sig = inspect.signature(obj)
            except (TypeError, ValueError):
                continue
            got = [n for n in sig.parameters if n not in ("self", "cls")]
            assert got == params(fn), f"{fn.name}: module {got} vs stub {params(fn)}"
            checked += 1
    assert checked > 20

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

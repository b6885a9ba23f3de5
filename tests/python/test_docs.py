"""The examples of docs/python.md and the README run as printed, and help(appell) reads as a manual."""
import os
import pydoc
import re

import pytest

import appell
from conftest import SOURCE


def python_blocks(path):
    text = (SOURCE / path).read_text()
    return re.findall(r"```python\n(.*?)```", text, flags=re.S)


@pytest.mark.parametrize("path", ["docs/python.md", "README.md"])
def test_examples_run_as_printed(path, tmp_path, monkeypatch):
    missing = [x for x in ("long-double", "dd", "float128", "mpfr") if x not in appell.built_scalars()]
    if missing and path == "docs/python.md":  # its examples run every scalar (the README's: interval)
        pytest.skip(f"this build left out {', '.join(missing)} (scripts/test.sh --full builds every scalar)")
    blocks = python_blocks(path)
    assert blocks, f"{path} has no Python example"
    os.symlink(SOURCE / "data", tmp_path / "data")
    monkeypatch.chdir(tmp_path)  # the examples' paths are relative to the source tree; their files land here
    import mpmath

    saved = mpmath.mp.dps  # the examples set mpmath's precision for themselves: restored after
    monkeypatch.setattr(mpmath.mp, "dps", saved)
    for code in blocks:
        namespace = {"__name__": "__example__"}
        exec(compile(code, f"{path} example", "exec"), namespace)
        for name, f in list(namespace.items()):  # an engine's test: run it as pytest would
            if name.startswith("test_") and callable(f):
                f()
    if path == "docs/python.md":
        assert (tmp_path / "precision.png").stat().st_size > 10000


def test_help_reads_as_a_manual():
    text = pydoc.render_doc(appell, renderer=pydoc.plaintext)
    for word in ("Scene", "Interval", "reference", "score", "enclose", "InputError", "NotCertified", "Interrupted"):
        assert word in text
    for obj in (appell.Scene, appell.Scene.eval, appell.Scene.with_state, appell.Interval, appell.reference,
                appell.score, appell.enclose, appell.simulate, appell.validity, appell.Evaluation, appell.Run):
        assert obj.__doc__ and len(obj.__doc__) > 60, obj

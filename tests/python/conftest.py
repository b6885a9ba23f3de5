"""The Python module's suite: run by CTest (`ctest -R python`) with the module from the build tree
(PYTHONPATH=build/python) and APPELL_SOURCE_DIR set; or by hand:
    PYTHONPATH=build/python APPELL_SOURCE_DIR=$PWD python3 -m pytest tests/python
Truth is computed here, independently of appell: closed forms in mpmath at 120 digits."""
import os
import pathlib

import pytest

SOURCE = pathlib.Path(os.environ.get("APPELL_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SCENES = SOURCE / "data" / "scenes"


@pytest.fixture
def scenes():
    return SCENES


def build_program(name, required=True):
    """A program of the build tree (the `appell` command, an engine). Under CTest
    (APPELL_BUILD_DIR set) a required one must be there; an optional one (an engine whose package
    CMake did not find) is None, and the test that needs it is skipped, saying so."""
    under_ctest = "APPELL_BUILD_DIR" in os.environ
    build = pathlib.Path(os.environ.get("APPELL_BUILD_DIR", SOURCE / "build"))
    for p in (build / name, build / "tests" / "engines" / name):
        if p.exists():
            return p
    if required and under_ctest:
        raise FileNotFoundError(f"{name}: not in the build tree {build}")
    return None

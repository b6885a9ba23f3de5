"""The standing humanoid's scenes are what their scripts write (docs/contacts.md): the torques of
data/scenes/urdf_atlas_standing.json from scripts/standing_torques.py run on the scene without
torques, and data/scenes/urdf_atlas_standing_held.json from scripts/standing_gains.py run on the
standing scene.  Each script is run with the build's `appell` and its output compared with the
shipped file: the same state and contacts, the torques within a rounding of the evaluations
(the scripts print 17 and 6 significant digits)."""
import json
import math
import pathlib
import re
import subprocess
import sys

import pytest

from conftest import SCENES, SOURCE, build_program

URDF = pathlib.Path("/usr/share/doc/dart/data/sdf/atlas/atlas_v3_no_head.urdf")
pytestmark = pytest.mark.skipif(not URDF.exists(), reason="dart-doc's Atlas URDF is not installed")


def run_script(name, *args):
    appell = build_program("appell")
    if appell is None:
        pytest.skip("no appell in the build tree")
    subprocess.run([sys.executable, str(SOURCE / "scripts" / name), str(appell), *map(str, args)],
                   check=True, capture_output=True, text=True)


def load(path):
    with open(path) as f:
        return json.load(f)


def close(a, b, rel):
    return math.isclose(float(a), float(b), rel_tol=rel, abs_tol=1e-9)


def test_the_standing_torques_are_the_script_s(tmp_path):
    out = tmp_path / "standing.json"
    run_script("standing_torques.py", SCENES / "urdf_atlas_standing_no_torques.json", out)
    written, shipped = load(out), load(SCENES / "urdf_atlas_standing.json")
    assert written["state"] == shipped["state"]
    assert written["contacts"] == shipped["contacts"]
    assert set(written["torques"]) == set(shipped["torques"])
    for joint, tau in shipped["torques"].items():
        assert close(written["torques"][joint], tau, 1e-9), joint


HELD = re.compile(r"^(\S+) \+ (\S+) \* \((\S+) - (\S+)\)$")


def test_the_held_scene_is_the_script_s(tmp_path):
    out = tmp_path / "held.json"
    run_script("standing_gains.py", SCENES / "urdf_atlas_standing.json", out, 30)
    written, shipped = load(out), load(SCENES / "urdf_atlas_standing_held.json")
    standing = load(SCENES / "urdf_atlas_standing.json")
    assert written["state"] == shipped["state"] == standing["state"]
    assert written["contacts"] == shipped["contacts"]
    assert set(written["torques"]) == set(shipped["torques"])
    joints = [j for j in standing["state"] if not j.startswith("base_")]
    assert sorted(shipped["torques"]) == sorted(joints)
    for joint in joints:
        w, s = HELD.match(written["torques"][joint]), HELD.match(shipped["torques"][joint])
        assert w and s, joint
        # the holding torque is the standing scene's, the pose its state, the joint itself
        assert s.group(1) == standing["torques"].get(joint, "0") and w.group(1) == s.group(1)
        assert s.group(3) == standing["state"][joint]["q"] and s.group(4) == joint
        assert w.group(3) == s.group(3) and w.group(4) == s.group(4)
        gain = float(s.group(2))
        assert gain > 0 and close(w.group(2), gain, 2e-5), joint

"""The standing humanoid's scenes are what their scripts write (docs/contacts.md): the torques of
data/scenes/urdf_atlas_standing.json from scripts/standing_torques.py run on the scene without
torques, and data/scenes/urdf_atlas_standing_held.json from scripts/standing_gains.py run on the
standing scene.  Each script is run with the build's `appell` and its output compared with the
shipped file: the same state and contacts, the torques within a rounding of the evaluations
(the scripts print 17 and 6 significant digits).  And scripts/standing_modes.py: the rests'
modes it measures are docs/contacts.md's ("The modes of the rest"), and the controller it writes
puts every mode at the frequency asked, measured again on the scene written."""
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


def script_output(name, *args):
    """A script of scripts/ run with the build's appell: its standard output."""
    appell = build_program("appell")
    if appell is None:
        pytest.skip("no appell in the build tree")
    return subprocess.run([sys.executable, str(SOURCE / "scripts" / name), str(appell), *map(str, args)],
                          check=True, capture_output=True, text=True).stdout


def run_script(name, *args):
    script_output(name, *args)


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


REST = re.compile(r"^rest: (\d+) modes; largest real part (\S+) per s( \(unstable: (\d+) of them)?.*?"
                  r"(; frequencies (\S+) to (\S+) rad/s)?$", re.M)


def rest_modes(scene):
    m = REST.search(script_output("standing_modes.py", scene))
    assert m, "no modes reported for %s" % scene
    return {"modes": int(m.group(1)), "growth": float(m.group(2)), "unstable": int(m.group(4) or 0),
            "frequencies": (float(m.group(6)), float(m.group(7))) if m.group(5) else None}


def test_the_rests_modes_are_the_docs(tmp_path):
    # docs/contacts.md, "The modes of the rest": on constant torques the knees buckle at 30.9 per
    # second; held by joint stiffness one slower mode still leaves the rest, at 3.3 per second
    standing = rest_modes(SCENES / "urdf_atlas_standing.json")
    assert standing["modes"] == 42 and 30.8 < standing["growth"] < 31.0 and standing["unstable"] == 12
    held = rest_modes(SCENES / "urdf_atlas_standing_held.json")
    assert held["modes"] == 42 and 3.25 < held["growth"] < 3.35 and held["unstable"] == 1
    assert 70.5 < held["frequencies"][1] < 71.0


@pytest.mark.parametrize("w", [10, 12.5])
def test_the_modal_controller_puts_every_mode_at_w(tmp_path, w):
    # the gains from the rest's linearization; the modes measured again on the scene written
    out = tmp_path / "modes.json"
    script_output("standing_modes.py", SCENES / "urdf_atlas_standing.json", out, w)
    written, standing = load(out), load(SCENES / "urdf_atlas_standing.json")
    assert written["state"] == standing["state"] and written["contacts"] == standing["contacts"]
    modes = rest_modes(out)
    assert modes["modes"] == 42 and modes["unstable"] == 0 and abs(modes["growth"]) < 1e-4
    low, high = modes["frequencies"]
    assert abs(low - w) < 1e-4 * w and abs(high - w) < 1e-4 * w

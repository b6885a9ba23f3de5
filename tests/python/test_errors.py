"""Errors as exceptions whose classes follow the command's exit statuses, with its one-line messages."""
import subprocess

import pytest

import appell
from conftest import SCENES, build_program


def cli_message(args):
    """The command's exit status and its one line on stderr, less the "appell: " prefix."""
    exe = build_program("appell")
    if exe is None:
        pytest.skip("the appell command is not built")
    r = subprocess.run([str(exe)] + args, capture_output=True, text=True)
    line = r.stderr.strip().splitlines()[-1]
    assert line.startswith("appell: ")
    return r.returncode, line[len("appell: "):]


def test_bad_input_is_input_error_with_the_commands_message(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"model": "euler_body", "inertia": {"A": "2", "B": "3", "C": "-4"}, "torque": ["0","0","0"],'
                   ' "state": {"omega": ["1", "2", "3"]}}')
    with pytest.raises(appell.InputError) as e:
        appell.Scene.from_file(bad)
    status, line = cli_message(["eval", str(bad)])
    assert status == 2 and str(e.value) == line
    assert isinstance(e.value, ValueError) and isinstance(e.value, appell.Error) and e.value.exit_status == 2


def test_refusals_name_what_is_wrong():
    s = appell.Scene.from_file(SCENES / "euler_body.json")
    with pytest.raises(appell.InputError, match="scalar"):
        s.eval("quad")
    with pytest.raises(appell.InputError, match="--bits"):
        s.eval("double", bits=100)
    with pytest.raises(appell.InputError, match="not a number of the scene"):
        s.with_state(theta="1")
    with pytest.raises(appell.InputError):
        s.with_state({"omega[0]": "one"})
    with pytest.raises(appell.InputError, match="not a double"):
        s.with_state({"omega[0]": __import__("fractions").Fraction(1, 3)})
    with pytest.raises(appell.InputError):
        s.with_state({"omega[0]": float("nan")})
    with pytest.raises(appell.InputError):
        appell.Scene.from_file(SCENES / "no_such_scene.json")
    with pytest.raises(appell.InputError):
        appell.Scene.from_dict({"model": "no_such_model"})
    with pytest.raises(appell.InputError):
        appell.Scene.from_json("{not json")
    # the original is untouched by a failed variant
    assert s.eval("interval").results["omega_dot"][0].contains("-0.1")


def test_an_uncertifiable_result_is_not_certified(tmp_path):
    # omega so large that the products overflow double: interval cannot certify (exit 3); mpfi can
    huge = tmp_path / "huge.json"
    huge.write_text('{"model": "euler_body", "inertia": {"A": "2", "B": "3", "C": "4"}, "torque": ["0","0","0"],'
                    ' "state": {"omega": ["1e200", "1e200", "1e200"]}}')
    s = appell.Scene.from_file(huge)
    with pytest.raises(appell.NotCertified) as e:
        s.eval("interval")
    status, line = cli_message(["eval", str(huge), "--scalar", "interval"])
    assert status == 3 and str(e.value) == line
    assert isinstance(e.value, ArithmeticError) and e.value.exit_status == 3
    assert s.eval("mpfi", 128).results["omega_dot"][0].contains(-(10**400) // 2)


def test_a_run_s_settings_take_numbers_or_decimals_and_refuse_the_rest():
    # A setting that is a number takes an int, a float or a decimal str, as the command's flag; anything
    # else is an InputError naming the setting (not pybind11's "Unable to cast").
    scene = SCENES / "rolling_sphere_bowl_contact.json"
    a = appell.validity(scene, ("mu", "0", "0.4"), "0.05", resolution=0.1)
    b = appell.validity(scene, ("mu", "0", "0.4"), "0.05", resolution="0.1")
    assert a.pieces["lo_text"] == b.pieces["lo_text"] and a.pieces["verdict"] == b.pieces["verdict"]
    for options, name in (({"resolution": [1]}, "resolution"), ({"resolution": "fine"}, "resolution"),
                          ({"tol": {}}, "tol"), ({"max_seconds": "soon"}, "max_seconds"), ({"order": "12.5"}, "order"),
                          ({"jobs": 1.5}, "jobs"), ({"bits": "many"}, "bits")):
        with pytest.raises(appell.InputError, match=name):
            appell.validity(scene, ("mu", "0", "0.4"), "0.05", **options)
    with pytest.raises(appell.InputError, match="field"):
        appell.validity(scene, (1, "0", "0.4"), "0.05")
    with pytest.raises(appell.InputError, match="resolution"):
        appell.validity(scene, ("mu", "0", "0.4"), "0.05", resolution=-1)  # the library's own check

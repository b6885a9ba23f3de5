"""Scenes and their evaluation: interval results contain the truth, point scalars agree with it."""
import json
import random
import subprocess

import mpmath
import numpy as np
import pytest

import appell
from conftest import SCENES, build_program



def dec(rng, lo, hi, digits=6):
    """A random decimal in [lo, hi] with `digits` decimals, as text (exact)."""
    return f"{rng.uniform(lo, hi):.{digits}f}"


def inertias(rng):
    """Principal moments of a body: A = b + c, B = c + a, C = a + b (the triangle inequality holds)."""
    from decimal import Decimal

    a, b, c = (Decimal(dec(rng, 0.1, 3)) for _ in range(3))
    return str(b + c), str(c + a), str(a + b)


def euler_truth(A, B, C, w, M):
    with mpmath.workdps(120):
        return _euler_truth(A, B, C, w, M)


def _euler_truth(A, B, C, w, M):
    A, B, C = (mpmath.mpf(x) for x in (A, B, C))
    w = [mpmath.mpf(x) for x in w]
    M = [mpmath.mpf(x) for x in M]
    return [((B - C) * w[1] * w[2] + M[0]) / A, ((C - A) * w[2] * w[0] + M[1]) / B, ((A - B) * w[0] * w[1] + M[2]) / C]


def test_euler_body_intervals_contain_eulers_equations_at_random_states():
    rng = random.Random(20261205)
    base = appell.Scene.from_file(SCENES / "euler_body.json")
    checked = 0
    for i in range(60):
        A, B, C = inertias(rng)
        w = [dec(rng, -30, 30) for _ in range(3)]
        M = [dec(rng, -2, 2) for _ in range(3)]
        s = appell.Scene.from_dict({"model": "euler_body", "inertia": {"A": A, "B": B, "C": C}, "torque": M,
                                    "state": {"omega": w}})
        truth = euler_truth(A, B, C, w, M)
        for scalar, bits in (("interval", None), ("mpfi", 200), ("arb", 128)):
            if scalar not in appell.built_scalars():
                continue
            ev = s.eval(scalar, bits)
            assert ev.rigorous
            for k in range(3):
                iv = ev.results["omega_dot"][k]
                assert isinstance(iv, appell.Interval)
                assert iv.contains(truth[k]), (scalar, A, B, C, w, M, k, iv, truth[k])
                assert iv.lo <= iv.mid() <= iv.hi  # a float: it may miss an interval narrower than a double
                # the floats are an enclosure too (the scalar's own bounds rounded outward)
                with mpmath.workdps(120):
                    assert mpmath.mpf(iv.lo) <= truth[k] <= mpmath.mpf(iv.hi)
                checked += 1
        # the same state given as a variant of the file's scene: the same enclosures
        v = base.with_state({"omega[0]": w[0], "omega[1]": w[1], "omega[2]": w[2]}).with_parameter(
            {"inertia.A": A, "inertia.B": B, "inertia.C": C, "torque[0]": M[0], "torque[1]": M[1], "torque[2]": M[2]})
        assert v.eval("interval").results["omega_dot"] == s.eval("interval").results["omega_dot"]
    assert checked >= 60 * 3 * 2


def test_point_scalars_agree_with_the_truth_to_their_precision():
    rng = random.Random(7)
    for i in range(20):
        A, B, C = inertias(rng)
        w = [dec(rng, -30, 30) for _ in range(3)]
        s = appell.Scene.from_dict({"model": "euler_body", "inertia": {"A": A, "B": B, "C": C},
                                    "torque": ["0", "0", "0"], "state": {"omega": w}})
        truth = euler_truth(A, B, C, w, ["0", "0", "0"])
        scale = max(abs(t) for t in truth)  # mpf at 120 digits: exact enough for 200 bits
        for scalar, bits, eps in (("double", None, 2.0**-53), ("long-double", None, 2.0**-64), ("dd", None, 2.0**-104),
                                  ("float128", None, 2.0**-113), ("mpfr", 200, 2.0**-200)):
            if scalar not in appell.built_scalars():  # scripts/test.sh's quick tier left it out
                continue
            ev = s.eval(scalar, bits)
            assert not ev.rigorous
            for k in range(3):
                x = ev.results["omega_dot"][k]
                if scalar == "double":
                    assert isinstance(x, float)
                else:
                    assert isinstance(x, mpmath.mpf)
                # a handful of roundings in a formula of three products: 64 ulps of the largest result
                with mpmath.workdps(120):  # x exactly (an mpf keeps its bits; arithmetic at 120 digits)
                    assert abs(x - truth[k]) <= 64 * eps * scale, (scalar, k, x, truth[k])


def test_sleigh_reaction_and_accelerations_contain_the_closed_form():
    rng = random.Random(11)
    sleigh = appell.Scene.from_file(SCENES / "system_chaplygin_sleigh.json")
    for i in range(40):
        m, I, a = dec(rng, 0.5, 3), dec(rng, 0.1, 2), dec(rng, 0.05, 1)
        u, w, theta = dec(rng, -3, 3), dec(rng, -5, 5), dec(rng, -3, 3)
        s = sleigh.with_parameter({"parameters.m": m, "parameters.I": I, "parameters.a": a}).with_state(u=u, w=w, theta=theta)
        with mpmath.workdps(120):
            M, J, A, U, W = (mpmath.mpf(x) for x in (m, I, a, u, w))
            J = J + M * A**2
            u_dot, w_dot = A * W**2, -M * A * U * W / J
            reaction = M * (A * w_dot + U * W)
        ev = s.eval("mpfi", 128)
        assert ev.results["u_dot"].contains(u_dot)
        assert ev.results["w_dot"].contains(w_dot)
        assert ev.results["knife_reaction"].contains(reaction)
        assert ev.results["v_dot"].contains(0)


def test_documents_are_those_of_the_command():
    appell_cmd = build_program("appell")
    if appell_cmd is None:
        pytest.skip("the appell command is not built")
    for name in ("euler_body.json", "heavy_top.json", "system_chaplygin_sleigh.json", "urdf_wam.json"):
        s = appell.Scene.from_file(SCENES / name)
        for scalar in ("interval", "double"):
            cli = subprocess.run([str(appell_cmd), "eval", str(SCENES / name), "--scalar", scalar], capture_output=True,
                                 text=True, check=True).stdout
            assert s.eval(scalar).json() == cli, (name, scalar)
            cli = subprocess.run([str(appell_cmd), "eval", str(SCENES / name), "--scalar", scalar, "--format", "text"],
                                 capture_output=True, text=True, check=True).stdout
            assert s.eval(scalar).text() == cli, (name, scalar)


def test_evaluation_access():
    ev = appell.Scene.from_file(SCENES / "heavy_top.json").eval()
    assert ev.model == "heavy_top" and ev.scalar == "interval" and ev.bits == 53
    names = ev.names()
    b = ev.bounds()
    assert b.shape == (len(names), 2) and np.all(b[:, 0] <= b[:, 1])
    assert "pivot_force[2]" in names
    assert ev["pivot_force"][2] == ev.results["pivot_force"][2]
    with pytest.raises(KeyError):
        ev["no_such_result"]
    d = json.loads(ev.json())
    assert d["results"]["pivot_force"][2]["lo"] == ev["pivot_force"][2].lo_text
    iv = ev["pivot_force"][2]
    m = iv.to_mpmath()
    # to_mpmath rounds the decimals outward at mpmath's precision: it holds the interval (exactly)
    from appell._interval import exact
    from fractions import Fraction
    assert exact(mpmath.mpf(m.a)) <= Fraction(iv.lo_text) and exact(mpmath.mpf(m.b)) >= Fraction(iv.hi_text)
    assert iv.contains(ev["pivot_force"][2]) and not iv.contains(appell.Interval(iv.lo_text, str(2 * iv.hi)))
    lo, hi = iv
    assert lo == iv.lo and hi == iv.hi


def test_contacts_and_urdf():
    wam = appell.Scene.from_file(SCENES / "urdf_wam.json")
    d = wam.to_dict()
    s = appell.Scene.from_urdf(d["file"], base="fixed", gravity=d["gravity"], state=d["state"], torques=d["torques"])
    assert s.eval("interval").json() == wam.eval("interval").json()
    # Atlas proved to stand (docs/contacts.md): both soles hold, each its centre of pressure
    # enclosed, as the command's document says
    atlas = appell.Scene.from_file(SCENES / "urdf_atlas_standing.json")
    contact = atlas.eval("interval")
    assert set(contact.contacts) == {"left_sole", "right_sole"}
    document = json.loads(contact.json())["contacts"]
    for name, c in contact.contacts.items():
        assert c["verdict"] == "holds" and c["mu"] == "0.7"
        cop = c["center_of_pressure"]
        assert [x.lo_text for x in cop] == [x["lo"] for x in document[name]["center_of_pressure"]]
        assert c["required_mu"].hi_text == document[name]["required_mu"]["hi"]
    # gravity tilted (5 m/s^2 sideways) and friction 0.01: the soles need mu 0.046, and fail
    tilted = atlas.with_parameter({"gravity[0]": "5", "contacts.left_sole.mu": "0.01",
                                   "contacts.right_sole.mu": "0.01"}).eval("interval")
    for c in tilted.contacts.values():
        assert c["verdict"] == "fails" and c["required_mu"].lo > 0.04

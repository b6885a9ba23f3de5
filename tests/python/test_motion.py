"""simulate, enclose and validity from Python: the sleigh's motion in closed form, progress, Ctrl-C."""
import _thread
import threading
import time
from fractions import Fraction

import mpmath
import numpy as np
import pytest

import appell
from conftest import SCENES



def sleigh_closed_form(t, m, I, a, u0, w0):
    """The Chaplygin sleigh (knife at the origin of the body, centre a ahead): u' = a w^2,
    w' = -m a u w / J with J = I + m a^2; energy m u^2 + J w^2 = m V^2 gives
    u = V tanh(k t + c), w = w0 cosh(c) / cosh(k t + c), k = a m V / J, tanh(c) = u0 / V."""
    with mpmath.workdps(60):
        m, I, a, u0, w0, t = (mpmath.mpf(x) for x in (m, I, a, u0, w0, t))
        J = I + m * a**2
        V = mpmath.sqrt(u0**2 + J * w0**2 / m)
        k, c = a * m * V / J, mpmath.atanh(u0 / V)
        return V * mpmath.tanh(k * t + c), w0 * mpmath.cosh(c) / mpmath.cosh(k * t + c)


def test_enclose_holds_the_sleighs_closed_form():
    scene = appell.Scene.from_file(SCENES / "system_chaplygin_sleigh.json")
    run = appell.enclose(scene, "1")
    assert run.complete and run.summary["complete"]
    steps = run.text("steps")
    table = run.table("steps")
    assert len(steps["t1"]) >= 2
    for i, t1 in enumerate(steps["t1"]):
        u, w = sleigh_closed_form(t1, "2", "0.3", "0.4", "1", "2")
        for name, truth in (("u", u), ("w", w)):
            with mpmath.workdps(60):
                lo, hi = mpmath.mpf(steps[f"{name}_lo"][i]), mpmath.mpf(steps[f"{name}_hi"][i])
                assert lo <= truth <= hi, (name, t1, lo, truth, hi)
            # the float columns are rounded outward from the exact text (compared exactly)
            assert Fraction(table[f"{name}_lo"][i]) <= Fraction(steps[f"{name}_lo"][i])
            assert Fraction(table[f"{name}_hi"][i]) >= Fraction(steps[f"{name}_hi"][i])
    assert float(steps["t1"][-1]) == 1.0


@pytest.mark.skipif("dd" not in appell.built_scalars(), reason="this build left out dd (scripts/test.sh --full builds every scalar)")
def test_simulate_agrees_with_the_closed_form():
    run = appell.simulate(SCENES / "system_chaplygin_sleigh.json", "1", every="0.25", scalar="dd")
    assert run.complete
    tr = run.table("trajectory")
    assert list(tr["t"]) == [0, 0.25, 0.5, 0.75, 1]
    for i, t in enumerate(run.text("trajectory")["t"]):
        u, w = sleigh_closed_form(t, "2", "0.3", "0.4", "1", "2")
        with mpmath.workdps(60):  # dd's 106 bits: 1e-25 is some thousand ulps over four steps
            assert abs(mpmath.mpf(run.text("trajectory")["u"][i]) - u) < 1e-25
            assert abs(mpmath.mpf(run.text("trajectory")["w"][i]) - w) < 1e-25
    values, names = run.array("trajectory")
    assert values.shape == (5, len(names)) and names[0] == "t"


def test_progress_is_reported_and_its_exception_stops_the_run():
    seen = []
    run = appell.enclose(SCENES / "heavy_top.json", "0.2", progress=seen.append)
    assert run.complete and seen and seen[-1] == pytest.approx(1.0) and seen == sorted(seen)

    class Stop(Exception):
        pass

    def stop(fraction):
        raise Stop()

    with pytest.raises(Stop):
        appell.enclose(SCENES / "heavy_top.json", "0.2", progress=stop)


def test_ctrl_c_stops_cleanly_with_what_was_computed():
    scene = appell.Scene.from_file(SCENES / "heavy_top.json")
    started = threading.Event()

    def progress(fraction):
        started.set()

    timer = threading.Thread(target=lambda: (started.wait(30), time.sleep(0.3), _thread.interrupt_main()))
    timer.start()
    t0 = time.monotonic()
    with pytest.raises(KeyboardInterrupt) as e:
        appell.enclose(scene, "1000", progress=progress)  # hours if not interrupted
    timer.join()
    assert time.monotonic() - t0 < 60
    assert isinstance(e.value, appell.Interrupted)
    partial = e.value.result
    assert not partial.complete and len(partial.table("steps")["t1"]) > 0
    assert "interrupted" in partial.summary["reason"]
    # another run goes on normally afterwards
    assert appell.enclose(scene, "0.01").complete


def interrupt_soon(started):
    """A thread that sends Ctrl-C to the main thread 0.3 s after the call reports progress."""
    th = threading.Thread(target=lambda: (started.wait(30), time.sleep(0.3), _thread.interrupt_main()))
    th.start()
    return th


@pytest.mark.parametrize("call", ["simulate", "validity", "reference"])
def test_ctrl_c_stops_every_long_call(call):
    started = threading.Event()
    progress = lambda fraction: started.set()
    th = interrupt_soon(started)
    t0 = time.monotonic()
    with pytest.raises(appell.Interrupted) as e:
        if call == "simulate":  # 10^7 outputs: hours if not interrupted
            appell.simulate(SCENES / "heavy_top.json", "1e5", every="0.01", progress=progress)
        elif call == "validity":  # a fine resolution over a long horizon: many pieces
            appell.validity(SCENES / "rolling_sphere_bowl_contact.json", ("mu", "0", "2"), "0.2", resolution=1e-9,
                            progress=progress)
        else:
            states = np.random.default_rng(2).uniform(-5, 5, (200_000, 3))
            appell.reference(SCENES / "euler_body.json", states, fields=["omega[0]", "omega[1]", "omega[2]"],
                             progress=progress)
    th.join()
    assert time.monotonic() - t0 < 60
    r = e.value.result
    if call == "simulate":
        assert not r.complete and len(r.table("trajectory")["t"]) > 0
    elif call == "validity":
        assert not r.complete and "interrupted" in r.summary["reason"]
    else:
        assert 0 < len(r) < 200_000 and len(r.states) == len(r.certified) == len(r.inputs)


def test_other_threads_run_while_a_long_call_runs():
    """The GIL is released: a Python thread counts while enclose runs."""
    count = [0]
    done = threading.Event()

    def counter():
        while not done.is_set():
            count[0] += 1
            time.sleep(0.001)

    th = threading.Thread(target=counter)
    th.start()
    t0 = time.monotonic()
    appell.enclose(SCENES / "heavy_top.json", "0.5")
    elapsed = time.monotonic() - t0
    done.set()
    th.join()
    assert elapsed > 0.05 and count[0] > 10 * elapsed  # a held GIL would give it ~0


def test_validity_splits_the_range():
    res = appell.validity(SCENES / "rolling_sphere_bowl_contact.json", ("mu", "0.01", "1"), "0.05")
    assert set(res.pieces["verdict"]) <= {"holds", "fails", "undecided"}
    assert np.all(res.pieces["lo"] <= res.pieces["hi"])
    assert res.summary["field"] == "mu"


def test_bad_motion_input():
    with pytest.raises(appell.InputError):
        appell.enclose(SCENES / "heavy_top.json", "-1")
    with pytest.raises(appell.InputError):
        appell.simulate(SCENES / "heavy_top.json", "1", scalar="interval")
    with pytest.raises(appell.InputError):
        appell.validity(SCENES / "heavy_top.json", ("mu", "0", "1"), "1")

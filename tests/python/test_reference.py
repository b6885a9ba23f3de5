"""reference and score: certified values at many states, and a round trip against an engine."""
import io
import os
import subprocess

import numpy as np
import pandas as pd
import pytest

import appell
from conftest import SCENES, build_program


def test_reference_matches_the_command_and_holds_the_truth(tmp_path):
    rng = np.random.default_rng(5)
    n = 200
    states = pd.DataFrame({"omega[0]": rng.uniform(-20, 20, n), "omega[1]": rng.uniform(-20, 20, n),
                           "omega[2]": rng.uniform(-20, 20, n)})
    scene = appell.Scene.from_file(SCENES / "euler_body.json")
    ref = appell.reference(scene, states)
    assert ref.quantities == ["omega_dot[0]", "omega_dot[1]", "omega_dot[2]"]
    assert ref.certified.all() and len(ref) == n
    # Euler's equations in exact rationals at the doubles given: inside every enclosure
    from fractions import Fraction as F
    A, B, C = F(2), F(3), F(4)
    for i in range(n):
        w = [F(float(states.iloc[i, k])) for k in range(3)]
        truth = [(B - C) * w[1] * w[2] / A, (C - A) * w[2] * w[0] / B, (A - B) * w[0] * w[1] / C]
        for k in range(3):
            assert ref.interval(i, k).contains(truth[k])
            assert ref.lower[i, k] <= truth[k] <= ref.upper[i, k]
    # the command, given the same states as exact decimals, certifies the same bounds
    exe = build_program("appell")
    if exe is not None:
        csv = tmp_path / "states.csv"
        with open(csv, "w") as f:
            f.write("omega[0],omega[1],omega[2]\n")
            for i in range(n):
                f.write(",".join(appell._core._exact_decimal(float(x)) for x in states.iloc[i]) + "\n")
        subprocess.run([str(exe), "reference", str(SCENES / "euler_body.json"), "--states", str(csv), "--out",
                        str(tmp_path / "out"), "--quiet"], check=True, capture_output=True)
        table = pd.read_csv(tmp_path / "out" / "reference.csv", dtype=str)
        for _, row in table.iterrows():
            i, k = int(row["state"]) - 1, ref.quantities.index(row["quantity"])
            assert ref.exact(i, k)[:2] == (row["lower"], row["upper"])


def test_score_passes_good_values_and_fails_bad_ones():
    rng = np.random.default_rng(9)
    n = 100
    w = rng.uniform(-10, 10, (n, 3))
    ref = appell.reference(appell.Scene.from_file(SCENES / "euler_body.json"), w, fields=["omega[0]", "omega[1]", "omega[2]"])
    A, B, C = 2.0, 3.0, 4.0
    engine = np.column_stack([(B - C) * w[:, 1] * w[:, 2] / A, (C - A) * w[:, 2] * w[:, 0] / B, (A - B) * w[:, 0] * w[:, 1] / C])
    s = appell.score(ref, engine, min_digits=14)
    assert s.passed and s, s.report()
    assert all(q["within"] == n for q in s.quantities.values())
    bad = engine.copy()
    bad[17, 1] *= 1 + 1e-9
    s = appell.score(ref, bad)
    assert not s.passed and s.failures() == ["omega_dot[1]"]
    assert s.quantities["omega_dot[1]"]["worst_state"] == ref.states[17]
    # the exact branch: values on and just off the float bounds, and at the tolerance's edge
    j, i = 0, 3
    lo_t, hi_t, _, tol_t, _ = ref.exact(i, j)
    from fractions import Fraction
    edge = engine.copy()
    edge[i, j] = ref.lower[i, j]  # the lower bound rounded down: outside by less than an ulp, within tolerance
    s = appell.score(ref, edge)
    q = s.quantities["omega_dot[0]"]
    assert q["inside"] == n - (Fraction(ref.lower[i, j]) < Fraction(lo_t)) and q["within"] == n and s.passed
    far = Fraction(lo_t) - 2 * Fraction(tol_t)  # twice the tolerance below the enclosure
    edge[i, j] = float(far)
    s = appell.score(ref, edge)
    assert s.quantities["omega_dot[0]"]["within"] == n - 1 and not s.passed
    with pytest.raises(appell.InputError):
        appell.score(ref, engine.astype(np.longdouble) / 3)  # not doubles: refused, never rounded
    with pytest.raises(appell.InputError):
        appell.score(ref, engine, skip=["omega_dot*"])  # nothing scored
    # a quantity left out is a failure unless skipped
    partial = {"omega_dot[0]": engine[:, 0]}
    assert not appell.score(ref, partial)
    assert appell.score(ref, partial, skip=["omega_dot[1]", "omega_dot[2]"])
    with pytest.raises(appell.InputError):
        appell.score(ref, engine[:, :2])


def test_refused_states_are_kept_with_their_reason():
    states = {"inertia.C": ["4", "-1", "4.5"]}
    ref = appell.reference(appell.Scene.from_file(SCENES / "euler_body.json"), states)
    assert list(ref.certified) == [True, False, True]
    assert ref.reasons[1].startswith("refused: ")
    assert np.isnan(ref.lower[1]).all()


def test_a_round_trip_against_dart():
    """DART's values at appell's states (tests/engines/dart_reference), scored in Python."""
    dart = build_program("dart_reference", required=False)
    if dart is None:
        pytest.skip("DART's reference program is not built")
    scene = SCENES / "urdf_wam.json"
    states = pd.read_csv(io.StringIO(subprocess.run([str(dart), "states", str(scene), "40", "3"], capture_output=True,
                                                    text=True, check=True).stdout), dtype=str)
    # as tests/engine_score.sh: the robot's numbers as the doubles DART reads
    ref = appell.reference(appell.Scene.from_file(scene), states, scalar="mpfi", bits=113, inputs="binary64")
    assert ref.certified.all()
    path = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"appell_py_states_{os.getpid()}.csv")
    states.to_csv(path, index=False)
    try:
        values = pd.read_csv(io.StringIO(subprocess.run([str(dart), "values", str(scene), path], capture_output=True,
                                                         text=True, check=True).stdout), float_precision="round_trip")
    finally:
        os.unlink(path)
    s = appell.score(ref, values, min_digits=10, skip=["j0_*"])
    assert s.passed, s.report()
    # one value moved by 100 times its tolerance fails the score, and names its state
    values.loc[5, "j3_ddot"] += 100 * ref.tolerance[5, ref.index("j3_ddot")]
    bad = appell.score(ref, values, skip=["j0_*"])
    assert not bad.passed and bad.failures() == ["j3_ddot"] and bad.quantities["j3_ddot"]["worst_state"] == "s5"
    assert bad.quantities["j3_ddot"]["worst_tolerance_state"] == "s5"
    report = bad.report()
    assert "(outside tolerance: worst s5)" in report and report.endswith("values outside the suggested tolerance")

#!/usr/bin/env python3
"""The joint torques that hold a robot at rest on its contacts (docs/contacts.md, "A humanoid
standing"), found with appell's own forward dynamics in double.

With the contacts held, the joints' accelerations and the contacts' reactions are affine in the
torques: a(tau) = a0 + B tau, lambda(tau) = l0 + C tau; n + 1 evaluations give B and C up to
rounding.  The torques that leave every joint unaccelerated (B tau = -a0; the base then cannot
move: the contacts fix it through the legs) form a family: those that only press the feet
against each other through the ground add to any of them.  Of the family this takes the one whose
reactions are least, |lambda|^2 (the weight shared between the feet, the centres of pressure
near the soles' centres).  It writes the scene with those torques (17 digits); the certified
evaluation of that scene (interval, mpfi) is the proof, not this script.

usage: standing_torques.py APPELL SCENE_WITHOUT_TORQUES OUT_SCENE
"""
import json
import os
import subprocess
import sys


def evaluate(appell, scene, path):
    with open(path, "w") as f:
        json.dump(scene, f)
    out = subprocess.run([appell, "eval", path, "--scalar", "double", "--format", "json"],
                         check=True, capture_output=True, text=True).stdout
    results = json.loads(out)["results"]
    acc = {k[:-5]: float(v["value"]) for k, v in results.items() if k.endswith("_ddot")}
    reactions = {k: float(v["value"]) for k, v in results.items() if k.endswith("_reaction")}
    return acc, reactions


def read_scene(source):
    """The scene at source, its robot's file made absolute: the scene written elsewhere still
    finds its robot."""
    with open(source) as f:
        scene = json.load(f)
    if "file" in scene and not os.path.isabs(scene["file"]):
        scene["file"] = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(source)), scene["file"]))
    return scene


def eliminate(A, b):
    """Reduced row echelon form of [A | b]: (rows, pivots as (row, column), free columns)."""
    n, m = len(A), len(A[0])
    M = [row[:] + [b[i]] for i, row in enumerate(A)]
    scale = max(abs(x) for row in A for x in row)
    pivots, r = [], 0
    for c in range(m):
        if r == n:
            break
        p = max(range(r, n), key=lambda i: abs(M[i][c]))
        if abs(M[p][c]) <= 1e-9 * scale:
            continue
        M[r], M[p] = M[p], M[r]
        piv = M[r][c]
        M[r] = [x / piv for x in M[r]]
        for i in range(n):
            if i != r and M[i][c] != 0:
                f = M[i][c]
                M[i] = [x - f * y for x, y in zip(M[i], M[r])]
        pivots.append((r, c))
        r += 1
    pivot_cols = {c for _, c in pivots}
    return M, pivots, [c for c in range(m) if c not in pivot_cols]


def solve_square(A, b):
    M, pivots, free = eliminate(A, b)
    if free:
        raise RuntimeError("singular system")
    x = [0.0] * len(b)
    for r, c in pivots:
        x[c] = M[r][-1]
    return x


def main():
    appell, source, target = sys.argv[1:4]
    with open(source) as f:
        scene = json.load(f)
    joints = [j for j in scene["state"] if not j.startswith("base_")]
    tmp = target + ".tmp.json"
    scene["torques"] = {}
    a0, l0 = evaluate(appell, scene, tmp)
    names = sorted(l0)
    n = len(joints)
    B = [[0.0] * n for _ in joints]
    C = [[0.0] * n for _ in names]
    for k, j in enumerate(joints):
        scene["torques"] = {j: "1"}
        a, l = evaluate(appell, scene, tmp)
        for i, ji in enumerate(joints):
            B[i][k] = a[ji] - a0[ji]
        for i, ni in enumerate(names):
            C[i][k] = l[ni] - l0[ni]
    os.remove(tmp)
    # every solution of B tau = -a0: a particular one plus the null space's combinations
    M, pivots, free = eliminate(B, [-a0[j] for j in joints])
    tp = [0.0] * n
    for r, c in pivots:
        tp[c] = M[r][-1]
    Z = []
    for f in free:
        z = [0.0] * n
        z[f] = 1.0
        for r, c in pivots:
            z[c] = -M[r][f]
        Z.append(z)
    # least reactions: minimize |l0 + C tp + C Z y|^2 over y
    lp = [l0[names[i]] + sum(C[i][k] * tp[k] for k in range(n)) for i in range(len(names))]
    CZ = [[sum(C[i][k] * z[k] for k in range(n)) for z in Z] for i in range(len(names))]
    m = len(Z)
    N = [[sum(CZ[i][a] * CZ[i][b] for i in range(len(names))) for b in range(m)] for a in range(m)]
    rhs = [-sum(CZ[i][a] * lp[i] for i in range(len(names))) for a in range(m)]
    y = solve_square(N, rhs) if m else []
    tau = [tp[k] + sum(y[a] * Z[a][k] for a in range(m)) for k in range(n)]
    scene["torques"] = {j: "%.17g" % t for j, t in zip(joints, tau)}
    with open(target, "w") as f:
        json.dump(scene, f, indent=1)
    print("wrote %s: %d torques (%d of them free: the feet pressed against each other)" % (target, n, m))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The joint torques that hold a robot at rest on its contacts (docs/contacts.md, "A humanoid
standing"), by appell's own forward dynamics: with the contacts held, the joints' accelerations
are affine in the torques, u''(tau) = u''(0) + B tau, so n + 1 evaluations in double give B
exactly up to rounding and tau solves u''(tau) = 0 for the joints (the base then cannot move:
the contacts fix it through the legs).  Writes the scene with those torques (17 digits); the
certified evaluation of that scene (interval, mpfi) is the proof, not this script.

usage: standing_torques.py APPELL SCENE_WITHOUT_TORQUES OUT_SCENE
"""
import json
import subprocess
import sys


def accelerations(appell, scene, path):
    with open(path, "w") as f:
        json.dump(scene, f)
    out = subprocess.run([appell, "eval", path, "--scalar", "double", "--format", "json"],
                         check=True, capture_output=True, text=True).stdout
    results = json.loads(out)["results"]
    return {k[:-5]: float(v) for k, v in results.items() if k.endswith("_ddot")}


def solve(A, b):
    n = len(b)
    M = [row[:] + [b[i]] for i, row in enumerate(A)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(M[r][c]))
        M[c], M[p] = M[p], M[c]
        for r in range(n):
            if r != c:
                f = M[r][c] / M[c][c]
                for k in range(c, n + 1):
                    M[r][k] -= f * M[c][k]
    return [M[i][n] / M[i][i] for i in range(n)]


def main():
    appell, source, target = sys.argv[1:4]
    with open(source) as f:
        scene = json.load(f)
    joints = [j for j in scene["state"] if not j.startswith("base_")]
    tmp = target + ".tmp.json"
    scene["torques"] = {}
    a0 = accelerations(appell, scene, tmp)
    B = [[0.0] * len(joints) for _ in joints]
    for k, j in enumerate(joints):
        scene["torques"] = {j: "1"}
        a = accelerations(appell, scene, tmp)
        for i, ji in enumerate(joints):
            B[i][k] = a[ji] - a0[ji]
    tau = solve(B, [-a0[j] for j in joints])
    scene["torques"] = {j: "%.17g" % t for j, t in zip(joints, tau)}
    import os
    os.remove(tmp)
    with open(target, "w") as f:
        json.dump(scene, f, indent=1)
    print("wrote %s: %d torques" % (target, len(joints)))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The modes of a robot's rest on its contacts, and a controller that puts every one at a chosen
frequency (docs/contacts.md, "The modes of the rest").

usage: standing_modes.py APPELL SCENE                      the modes of SCENE's rest
       standing_modes.py APPELL STANDING_SCENE OUT [W]     OUT: the scene held at W rad/s (default 10)

With the contacts held, the motion near a rest keeps to a space T of the coordinates (dimension:
coordinates less constraints).  There

    delta q'' = A delta q + G delta tau    (A = d q''/d q at fixed torques, G = d q''/d tau)

(the rates enter the accelerations in products of two, nothing at rest, where the torques name
no rate: a scene whose torques do is refused) and the images of A and G lie in T (the
accelerations at rest are tangent to the contacts).  U, an orthonormal basis of T, comes from G's
singular vectors (the torques move the robot along every motion the contacts allow); the rest's
modes are the eigenvalues of the first-order system [[0, I], [A_T, 0]] on T (A_T = U' A U): a
positive real part is a rate at which the robot leaves its rest (Atlas on its bent knees, on
constant torques: 30.9 per second), an imaginary part a frequency.  A comes from appell's own
forward dynamics in double, by central differences along U; G exactly (the accelerations are
affine in the torques).  This is an estimate in double, not a proof: `enclose` proves how the
robot moves.

The controller: each actuated joint's torque becomes `tau_hold_j + sum_k K_jk (q0_k - q_k)`, with
G_T = U' G and U_j the joint rows of U (the legs hold the base: U_j has full column rank),

    K = G_T^+ (A_T + w^2 I) U_j^+,

so that on T the closed loop is A_T - G_T K U_j = -w^2 I: every mode at w rad/s, the buckling
included, and no rate term.  Written from the scene with constant torques that hold the rest
(scripts/standing_torques.py); the script then measures the written scene's modes as above and
prints them.
"""
import json
import os
import re
import sys
import tempfile

import numpy as np

from standing_torques import evaluate, read_scene  # appell eval in double; a scene, its robot's path absolute

STEP = 1e-6  # the central differences' step along each direction of T (rad, m)


def accelerations(appell, scene, path, names):
    """appell eval in double: the accelerations of names, in their order."""
    acc = evaluate(appell, scene, path)[0]
    return np.array([acc[c] for c in names])


def state_jacobian(appell, scene, path, coords, field, D):
    """d q''/d (field) times each column of D (directions in the coordinates' field) at the
    scene's state, its torques fixed: central differences, 2 D.shape[1] evaluations."""
    J = np.zeros((len(coords), D.shape[1]))
    for k in range(D.shape[1]):
        cols = []
        for sign in (1, -1):
            moved = json.loads(json.dumps(scene))
            for i, c in enumerate(coords):
                if D[i, k] != 0:
                    moved["state"][c][field] = repr(float(scene["state"][c].get(field, "0")) + sign * STEP * D[i, k])
            cols.append(accelerations(appell, moved, path, coords))
        J[:, k] = (cols[0] - cols[1]) / (2 * STEP)
    return J


def torque_matrix(appell, scene, path, coords, joints):
    """d q''/d tau (coordinates x joints): each torque moved by 1 N m (the accelerations are
    affine in the torques); the scene's torques must be numbers."""
    torques = scene.get("torques", {})
    a0 = accelerations(appell, scene, path, coords)
    G = np.zeros((len(coords), len(joints)))
    for k, j in enumerate(joints):
        moved = json.loads(json.dumps(scene))
        moved.setdefault("torques", {})[j] = repr(float(torques.get(j, "0")) + 1.0)
        G[:, k] = accelerations(appell, moved, path, coords) - a0
    return G, a0


def tangent_basis(G):
    """An orthonormal basis of G's image (the motions the contacts allow near the rest)."""
    u, s, _ = np.linalg.svd(G)
    rank = int(np.sum(s > 1e-9 * s[0]))
    return u[:, :rank], s


def modes(appell, scene, path, coords, U):
    """The eigenvalues of the rest's first-order system on T (per second).  d q''/d q' is 0 at
    rest: the rates enter the accelerations in products of two (load_scene refuses torques that
    name a rate)."""
    A_T = U.T @ state_jacobian(appell, scene, path, coords, "q", U)
    m = U.shape[1]
    B_T = np.zeros((m, m))
    return np.linalg.eigvals(np.block([[np.zeros((m, m)), np.eye(m)], [A_T, B_T]])), A_T


def describe(name, lam):
    growth = lam.real.max()
    freq = np.abs(lam.imag)
    oscillating = freq[freq > 1e-6 * max(1.0, np.abs(lam).max())]
    text = "%s: %d modes; largest real part %.4g per s" % (name, len(lam), growth)
    unstable = int(np.sum(lam.real > 1e-3 * max(1.0, np.abs(lam).max())))
    if unstable:
        text += " (unstable: %d of them leave the rest, the fastest at that rate)" % unstable
    if len(oscillating):
        text += "; frequencies %.5g to %.5g rad/s" % (oscillating.min(), oscillating.max())
    return text


def load_scene(source):
    """The scene (read_scene), refused unless at rest and with torques that name no rate."""
    scene = read_scene(source)
    for c, s in scene["state"].items():
        if float(s.get("q_dot", "0")) != 0:
            sys.exit("standing_modes.py: %s's rate is %s: the scene is not at rest" % (c, s["q_dot"]))
    for j, tau in scene.get("torques", {}).items():
        if re.search(r"_dot\b", tau):
            sys.exit("standing_modes.py: the torque of %s names a rate (%s): only torques of the coordinates and "
                     "time are handled" % (j, tau))
    return scene


def term(k, q0, joint):
    return "%s %.17g * (%s - %s)" % ("-" if k < 0 else "+", abs(k), q0, joint)


def main():
    if len(sys.argv) not in (3, 4, 5):
        sys.exit(__doc__)
    appell, source = sys.argv[1:3]
    out = sys.argv[3] if len(sys.argv) >= 4 else None
    w = float(sys.argv[4]) if len(sys.argv) == 5 else 10.0
    if not w > 0:
        sys.exit("standing_modes.py: W must be positive")
    scene = load_scene(source)
    torques = scene.get("torques", {})
    coords = list(scene["state"])
    joints = [c for c in coords if not c.startswith("base_")]
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "scene.json")
        if out is None:
            # G does not depend on the torques (the accelerations are affine in them): found
            # about zero torques, whatever expressions the scene's are
            a_rest = accelerations(appell, scene, path, coords)
            G, _ = torque_matrix(appell, dict(scene, torques={}), path, coords, joints)
            U, s = tangent_basis(G)
            lam, _ = modes(appell, scene, path, coords, U)
            print("%s: %d coordinates, %d actuated joints, motions near the rest: %d dimensions; the largest "
                  "acceleration at the state %.3g" % (source, len(coords), len(joints), U.shape[1], np.abs(a_rest).max()))
            print(describe("rest", lam))
            return
        for j, tau in torques.items():
            try:
                float(tau)
            except ValueError:
                sys.exit("standing_modes.py: the torque of %s is not a number (%s): give the standing scene "
                         "of scripts/standing_torques.py" % (j, tau))
        G, _ = torque_matrix(appell, scene, path, coords, joints)
        U, s = tangent_basis(G)
        rows = [coords.index(j) for j in joints]
        U_j = U[rows, :]
        if np.linalg.matrix_rank(U_j) < U.shape[1]:
            sys.exit("standing_modes.py: the joints do not determine the base near the rest")
        lam_open, A_T = modes(appell, scene, path, coords, U)
        G_T = U.T @ G
        K = np.linalg.pinv(G_T) @ (A_T + w * w * np.eye(U.shape[1])) @ np.linalg.pinv(U_j)
        written = json.loads(json.dumps(scene))
        written["torques"] = {
            j: "%s %s" % (torques.get(j, "0"),
                          " ".join(term(K[i, k], scene["state"][jk]["q"], jk) for k, jk in enumerate(joints)))
            for i, j in enumerate(joints)}
        with open(out, "w") as f:
            json.dump(written, f, indent=1)
            f.write("\n")
        lam, _ = modes(appell, written, path, coords, U)
    print("wrote %s: %d joints, %d coordinates, motions near the rest: %d dimensions (G's singular values %.3g "
          "to %.3g, then %.3g); gains up to %.3g N m/rad" %
          (out, len(joints), len(coords), U.shape[1], s[0], s[U.shape[1] - 1],
           s[U.shape[1]] if U.shape[1] < len(s) else 0.0, np.abs(K).max()))
    print(describe("the rest on constant torques", lam_open))
    print(describe("the rest held (measured on the scene written)", lam))


if __name__ == "__main__":
    main()

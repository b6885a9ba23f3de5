#!/usr/bin/env python3
"""A standing robot held by joint stiffness: each actuated joint's torque becomes
`tau_hold + kp_j * (q0_j - q_j)`, a proportional controller about the standing pose
(docs/contacts.md, "A humanoid held by joint stiffness").

The torques that hold the robot at rest (scripts/standing_torques.py) leave an unstable rest:
Atlas on its bent knees buckles at about 31 per second.  Stiffness about the pose removes the
buckling: kp_j = w^2 I_j, I_j = 1 / (d q''_j / d tau_j) the joint's effective inertia with the
contacts held (the accelerations are affine in the torques, so one evaluation with the torque
moved by 1 N m gives the derivative up to rounding).  No damping term: a rate term with gains
from the effective inertias makes the rates' equations stiff (its largest rate about n 2 zeta w
over n joints), and the steps of `enclose` shrink with it (docs/motion.md).  Without it the
buckling is gone, but at w = 30 one slow mode of the torso's and hips' pitch still leaves the rest,
at 3.3 per second (scripts/standing_modes.py measures it: 2.5 at w = 40, 1.5 at w = 50, and
every mode held at w = 60, up to 146 rad/s).

usage: standing_gains.py APPELL STANDING_SCENE OUT_SCENE [W]    (W in rad/s, default 30)
"""
import json
import os
import sys
import tempfile

from standing_torques import evaluate, read_scene  # appell eval in double: (accelerations, reactions)


def accelerations(appell, scene, path):
    return evaluate(appell, scene, path)[0]


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    appell, source, out = sys.argv[1:4]
    w = float(sys.argv[4]) if len(sys.argv) == 5 else 30.0
    if not w > 0:
        sys.exit("standing_gains.py: W must be positive")
    scene = read_scene(source)
    torques = scene.get("torques", {})
    joints = [j for j in scene["state"] if not j.startswith("base_")]
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "scene.json")
        base = accelerations(appell, scene, path)
        gains = {}
        for j in joints:
            moved = json.loads(json.dumps(scene))
            moved.setdefault("torques", {})[j] = repr(float(torques.get(j, "0")) + 1.0)
            d = accelerations(appell, moved, path)[j] - base[j]
            if not d > 0:
                sys.exit("standing_gains.py: joint %s: d q''/d tau = %g, not positive" % (j, d))
            gains[j] = w * w / d
    held = dict(torques)
    for j in joints:
        q0 = scene["state"][j]["q"]
        held[j] = "%s + %.6g * (%s - %s)" % (torques.get(j, "0"), gains[j], q0, j)
    scene["torques"] = held
    with open(out, "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")
    print("wrote %s: %d joints, w = %g rad/s, kp from %.3g to %.3g N m/rad" %
          (out, len(joints), w, min(gains.values()), max(gains.values())))


if __name__ == "__main__":
    main()

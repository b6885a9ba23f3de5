#!/usr/bin/env python3
"""Writes data/scenes/system_whipple_bicycle.json: the Whipple-Carvallo bicycle
with the benchmark parameters of Meijaard, Papadopoulos, Ruina and Schwab (2007,
Proc. R. Soc. A 463, Table 1) as a "system" scene file (SCENES.md).

Axes as in the benchmark: x forward, y to the right, z down; gravity (0, 0, g).
Coordinates: the rear contact point (xP, yP), yaw psi, lean phi, pitch theta of
the rear frame, steer delta, and the wheels' rotations thR, thF.
  rear frame B:  R_B = Rz(psi) Rx(phi) Ry(theta), about the rear axle C_R
  rear wheel R:  Rz(psi) Rx(phi) Ry(thR), centre C_R = P + rR Rz(psi) Rx(phi) (0, 0, -1)
  front frame H: R_H = R_B Ry(lambda) Rz(delta) Ry(-lambda) (steer about the axis
                 tilted back by lambda), about the point A where the steer axis meets
                 the ground in the nominal configuration
  front wheel F: R_H Ry(thF), centre C_F = A + R_H (-c, 0, -rF)
Every body's position is the benchmark's nominal position carried by these
rotations.  Constraints: the front wheel touches the ground (holonomic:
z(C_F) + rF sqrt(1 - a_z^2) = 0, a = R_H e_y its axle), and both contact points
have no horizontal velocity (point_velocity, x and y).
Run from the repository root: python3 data/generators/whipple_bicycle.py"""
import json, os


def rot(axis, angle, v):
    """Elementary rotation of a symbolic vector (strings), as rx/ry/rz in SCENES.md."""
    i, j = (axis + 1) % 3, (axis + 2) % 3
    c, s = "cos(%s)" % angle, "sin(%s)" % angle
    v = ["(%s)" % x if not x.replace(".", "").replace("-", "").isalnum() else x for x in v]
    r = list(v)
    r[i] = "(%s*%s - %s*%s)" % (c, v[i], s, v[j])
    r[j] = "(%s*%s + %s*%s)" % (s, v[i], c, v[j])
    return r


def rotate(factors, v):
    """R_1 R_2 ... R_n v for factors [(axis, angle), ...]."""
    for axis, angle in reversed(factors):
        v = rot(axis, angle, v)
    return v


def add(a, b):
    return ["(%s + %s)" % (x, y) for x, y in zip(a, b)]


X, Y, Z = 0, 1, 2
yaw_lean = [(Z, "psi"), (X, "phi")]
frame_B = yaw_lean + [(Y, "theta")]
frame_H = frame_B + [(Y, "lambda"), (Z, "delta"), (Y, "-lambda")]

P = ["xP", "yP", "0"]
C_R = add(P, rotate(yaw_lean, ["0", "0", "-rR"]))
G_B = add(C_R, rotate(frame_B, ["xB", "0", "zB + rR"]))
A = add(C_R, rotate(frame_B, ["w + c", "0", "rR"]))
G_H = add(A, rotate(frame_H, ["xH - w - c", "0", "zH"]))
C_F = add(A, rotate(frame_H, ["-c", "0", "-rF"]))
a = rotate(frame_H, ["0", "1", "0"])           # the front axle
az = a[2]
# the front contact point: C_F + rF (e_z - a_z a) / sqrt(1 - a_z^2)
root = "sqrt(1 - (%s)^2)" % az
P_F = ["(%s + rF*(%s - (%s)*%s)/%s)" % (C_F[k], "1" if k == 2 else "0", az, a[k], root) for k in range(3)]


def orientation(factors):
    return " ".join("r%s(%s)" % ("xyz"[axis], angle) for axis, angle in factors)


scene = {
    "model": "system",
    "parameters": {
        "w": "1.02", "c": "0.08", "lambda": "pi/10", "g": "9.81",
        "rR": "0.3", "mR": "2", "IRxx": "0.0603", "IRyy": "0.12",
        "xB": "0.3", "zB": "-0.9", "mB": "85", "IBxx": "9.2", "IByy": "11", "IBzz": "2.8", "IBxz": "2.4",
        "xH": "0.9", "zH": "-0.7", "mH": "4", "IHxx": "0.05892", "IHyy": "0.06", "IHzz": "0.00708", "IHxz": "-0.00756",
        "rF": "0.35", "mF": "3", "IFxx": "0.1405", "IFyy": "0.28",
        "T_phi": "0", "T_delta": "0"},
    "coordinates": ["xP", "yP", "psi", "phi", "theta", "delta", "thR", "thF"],
    "gravity": ["0", "0", "g"],
    "bodies": {
        "rear_wheel": {"mass": "mR", "inertia": ["IRxx", "IRyy", "IRxx"], "center": C_R,
                       "orientation": orientation(yaw_lean + [(Y, "thR")])},
        "rear_frame": {"mass": "mB", "inertia": ["IBxx", "IByy", "IBzz", "0", "0", "IBxz"], "center": G_B,
                       "orientation": orientation(frame_B),
                       # the lean torque, and the reaction of the steer torque (about the steer axis)
                       "couple": add(rotate(yaw_lean, ["T_phi", "0", "0"]),
                                     rotate(frame_B, ["-T_delta*sin(lambda)", "0", "-T_delta*cos(lambda)"]))},
        "front_frame": {"mass": "mH", "inertia": ["IHxx", "IHyy", "IHzz", "0", "0", "IHxz"], "center": G_H,
                        "orientation": orientation(frame_H),
                        "couple": rotate(frame_B, ["T_delta*sin(lambda)", "0", "T_delta*cos(lambda)"])},
        "front_wheel": {"mass": "mF", "inertia": ["IFxx", "IFyy", "IFxx"], "center": C_F,
                        "orientation": orientation(frame_H + [(Y, "thF")])},
    },
    "constraints": {
        "front_contact": {"holonomic": "%s + rF*%s" % (C_F[2], root)},
        "rear_x": {"point_velocity": {"body": "rear_wheel", "point": P, "direction": ["1", "0", "0"]}},
        "rear_y": {"point_velocity": {"body": "rear_wheel", "point": P, "direction": ["0", "1", "0"]}},
        "front_x": {"point_velocity": {"body": "front_wheel", "point": P_F, "direction": ["1", "0", "0"]}},
        "front_y": {"point_velocity": {"body": "front_wheel", "point": P_F, "direction": ["0", "1", "0"]}},
    },
    # upright, straight ahead at 5 m/s, leaning and steering: the other rates follow from rolling
    "solve_speeds": ["yP_dot", "psi_dot", "theta_dot", "thR_dot", "thF_dot"],
    "state": {"xP": "0", "yP": "0", "psi": "0", "phi": "0", "theta": "0", "delta": "0", "thR": "0", "thF": "0",
              "xP_dot": "5", "phi_dot": "0.1", "delta_dot": "-0.2"},
    # appell linearize: lean and steer about upright straight running at 5 m/s (the
    # benchmark's eq. 5.4 and its Table 2 of eigenvalues; weave and capsize speeds)
    "linearize": {"coordinates": ["phi", "delta"], "speed": "xP_dot", "gravity": "g",
                  "about": {"xP_dot": "5", "phi_dot": "0", "delta_dot": "0"},
                  "eigenvalues_at": ["0", "1", "2", "3", "4", "5", "6", "7", "8", "9", "10"],
                  "critical_speeds": {"from": "0", "to": "10", "steps": 200}},
}
path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "system_whipple_bicycle.json")
with open(path, "w") as f:
    json.dump(scene, f, indent=1)
    f.write("\n")
print("wrote", os.path.normpath(path), max(len(x) for x in P_F + C_F), "characters at most per expression")

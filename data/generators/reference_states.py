#!/usr/bin/env python3
"""Writes the states of the reference datasets that Simbody is scored on
(data/reference/*_states.csv): deterministic pseudo-random states, as decimals
with 6 digits.  Run from the repository root: python3 data/generators/reference_states.py"""
import random

def d(rng, lo, hi):
    return "%.6f" % rng.uniform(lo, hi)

rng = random.Random(13)
with open("data/reference/heavy_top_states.csv", "w") as f:
    f.write("state,psi,theta,phi,psi_dot,theta_dot,phi_dot\n")
    for i in range(40):
        f.write("top%02d,%s,%s,%s,%s,%s,%s\n" % (i, d(rng, -3, 3), d(rng, 0.2, 2.9), d(rng, -3, 3),
                                                 d(rng, -5, 5), d(rng, -5, 5), d(rng, -60, 60)))
with open("data/reference/sphere_plane_states.csv", "w") as f:
    f.write("state,center[0],center[1],center[2],omega[0],omega[1],omega[2]\n")
    for i in range(40):
        # on the plane z = 0 (the centre at the radius, 0.2), no spin about the normal
        f.write("ball%02d,%s,%s,0.2,%s,%s,0\n" % (i, d(rng, -2, 2), d(rng, -2, 2), d(rng, -20, 20), d(rng, -20, 20)))

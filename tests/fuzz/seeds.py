#!/usr/bin/env python3
"""Writes the hand-made seeds of the fuzz corpus (tests/fuzz/corpus/*/seed-*):
the shipped scenes and the bad inputs docs/testing.md's table lists.  The fuzzer's
own finds are added next to them by scripts/fuzz.sh (merged, minimized).
Run from the repository root: python3 tests/fuzz/seeds.py"""
import glob, json, os

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")
scene_dir, expr_dir = os.path.join(root, "scene"), os.path.join(root, "expression")
os.makedirs(scene_dir, exist_ok=True)
os.makedirs(expr_dir, exist_ok=True)

def put(directory, name, data):
    if isinstance(data, str):
        data = data.encode("utf-8", "surrogateescape")
    with open(os.path.join(directory, "seed-" + name), "wb") as f:
        f.write(data)

here = os.path.dirname(os.path.abspath(__file__))
for path in sorted(glob.glob(os.path.join(here, "..", "..", "data", "scenes", "*.json"))):
    with open(path, "rb") as f:
        put(scene_dir, "shipped-" + os.path.basename(path), f.read())

euler = {"model": "euler_body", "inertia": {"A": "2", "B": "3", "C": "4"},
         "torque": ["0", "0", "0"], "state": {"omega": ["0.1", "1.0", "0.2"]}}
top = {"model": "top_on_cone", "top": {"A": "0.08", "C": "0.02", "mass": "1.5", "l": "0.2"},
       "gravity": "9.81", "cone": "0.5*theta + 0.1*sin(2*theta)",
       "state": {"theta": "0.7", "phi": "0.3", "theta_dot": "1.2", "phi_dot": "40"}}

def with_field(scene, path, value):
    s = json.loads(json.dumps(scene))
    node = s
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    return json.dumps(s)

# numbers
put(scene_dir, "digits-1e5", with_field(euler, ["inertia", "A"], "2." + "0" * 100000 + "1"))
put(scene_dir, "exponent-1e999999", with_field(euler, ["inertia", "A"], "1e999999"))
put(scene_dir, "exponent-minus-1e999999", with_field(euler, ["state", "omega"], ["1e-999999", "1", "0"]))
put(scene_dir, "exponent-8-digits", with_field(euler, ["inertia", "A"], "1e10000000"))
put(scene_dir, "overflow-double", with_field(euler, ["state", "omega"], ["1e300", "1e300", "1e300"]))
put(scene_dir, "huge-spin", with_field(euler, ["state", "omega"], ["1e150", "1e150", "1e150"]))
put(scene_dir, "nan", json.dumps(euler).replace('"0.1"', "NaN"))
put(scene_dir, "infinity", json.dumps(euler).replace('"0.1"', '"Infinity"'))
put(scene_dir, "hex", json.dumps(euler).replace('"0.1"', '"0x1p-3"'))
put(scene_dir, "minus-zero", with_field(euler, ["state", "omega"], ["-0", "-0.0", "-0e5"]))
put(scene_dir, "big-integer", json.dumps(euler).replace('"0.1"', "1" + "0" * 400))
# JSON structure
put(scene_dir, "nesting-1e5", "[" * 100000 + "]" * 100000)
put(scene_dir, "nesting-objects", '{"a":' * 5000 + "0" + "}" * 5000)
put(scene_dir, "bom", b"\xef\xbb\xbf" + json.dumps(euler).encode())
put(scene_dir, "invalid-utf8-value", json.dumps(euler).encode().replace(b"euler_body", b"euler\xff\xfebody"))
put(scene_dir, "invalid-utf8-key", json.dumps(euler).encode().replace(b'"torque"', b'"torq\xc3\x28ue"'))
put(scene_dir, "newline-in-key", json.dumps(euler).replace('"torque"', '"tor\\nque"'))
put(scene_dir, "duplicate-key", json.dumps(euler)[:-1] + ', "model": "euler_body"}')
put(scene_dir, "truncated", json.dumps(top)[:97])
put(scene_dir, "trailing", json.dumps(euler) + " {}")
put(scene_dir, "many-keys", "{" + ",".join('"k%d": 0' % i for i in range(20000)) + "}")
put(scene_dir, "long-list", with_field(euler, ["torque"], ["0"] * 20000))
put(scene_dir, "nul-bytes", b"\x00" * 64)
put(scene_dir, "not-object", "[1, 2, 3]")
put(scene_dir, "empty", b"")
# models: unknown, wrong kinds, off the constraints
put(scene_dir, "unknown-model", with_field(euler, ["model"], "whipple_bicycle"))
put(scene_dir, "unknown-key", with_field(euler, ["state", "q"], "1"))
put(scene_dir, "negative-inertia", with_field(euler, ["inertia", "A"], "-2"))
put(scene_dir, "triangle", with_field(euler, ["inertia", "C"], "5.0000000000000000000001"))
put(scene_dir, "sphere-off-surface", json.dumps({"model": "rolling_sphere", "sphere": {"mass": "2", "radius": "0.1"},
    "surface": {"type": "sphere", "radius": "1", "side": "inside"}, "gravity": ["0", "0", "-9.81"],
    "state": {"center": ["0.54", "0", "-0.7200000000000000001"], "omega": ["0", "2", "0"]}}))
put(scene_dir, "sphere-tiny-radius", json.dumps({"model": "rolling_sphere", "sphere": {"mass": "2", "radius": "1e-300"},
    "surface": {"type": "plane"}, "gravity": ["0", "0", "-9.81"],
    "state": {"center": ["0", "0", "1e-300"], "omega": ["1e300", "0", "0"]}}))
# cones inside scenes
cones = {"pow-1e9": "theta^1e9", "pow-big-int": "theta^999999", "zero-over-zero": "0/0",
         "log-minus-one": "log(theta - 1.7)", "sqrt-zero": "sqrt(theta - 0.7)", "tan-pole": "tan(theta + 0.8707963267948966)",
         "long-sum": "+".join(["theta"] * 3000), "deep-parentheses": "(" * 10000 + "theta" + ")" * 10000,
         "deep-unary": "-" * 10000 + "theta", "nested-exp": "exp(" * 60 + "theta" + ")" * 60,
         "product-chain": "*".join(["sin(theta)"] * 400), "power-tower": "^".join(["theta"] * 90),
         "newline": "theta\n+1", "unknown-name": "phi + theta", "empty": ""}
for name, cone in cones.items():
    put(scene_dir, "cone-" + name, with_field(top, ["cone"], cone))
    put(expr_dir, name, cone)
heavy = {"model": "heavy_top", "top": {"A": "0.08", "C": "0.02", "mass": "1.5", "l": "0.2"}, "gravity": "9.81",
         "state": {"psi": "0", "theta": "0.7", "phi": "0.3", "psi_dot": "1.5", "theta_dot": "1.2", "phi_dot": "40"}}
put(scene_dir, "heavy-top-vertical", with_field(heavy, ["state", "theta"], "0"))
put(scene_dir, "heavy-top-near-vertical", with_field(heavy, ["state", "theta"], "1e-300"))
put(scene_dir, "heavy-top-not-revolution", with_field(heavy, ["top", "C"], "0.05"))
put(scene_dir, "heavy-top-huge-spin", with_field(heavy, ["state", "phi_dot"], "1e200"))
for name, text in {"shipped": "0.5*theta + 0.1*sin(2*theta)", "constant": "1.25", "pi": "pi/2 - theta",
                   "all-functions": "sin(theta)*cos(theta)/tan(theta)+exp(theta)-log(theta)+sqrt(theta)^3",
                   "real-power": "theta^0.5 + 2^theta + theta^theta", "numbers": "1e-3*theta + .5 - 2.E+1",
                   "bad-number": "1.2.3 + theta", "dangling": "theta +", "unbalanced": "sin(theta",
                   "invalid-utf8": b"theta\xff", "digits-1e5": "1." + "0" * 9990}.items():
    put(expr_dir, name, text)
# system files: the shipped ones are seeds above; here the ways they go wrong
disk = json.load(open(os.path.join(here, "..", "..", "data", "scenes", "system_rolling_disk.json")))
systems = {
    "circular-parameters": (["parameters"], {"m": "a", "a": "2*m", "g": "9.81"}),
    "speed-in-holonomic": (["constraints", "ground", "holonomic"], "z - a*cos(theta) + x_dot"),
    "nonlinear-nonholonomic": (["constraints", "roll_x", "nonholonomic"], "x_dot^2"),
    "dependent": (["constraints", "roll_y", "nonholonomic"], "x_dot - a*(psi_dot*cos(psi)*sin(theta) + theta_dot*sin(psi)*cos(theta) + phi_dot*cos(psi))"),
    "off-constraint": (["state", "z"], "0.2866"),
    "reserved-name": (["coordinates"], ["x", "y", "t", "psi", "theta", "phi"]),
    "bad-orientation": (["bodies", "disk", "orientation"], "rz(psi) rq(theta)"),
    "deep-orientation": (["bodies", "disk", "orientation"], "rz(" * 5000 + "psi" + ")" * 5000),
    "many-rotations": (["bodies", "disk", "orientation"], " ".join(["rx(theta)"] * 3000)),
    "negative-mass": (["bodies", "disk", "mass"], "-m"),
    "undefined-at-state": (["bodies", "disk", "center"], ["x", "y", "sqrt(z - 1)"]),
    "no-bodies": (["bodies"], {}),
    "too-many-constraints": (["constraints", "more"], {"nonholonomic": "psi_dot"}),
}
systems["point-velocity-no-body"] = (["constraints", "roll_x"], {"point_velocity": {"body": "wheel", "point": ["x", "y", "0"], "direction": ["1", "0", "0"]}})
systems["point-velocity-zero-direction"] = (["constraints", "roll_x"], {"point_velocity": {"body": "disk", "point": ["x", "y", "0"], "direction": ["0", "0", "0"]}})
systems["solve-speeds-singular"] = (["solve_speeds"], ["x_dot", "x_dot", "y_dot"])
systems["wrench-no-body"] = (["wrenches"], {"w": {"body": "wheel", "point": ["x", "y", "0"], "constraints": ["ground"]}})
systems["wrench-other-constraint"] = (["wrenches"], {"w": {"body": "disk", "point": ["x", "y", "0"], "constraints": ["slide"]}})
systems["orientation-matrix-scaled"] = (["bodies", "disk", "orientation"], [["2", "0", "0"], ["0", "1", "0"], ["0", "0", "1"]])
systems["orientation-matrix-rows"] = (["bodies", "disk", "orientation"], [["1", "0", "0"], ["0", "1"]])
for name, (path, value) in systems.items():
    put(scene_dir, "system-" + name, with_field(disk, path, value))
print("seeds written to", root)

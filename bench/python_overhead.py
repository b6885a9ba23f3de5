#!/usr/bin/env python3
"""The Python module's cost over the library's (issue 59), as ratios measured in one run:

1. `eval` of the WAM arm in `interval`, called in a loop from Python, against the same loop in
   C++ (the module's _cpp_eval_loop: the same library call, evaluation and printing, without
   Python between the iterations); the same with every result's bounds taken into NumPy; and,
   where the benchmarks are built, the same calls in a program (appell_bench_eval_loop: the
   library's thread-local storage accessed as a program's, not as a shared object's).
2. `reference` of N states (default 10^4) of the heavy top from a NumPy array, against `appell
   reference --states` on the same states (exact decimals of the same doubles) in the same run.

Usage (from the source tree, after a build):
    PYTHONPATH=build/python python3 bench/python_overhead.py [--build build] [--n 10000] [--reps 5]
Each figure is the median of --reps runs; the machine is shared, so only ratios of runs made
side by side are quoted."""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import appell

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def median_time(f, reps):
    times = []
    for _ in range(reps):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def eval_overhead(reps, loops, build):
    scene = appell.Scene.from_file(os.path.join(SOURCE, "data/scenes/urdf_wam.json"))
    scene.eval("interval")  # warm: the first call prepares caches

    def python_loop():
        for _ in range(loops):
            scene.eval("interval")

    def python_loop_bounds():
        for _ in range(loops):
            scene.eval("interval").bounds()

    program = os.path.join(build, "bench", "appell_bench_eval_loop")
    cpp, py, py_b, prog = [], [], [], []
    for _ in range(reps):  # interleaved: the machine's load moves them all alike
        if os.path.exists(program):  # the same calls in a program (seconds per evaluation)
            prog.append(loops * float(subprocess.run([program, os.path.join(SOURCE, "data/scenes/urdf_wam.json"),
                                                      "interval", str(loops)], capture_output=True, text=True,
                                                     check=True).stdout))
        cpp.append(appell._core._cpp_eval_loop(scene._s, "interval", None, True, loops))
        t0 = time.perf_counter()
        python_loop()
        py.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        python_loop_bounds()
        py_b.append(time.perf_counter() - t0)
    c, p, b = (statistics.median(x) / loops for x in (cpp, py, py_b))
    print(f"WAM eval in interval, {loops} calls x {reps} runs (medians):")
    print(f"  C++ loop      {c * 1e6:9.1f} us per eval")
    print(f"  Python loop   {p * 1e6:9.1f} us per eval   overhead {100 * (p / c - 1):+.1f}%")
    print(f"  + bounds()    {b * 1e6:9.1f} us per eval   overhead {100 * (b / c - 1):+.1f}%  (every result into NumPy)")
    if prog:
        g = statistics.median(prog) / loops
        print(f"  in a program  {g * 1e6:9.1f} us per eval   (the library linked into a program, appell_bench_eval_loop;"
              f" the module's C++ loop / this = {c / g:.3f})")
    return p / c


def reference_throughput(build, n, reps):
    scene_path = os.path.join(SOURCE, "data/scenes/heavy_top.json")
    rng = np.random.default_rng(1)
    fields = ["psi", "theta", "phi", "psi_dot", "theta_dot", "phi_dot"]
    lo = np.array([-3, 0.2, -3, -5, -5, -60.0])
    hi = np.array([3, 2.9, 3, 5, 5, 60.0])
    states = lo + (hi - lo) * rng.random((n, len(fields)))
    scene = appell.Scene.from_file(scene_path)
    exe = os.path.join(build, "appell")
    with tempfile.TemporaryDirectory() as work:
        csv = os.path.join(work, "states.csv")
        with open(csv, "w") as f:
            f.write(",".join(fields) + "\n")
            for row in states:
                f.write(",".join(appell._core._exact_decimal(float(x)) for x in row) + "\n")
        py, cli = [], []
        ref = None
        for r in range(reps):
            t0 = time.perf_counter()
            ref = appell.reference(scene, states, fields=fields)
            py.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            subprocess.run([exe, "reference", scene_path, "--states", csv, "--out", os.path.join(work, f"out{r}"),
                            "--quiet"], check=True)
            cli.append(time.perf_counter() - t0)
        # the same certified bounds both ways (first and last states)
        import csv as csvmod

        with open(os.path.join(work, "out0", "reference.csv")) as f:
            rows = list(csvmod.DictReader(f))
        first = [r_ for r_ in rows if r_["state"] == "1"]
        for r_ in first:
            assert ref.exact(0, r_["quantity"])[:2] == (r_["lower"], r_["upper"]), r_["quantity"]
    p, c = statistics.median(py), statistics.median(cli)
    print(f"reference of {n} heavy-top states in interval ({reps} runs, medians; the command's time includes its"
          f" process start and its files):")
    print(f"  appell.reference     {n / p:9.0f} states/s")
    print(f"  appell reference     {n / c:9.0f} states/s   Python / command {p / c:.3f}")
    return p / c


def main():
    a = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    a.add_argument("--build", default=os.path.join(SOURCE, "build"))
    a.add_argument("--n", type=int, default=10000)
    a.add_argument("--reps", type=int, default=5)
    a.add_argument("--loops", type=int, default=2000)
    o = a.parse_args()
    print(f"python {sys.version.split()[0]}, appell module {appell.__file__}")
    eval_overhead(o.reps, o.loops, o.build)
    reference_throughput(o.build, o.n, o.reps)


if __name__ == "__main__":
    main()

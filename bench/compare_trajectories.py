#!/usr/bin/env python3
"""The largest difference between two trajectories written as exact decimals (appell's
`horizon` reference.csv, `simulate` trajectory.csv), on the columns they share, at the rows of
equal t: max_i |a_i - b_i| / max(1, |b_i|), horizon's own error measure.  Prints that error
at every row whose index is a power of ten (1, 10, 100, ... outputs; with --every one period,
1, 10, 100, ... periods) as the largest up to that row, and the largest over all rows.
Exact decimal arithmetic (Python's decimal at 120 digits): no rounding of the 80-digit values.

Usage: bench/compare_trajectories.py A.csv B.csv [COLUMN,COLUMN,...]   (default: every shared column)
"""
import csv
import decimal
import sys

decimal.getcontext().prec = 120
D = decimal.Decimal


def rows(path):
    with open(path, newline="") as f:
        r = csv.reader(f)
        header = next(r)
        return header, [row for row in r if row]


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    ha, ra = rows(sys.argv[1])
    hb, rb = rows(sys.argv[2])
    shared = [c for c in ha if c != "t" and c in hb]
    if len(sys.argv) == 4:
        wanted = sys.argv[3].split(",")
        missing = [c for c in wanted if c not in shared]
        if missing:
            sys.exit("not in both files: " + ",".join(missing))
        shared = wanted
    if not shared:
        sys.exit("no shared columns")
    ia = [ha.index(c) for c in shared]
    ib = [hb.index(c) for c in shared]
    n = min(len(ra), len(rb))
    worst = D(0)
    marks = []
    next_mark = 1
    for k in range(n):
        ta, tb = D(ra[k][0]), D(rb[k][0])
        if abs(ta - tb) > D("1e-60") * max(D(1), abs(tb)):
            sys.exit(f"row {k}: t differs ({ra[k][0]} and {rb[k][0]})")
        for a, b in zip(ia, ib):
            x, y = D(ra[k][a]), D(rb[k][b])
            worst = max(worst, abs(x - y) / max(D(1), abs(y)))
        if k == next_mark:
            marks.append((k, worst))
            next_mark *= 10
    print("columns:", ",".join(shared), f"rows compared: {n}")
    for k, w in marks:
        print(f"up to row {k:>7} (t = {float(D(ra[k][0])):.6g}): largest difference {float(w):.3e}")
    print(f"all {n} rows: largest difference {float(worst):.3e}")


if __name__ == "__main__":
    main()

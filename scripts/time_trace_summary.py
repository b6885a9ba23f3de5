#!/usr/bin/env python3
"""Summary of a clang -ftime-trace file (scripts/time_trace.sh): the compiler's phases, then the
templates whose instantiation took longest, each template's intervals merged (a nested
instantiation of the same template is not counted twice; different templates overlap, so the
column does not sum to the total)."""
import collections
import json
import re
import sys


def main(path, count=30):
    events = [e for e in json.load(open(path))["traceEvents"] if e.get("ph") == "X"]
    totals = {e["name"]: e["dur"] for e in events if e["name"].startswith("Total ")}
    for name in ("Total ExecuteCompiler", "Total Frontend", "Total Backend", "Total InstantiateFunction",
                 "Total InstantiateClass"):
        if name in totals:
            print("%8.2f s  %s" % (totals[name] / 1e6, name[len("Total "):]))
    spans = collections.defaultdict(list)
    for e in events:
        if e["name"] in ("InstantiateFunction", "InstantiateClass"):
            spans[re.sub(r"<.*", "", e["args"]["detail"])].append((e["ts"], e["ts"] + e["dur"]))
    merged = []
    for name, iv in spans.items():
        iv.sort()
        total, start, end = 0, None, None
        for s, t in iv:
            if end is None or s > end:
                if end is not None:
                    total += end - start
                start, end = s, t
            else:
                end = max(end, t)
        if end is not None:
            total += end - start
        merged.append((total, name))
    print("\ninstantiation, seconds (each template once):")
    for total, name in sorted(merged, reverse=True)[:count]:
        print("%8.2f  %s" % (total / 1e6, name[:140]))


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 30)

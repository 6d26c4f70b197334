"""Not a test: the cohesive law's pull-off over a grid, saved before a change to the trace and compared after it.

Run: python benchmarks/compare_pull_off_grid.py --save before.json     (on the commit before the change)
     python benchmarks/compare_pull_off_grid.py --compare before.json  (after it: the worst relative difference)

Grid: lambda 0.1 .. 1000 x h0/Delta 0.1 .. 1.6 x three pairs (identical bodies, a rubber pin in a rigid cradle,
two rigid bodies -- the pin then elastic: tests/cases.py) x load / grip, each a fresh contact (Contact.pull_off).
Prints per case the relative differences of P, contact width and approach, and whether the reasons are equal.
"""
import argparse
import json
import math
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests"))
from cases import cohesive_contact  # noqa: E402

LAMBDAS = (0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0)
H0S = (0.1, 0.5, 1.0, 1.6)
PAIRS = {"identical": (2.6e9, 0.3, 2.6e9, 0.3), "rubber-in-rigid": (math.inf, 0.0, 2e6, 0.49),
         "rigid-rigid": (math.inf, 0.0, math.inf, 0.3)}
FIELDS = ("P", "contact_width", "delta")


def run():
    out = {}
    for name, pair in PAIRS.items():
        for lam in LAMBDAS:
            for h0 in H0S:
                for ctl in ("load", "grip"):
                    key = f"{name} lambda={lam:g} h0={h0:g} {ctl}"
                    t = time.process_time()
                    try:
                        r = cohesive_contact(*pair, h0, lam).pull_off(ctl)
                        out[key] = {f: getattr(r, f) for f in FIELDS} | {"reason": r.reason}
                    except Exception as why:            # noqa: BLE001 -- recorded, compared as text
                        out[key] = {"error": f"{type(why).__name__}: {why}"}
                    out[key]["cpu_s"] = time.process_time() - t
    return out


def rel(x, y):
    if x is None or y is None:
        return 0.0 if x is y else math.inf
    return abs(x - y) / max(abs(x), 1e-300) if x != y else 0.0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--save")
    ap.add_argument("--compare")
    args = ap.parse_args()
    got = run()
    if args.save:
        with open(args.save, "w") as f:
            json.dump(got, f, indent=1)
    if args.compare:
        with open(args.compare) as f:
            ref = json.load(f)
        worst, worst_key, reasons = 0.0, None, 0
        for key, r in ref.items():
            g = got[key]
            if "error" in r or "error" in g:
                same = r.get("error") == g.get("error")
                reasons += not same
                print(f"{key}: error {'same' if same else 'DIFFERS'}: {r.get('error')} | {g.get('error')}")
                continue
            d = max(rel(r[f], g[f]) for f in FIELDS)
            reasons += r["reason"] != g["reason"]
            if d > worst:
                worst, worst_key = d, key
            if d > 0 or r["reason"] != g["reason"]:
                print(f"{key}: max rel diff {d:.2e}; reason {'same' if r['reason'] == g['reason'] else 'DIFFERS'}")
        cpu_ref = sum(r["cpu_s"] for r in ref.values())
        cpu = sum(g["cpu_s"] for g in got.values())
        print(f"\n{len(ref)} cases: worst relative difference (P, width, approach) {worst:.2e} ({worst_key}); "
              f"{reasons} reasons/errors differ; CPU {cpu_ref:.1f} s before, {cpu:.1f} s now")


if __name__ == "__main__":
    main()

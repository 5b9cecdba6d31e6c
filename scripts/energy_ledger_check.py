#!/usr/bin/python3
"""Checks a run's CSV energy ledger: the dissipated energy never decreases,
and the mechanical energy (kinetic + potential + elastic) never rises by
more than a tolerance between samples (an undriven scene).

usage: energy_ledger_check.py RUN.csv [TOLERANCE_J]
Prints the worst of each and exits 1 when either is beyond the tolerance
(default 1e-9 J: rounding, as tests/sim/inner_contact_test.cc's box stack).
"""
import csv
import sys


def main():
    path = sys.argv[1]
    tolerance = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-9
    with open(path) as f:
        rows = list(csv.DictReader(f))
    t = [float(r["time"]) for r in rows]
    mech = [float(r["energy.kinetic"]) + float(r["energy.potential"]) +
            float(r["energy.elastic"]) for r in rows]
    dis = [float(r["energy.dissipated"]) for r in rows]
    tot = [float(r["energy.total"]) for r in rows]
    rise = max(((mech[k] - mech[k - 1], t[k]) for k in range(1, len(rows))), default=(0, 0))
    fall = min(((dis[k] - dis[k - 1], t[k]) for k in range(1, len(rows))), default=(0, 0))
    drift = max(abs(x - tot[0]) for x in tot)
    print(f"mechanical energy: largest rise {rise[0]:.3g} J (at t = {rise[1]:.6g} s), "
          f"tolerance {tolerance:.3g} J")
    print(f"dissipated energy: largest change down {fall[0]:.3g} J (at t = {fall[1]:.6g} s), "
          f"tolerance {tolerance:.3g} J")
    print(f"total energy: largest drift from the start {drift:.3g} J")
    ok = rise[0] <= tolerance and -fall[0] <= tolerance
    print("ok" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

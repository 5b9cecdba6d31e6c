"""The numbers of docs/paper-reproduction.md, read from the CSV of scripts/run.sh.

    /usr/bin/python3 scripts/reproduction.py [RESULTS_DIR]

Prints, for each claim of Flores et al. (2011) sections 6-7 that the docs
discuss, what results/ measures; and the integral of the paper's eq. (38),
exactly (Beta function) and by the paper's trapezoid. Standard library only.
"""

import csv
import math
import os
import sys

LAWS = ["hertz", "kelvin-voigt", "hunt-crossley", "lankarani-nikravesh",
        "flores"]


def read(path):
    if not os.path.exists(path):
        sys.exit(f"reproduction.py: missing {path}; make it with: "
                 "bash scripts/run.sh")
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def number(text):
    return float(text) if text != "" else None


def integral_38():
    """int_0^1 x^(3/2) sqrt(1 - x^2) dx: x^2 = u gives B(5/4, 3/2) / 2."""
    exact = 0.5 * math.gamma(1.25) * math.gamma(1.5) / math.gamma(2.75)
    n = 1001  # the paper's appendix: trapezoid on 1001 points
    dx = 1.0 / (n - 1)
    f = [(i * dx) ** 1.5 * math.sqrt(max(0.0, 1 - (i * dx) ** 2))
         for i in range(n)]
    trapezoid = dx / 2 * (f[0] + f[-1]) + dx * sum(f[1:-1])
    print("Eq. (38): int_0^1 x^1.5 sqrt(1 - x^2) dx")
    print(f"  exact B(5/4, 3/2) / 2 = {exact:.14f}")
    print(f"  trapezoid, 1001 points = {trapezoid:.14f}"
          f"  (error {trapezoid - exact:+.3e})")
    print(f"  1/4 (used in eq. 39)  = 0.25  (1/4 over exact: "
          f"{0.25 / exact:.6f})")


def fig5(results):
    s = read(os.path.join(results, "fig5", "summary.csv"))[0]
    print("\nFig. 5: bouncing ball, Flores, e = 0.9, 10 s")
    print(f"  impacts {s['impacts']}, first e_post "
          f"{float(s['restitution_post']):.6f}, at rest from "
          f"{float(s['time_to_rest']):.4f} s, dissipated "
          f"{float(s['dissipated_energy']):.4f} J")
    rows = read(os.path.join(results, "fig5", "trajectories.csv"))
    totals = [float(r["energy.total"]) for r in rows]
    print(f"  energy total: start {totals[0]:.6f} J, end {totals[-1]:.6f} J,"
          f" largest |total - start| {max(abs(t - totals[0]) for t in totals):.3e} J")


def fig6(results):
    print("\nFig. 6: first contact, Flores (summary.csv)")
    print(f"  {'e':>4} {'max depth (mm)':>15} {'max force (kN)':>15} "
          f"{'duration (ms)':>14} {'dissipated (J)':>15} {'e_post':>9}")
    for s in read(os.path.join(results, "fig6", "summary.csv")):
        print(f"  {float(s['restitution']):>4.1f} "
              f"{1e3 * float(s['max_depth']):>15.4f} "
              f"{1e-3 * float(s['max_force']):>15.3f} "
              f"{1e3 * float(s['contact_duration']):>14.4f} "
              f"{float(s['dissipated_energy']):>15.4f} "
              f"{float(s['restitution_post']):>9.6f}")


def fig7(results):
    rows = read(os.path.join(results, "fig7.csv"))
    print("\nFig. 7: first-impact e_post against e (fig7.csv)")
    for law in LAWS:
        mine = [(float(r["restitution"]), number(r["restitution_post"]))
                for r in rows if r["law"] == law]
        worst = max(mine, key=lambda p: abs(p[1] - p[0]))
        at = {e: p for e, p in mine}
        print(f"  {law:<20} e_post at e = 0.1: {at[0.1]:.4f}, 0.5: "
              f"{at[0.5]:.4f}, 0.9: {at[0.9]:.4f}; largest |e_post - e| "
              f"{abs(worst[1] - worst[0]):.4f} at e = {worst[0]}")


def fig8(results):
    """Does each Hertz impact on the rising table raise the next apex?"""
    rows = read(os.path.join(results, "fig8", "trajectories.csv"))
    t = [float(r["time"]) for r in rows]
    z = [float(r["ball.z"]) for r in rows]
    apexes = [(t[i], z[i]) for i in range(1, len(z) - 1)
              if z[i - 1] < z[i] >= z[i + 1]]
    impacts = read(os.path.join(results, "fig8", "impacts.csv"))
    agree = total = 0
    for i in impacts:
        tc = float(i["time_contact"])
        before = [a for a in apexes if a[0] < tc]
        after = [a for a in apexes if a[0] > tc]
        if not before or not after:
            continue
        total += 1
        table_rising = math.cos(7.5 * tc) > 0  # z = 0.5 + 0.1 sin(7.5 t)
        higher = after[0][1] > before[-1][1]
        agree += table_rising == higher
    top = max(apexes, key=lambda a: a[1])
    print("\nFig. 8: ball on the driven table, Hertz, 10 s")
    print(f"  impacts {len(impacts)}; {agree} of {total} impacts between two "
          "apexes raise the next apex exactly when the table is rising")
    print(f"  highest apex: centre at {top[1]:.3f} m at {top[0]:.2f} s")


def fig9(results):
    rows = read(os.path.join(results, "fig9", "summary.csv"))
    print("\nFig. 9: ball on the table, first e_post / impacts / at rest (s)")
    for e in ("0.9", "0.6", "0.3"):
        cells = []
        for law in ("hunt-crossley", "lankarani-nikravesh", "flores"):
            s = next(r for r in rows
                     if r["law"] == law and r["restitution"] == e)
            rest = number(s["time_to_rest"])
            cells.append(f"{law} {float(s['restitution_post']):.4f} / "
                         f"{s['impacts']} / "
                         f"{'-' if rest is None else f'{rest:.3f}'}")
        print(f"  e = {e}: " + "; ".join(cells))


def main():
    results = sys.argv[1] if len(sys.argv) > 1 else "results"
    integral_38()
    fig5(results)
    fig6(results)
    fig7(results)
    fig8(results)
    fig9(results)


if __name__ == "__main__":
    main()

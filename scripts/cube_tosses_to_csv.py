#!/usr/bin/python3
"""Converts the cube tosses (data/cube_tosses/train.csv.gz) into the measured-trajectory format
of docs/identification.md: one row per sample,

    trajectory,time,cube.x,cube.y,cube.z,cube.qw,cube.qx,cube.qy,cube.qz,
    cube.vx,cube.vy,cube.vz,cube.wx,cube.wy,cube.wz

positions in m, the orientation the unit quaternion (w, x, y, z) from the cube's frame to the
board's, velocities in m/s and rad/s. The data's angular velocity is in the cube's own frame; the
format's is in the world (board) frame, as `contactlaws run` writes it: w_world = R(q) w_body.

    scripts/cube_tosses_to_csv.py data/cube_tosses/train.csv.gz OUT.csv [--tosses A:B]

--tosses A:B keeps tosses A..B-1 (of the data's numbering), for a split into training and
validation sets. Standard library only.
"""
import argparse
import csv
import gzip
import sys

BODY = "cube"
COLUMNS = ["x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy", "vz", "wx", "wy", "wz"]


def rotate(q, v):
    """R(q) v for the unit quaternion q = (w, x, y, z)."""
    w, x, y, z = q
    # v + 2 w (u x v) + 2 u x (u x v), u the vector part
    cx = y * v[2] - z * v[1]
    cy = z * v[0] - x * v[2]
    cz = x * v[1] - y * v[0]
    return (v[0] + 2 * (w * cx + y * cz - z * cy),
            v[1] + 2 * (w * cy + z * cx - x * cz),
            v[2] + 2 * (w * cz + x * cy - y * cx))


def parse_range(text):
    try:
        a, b = (int(p) for p in text.split(":"))
    except ValueError:
        sys.exit(f"cube_tosses_to_csv: --tosses={text} must be A:B, whole numbers")
    if not 0 <= a < b:
        sys.exit(f"cube_tosses_to_csv: --tosses={text} must have 0 <= A < B")
    return a, b


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("data")
    parser.add_argument("output")
    parser.add_argument("--tosses", default=None, help="A:B, tosses A..B-1")
    args = parser.parse_args()
    first, last = parse_range(args.tosses) if args.tosses else (0, None)

    opener = gzip.open if args.data.endswith(".gz") else open
    with opener(args.data, "rt", newline="") as f, open(args.output, "w", newline="") as out:
        rows = csv.DictReader(f)
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(["trajectory", "time"] + [f"{BODY}.{c}" for c in COLUMNS])
        kept = 0
        for row in rows:
            toss = int(row["toss"])
            if toss < first or (last is not None and toss >= last):
                continue
            q = tuple(float(row[k]) for k in ("qw", "qx", "qy", "qz"))
            w = rotate(q, tuple(float(row[k]) for k in ("wx", "wy", "wz")))
            values = [row[k] for k in COLUMNS[:10]] + [f"{c:.6g}" for c in w]
            writer.writerow([toss, row["t"]] + values)
            kept += 1
    if kept == 0:
        sys.exit(f"cube_tosses_to_csv: {args.data}: no toss in {args.tosses}")


if __name__ == "__main__":
    main()

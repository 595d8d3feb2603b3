#!/usr/bin/env python3
"""Which screen edge each pushed fragment was pushed toward, from `fragsim run|compare --csv DIR
--trajectories`: every force of a strategy's rows projected on that step's camera right and up
(camera.csv), summed per fragment; the larger of the two components and its sign name the edge.
Prints, per strategy, the pushed fragments and the share pushed toward top, bottom, left, right.

  scripts/push_directions.py DIR [STRATEGY]      (default strategy: edge-min)
"""
import collections
import csv
import sys


def main():
    if len(sys.argv) not in (2, 3):
        print("usage: scripts/push_directions.py DIR [STRATEGY]", file=sys.stderr)
        return 2
    folder = sys.argv[1].rstrip("/")
    strategy = sys.argv[2] if len(sys.argv) == 3 else "edge-min"
    try:
        camera = {}
        with open(folder + "/camera.csv", newline="") as f:
            for r in csv.DictReader(f):
                if r["strategy"] == strategy:
                    camera[int(r["step"])] = r
        push = collections.defaultdict(lambda: [0.0, 0.0])
        with open(folder + "/trajectories.csv", newline="") as f:
            for r in csv.DictReader(f):
                if r["strategy"] != strategy:
                    continue
                force = [float(r["fx_N"]), float(r["fy_N"]), float(r["fz_N"])]
                if force == [0.0, 0.0, 0.0]:
                    continue
                c = camera[int(r["step"])]
                up = [float(c["up_x"]), float(c["up_y"]), float(c["up_z"])]
                fw = [float(c["forward_x"]), float(c["forward_y"]), float(c["forward_z"])]
                right = [fw[1] * up[2] - fw[2] * up[1], fw[2] * up[0] - fw[0] * up[2],
                         fw[0] * up[1] - fw[1] * up[0]]
                p = push[int(r["fragment"])]
                p[0] += sum(a * b for a, b in zip(force, right))
                p[1] += sum(a * b for a, b in zip(force, up))
    except (OSError, KeyError, ValueError) as e:
        print(f"push_directions.py: {folder}: {e} (written by fragsim --csv DIR --trajectories?)",
              file=sys.stderr)
        return 1
    count = collections.Counter()
    for x, y in push.values():
        if abs(y) >= abs(x):
            count["top" if y > 0 else "bottom"] += 1
        else:
            count["right" if x > 0 else "left"] += 1
    n = len(push)
    shares = " ".join(f"{k} {100.0 * count[k] / n:.0f}%" if n else f"{k} -"
                      for k in ("top", "bottom", "left", "right"))
    print(f"{strategy}: {n} pushed fragments, pushed toward {shares}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

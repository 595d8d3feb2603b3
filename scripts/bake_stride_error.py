#!/usr/bin/env python3
"""What keying fewer steps would cost a bake: from a file `fragsim run --bake` keyed at every
step, for each stride N, the distance between each piece's position interpolated linearly between
every N-th key and its keyed position at each step (largest and mean), and the largest rotation
error (slerp between the kept keys); also the largest turn of a piece between consecutive keys.
Python standard library only.

Usage: scripts/bake_stride_error.py FILE.glb [N ...]   (default N: 2 4)
"""
import array
import json
import math
import struct
import sys


def read_glb(path):
    data = open(path, "rb").read()
    json_len = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + json_len])
    return doc, data[20 + json_len + 8:]


def accessor(doc, binary, index):
    a = doc["accessors"][index]
    view = doc["bufferViews"][a["bufferView"]]
    n = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[a["type"]]
    offset = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    f = array.array("f")
    f.frombytes(binary[offset:offset + 4 * n * a["count"]])
    return [tuple(f[k * n:(k + 1) * n]) for k in range(a["count"])]


def slerp(a, b, u):
    d = sum(x * y for x, y in zip(a, b))
    if d < 0:
        b, d = tuple(-x for x in b), -d
    th = math.acos(min(d, 1.0))
    s = math.sin(th)
    w1, w2 = (1 - u, u) if s < 1e-9 else (math.sin((1 - u) * th) / s, math.sin(u * th) / s)
    q = [w1 * x + w2 * y for x, y in zip(a, b)]
    n = math.sqrt(sum(x * x for x in q))
    return [x / n for x in q]


def turn_deg(a, b):
    return 2 * math.degrees(math.acos(min(1.0, abs(sum(x * y for x, y in zip(a, b))))))


def main():
    doc, binary = read_glb(sys.argv[1])
    strides = [int(x) for x in sys.argv[2:]] or [2, 4]
    anim = doc["animations"][0]
    tr, rot = {}, {}
    for c in anim["channels"]:
        out = accessor(doc, binary, anim["samplers"][c["sampler"]]["output"])
        (tr if c["target"]["path"] == "translation" else rot)[c["target"]["node"]] = out
    times = [t[0] for t in accessor(doc, binary, anim["samplers"][0]["input"])]
    pieces = [i for i, n in enumerate(doc["nodes"]) if n["name"].startswith("fragment_")]
    samples = len(times)
    turns = [turn_deg(rot[i][s - 1], rot[i][s]) for i in pieces for s in range(1, samples)]
    print(f"{len(pieces)} pieces, {samples} keys each; largest turn between keys "
          f"{max(turns):.1f} deg, {sum(t > 90 for t in turns)} of {len(turns)} over 90 deg")
    for n in strides:
        keys = list(range(0, samples, n))
        if keys[-1] != samples - 1:
            keys.append(samples - 1)
        e_max = e_sum = g_max = 0.0
        for i in pieces:
            p, q, k = tr[i], rot[i], 0
            for s in range(samples):
                while k + 2 < len(keys) and keys[k + 1] <= s:
                    k += 1
                a, b = keys[k], keys[k + 1]
                u = (times[s] - times[a]) / (times[b] - times[a])
                e = math.dist([x * (1 - u) + y * u for x, y in zip(p[a], p[b])], p[s])
                e_max, e_sum = max(e_max, e), e_sum + e
                g_max = max(g_max, turn_deg(slerp(q[a], q[b], u), q[s]))
        print(f"every {n}: {len(keys)} keys; position error max {e_max * 1000:.1f} mm, "
              f"mean {e_sum / (len(pieces) * samples) * 1000:.2f} mm; "
              f"rotation error max {g_max:.1f} deg")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Writes the seed corpus of first_root_fuzz to tests/fuzz/corpus/first_root/.

Layout (first_root_fuzz.cpp): 7 little-endian doubles c0 c1 c2 c3 c4 lo hi, then an optional form
byte; form 1 reads c0..c3 as roots and c4 as the leading factor.
"""
import pathlib
import struct

COEFFS, ROOTS = 0, 1

SEEDS = {
    # (x - 1)^4: a fourfold root, only determined to ~eps^(1/4).
    "quadruple_root": ([1, -4, 6, -4, 1], 0, 2, COEFFS),
    # (x - 1)^2 (x - 3)^2: two touches, p >= 0.
    "two_double_roots": ([1, 1, 3, 3, 1], 0, 10, ROOTS),
    # Four roots 1e-3 apart.
    "clustered_roots": ([2.0, 2.001, 2.002, 2.003, 1], 0, 4, ROOTS),
    # A pair of roots 2e-6 apart: (x - 1)^2 - 1e-12.
    "near_double_root": ([1 - 1e-12, -2, 1, 0, 0], 0, 3, COEFFS),
    # (x - 1)^2 (x - 3)^2 + 1e-9: positive, two near touches.
    "near_touch_positive": ([9 + 1e-9, -24, 22, -8, 1], 0, 10, COEFFS),
    # (x - 2)^3: a cubic with a triple root.
    "triple_root_cubic": ([-8, 12, -6, 1, 0], 0, 5, COEFFS),
    # x^4 + 1: no real root.
    "no_root": ([1, 0, 0, 0, 1], -10, 10, COEFFS),
    # 2 - x.
    "linear": ([2, -1, 0, 0, 0], 0, 5, COEFFS),
    # Negative at lo: the answer is lo.
    "starts_inside": ([-1, 2, 5, 6, 1], 0, 10, ROOTS),
    # lo > hi: an empty interval.
    "empty_interval": ([1, -4, 6, -4, 1], 2, 0, COEFFS),
    # Roots 1, 2, 3, 4 scaled by 1e100 (large terms, no overflow).
    "scaled_up": ([1, 2, 3, 4, 1e100], -10, 10, ROOTS),
    # Clustered tiny roots near 1e-5.
    "tiny_roots": ([1e-5, 1.0001e-5, 3e-5, -2e-5, 1], -1e-4, 1e-4, ROOTS),
    # A wide interval: x^4 - 1 on [-1e30, 1e30].
    "wide_interval": ([-1, 0, 0, 0, 1], -1e30, 1e30, COEFFS),
    # Overflowing terms (structural checks only): 1e200 x^4 - 1 on [0, 1e100].
    "overflow": ([-1, 0, 0, 0, 1e200], 0, 1e100, COEFFS),
}


def main():
    out = pathlib.Path(__file__).resolve().parent / "corpus" / "first_root"
    out.mkdir(parents=True, exist_ok=True)
    for name, (c, lo, hi, form) in SEEDS.items():
        data = struct.pack("<7d", *[float(x) for x in c], float(lo), float(hi))
        if form == ROOTS:
            data += bytes([1])
        (out / name).write_bytes(data)


if __name__ == "__main__":
    main()

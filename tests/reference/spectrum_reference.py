#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Reference spectral ordinates for tests/excitation/test_intensity_measures.cpp, computed independently of
blockdyn: the oscillator's closed form over each linear segment of tests/fixtures/random_300.csv in
40-digit arithmetic (mpmath), every zero of the velocity inside a segment found on a grid of a
sixteenth of the damped period and refined by bisection, then the free vibration after
the record. Prints "T zeta Sa" lines (Sa in g, g = 9.81)."""
import os
import sys

import mpmath as mp

mp.mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))


def load(path):
    t, a = [], []
    with open(path) as f:
        next(f)
        for line in f:
            x, y = line.split(",")
            t.append(mp.mpf(x))
            a.append(mp.mpf(y))
    return t, a


def sa(t, a, T, zeta, g=mp.mpf("9.81")):
    T, zeta = mp.mpf(T), mp.mpf(zeta)
    w = 2 * mp.pi / T
    wd = w * mp.sqrt(1 - zeta**2)
    peak = mp.mpf(0)

    def segment(u0, v0, a0, s):
        p0, p1 = -a0 / w**2 + 2 * zeta * s / w**3, -s / w**2
        c = u0 - p0
        d = (v0 - p1 + zeta * w * c) / wd
        U = lambda x: p0 + p1 * x + mp.e ** (-zeta * w * x) * (c * mp.cos(wd * x) + d * mp.sin(wd * x))
        V = lambda x: p1 + mp.e ** (-zeta * w * x) * ((wd * d - zeta * w * c) * mp.cos(wd * x)
                                                     - (zeta * w * d + wd * c) * mp.sin(wd * x))
        return U, V

    def scan(U, V, h):
        nonlocal peak
        m = max(8, int(mp.ceil(16 * h / (2 * mp.pi / wd))))
        xs = [h * k / m for k in range(m + 1)]
        vs = [V(x) for x in xs]
        for k in range(m):
            if vs[k] * vs[k + 1] < 0:
                lo, hi = xs[k], xs[k + 1]
                for _ in range(140):  # bisection to 1e-42 of the interval
                    mid = (lo + hi) / 2
                    if (V(mid) < 0) == (vs[k] < 0):
                        lo = mid
                    else:
                        hi = mid
                peak = max(peak, abs(U(lo)))
        peak = max(peak, abs(U(h)))

    u = v = mp.mpf(0)
    for i in range(len(t) - 1):
        h = t[i + 1] - t[i]
        U, V = segment(u, v, g * a[i], g * (a[i + 1] - a[i]) / h)
        scan(U, V, h)
        u, v = U(h), V(h)
    U, V = segment(u, v, 0, 0)
    scan(U, V, 2 * mp.pi / wd)
    return peak * w**2 / g


if __name__ == "__main__":
    t, a = load(os.path.join(HERE, "..", "fixtures", "random_300.csv"))
    for T, zeta in [("0.02", "0.05"), ("0.3", "0.05"), ("5", "0.05"), ("50", "0.05"), ("10000", "0.05"),
                    ("0.7", "0"), ("0.004", "0.02")]:
        print(T, zeta, mp.nstr(sa(t, a, T, zeta), 20))
        sys.stdout.flush()

# SPDX-License-Identifier: Apache-2.0
"""The tilted equilibria at r = 0.1, k = 599.1 (thesis Fig. 4.36, issue 12 item 5) against an
independent computation: the model restated in ../shared/spec (lower envelope of the rotated
rectangle, exact integrals of the compression), 40-digit decimal arithmetic, bisection only - no
code shared with the program. See docs/equilibria.md."""
import json
import os
import subprocess
from decimal import Decimal as D, localcontext

CLI = os.environ["BLOCKDYN_CLI"]


def sincos(x):
    s, c, ts, tc, n = D(0), D(0), x, D(1), 0
    while abs(ts) > D(10) ** -45 or abs(tc) > D(10) ** -45:
        s, c, n = s + ts, c + tc, n + 2
        ts, tc = -ts * x * x / (n * (n + 1)), -tc * x * x / ((n - 1) * n)
    return s, c


def piece(a, ya, b, yb):
    """(area, first moment) of the compression max(0, -Y) along one straight piece of the envelope."""
    fa, fb = -ya, -yb
    if fa <= 0 and fb <= 0:
        return D(0), D(0)
    if fa < 0 or fb < 0:  # clip at the surface
        xm = a + (b - a) * fa / (fa - fb)
        a, fa, b, fb = (xm, D(0), b, fb) if fa < 0 else (a, fa, xm, D(0))
    return (b - a) * (fa + fb) / 2, (b - a) / 6 * (fa * (2 * a + b) + fb * (a + 2 * b))


def integrals(r, y, w):
    # 0 < w < alpha: the lower envelope is the left side edge (top-left to bottom-left corner)
    # then the bottom edge (to the bottom-right corner); centre at x = 0.
    s, c = sincos(w)
    tl, bl, br = [(u * c - v * s, y + u * s + v * c) for u, v in ((-r / 2, D("0.5")), (-r / 2, D("-0.5")),
                                                                  (r / 2, D("-0.5")))]
    a1, m1 = piece(*tl, *bl)
    a2, m2 = piece(*bl, *br)
    return a1 + a2, m1 + m2


def arm(r, k, w):
    s, c = sincos(w)
    lo, hi = (c + r * s) / 2 - 1, (c + r * s) / 2  # Ry = (k/r) area falls with the height y
    for _ in range(140):
        m = (lo + hi) / 2
        lo, hi = (m, hi) if k / r * integrals(r, m, w)[0] > 1 else (lo, m)
    area, moment = integrals(r, (lo + hi) / 2, w)
    return moment / area  # x_R - x


def root(r, k, lo, hi):
    glo = arm(r, k, lo)
    assert (glo > 0) != (arm(r, k, hi) > 0)
    for _ in range(55):
        m = (lo + hi) / 2
        gm = arm(r, k, m)
        lo, hi, glo = (m, hi, gm) if (gm > 0) == (glo > 0) else (lo, m, glo)
    return (lo + hi) / 2


def test_tilted_equilibria_at_r01_k5991_agree_with_an_independent_computation():
    with localcontext() as ctx:
        ctx.prec = 40
        r, k = D("0.1"), D("599.1")
        stable = root(r, k, D("0.005"), D("0.025"))
        unstable = root(r, k, D("0.025"), D("0.04"))
        thesis = D("0.01433593")
        thesis_arm = arm(r, k, thesis)
    out = json.loads(subprocess.run([CLI, "equilibria", "--r", "0.1", "--k", "599.1", "--json"], check=True,
                                    capture_output=True, text=True).stdout)
    tilted = [e for e in out["equilibria"] if e["w"] > 0]
    assert [e["stability"] for e in tilted] == ["stable", "unstable"]
    # The program's roots are refined to 1e-12 in w.
    assert abs(tilted[0]["w"] - float(stable)) < 1e-12
    assert abs(tilted[1]["w"] - float(unstable)) < 1e-12
    # The thesis's 0.01433593 is 2.5e-6 past the root: there the arm is -7.8e-10, not 0 (the
    # arm is this flat: its slope at the root is only -3.1e-4).
    assert abs(stable - thesis) > D("2e-6")
    assert D("-1e-9") < thesis_arm < D("-5e-10")

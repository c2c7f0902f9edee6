#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the synthetic earthquake-like accelerogram used by the tests and examples.

Kanai-Tajimi filtered white noise (ground frequency 2.5 Hz, damping 0.6) under a Jennings
envelope (rise 0-2 s, strong phase 2-12 s, exponential decay), 60 s at 0.01 s, scaled to a peak
of 0.3 g, written in the PEER NGA .AT2 layout (4 header lines, 5 values per line).
Deterministic: a fixed seed, so the file is reproducible byte for byte.
Usage: make_synthetic_record.py OUT.AT2
"""
import sys

import numpy as np

dt, n = 0.01, 6000
rng = np.random.default_rng(20261123)
w = rng.standard_normal(n) / np.sqrt(dt)
wg, zg = 2 * np.pi * 2.5, 0.6
# Kanai-Tajimi filter x'' + 2 zg wg x' + wg^2 x = -w, output a = 2 zg wg x' + wg^2 x (RK4, ZOH input)
x = v = 0.0
out = np.empty(n)
for i in range(n):
    f = lambda x_, v_: (v_, -2 * zg * wg * v_ - wg * wg * x_ - w[i])
    k1 = f(x, v); k2 = f(x + dt / 2 * k1[0], v + dt / 2 * k1[1])
    k3 = f(x + dt / 2 * k2[0], v + dt / 2 * k2[1]); k4 = f(x + dt * k3[0], v + dt * k3[1])
    x += dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
    v += dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
    out[i] = 2 * zg * wg * v + wg * wg * x
t = np.arange(n) * dt
env = np.where(t < 2, (t / 2) ** 2, np.where(t < 12, 1.0, np.exp(-0.25 * (t - 12))))
a = out * env
a *= 0.3 / np.max(np.abs(a))
a[0] = 0.0
with open(sys.argv[1], "w") as fh:
    fh.write("SYNTHETIC RECORD FOR BLOCKDYN TESTS (Kanai-Tajimi noise, Jennings envelope)\n")
    fh.write("seed 20261123, peak 0.3 g, not a real earthquake\n")
    fh.write("ACCELERATION TIME SERIES IN UNITS OF G\n")
    fh.write("NPTS=  %d, DT=   %.5f SEC\n" % (n, dt))
    for i in range(0, n, 5):
        fh.write("".join("%15.7E" % v for v in a[i:i + 5]) + "\n")

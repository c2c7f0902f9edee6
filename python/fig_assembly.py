#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Figures of docs/assemblies.md, computed with the blockdyn program.

usage: fig_assembly.py BLOCKDYN OUTDIR

Writes OUTDIR/assembly_frame_rocking.png (the trilith released from a tilt against the rigid
four-bar frame, integrated here independently with RK4), assembly_seed002_harmonic.png (seed 002's
phi = 90, beta = 4, omega = 10 case), assembly_friction.png (the command's own --plot figure)
and trilith.gif.
"""
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile

from plotkit import np, plt, save

B, OUT = sys.argv[1], sys.argv[2]
os.makedirs(OUT, exist_ok=True)
TMP = tempfile.mkdtemp(prefix="blockdyn-fig-")

# Seed 002's blocks: b = 0.12 m, lambda = 4.
b, h = 0.12, 0.48
R = 0.5 * math.hypot(b, h)
ALPHA = math.atan2(b, h)
P = math.sqrt(0.75 * 9.81 / R)


def run(*args):
    r = subprocess.run([B, *map(str, args)], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"blockdyn {' '.join(map(str, args))}: {r.stderr}")
    return r.stdout


def trajectory(*args, interval=0.002):
    path = os.path.join(TMP, "traj.csv")
    run("assembly", *args, "--trajectory", path, "--output-interval", interval, "--quiet")
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(f)]
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0] if k != "event" and not k.startswith("state")}


def frame_swing(theta0, p, t_end, dt=1e-5):
    """Rigid four-bar frame (lintel translating on the columns' corners) released from theta0 > 0:
    theta'' = -p^2 sin(alpha - theta) until theta = 0 (RK4)."""
    f = lambda th, w: (w, -p * p * math.sin(ALPHA - th))  # noqa: E731
    t, th, w = 0.0, theta0, 0.0
    ts, ths = [t], [th]
    while th > 0 and t < t_end:
        k1 = f(th, w)
        k2 = f(th + 0.5 * dt * k1[0], w + 0.5 * dt * k1[1])
        k3 = f(th + 0.5 * dt * k2[0], w + 0.5 * dt * k2[1])
        k4 = f(th + dt * k3[0], w + dt * k3[1])
        th += dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        w += dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        t += dt
        ts.append(t)
        ths.append(th)
    return np.array(ts), np.array(ths)


def frame_rocking():
    theta0 = 0.06
    gamma = 0.5  # identical blocks: m_lintel / (2 m_column)
    p_frame = P * math.sqrt((1 + 2 * gamma) / (1 + 3 * gamma))
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    for k, style in ((1e7, "-"), (1e9, "--")):
        c = trajectory("--preset", "trilith", "--tilt", theta0, "--normal-stiffness", k, "--t-end", 1.2,
                       interval=0.001)
        ax[0].plot(c["t"], c["theta_0"], style, lw=1.0, label=f"columns, k_N = {k:.0e} N/m")
        ax[1].plot(c["t"], c["theta_0"], style, lw=1.0, label=f"k_N = {k:.0e} N/m")
    for p, name in ((p_frame, "rigid frame, p_frame"), (P, "single column, p")):
        t, th = frame_swing(theta0, p, 1.0)
        ax[0].plot(t, th, ":", lw=1.6, label=name)
        ax[1].plot(t, th, ":", lw=1.6, label=name)
    ax[0].set_xlabel("t [s]")
    ax[0].set_ylabel("column rotation [rad]")
    ax[0].set_title("trilith released at theta0 = 0.06 rad (lambda = 4)", fontsize=9)
    ax[0].legend(fontsize=7)
    ax[1].set_xlim(0.12, 0.18)
    ax[1].set_ylim(-0.004, 0.012)
    ax[1].set_xlabel("t [s]")
    ax[1].set_title("first return to upright (zoom)", fontsize=9)
    ax[1].axhline(0, color="0.6", lw=0.5)
    ax[1].legend(fontsize=7)
    for a in ax:
        a.grid(alpha=0.3)
    save(fig, os.path.join(OUT, "assembly_frame_rocking.png"))


def seed_harmonic():
    # a_H = beta alpha g cos(Omega t), Omega = omega p (seed 002, Figs. 12-14).
    beta, omega = 4.0, 10.0
    amp, hz = beta * ALPHA, omega * P / (2 * math.pi)
    c = trajectory("--preset", "trilith", "--t-end", 60, "--ground-h-amplitude", amp, "--ground-h-frequency", hz,
                   "--ground-h-phase", 0.5 * math.pi, interval=0.002)
    fig, ax = plt.subplots(2, 1, figsize=(10, 6), sharex=True)
    ax[0].plot(c["t"], c["theta_0"] / ALPHA, lw=0.5, label="left column")
    ax[0].plot(c["t"], c["theta_1"] / ALPHA, lw=0.5, label="right column")
    ax[0].plot(c["t"], c["theta_2"] / ALPHA, lw=0.5, label="lintel")
    ax[0].set_ylabel("theta / alpha")
    ax[0].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1))
    ax[1].plot(c["t"], c["x_2"] - c["x_2"][0], lw=0.5, label="lintel x")
    ax[1].plot(c["t"], c["x_0"] - c["x_0"][0], lw=0.5, label="left column x")
    ax[1].set_ylabel("displacement [m]")
    ax[1].set_xlabel("t [s]")
    ax[1].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1))
    ax[0].set_title("seed 002 trilith, phi_s = phi_l = 90 deg, beta = 4, omega = 10 (first 60 s)", fontsize=9)
    for a in ax:
        a.grid(alpha=0.3)
    save(fig, os.path.join(OUT, "assembly_seed002_harmonic.png"))


def friction_case():
    out = os.path.join(OUT, "assembly_friction.png")
    run("assembly", "--preset", "trilith", "--phi-s", 20, "--phi-l", 15, "--t-end", 8, "--ground-h-amplitude", 0.35,
        "--ground-h-frequency", 1.5, "--plot", out, "--quiet")
    run("assembly", "--preset", "trilith", "--phi-s", 20, "--phi-l", 15, "--t-end", 8, "--ground-h-amplitude", 0.35,
        "--ground-h-frequency", 1.5, "--animate", os.path.join(OUT, "trilith.gif"), "--animate-frames", 80, "--quiet")


frame_rocking()
seed_harmonic()
friction_case()
shutil.rmtree(TMP, ignore_errors=True)

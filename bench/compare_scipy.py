# SPDX-License-Identifier: Apache-2.0
"""Side-by-side comparison of blockdyn and the SciPy reference (bench/scipy_reference.py).

Grid: r in {0.1, 0.2, 0.5, 1} x k in {1e2, 1e4, 1e6} x {ic1, ic2}, mu = 0.2, t_end = 30,
rtol = 1e-10 (--quick: r in {0.2, 1}, k in {1e2, 1e4}, t_end = 10). For each point: accepted
steps of each code, the CPU time of each one's integration (blockdyn: `--timing --timing-repeat 5`,
timing.integration_cpu_s of the fastest in-process repetition; SciPy: process_time around the
integration loop, in a process warmed up by one short run; like with like, and robust on a shared
machine), their ratio, the wall times for reference, and how far the event
sequences agree: the first event whose kind differs or whose time differs by more than --tol
(default 1e-6), and the first event whose kind differs (the sequence of kinds alone).

Usage: /usr/bin/python3 bench/compare_scipy.py [--quick] [--blockdyn PATH] [--method dopri5|dop853]
       [--out bench/compare_scipy.json] [--md bench/compare_scipy.md]
BLOCKDYN=<path> also selects the binary (default build/blockdyn of this tree).
"""
import argparse
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scipy_reference as ref  # noqa: E402

def run_blockdyn(exe, r, k, mu, ic, t_end, rtol, method, repeat=1):
    """blockdyn's JSON summary; with --timing the integration's CPU and wall time (the least of
    `repeat` runs), else the process's (binaries without --timing)."""
    cmd = [exe, "simulate", "--r", repr(r), "--k", repr(k), "--mu", repr(mu), "--ic", ic,
           "--t-end", repr(t_end), "--rtol", repr(rtol), "--json", "--quiet"]
    if method:
        cmd += ["--method", method]
    best = None
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), os.times()
        p = subprocess.run(cmd + ["--timing", "--timing-repeat", "5"], capture_output=True, text=True)
        if p.returncode != 0:  # an older binary without --timing: process times
            p = subprocess.run(cmd, check=True, capture_output=True, text=True)
        wall, c1 = time.perf_counter() - t0, os.times()
        d = json.loads(p.stdout)
        if isinstance(d.get("timing"), dict):
            d["_cpu"], d["_wall"], d["_kind"] = (d["timing"]["integration_cpu_s"],
                                                 d["timing"]["integration_wall_s"], "integration")
        else:
            d["_cpu"] = (c1.children_user + c1.children_system) - (c0.children_user + c0.children_system)
            d["_wall"], d["_kind"] = wall, "process"
        if best is None or d["_cpu"] < best["_cpu"]:
            best = d
    return best


def warm_up():
    """One short reference run first: every measured SciPy run then finds its code loaded."""
    m = ref.Winkler(0.5, 1e4, 0.2)
    ref.simulate(m, m.ic("ic1"), 0.0, 0.5, 1e-10, 1e-12)


def agreement(ea, eb, tol):
    """(index, time) of the first event differing in kind or by more than tol in time, and of the
    first event differing in kind; None where the sequences agree to the end of both."""
    first_t = first_kind = None
    for i, (a, b) in enumerate(zip(ea, eb)):
        if first_kind is None and a["kind"] != b["kind"]:
            first_kind = (i, min(a["t"], b["t"]))
        if first_t is None and (a["kind"] != b["kind"] or abs(a["t"] - b["t"]) > tol):
            first_t = (i, min(a["t"], b["t"]))
        if first_kind:
            break
    n = min(len(ea), len(eb))
    if len(ea) != len(eb):
        tail = (n, (ea if len(ea) > n else eb)[n]["t"])
        first_t = first_t or tail
        first_kind = first_kind or tail
    return first_t, first_kind


def run_point(exe, r, k, ic, a):
    bd = run_blockdyn(exe, r, k, a.mu, ic, a.t_end, a.rtol, a.method, repeat=a.repeat)
    m = ref.Winkler(r, k, a.mu)
    sp = ref.simulate(m, m.ic(ic), 0.0, a.t_end, a.rtol, 1e-12)
    ft, fk = agreement(sp["events"], bd["events"], a.tol)
    return {"r": r, "k": k, "ic": ic, "mu": a.mu, "t_end": a.t_end,
            "blockdyn": {"steps": bd["steps"], "rhs_evals": bd["rhs_evals"], "cpu_s": bd["_cpu"],
                         "wall_s": bd["_wall"], "time_kind": bd["_kind"], "status": bd["status"],
                         "events": len(bd["events"]), "event_counts": bd["event_counts"]},
            "scipy": {"steps": sp["steps"], "nfev": sp["nfev"], "cpu_s": sp["cpu_s"], "wall_s": sp["wall_s"],
                      "status": sp["status"], "events": len(sp["events"]),
                      "event_counts": sp["event_counts"]},
            "speed_ratio": sp["cpu_s"] / max(bd["_cpu"], 1e-6),
            "steps_ratio": bd["steps"] / max(sp["steps"], 1),
            "agree": ft is None,
            "first_divergence": None if ft is None else {"index": ft[0], "t": ft[1]},
            "first_kind_divergence": None if fk is None else {"index": fk[0], "t": fk[1]}}


def markdown(rows, a):
    head = ("| r | k | ic | steps blockdyn | steps SciPy | CPU blockdyn [ms] | CPU SciPy [s] | "
            "SciPy/blockdyn | events bd / SciPy | take-offs bd / SciPy | agree to (tol) | same kinds to |\n"
            "|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    fmt = lambda d: "all" if d is None else f"#{d['index']}, t = {d['t']:.4g}"
    lines = [f"| {x['r']} | {x['k']:.0e} | {x['ic']} | {x['blockdyn']['steps']} | {x['scipy']['steps']} | "
             f"{1e3 * x['blockdyn']['cpu_s']:.2f} | {x['scipy']['cpu_s']:.2f} | {x['speed_ratio']:.0f} | "
             f"{x['blockdyn']['events']} / {x['scipy']['events']} | "
             f"{x['blockdyn']['event_counts'].get('takeoff', 0)} / {x['scipy']['event_counts'].get('takeoff', 0)} | "
             f"{fmt(x['first_divergence'])} | {fmt(x['first_kind_divergence'])} |" for x in rows]
    note = (f"\nmu = {a.mu}, t_end = {a.t_end}, rtol = {a.rtol}, atol = 1e-12, time tolerance {a.tol}; "
            f"CPU times of the {rows[0]['blockdyn']['time_kind']} (blockdyn: the least of 5 in-process repetitions)"
            + (f", --method {a.method}" if a.method else "") + ".\n")
    return head + "\n".join(lines) + "\n" + note


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--blockdyn", default=os.environ.get(
        "BLOCKDYN", os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "build", "blockdyn")))
    ap.add_argument("--method", choices=["dopri5", "dop853"], help="passed to blockdyn if given")
    ap.add_argument("--quick", action="store_true", help="a subset: r 0.2, 1; k 1e2, 1e4; t_end 10")
    ap.add_argument("--mu", type=float, default=0.2)
    ap.add_argument("--t-end", type=float, default=None)
    ap.add_argument("--rtol", type=float, default=1e-10)
    ap.add_argument("--tol", type=float, default=1e-6, help="event time tolerance")
    ap.add_argument("--repeat", type=int, default=1, help="blockdyn processes per point (the least CPU time counts)")
    ap.add_argument("--out", default="compare_scipy.json")
    ap.add_argument("--md", default=None, help="markdown table file (default: --out with .md)")
    a = ap.parse_args()
    rs, ks = ([0.2, 1.0], [1e2, 1e4]) if a.quick else ([0.1, 0.2, 0.5, 1.0], [1e2, 1e4, 1e6])
    a.t_end = a.t_end or (10.0 if a.quick else 30.0)
    warm_up()
    rows = []
    for r in rs:
        for k in ks:
            for ic in ("ic1", "ic2"):
                rows.append(run_point(a.blockdyn, r, k, ic, a))
                x = rows[-1]
                print(f"r={r} k={k:.0e} {ic}: steps {x['blockdyn']['steps']} / {x['scipy']['steps']}, "
                      f"CPU {x['blockdyn']['cpu_s']:.4f} / {x['scipy']['cpu_s']:.2f} s, "
                      f"agree {x['agree']} {x['first_divergence']}", file=sys.stderr, flush=True)
                md = write(rows, a)  # after every point: a long run keeps what it has
    print(md)


def write(rows, a):
    with open(a.out, "w") as fh:
        json.dump({"blockdyn": a.blockdyn, "method": a.method, "mu": a.mu, "t_end": a.t_end,
                   "rtol": a.rtol, "tol": a.tol, "points": rows}, fh, indent=1)
    md = markdown(rows, a)
    with open(a.md or os.path.splitext(a.out)[0] + ".md", "w") as fh:
        fh.write(md)
    return md


if __name__ == "__main__":
    main()

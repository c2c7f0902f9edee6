# SPDX-License-Identifier: Apache-2.0
"""Issue 10: the late regime of ic1, r = 1, k = 1e6, mu = 0.2 in blockdyn and the SciPy reference.

Restarts both codes from one blockdyn state (its final state at --t-start, default 7.64: mid-flight
after the take-off at 7.599) at several tolerances (rtol 1e-8, 1e-10, 1e-12; atol = rtol/100) to
--t-end (default 12), and reports per run: take-offs, the last take-off time, the energy at the end
(E = 0 is the flight threshold: flight needs E >= 0; rest is E = -1/(2k)), and for the reference's
flights the largest height of the lowest corner (relative to 1/k, the static sinking).

Usage: /usr/bin/python3 bench/late_regime_study.py [--blockdyn PATH] [--t-start 7.64] [--t-end 12]
       [--rtols 1e-8,1e-10,1e-12] [--driver sampled|solve_ivp] [--out F.json]
"""
import argparse
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scipy_reference as ref  # noqa: E402

R, K, MU = 1.0, 1e6, 0.2


def blockdyn(exe, *args):
    cmd = [exe, "simulate", "--r", repr(R), "--k", repr(K), "--mu", repr(MU), "--json", "--quiet", *args]
    return json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)


def flight_apex(model, events):
    """Largest height of the lowest corner over the flights (free fall between take-off/landing)."""
    best = 0.0
    for a, b in zip(events, events[1:]):
        if a["kind"] == "takeoff":
            x, y, w, vx, vy, vw = a["state"]
            n = 64
            for j in range(n + 1):
                dt = (b["t"] - a["t"]) * j / n
                low = model.corners(y - 0.5 + vy * dt - 0.5 * dt * dt, w + vw * dt)[0][0]
                best = max(best, low)
    return best


def summary(events, t0, e_end, wall, steps):
    tk = [e["t"] + t0 for e in events if e["kind"] == "takeoff"]
    return {"takeoffs": len(tk), "last_takeoff": tk[-1] if tk else None,
            "w_zero": sum(e["kind"] == "w_zero" for e in events), "events": len(events),
            "E_end_times_k": e_end * K, "steps": steps, "wall_s": wall}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--blockdyn", default=os.environ.get(
        "BLOCKDYN", os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "build", "blockdyn")))
    ap.add_argument("--t-start", type=float, default=7.64)
    ap.add_argument("--t-end", type=float, default=12.0)
    ap.add_argument("--rtols", default="1e-8,1e-10,1e-12")
    ap.add_argument("--driver", default="sampled", choices=sorted(ref.DRIVERS))
    ap.add_argument("--out", default="late_regime_study.json")
    a = ap.parse_args()
    s = blockdyn(a.blockdyn, "--ic", "ic1", "--t-end", repr(a.t_start))["final_state"]
    start = [s[c] for c in ("x", "y", "w", "vx", "vy", "vw")]
    model = ref.Winkler(R, K, MU)
    z0 = [start[0], start[1] - 0.5, start[2], start[3], start[4], start[5], 0.0, 0.0, 0.0]
    out = {"t_start": a.t_start, "t_end": a.t_end, "start_state": start,
           "E_start_times_k": ref.energy(model, z0) * K, "runs": []}
    print(f"start t = {a.t_start}: state {start}, E*k = {out['E_start_times_k']:.4g}", flush=True)
    flags = [f"--{n}0" for n in ("x", "y", "w", "vx", "vy", "vw")]
    for rtol in (float(v) for v in a.rtols.split(",")):
        atol = rtol / 100.0
        args = ["--ic", "custom", "--t-end", repr(a.t_end - a.t_start), "--rtol", repr(rtol),
                "--atol", repr(atol)] + [x for f, v in zip(flags, start) for x in (f, repr(v))]
        b = blockdyn(a.blockdyn, *args)
        fs = b["final_state"]
        zb = [fs["x"], fs["y"] - 0.5, fs["w"], fs["vx"], fs["vy"], fs["vw"]]
        bd = summary(b["events"], a.t_start, ref.energy(model, zb), None, b["steps"])
        sp_full = ref.simulate(model, z0, 0.0, a.t_end - a.t_start, rtol, atol, keep_states=True,
                               driver=a.driver)
        sp = summary(sp_full["events"], a.t_start, sp_full["final_energy"], sp_full["wall_s"],
                     sp_full["steps"])
        sp["max_flight_height_times_k"] = flight_apex(model, sp_full["events"]) * K
        bd_states = [dict(e, state=[e["state"][c] for c in ("x", "y", "w", "vx", "vy", "vw")])
                     for e in b["events"]]
        bd["max_flight_height_times_k"] = flight_apex(model, bd_states) * K
        out["runs"].append({"rtol": rtol, "atol": atol, "blockdyn": bd, "scipy": sp})
        print(json.dumps(out["runs"][-1]), flush=True)
    with open(a.out, "w") as fh:
        json.dump(out, fh, indent=1)


if __name__ == "__main__":
    main()

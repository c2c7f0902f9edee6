# SPDX-License-Identifier: Apache-2.0
"""The performance targets of issue 10, measured side by side in one run (docs/performance.md).

Sections (--only, comma-separated; default all):
  steps   accepted steps of blockdyn and of the SciPy DOP853 reference at equal tolerance on the
          issue's case (ic2, r = 1, k = 1e6, mu = 0.2, t = 30, rtol 1e-10); target <= 2x.
  grid    integration CPU time against the SciPy reference on {r 0.1, 0.2, 0.5, 1} x
          {k 1e2, 1e4, 1e6} x {ic1, ic2}, t = 30 (compare_scipy.py); target >= 100x everywhere,
          with the agreement of the event sequences.
  map     the 40 x 30 response map of docs/map.md (ic2, t = 30) on 1 and 2 threads: wall and CPU
          time, and whether the two CSVs are byte-identical; target < 15 s wall on 2 cores.
  memory  peak RSS (getrusage of the child) of `simulate --json-out` for t = 100 and t = 10000 on
          the Winkler, Housner and rigid paths under a harmonic ground motion (events all along);
          target: independent of t_end.
  bench   the rigid-ground and assembly benchmarks of blockdyn_bench (CPU time per run).

With --baseline (and --baseline-bench) every section that runs blockdyn runs the baseline binary
too, in the same session, for before/after tables. Wall times depend on the machine's load: on a
shared machine compare CPU times.

Usage: /usr/bin/python3 bench/perf_targets.py [--only steps,map] [--blockdyn build/blockdyn]
       [--bench build/bench/blockdyn_bench] [--baseline /tmp/blockdyn-baseline]
       [--baseline-bench /tmp/blockdyn-bench-baseline] [--out perf_targets.json]
"""
import argparse
import filecmp
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import compare_scipy  # noqa: E402
import scipy_reference as ref  # noqa: E402

ISSUE_CASE = dict(r=1.0, k=1e6, mu=0.2, ic="ic2", t_end=30.0, rtol=1e-10)
MAP_ARGS = ["map", "--mu", "0.2", "--ic", "ic2", "--k", "1e2:1e8:40", "--inv-r", "1:20:30",
            "--boundary-points", "0", "--overwrite", "--quiet"]
# Runs that keep moving (and producing events) for any t_end: harmonic ground motions.
MEMORY_CASES = {
    "winkler": ["simulate", "--r", "0.5", "--k", "1e4", "--mu", "0.2", "--ic", "ic1",
                "--ground-h-amplitude", "0.3", "--ground-h-frequency", "0.2"],
    "housner": ["simulate", "--model", "housner", "--width", "0.4", "--height", "1.2", "--w0", "0.05",
                "--ground-h-amplitude", "0.25", "--ground-h-frequency", "1"],
    "rigid": ["simulate", "--model", "rigid", "--width", "0.4", "--height", "1.2", "--w0", "0.05", "--mu-s", "0.6",
              "--ground-h-amplitude", "0.25", "--ground-h-frequency", "1"],
    # Seed 002's trilith rocking without collapse under a harmonic motion, both contact laws.
    # (about 650 events per second with either contact law; runs of 10 and 1000 s).
    "assembly": ["assembly", "--preset", "trilith", "--phi-s", "30", "--phi-l", "30",
                 "--ground-h-amplitude", "0.26", "--ground-h-frequency", "5"],
    "assembly-rigid": ["assembly", "--preset", "trilith", "--contact", "rigid", "--phi-s", "30", "--phi-l", "30",
                       "--ground-h-amplitude", "0.26", "--ground-h-frequency", "5"],
}
MEMORY_T_ENDS = {"assembly": (10, 1000), "assembly-rigid": (10, 1000)}  # others: (100, 10000)


def run_timed(cmd):
    """(stdout, wall s, CPU s of the child, peak RSS KiB of the child)."""
    t0 = time.perf_counter()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(cmd, check=True, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    return p.stdout, time.perf_counter() - t0, cpu, after.ru_maxrss


def peak_rss_kib(cmd):
    """Peak RSS of one child, from /usr/bin/time (getrusage's children maximum is cumulative)."""
    with tempfile.NamedTemporaryFile("r", suffix=".txt") as f:
        subprocess.run(["/usr/bin/time", "-f", "%M", "-o", f.name] + cmd, check=True,
                       capture_output=True, text=True)
        return int(f.read().strip().splitlines()[-1])


def section_steps(a, out):
    c = ISSUE_CASE
    bd = compare_scipy.run_blockdyn(a.blockdyn, c["r"], c["k"], c["mu"], c["ic"], c["t_end"], c["rtol"], None)
    m = ref.Winkler(c["r"], c["k"], c["mu"])
    sp = ref.simulate(m, m.ic(c["ic"]), 0.0, c["t_end"], c["rtol"], 1e-12)
    row = {"blockdyn_steps": bd["steps"], "scipy_steps": sp["steps"], "ratio": bd["steps"] / sp["steps"],
           "blockdyn_method": bd["tolerances"]["method"], "blockdyn_cpu_s": bd["_cpu"], "scipy_cpu_s": sp["cpu_s"]}
    if a.baseline:
        base = compare_scipy.run_blockdyn(a.baseline, c["r"], c["k"], c["mu"], c["ic"], c["t_end"], c["rtol"], None)
        row["baseline_steps"] = base["steps"]
    out["steps"] = row
    print(f"## Steps (ic2, r = 1, k = 1e6, mu = 0.2, t = 30, rtol 1e-10)\n\n"
          f"blockdyn ({row['blockdyn_method']}): {row['blockdyn_steps']} accepted steps; SciPy DOP853: "
          f"{row['scipy_steps']}; ratio {row['ratio']:.2f} (target <= 2)"
          + (f"; baseline {row['baseline_steps']}" if a.baseline else "") + "\n", flush=True)


def section_grid(a, out):
    ga = argparse.Namespace(mu=0.2, t_end=30.0, rtol=1e-10, tol=1e-6, method=None, repeat=1)
    compare_scipy.warm_up()
    rows = []
    for r in (0.1, 0.2, 0.5, 1.0):
        for k in (1e2, 1e4, 1e6):
            for ic in ("ic1", "ic2"):
                rows.append(compare_scipy.run_point(a.blockdyn, r, k, ic, ga))
                x = rows[-1]
                print(f"  r={r} k={k:.0e} {ic}: CPU {1e3 * x['blockdyn']['cpu_s']:.2f} ms / "
                      f"{x['scipy']['cpu_s']:.2f} s = {x['speed_ratio']:.0f}x", file=sys.stderr, flush=True)
    out["grid"] = rows
    worst = min(rows, key=lambda x: x["speed_ratio"])
    print("## Grid against SciPy (integration CPU time)\n\n" + compare_scipy.markdown(rows, ga)
          + f"\nSmallest ratio {worst['speed_ratio']:.0f}x (r = {worst['r']}, k = {worst['k']:.0e}, {worst['ic']}; "
          "target >= 100x)\n", flush=True)


def run_map(exe, threads, path):
    _, wall, cpu, _ = run_timed([exe] + MAP_ARGS + ["--threads", str(threads), "-o", path])
    return wall, cpu


def section_map(a, out):
    rows = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name, exe in [("blockdyn", a.blockdyn)] + ([("baseline", a.baseline)] if a.baseline else []):
            r = {}
            for th in (1, 2):
                r[f"threads{th}"] = dict(zip(("wall_s", "cpu_s"), run_map(exe, th, f"{tmp}/{name}{th}.csv")))
            r["identical"] = filecmp.cmp(f"{tmp}/{name}1.csv", f"{tmp}/{name}2.csv", shallow=False)
            rows[name] = r
        if a.baseline:
            rows["same_as_baseline"] = filecmp.cmp(f"{tmp}/blockdyn1.csv", f"{tmp}/baseline1.csv", shallow=False)
    out["map"] = rows
    lines = ["## Map 40 x 30 (ic2, t = 30)\n", "| binary | threads | wall [s] | CPU [s] |", "|---|---|---|---|"]
    for name in ("blockdyn", "baseline"):
        if name in rows:
            for th in (1, 2):
                x = rows[name][f"threads{th}"]
                lines.append(f"| {name} | {th} | {x['wall_s']:.1f} | {x['cpu_s']:.1f} |")
    lines.append(f"\nCSV byte-identical for 1 and 2 threads: {rows['blockdyn']['identical']}"
                 + (f"; same CSV as the baseline: {rows['same_as_baseline']}" if a.baseline else "") + "\n")
    print("\n".join(lines), flush=True)


def section_memory(a, out):
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for case, args in MEMORY_CASES.items():
            for name, exe in [("blockdyn", a.blockdyn)] + ([("baseline", a.baseline)] if a.baseline else []):
                row = {"case": case, "binary": name}
                t_short, t_long = MEMORY_T_ENDS.get(case, (100, 10000))
                row["t_short"], row["t_long"] = t_short, t_long
                for t_end, key in ((t_short, "short"), (t_long, "long")):
                    js = f"{tmp}/{case}_{name}_{t_end}.json"
                    row[f"rss_kib_{key}"] = peak_rss_kib([exe] + args + [
                        "--t-end", str(t_end), "--json-out", js, "--quiet"])
                    with open(js) as f:
                        row[f"events_{key}"] = len(json.load(f)["events"])
                rows.append(row)
                print(f"  {case} {name}: {row}", file=sys.stderr, flush=True)
    out["memory"] = rows
    lines = ["## Peak memory (--json-out, harmonic ground motion)\n",
             "| path | binary | t_end short / long [s] | events | peak RSS [MiB] | events | peak RSS [MiB] |",
             "|---|---|---|---|---|---|---|"]
    for x in rows:
        lines.append(f"| {x['case']} | {x['binary']} | {x['t_short']} / {x['t_long']} | {x['events_short']} | "
                     f"{x['rss_kib_short'] / 1024:.1f} | {x['events_long']} | {x['rss_kib_long'] / 1024:.1f} |")
    print("\n".join(lines) + "\n", flush=True)


def run_bench(exe, flt):
    p = subprocess.run([exe, f"--benchmark_filter={flt}", "--benchmark_format=json"], check=True,
                       capture_output=True, text=True)
    return {b["name"]: b for b in json.loads(p.stdout)["benchmarks"]}


def section_bench(a, out):
    flt = "Housner|Rigid|Trilith"
    res = {"blockdyn": run_bench(a.bench, flt)}
    if a.baseline_bench:
        res["baseline"] = run_bench(a.baseline_bench, flt)
    out["bench"] = res
    lines = ["## Rigid-ground and assembly benchmarks (CPU time per run)\n",
             "| benchmark | " + " | ".join(f"{n} CPU [ms] | {n} steps | {n} rhs" for n in res) + " |",
             "|---|" + "---|---|---|" * len(res)]
    for name in res["blockdyn"]:
        cells = []
        for n in res:
            b = res[n].get(name)
            if not b:
                cells.append("- | - | -")
                continue
            scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
            cells.append(f"{b['cpu_time'] * scale:.2f} | {b.get('steps', 0):.0f} | {b.get('rhs_evals', 0):.0f}")
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    print("\n".join(lines) + "\n", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", default="steps,grid,map,memory,bench")
    ap.add_argument("--blockdyn", default=os.path.join(ROOT, "build", "blockdyn"))
    ap.add_argument("--bench", default=os.path.join(ROOT, "build", "bench", "blockdyn_bench"))
    ap.add_argument("--baseline", default=None, help="a baseline blockdyn binary run side by side")
    ap.add_argument("--baseline-bench", default=None, help="the baseline's blockdyn_bench")
    ap.add_argument("--out", default="perf_targets.json")
    a = ap.parse_args()
    out = {"blockdyn": a.blockdyn, "baseline": a.baseline, "date": time.strftime("%Y-%m-%d %H:%M"),
           "cpus": os.cpu_count(), "load_average": os.getloadavg()}
    sections = {"steps": section_steps, "grid": section_grid, "map": section_map, "memory": section_memory,
                "bench": section_bench}
    print(f"# issue 10 targets ({out['date']}, {out['cpus']} CPUs, load {out['load_average'][0]:.1f})\n")
    for name in a.only.split(","):
        sections[name.strip()](a, out)
        with open(a.out, "w") as f:
            json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()

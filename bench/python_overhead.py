# SPDX-License-Identifier: Apache-2.0
"""Per-call cost of `blockdyn.simulate` from Python against the integration alone (issue 26: at
most 0.5 ms of overhead for a 0.1 s Housner run). Run with the build's package:
    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py build/blockdyn
Prints the medians of the library call, of a prepared Simulator's run, of the command-line path
(the earlier implementation: the in-process command line, its JSON through a file) and the integration,
a small sweep in memory against the same sweep through its files (the earlier path), and
simulate_many on 1 and 2 threads."""
import json
import os
import subprocess
import sys
import tempfile
import time

import blockdyn

OPTS = dict(model="housner", width=0.3, height=1.5, w0=0.1, t_end=0.1)


def median(f, n):
    ts = []
    for _ in range(n):
        t0 = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t0)
    ts.sort()
    return ts[len(ts) // 2]


def main():
    program = sys.argv[1] if len(sys.argv) > 1 else "blockdyn"
    library = median(lambda: blockdyn.simulate(**OPTS), 500)
    sim = blockdyn.Simulator(**OPTS)
    prepared = median(sim.run, 500)
    # The command line in this process (blockdyn.run), its JSON to a file read back: the earlier path.
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "s.json")
        cli_args = ["simulate", *blockdyn._args("simulate", OPTS)[1:], "--json-out", out, "--quiet"]

        def via_command_line():
            blockdyn.run(*cli_args)
            with open(out) as f:
                json.load(f)
        via_cli = median(via_command_line, 100)
    args = [program, "simulate", "--model", "housner", "--width", "0.3", "--height", "1.5", "--w0", "0.1",
            "--t-end", "0.1", "--json", "--timing", "--timing-repeat", "200"]
    integration = json.loads(subprocess.run(args, capture_output=True, text=True, check=True).stdout)["timing"]
    sweep = dict(model="housner", width=0.25, height=1.5, ground_h_pulse="rect", t_end=2,
                 axis=["ground_h_duration=0.1:1:4", "ground_h_amplitude=0.15:0.8:5"], threads=1)
    sweep_memory = median(lambda: blockdyn.sweep(**sweep), 50)
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "s.csv")
        sweep_files = median(lambda: blockdyn.sweep(**dict(sweep, output=out, overwrite=True)), 50)
    # simulate_many: 200 Housner runs of 10 s (harmonic ground), 1 and 2 threads, in one run.
    many = [dict(model="housner", width=0.3, height=1.5, ground_h_amplitude=0.3 + 0.001 * i,
                 ground_h_frequency=1.5, t_end=10) for i in range(200)]
    many_1 = median(lambda: blockdyn.simulate_many(many, threads=1), 7)
    many_2 = median(lambda: blockdyn.simulate_many(many, threads=2), 7)
    print(json.dumps({"simulate_ms": library * 1e3, "simulator_run_ms": prepared * 1e3,
                      "simulate_many_200_1_thread_ms": many_1 * 1e3, "simulate_many_200_2_threads_ms": many_2 * 1e3,
                      "simulate_many_speedup": many_1 / many_2,
                      "command_line_path_ms": via_cli * 1e3,
                      "integration_ms": integration["integration_cpu_s"] * 1e3,
                      "sweep_20_points_in_memory_ms": sweep_memory * 1e3,
                      "sweep_20_points_through_files_ms": sweep_files * 1e3}, indent=2))


if __name__ == "__main__":
    main()

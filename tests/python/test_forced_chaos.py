# SPDX-License-Identifier: Apache-2.0
"""blockdyn.lyapunov (forced), blockdyn.chaos_map and blockdyn.periodic_orbits (issue 9, items 6-7):
the same numbers as the command line, as NumPy arrays."""
import json
import os
import subprocess
import tempfile

import numpy as np

import blockdyn

CLI = os.environ["BLOCKDYN_CLI"]
BLOCK = dict(model="housner", width=0.3, height=1.5)


def cli_json(*args):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "s.json")
        r = subprocess.run([CLI, *map(str, args), "--json-out", out], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        with open(out) as f:
            return json.load(f)


def test_forced_lyapunov_equals_the_command_line():
    j = blockdyn.lyapunov(**BLOCK, beta=1.5, omega=3, t_end=30, t_transient=10)
    c = cli_json("lyapunov", "--model", "housner", "--width", 0.3, "--height", 1.5, "--beta", 1.5, "--omega", 3,
                 "--t-end", 30, "--t-transient", 10)
    assert j["exponent"] == c["exponent"]
    assert j["exponent"] < 0
    assert isinstance(j["estimate"], np.ndarray) and j["estimate"][-1] == j["exponent"]
    assert j["twin_separation"][0] > 0 and j["twin_separation"][-1] < j["twin_separation"][0]


def test_chaos_map_equals_the_command_line():
    opts = dict(BLOCK, beta_min=0.8, beta_max=2, beta_points=2, omega_min=3, omega_max=6, omega_points=2, periods=30,
                transient_periods=10)
    j = blockdyn.chaos_map(**opts)
    c = cli_json("chaos-map", "--model", "housner", "--width", 0.3, "--height", 1.5, "--beta-min", 0.8, "--beta-max", 2,
                 "--beta-points", 2, "--omega-min", 3, "--omega-max", 6, "--omega-points", 2, "--periods", 30,
                 "--transient-periods", 10, "--quiet")
    assert list(j["motion"]) == [p["motion"] for p in c["points"]]
    ex = [np.nan if p["exponent"] is None else p["exponent"] for p in c["points"]]
    np.testing.assert_array_equal(j["exponent"], np.array(ex))
    assert j["beta"].shape == (4,)


def test_periodic_orbits_equal_the_command_line():
    opts = dict(width=0.151, height=1, restitution=0.9, beta=1.2, omega=2)
    j = blockdyn.periodic_orbits(**opts)
    c = cli_json("periodic-orbits", "--width", 0.151, "--height", 1, "--restitution", 0.9, "--beta", 1.2, "--omega", 2,
                 "--quiet")
    assert [o["phase"] for o in c["orbits"]] == list(j["phase"])
    assert list(j["stable"]) == [1.0 if o["stable"] else 0.0 for o in c["orbits"]]
    b = blockdyn.periodic_orbits(**opts, continue_="ks", continue_min=0.05, continue_max=0.3)
    assert b["mode"] == "continue" and len(b["branches"]) == 4 and b["ks"].size > 10

# SPDX-License-Identifier: Apache-2.0
"""The gallery's thesis-figure scripts (python/fig_*.py, run by scripts/gallery.sh) run end to end
on a tiny input: every figure they promise is written (PNG and SVG, non-empty) and the JSON
summary they print parses and holds the numbers the docs quote. The full-size runs are the
gallery's, not the tests'."""
import json
import os
import subprocess
import sys

import pytest

CLI = os.environ["BLOCKDYN_CLI"]
SRC = os.environ["BLOCKDYN_SOURCE_DIR"]

SCRIPTS = {
    "fig_convergence.py": ["conv_test1", "conv_test2", "conv_forces_fig3_8", "conv_forces_fig3_9",
                           "vertical_oscillation_mu0.2", "vertical_oscillation_mu0"],
    "fig_flight_time.py": ["flight_time_fig4_6-4_9"],
    "fig_overturn.py": ["overturn_fig4_25"],
    "fig_long_term.py": ["response_fig4_41", "response_fig4_47", "response_fig4_52", "response_fig4_56"],
    "fig_chaos.py": ["chaos_fig5_1", "chaos_fig5_3", "chaos_fig5_13", "chaos_fig5_14"],
}


def run_script(name, out, *extra):
    return subprocess.run([sys.executable, os.path.join(SRC, "python", name), CLI, str(out), *extra],
                          capture_output=True, text=True)


@pytest.mark.parametrize("name", sorted(SCRIPTS))
def test_script_writes_its_figures(name, tmp_path):
    r = run_script(name, tmp_path, "--tiny")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    assert doc["schema"] == f"blockdyn.{name[:-3].replace('_', '-')}.summary/1" and doc["program"]
    summary = doc[{"fig_convergence.py": "checks", "fig_flight_time.py": "panels", "fig_overturn.py": "panels"}
                  .get(name, "figures")]
    assert summary
    for stem in SCRIPTS[name]:
        for ext in ("png", "svg"):
            path = tmp_path / f"{stem}.{ext}"
            assert path.is_file() and path.stat().st_size > 1000, path
    if name == "fig_convergence.py":
        # the R-E block approaches the R-R one as k grows (thesis Table 3.1 / Figs 3.2-3.5) ...
        dw = [row["max_dw"] for row in summary["test1"]]
        assert dw[-1] < 0.01 * dw[0]
        # ... and the bounce follows its closed form with w, w' exactly zero (Figs 3.10-3.11)
        for v in summary["vertical"]:
            assert v["max_abs_w_or_vw"] == 0 and v["max_dev_y"] < 1e-9 and v["events"] >= 4
    if name == "fig_long_term.py":
        assert all(row["agrees"] for row in summary if "agrees" in row)


@pytest.mark.parametrize("args", [["OUT", "--huge"], []], ids=["unknown-flag", "no-outdir"])
def test_a_script_rejects_a_wrong_argument_list(args, tmp_path):
    args = [str(tmp_path) if a == "OUT" else a for a in args]
    r = subprocess.run([sys.executable, os.path.join(SRC, "python", "fig_overturn.py"), CLI, *args],
                       capture_output=True, text=True)
    assert r.returncode != 0 and "usage: fig_overturn.py" in r.stderr
    assert not any(tmp_path.iterdir())  # nothing written


def test_gallery_rejects_an_unknown_target(tmp_path):
    r = subprocess.run([os.path.join(SRC, "scripts", "gallery.sh"), str(tmp_path), "no-such-target"],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "unknown target" in r.stderr

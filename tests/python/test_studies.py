# SPDX-License-Identifier: Apache-2.0
"""The library's studies (flight, stability, equilibria) from Python: the same numbers as the
command line's CSV and JSON, from memory; errors name the option."""
import csv
import json
import os
import subprocess

import numpy as np
import pytest

import blockdyn

CLI = os.environ.get("BLOCKDYN_CLI", "blockdyn")


def cli_table_and_summary(tmp_path, *args):
    out, summ = tmp_path / "t.csv", tmp_path / "s.json"
    subprocess.run([CLI, *args, "--csv", str(out), "--json", str(summ)], check=True, capture_output=True)
    with open(out) as f:
        rows = list(csv.DictReader(f))
    return rows, json.loads(summ.read_text())


def without_version(j):
    return {k: v for k, v in j.items() if k not in ("run_info", "schema")}


def test_every_study_is_a_function_and_listed():
    names = blockdyn.studies()
    for n in ("flight-time", "flight-boundary", "kmin", "flight-map", "overturn", "stability-curve", "blowup",
              "equilibria", "bifurcation", "bifurcation-curves"):
        assert n in names
        assert callable(getattr(blockdyn, n.replace("-", "_")))
    desc, opts = names["flight-time"]
    assert opts["r"][0] == "0.5" and "aspect ratio" in opts["r"][1]


def test_flight_time_equals_the_command_line(tmp_path):
    args = dict(r=0.4, mu=0.3, k_min=1e3, k_max=1e6, points=5, t_end=4)
    rows, summary = cli_table_and_summary(
        tmp_path, "flight-time", *sum(([f"--{k.replace('_', '-')}", repr(v)] for k, v in args.items()), []))
    r = blockdyn.flight_time(**args)
    assert without_version(r.summary) == without_version(summary)
    np.testing.assert_array_equal(r["k"], [float(x["k"]) for x in rows])
    np.testing.assert_array_equal(r["time"], [float(x["time"]) for x in rows])
    assert list(r["status"]) == [x["status"] for x in rows]
    assert "runs" in r.text


def test_kmin_columns_equal_its_curves():
    r = blockdyn.kmin(ic="ic1", points=3, r_min=0.1, r_max=0.4)
    curve = r.summary["curves"]["ic1"]
    assert [c["status"] for c in curve] == ["found"] * 3
    np.testing.assert_array_equal(r["k_min_ic1"], [c["value"] for c in curve])
    assert np.all(np.diff(r["r"]) > 0)


def test_equilibria_from_memory_with_and_without_the_landscape():
    full = blockdyn.equilibria(r=0.4, k=50)
    lean = blockdyn.study("equilibria", table=False, r=0.4, k=50)
    assert full.summary["equilibria"] == lean.summary["equilibria"]
    assert lean.table == {}
    # The landscape's arm vanishes at every equilibrium tilt (its zeros are the equilibria).
    w, arm = full["w"], full["arm"]
    interior = [e["w"] for e in full.summary["equilibria"] if 0 < e["w"] < w[-1]]
    assert len(interior) == 1  # the unstable tilted one, k > k_os
    for we in interior:
        i = np.searchsorted(w, we)
        assert arm[i - 1] * arm[i] <= 0


def test_errors_name_the_option():
    with pytest.raises(ValueError, match="r = -1 is out of range"):
        blockdyn.flight_time(r=-1)
    with pytest.raises(ValueError, match="points = 'x' is not an integer"):
        blockdyn.overturn(points="x")
    with pytest.raises(ValueError, match="csv: not an option of equilibria"):
        blockdyn.equilibria(csv="a.csv")
    with pytest.raises(ValueError, match="not one of"):
        blockdyn.study("no-such-study")


def test_orbit_studies_give_their_series_as_arrays(tmp_path):
    opts = dict(r=0.4, k=2000, mu=0, t_end=60)
    p = blockdyn.poincare(**opts)
    x = p["crossings"]
    assert p.summary["crossings"] == len(x["t"]) > 10
    # The energy balance at every crossing: E + W_friction - W_nonpotential = E0 (to the
    # integration error, ~1e-10 at rtol 1e-10); the non-potential work itself is ~4e-7 here.
    balance = x["energy"] + x["work_friction"] - x["work_nonpotential"]
    np.testing.assert_allclose(balance, p.summary["energy_initial"], rtol=0, atol=1e-9)
    assert np.max(np.abs(x["work_nonpotential"])) > 1e-8
    prefix = tmp_path / "re"
    subprocess.run([CLI, "response", "--r", "0.3", "--k", "300", "--t-end", "20", "--csv-prefix", str(prefix)],
                   check=True, capture_output=True)
    r = blockdyn.response(r=0.3, k=300, t_end=20)
    with open(f"{prefix}_swings.csv") as f:
        rows = list(csv.DictReader(f))
    assert r.summary["type"] == "steady_rocking"
    np.testing.assert_array_equal(r["swings"]["t_end"], [float(x["t_end"]) for x in rows])
    lean = blockdyn.study("response", table=False, r=0.3, k=300, t_end=20)
    assert lean.series == {} and lean.summary["type"] == r.summary["type"]


@pytest.mark.parametrize("extra", [[], ["--refine", "2"]])
def test_survival_in_memory_equals_the_runner(tmp_path, extra):
    """The grid computed in memory (stage after stage for --refine) gives the runner's table and
    summary: the same points, classes and times."""
    args = ["--model", "housner", "--width", "0.3", "--height", "1.5", "--beta-points", "3", "--omega-points", "3",
            "--periods", "6", *extra]
    out, summ = tmp_path / "s.csv", tmp_path / "summary.json"
    subprocess.run([CLI, "survival", *args, "--out", str(out), "--json-out", str(summ), "--quiet"], check=True,
                   capture_output=True)
    cli = json.loads(summ.read_text())
    opts = {a[2:].replace("-", "_"): b for a, b in zip(args[::2], args[1::2])}
    mem = blockdyn.survival(**opts)
    assert without_version(cli)["points"] == mem["points"]
    assert cli["counts"] == mem["counts"] and cli["options"] == mem["options"]
    with open(out) as f:
        rows = list(csv.DictReader(f))
    np.testing.assert_array_equal(mem["table"]["index"], [float(r["index"]) for r in rows])
    assert list(mem["table"]["motion"]) == [r["motion"] for r in rows]
    if extra:
        assert len(rows) > 9  # refined points were added near class changes


def test_spectrum_in_memory_equals_the_runner(tmp_path):
    args = ["--model", "housner", "--width", "0.3", "--height", "1.5", "--pulse", "rect", "--durations", "0.2,0.6",
            "--scan-points", "12"]
    out, summ = tmp_path / "s.csv", tmp_path / "summary.json"
    subprocess.run([CLI, "spectrum", *args, "--csv", str(out), "--json-out", str(summ), "--quiet"], check=True,
                   capture_output=True)
    cli = json.loads(summ.read_text())
    mem = blockdyn.spectrum(model="housner", width=0.3, height=1.5, pulse="rect", durations=[0.2, 0.6], scan_points=12)
    assert cli["rows"] == mem["rows"] and cli["runs"] == mem["runs"]
    # The rectangular pulse's minimum against the linearised closed form (a few per cent at b/h = 0.2).
    for r in mem["rows"]:
        assert abs(r["min_overturning_amplitude"] / r["linearised_rect"] - 1) < 0.05


def test_response_curve_in_memory_equals_the_runner(tmp_path):
    args = ["--model", "assembly", "--preset", "trilith", "--betas", "1.5", "--omega", "3", "--phi-l-values", "30,90",
            "--t-end", "2"]
    out, summ = tmp_path / "c.csv", tmp_path / "summary.json"
    subprocess.run([CLI, "response-curve", *args, "--out", str(out), "--json-out", str(summ), "--quiet"],
                   check=True, capture_output=True)
    cli = json.loads(summ.read_text())
    mem = blockdyn.response_curve(model="assembly", preset="trilith", betas=[1.5], omega=3, phi_l_values="30,90",
                                  t_end=2)
    np.testing.assert_array_equal(mem["phi_l"], [30, 90])
    assert [p["theta_max_over_alpha"] for p in cli["points"]] == list(mem["theta_max_over_alpha"])
    assert [p["motion"] for p in cli["points"]] == list(mem["motion"])
    assert cli["options"] == mem["options"] and cli["model"] == mem["model"]

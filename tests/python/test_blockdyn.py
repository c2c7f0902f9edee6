# SPDX-License-Identifier: Apache-2.0
"""The Python module (issue 12): `import blockdyn` gives the command line's results to the last
digit, as NumPy arrays and dicts; invalid input raises ValueError naming the field; runs release
the GIL (threads give the same results as sequential runs)."""
import csv
import json
import os
import subprocess
import tempfile
import threading

import numpy as np
import pytest

import blockdyn

CLI = os.environ["BLOCKDYN_CLI"]
SRC = os.environ["BLOCKDYN_SOURCE_DIR"]
RECORD = os.path.join(SRC, "tests", "fixtures", "synthetic_60s.AT2")

CASES = [
    dict(model="housner", width=0.3, height=1.5, w0=0.1, t_end=4),
    dict(model="rigid", width=0.3, height=1.2, mu_s=0.3, mu_k=0.25, ground_h_record=RECORD,
         ground_h_scale=1.5, t_end=15, output_interval=0.005),
    dict(model="rigid", width=0.3, height=1.0, impact="newton", restitution=0.4, w0=0.08, t_end=3),
    dict(r=0.2, mu=0.2, k=1e5, ic="ic1", t_end=5),
    dict(height=1.8, width=0.45, mass=300.0, line_stiffness=2e8, mu=0.5, t_end=2,
         ground_h_pulse="half-sine", ground_h_amplitude=0.3, ground_h_duration=0.5),
]


def cli(*args):
    r = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout


def cli_simulate(opts):
    with tempfile.TemporaryDirectory() as tmp:
        traj = os.path.join(tmp, "t.csv")
        out = cli(*blockdyn._args("simulate", dict(opts, trajectory=traj, json=True)))
        with open(traj, newline="") as f:
            rows = list(csv.reader(f))
        return json.loads(out), rows


@pytest.mark.parametrize("opts", CASES, ids=lambda o: o.get("model", "winkler"))
def test_simulate_equals_the_command_line(opts):
    summary, rows = cli_simulate(opts)
    r = blockdyn.simulate(**opts)
    assert r.summary == summary  # every key, every digit
    header = rows[0]
    assert list(r.data.keys()) == header
    for i, name in enumerate(header):
        col = [row[i] for row in rows[1:]]
        got = r.data[name]
        if got.dtype == object:
            assert list(got) == col
        else:
            np.testing.assert_array_equal(got, np.array([float(c) if c else np.nan for c in col]))
    assert r.state.shape == (len(rows) - 1, 6)
    np.testing.assert_array_equal(r.state[:, 2], r["w"])
    assert r.events == summary["events"]


def test_sweep_equals_the_command_line():
    opts = dict(model="housner", width=0.25, height=1.5, ground_h_pulse="rect",
                axis=["ground_h_duration=0.1:1:4", "ground_h_amplitude=0.15:0.8:5"], t_end=5)
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "s.csv")
        cli(*blockdyn._args("sweep", dict(opts, output=out, quiet=True)))
        with open(out, newline="") as f:
            rows = list(csv.reader(f))
    s = blockdyn.sweep(**opts)
    assert s["_sidecar"]["schema"] == "blockdyn.sweep.sidecar/1"
    for i, name in enumerate(rows[0]):
        col = [row[i] for row in rows[1:]]
        if s[name].dtype == object:
            assert list(s[name]) == col
        else:
            np.testing.assert_array_equal(s[name], np.array([float(c) if c else np.nan for c in col]))
    assert len(s["index"]) == 20


def test_invalid_input_raises_value_error_naming_the_field():
    with pytest.raises(ValueError, match="mu-k"):
        blockdyn.simulate(model="rigid", width=0.3, height=1, mu_s=0.2, mu_k=0.5)
    with pytest.raises(ValueError, match="restitution"):
        blockdyn.simulate(model="housner", width=0.3, height=1, restitution=2)
    with pytest.raises(ValueError):
        blockdyn.simulate(model="rigid", width=0.3, height=1, no_such_option=1)


def test_threads_give_the_sequential_results():
    opts = [dict(model="housner", width=0.3, height=1.5, w0=0.01 * (i + 1), t_end=20) for i in range(4)]
    seq = [blockdyn.simulate(**o).summary["events"] for o in opts]
    par = [None] * len(opts)

    def work(i):
        par[i] = blockdyn.simulate(**opts[i]).summary["events"]

    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(opts))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert par == seq


def test_version_matches_the_program():
    assert cli("--version").strip().startswith(blockdyn.__version__)


@pytest.mark.parametrize("opts", [dict(model="housner", width=0.3, height=1.5, w0=0.1, t_end=2),
                                  dict(r=0.3, mu=0.3, k=1e4, ic="ic1", t_end=2)],
                         ids=["housner", "winkler"])
def test_animation_has_the_requested_frames(opts):
    from PIL import Image
    with tempfile.TemporaryDirectory() as tmp:
        gif = os.path.join(tmp, "a.gif")
        cli(*blockdyn._args("simulate", dict(opts, animate=gif, animate_frames=17, quiet=True)))
        assert os.path.getsize(gif) > 1000
        with Image.open(gif) as im:
            assert im.n_frames == 17
            assert im.size[0] > 100 and im.size[1] > 100


def test_animation_rejects_unknown_extension():
    r = subprocess.run([CLI, "simulate", "--model", "housner", "--width", "0.3", "--height", "1",
                        "--animate", "x.avi"], capture_output=True, text=True)
    assert r.returncode == 2 and "animate" in r.stderr


def test_assembly_spectrum_and_survival_from_python():
    a = blockdyn.assembly(preset="trilith", tilt=0.05, t_end=1)
    assert a.summary["status"] == "t_end" and a.summary["motion"] == "stable"
    assert a.theta.shape == (len(a.t), 3)
    assert abs(a.theta[0, 0] - 0.05) < 1e-15 and np.all(np.isfinite(a.theta))
    with tempfile.TemporaryDirectory() as tmp:
        traj = os.path.join(tmp, "a.csv")
        out = json.loads(cli("assembly", "--preset", "trilith", "--tilt", "0.05", "--t-end", "1",
                             "--trajectory", traj, "--json"))
    assert out["events"] == a.summary["events"] and out["blocks"] == a.summary["blocks"]
    s = blockdyn.spectrum(model="housner", width=0.3, height=1.5, durations=[0.1, 0.5])
    assert s["duration"].tolist() == [0.1, 0.5]
    assert s["min_overturning_amplitude"][0] > s["min_overturning_amplitude"][1] > 0
    v = blockdyn.survival(model="housner", width=0.3, height=1.5, beta_points=3, omega_points=2, t_end=5)
    assert len(v["beta"]) == 6 and v["motion"][0] == "rest"
    with pytest.raises(ValueError, match="preset"):
        blockdyn.assembly(preset="dome")


def test_response_curve_equals_the_command_line():
    r = blockdyn.response_curve(model="housner", width=0.3, height=1.5, betas=[2, 3], omega_points=3, periods=10)
    j = json.loads(cli("response-curve", "--model", "housner", "--width", "0.3", "--height", "1.5", "--betas", "2,3",
                       "--omega-points", "3", "--periods", "10", "--json"))
    assert r["points"] == j["points"] and len(r["beta"]) == 6
    assert r["beta"].tolist() == [p["beta"] for p in j["points"]]
    assert r["theta_max_over_alpha"].tolist() == [p["theta_max_over_alpha"] for p in j["points"]]
    assert set(r["motion"]) <= {"rest", "stable", "collapse", "invalid"}


def test_cycles_and_impact_map_equal_the_command_line():
    opts = dict(model="housner", width=0.3, height=1.5, beta=2, omega=5, periods=80)
    c = blockdyn.cycles(**opts)
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "s.csv")
        j = json.loads(cli("cycles", "--model", "housner", "--width", "0.3", "--height", "1.5", "--beta", "2",
                           "--omega", "5", "--periods", "80", "--out", out, "--json"))
        with open(out, newline="") as f:
            rows = list(csv.DictReader(f))
    assert c["segments"] == j["segments"] and c["dominant_cycle"] == j["dominant_cycle"] == "(1,1)"
    assert c["theta"].tolist() == [float(r["theta_0"]) for r in rows]
    assert list(c["strobe"]["cycle"]) == [r["cycle"] for r in rows]
    assert len(c["t"]) == 81 and c["t"][0] == 0.0
    m = blockdyn.impact_map(trace=True, transient=20, section_phase=1.0, **opts)
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "i.csv")
        j = json.loads(cli("impact-map", "--model", "housner", "--width", "0.3", "--height", "1.5", "--beta", "2",
                           "--omega", "5", "--periods", "80", "--transient", "20", "--section-phase", "1",
                           "--out", out, "--json"))
        with open(out, newline="") as f:
            rows = list(csv.DictReader(f))
    assert m["impacts"]["phase"].tolist() == [float(r["phase"]) for r in rows]
    assert np.all((m["phase"] >= 0) & (m["phase"] < 2 * np.pi)) and len(m["phase"]) == 120
    assert j["poincare_samples"] == len(m["poincare"]["t"]) == 60
    assert len(m["trace"]["t"]) > len(m["poincare"]["t"])
    with pytest.raises(ValueError, match="beta"):
        blockdyn.cycles(model="housner", width=0.3, height=1.5, omega=5)


def _csv_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def _assert_columns_equal(got, header, body):
    for i, name in enumerate(header):
        col = [row[i] for row in body]
        if got[name].dtype == object:
            assert list(got[name]) == col, name
        else:
            np.testing.assert_array_equal(got[name], np.array([float(c) if c else np.nan for c in col]), name)


def test_sweep_in_memory_writes_no_file_and_is_the_same_on_any_thread_count(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    opts = dict(k="1e3:1e5:3", r="0.2,0.3", mu=0.3, t_end=2, metric=["response_type"])
    one, two = blockdyn.sweep(threads=1, **opts), blockdyn.sweep(threads=2, **opts)
    assert list(tmp_path.iterdir()) == []
    for name in one:
        if name.startswith("_"):
            continue
        if one[name].dtype == object:
            assert list(one[name]) == list(two[name])
        else:
            np.testing.assert_array_equal(one[name], two[name])
    cli(*blockdyn._args("sweep", dict(opts, output="s.csv", quiet=True)))
    header, body = _csv_columns("s.csv")
    _assert_columns_equal(one, header, body)
    with open("s.json") as f:
        side = json.load(f)
    for key in ("schema", "fingerprint", "point_count", "columns", "definition", "tolerances"):
        assert one["_sidecar"][key] == side[key], key


def test_sweep_from_a_definition_file_in_memory(tmp_path):
    d = tmp_path / "d.toml"
    d.write_text('model = "housner"\n[physical]\nwidth = 0.25\nheight = 1.5\n'
                 '[axes]\nground_h_amplitude = "0.2:0.6:3"\n')
    s = blockdyn.sweep(d, ground_h_pulse="rect", ground_h_duration=0.4, t_end=3)
    assert list(s["ground_h_amplitude"]) == pytest.approx([0.2, 0.4, 0.6])
    assert s["_sidecar"]["definition"]["model"] == "housner"
    with pytest.raises(ValueError, match="no_such_option"):
        blockdyn.sweep(d, no_such_option=1)
    with pytest.raises(ValueError, match="k belongs to the winkler sweep"):
        blockdyn.sweep(d, k="1e3:1e4:2")


def test_map_in_memory_equals_the_command_line(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    opts = dict(k="1e3:1e6:4", inv_r="2:6:3", t_end=5, boundary_points=2, fine_per_decade=0)
    m = blockdyn.map(threads=2, **opts)
    assert list(tmp_path.iterdir()) == []
    cli(*blockdyn._args("map", dict(opts, output="m.csv", quiet=True)))
    _assert_columns_equal(m, *_csv_columns("m.csv"))
    _assert_columns_equal(m["_boundaries"], *_csv_columns("m_boundaries.csv"))
    assert set(m["response_type"]) <= {"steady_rocking", "settle_down", "settled", "rock_flight_zero_friction",
                                       "rock_to_vertical", "overturned"}
    with pytest.raises(ValueError, match="critical-n"):
        blockdyn.map(critical_n=1)

# SPDX-License-Identifier: Apache-2.0
"""The Python module on the library (issue 26): runs from memory, records as arrays, prepared runs
repeated, many runs on threads, each equal to the single call to the last bit."""
import json
import os
import tempfile

import numpy as np
import pytest

import blockdyn



def synthetic_record():
    """A 12 s record (s, g): two tones under a smooth envelope, sampled at 100 Hz."""
    t = np.arange(0, 12.0, 0.01)
    env = np.sin(np.pi * t / 12.0) ** 2
    return t, 0.35 * env * (np.sin(2 * np.pi * 1.3 * t) + 0.5 * np.sin(2 * np.pi * 3.1 * t + 0.4))


def assert_same(a, b):
    assert a.summary == b.summary
    assert list(a.data) == list(b.data)
    for k in a.data:
        if a.data[k].dtype == object:
            assert list(a.data[k]) == list(b.data[k])
        else:
            np.testing.assert_array_equal(a.data[k], b.data[k])


def test_record_as_arrays_equals_the_record_file(tmp_path):
    t, a = synthetic_record()
    path = tmp_path / "record.csv"
    path.write_text("t,a\n" + "".join(f"{ti!r},{ai!r}\n" for ti, ai in zip(t, a)))
    opts = dict(model="rigid", width=0.3, height=1.2, mu_s=0.3, mu_k=0.25, ground_h_scale=1.5, t_end=12)
    from_file = blockdyn.simulate(ground_h_record=str(path), **opts)
    from_arrays = blockdyn.simulate(ground_h_record=(t, a), **opts)
    from_lists = blockdyn.simulate(ground_h_record=(t.tolist(), a.tolist()), **opts)
    assert from_file.summary["impacts"] > 0  # the record moves the block
    for r in (from_arrays, from_lists):
        np.testing.assert_array_equal(r.state, from_file.state)
        assert r.events == from_file.events
        assert r.summary["status"] == from_file.summary["status"]
    with pytest.raises(ValueError, match="ground-v-record"):
        blockdyn.simulate(model="housner", width=0.3, height=1.5, ground_v_record=([0, 0.01, 0.02], [0, 0.1]))
    with pytest.raises(ValueError, match="increasing"):
        blockdyn.simulate(model="housner", width=0.3, height=1.5, ground_h_record=([0, 0.02, 0.01], [0, 0.1, 0]))


def test_prepared_runs_repeat_bit_for_bit():
    sim = blockdyn.Simulator(model="housner", width=0.3, height=1.5, ground_h_amplitude=0.3,
                             ground_h_frequency=1.5, t_end=6)
    first, second = sim.run(), sim.run()
    assert_same(first, second)
    assert_same(first, blockdyn.simulate(model="housner", width=0.3, height=1.5, ground_h_amplitude=0.3,
                                         ground_h_frequency=1.5, t_end=6))
    summary_only = sim.run(trajectory=False)
    assert summary_only.summary == first.summary and len(summary_only.t) == 0


def test_simulate_many_on_threads_equals_serial_calls():
    runs = [dict(model="rigid", width=0.3, height=1.2, mu_s=0.4, ground_h_amplitude=0.2 + 0.05 * i,
                 ground_h_frequency=2.0, t_end=5) for i in range(6)]
    runs.append(dict(r=0.2, mu=0.3, k=1e4, ic="ic1", t_end=3))
    serial = [blockdyn.simulate(**o) for o in runs]
    for threads in (1, 2, 3):
        for a, b in zip(blockdyn.simulate_many(runs, threads=threads), serial):
            assert_same(a, b)
    with pytest.raises(ValueError, match="mu-k"):
        blockdyn.simulate_many([runs[0], dict(model="rigid", width=0.3, height=1, mu_s=0.2, mu_k=0.5)], threads=2)


def test_unknown_and_misplaced_options_are_refused():
    with pytest.raises(ValueError, match="no_such_option"):
        blockdyn.simulate(model="housner", width=0.3, height=1.5, no_such_option=1)
    with pytest.raises(ValueError, match="mu_s belongs to model rigid"):
        blockdyn.simulate(model="housner", width=0.3, height=1.5, mu_s=0.5)
    with pytest.raises(ValueError, match="t_end"):
        blockdyn.simulate(model="housner", width=0.3, height=1.5, t_end="soon")


def test_assembly_from_memory_equals_the_command_line(tmp_path):
    import csv
    import json
    import subprocess
    cli = os.environ["BLOCKDYN_CLI"]
    args = ["--preset", "trilith", "--contact", "rigid", "--ground-h-amplitude", "0.3", "--ground-h-frequency", "2",
            "--t-end", "1.5"]
    traj = tmp_path / "a.csv"
    out = subprocess.run([cli, "simulate", "--model", "assembly", *args, "--trajectory", str(traj), "--json"],
                         capture_output=True, text=True, check=True).stdout
    summary = json.loads(out)
    with open(traj, newline="") as f:
        rows = list(csv.reader(f))
    a = blockdyn.assembly(preset="trilith", contact="rigid", ground_h_amplitude=0.3, ground_h_frequency=2, t_end=1.5)
    s = blockdyn.simulate(model="assembly", preset="trilith", contact="rigid", ground_h_amplitude=0.3,
                          ground_h_frequency=2, t_end=1.5)
    assert a.summary["schema"].startswith("blockdyn.assembly.summary/")
    assert summary["schema"].startswith("blockdyn.simulate.summary/")
    for r in (a.summary, s.summary):
        assert {k: v for k, v in r.items() if k != "schema"} == {k: v for k, v in summary.items() if k != "schema"}
    assert summary["impacts"] > 0 and list(a.data) == rows[0]
    for i, name in enumerate(rows[0]):
        col = [row[i] for row in rows[1:]]
        if a.data[name].dtype == object:
            assert list(a.data[name]) == col
        else:
            np.testing.assert_array_equal(a.data[name], np.array([float(c) for c in col]))
    with pytest.raises(ValueError, match="tilt: not an option of model housner"):
        blockdyn.simulate(model="housner", width=0.3, height=1.5, tilt=0.1)


def test_motion_info_from_a_file_and_from_arrays_agree():
    t = np.arange(0, 8, 0.01)
    a = 0.3 * np.sin(2 * np.pi * 1.1 * t) * np.exp(-0.3 * t)
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "r.csv")
        with open(path, "w") as f:
            f.write("t, a\n" + "".join(f"{x!r}, {y!r}\n" for x, y in zip(t, a)))
        from_file = blockdyn.motion_info(path, periods=[0.1, 0.5, 2.0])
    from_arrays = blockdyn.motion_info((t, a), periods=[0.1, 0.5, 2.0])
    for key in ("pga", "pgv", "pgd", "arias", "d5_95", "t_mid", "mean_period"):
        assert from_file[key] == from_arrays[key], key
    np.testing.assert_array_equal(from_file["sa"], from_arrays["sa"])
    assert from_arrays["pga"] == pytest.approx(np.abs(a).max())
    assert from_arrays["sa"].shape == (3,)
    with pytest.raises(ValueError, match="damping"):
        blockdyn.motion_info((t, a), spectrum=True, damping=-0.1)


def test_rocking_spectrum_from_arrays_equals_simulate():
    t = np.arange(0, 6, 0.01)
    a = 0.35 * np.sin(2 * np.pi * 1.5 * t) * np.exp(-0.4 * t)
    j = blockdyn.rocking_spectrum(record=(t, a), alpha=0.15, p_values=[2.0, 5.0], t_after=2, threads=2)
    assert j["p"].tolist() == [2.0, 5.0]
    for p, ratio in zip(j["p"], j["max_abs_rotation_over_alpha"]):
        R = 0.75 * 9.81 / p ** 2
        r = blockdyn.simulate(model="housner", width=2 * R * np.sin(0.15), height=2 * R * np.cos(0.15),
                              ground_h_record=(t, a), t_end=float(t[-1]) + 2)
        assert ratio == pytest.approx(r.summary["max_abs_rotation"] / 0.15, rel=1e-12)


def test_motion_generate_writes_records_that_motion_info_measures_alike(tmp_path):
    j = blockdyn.motion_generate(tmp_path / "suite", arias=0.3, d5_95=6, t_mid=4, f_mid=5, t_end=15, count=3,
                                 seed=5, threads=2)
    assert len(j["files"]) == 3
    for f, rec in zip(j["files"], j["records"]):
        assert blockdyn.motion_info(f)["arias"] == rec["arias"]
    with pytest.raises(ValueError, match="overwrite"):
        blockdyn.motion_generate(tmp_path / "suite", arias=0.3, d5_95=6, t_mid=4, f_mid=5, t_end=15)


def test_fragility_in_memory_equals_the_command_line(tmp_path):
    blockdyn.motion_generate(tmp_path / "suite", arias=0.6, d5_95=6, t_mid=4, f_mid=3, t_end=10, count=4, seed=2)
    opts = dict(model="housner", width=0.4, height=1.7, records=str(tmp_path / "suite" / "*.AT2"), im="pga",
                levels="0.2:0.8:4", t_after=2, bootstrap=20)
    j = blockdyn.fragility(threads=2, **opts)
    assert j["level"].shape == (4,)
    assert len(j["runs"]) == 16
    out = str(tmp_path / "f.json")
    blockdyn.run(*blockdyn._args("fragility", dict(opts, json_out=out, quiet=True)))
    with open(out) as f:
        cli = json.load(f)
    assert [r["max_abs_rotation"] for r in cli["runs"]] == [r["max_abs_rotation"] for r in j["runs"]]
    assert cli["fit"] == j["fit"]


def test_limit_analysis_and_the_arch_from_python():
    j = blockdyn.limit_analysis(preset="column", drums=3, slenderness=5)
    assert abs(j["lambda"] - 0.2) < 1e-12 and j["status"] == "ok"
    arch = blockdyn.limit_analysis(preset="arch", voussoirs=15, thickness_ratio=0.12, min_thickness=True)
    assert 0.1 < arch["min_thickness_ratio"] < 0.1075
    assert [m["state"] for m in arch["mechanism"]["interfaces"]].count("hinge") == 4
    # Thinner than its minimum the arch falls in the dynamics; thicker it stands.
    t = arch["min_thickness_ratio"]
    fall = blockdyn.assembly(preset="arch", voussoirs=15, thickness_ratio=0.9 * t, contact="rigid", t_end=3)
    stand = blockdyn.assembly(preset="arch", voussoirs=15, thickness_ratio=1.1 * t, contact="rigid", t_end=3)
    assert fall.summary["motion"] == "collapse" and stand.summary["motion"] == "rest"
    # 15 voussoirs run by time-stepping (the rigid law's default above 8 blocks), every contact
    # problem solved exactly.
    assert stand.summary["scheme"] == "time-stepping"
    assert stand.summary["contact_solves"]["gauss_seidel"] == 0
    with pytest.raises(ValueError, match="direction"):
        blockdyn.limit_analysis(preset="block", direction=2)


def test_families_are_the_registry():
    """blockdyn.families() is the C++ registry: the default first, each with what it takes part in;
    a model that is not registered is a ValueError naming the choices."""
    fams = blockdyn.families()
    names = [f["name"] for f in fams]
    assert names[0] == "winkler" and set(names) >= {"winkler", "housner", "rigid", "assembly"}
    by = {f["name"]: f for f in fams}
    assert by["winkler"]["free_lyapunov"] and not by["winkler"]["forced"]
    assert by["housner"]["rigid_ground"] and by["housner"]["forced"] and by["housner"]["sweep"]
    assert by["assembly"]["forced"] and not by["assembly"]["scenario"] and not by["assembly"]["sweep"]
    with pytest.raises(ValueError, match="not one of: winkler"):
        blockdyn.lyapunov(model="cylinder", t_end=1)


def test_rigid3d_run_from_python_has_its_own_state_columns():
    """The 3D family registers its state (centroid, quaternion, velocity, angular velocity): a run
    from Python carries it as NumPy columns, and its quaternion stays unit."""
    r = blockdyn.simulate(model="rigid3d", width=0.4, depth=0.3, height=1.2, tilt=0.1, tilt_azimuth=30,
                          angular_velocity=[0, 0, 0.3], t_end=1.0)
    assert r.state_columns == ("x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy", "vz", "wx", "wy", "wz")
    assert r.state.shape[1] == 13 and r.state.shape[0] == len(r.t)
    q = r.state[:, 3:7]
    assert np.max(np.abs(np.sum(q * q, axis=1) - 1.0)) < 1e-14
    assert r.summary["model"] == "rigid3d" and r.summary["status"] == "t_end"
    assert abs(r.data["tilt"][0] - 0.1) < 1e-14

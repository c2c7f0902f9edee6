# SPDX-License-Identifier: Apache-2.0
"""Files asked of Python (trajectory CSV, JSON summary, figures, sweep and map tables) are written
by the command line's writers, called directly: byte for byte what the program writes, from the
same run that returns the arrays, and nothing left behind."""
import glob
import json
import os
import subprocess

import numpy as np
import pytest

import blockdyn

CLI = os.environ["BLOCKDYN_CLI"]
HOUSNER = dict(model="housner", width=0.3, height=1.5, ground_h_amplitude=0.3, ground_h_frequency=1.5, t_end=4)
TRILITH = dict(preset="trilith", contact="rigid", ground_h_amplitude=0.3, ground_h_frequency=2, t_end=1.5)


def cli(*args):
    r = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout


def read(path):
    with open(path, "rb") as f:
        return f.read()


def assert_same_columns(a, b):
    assert list(a) == list(b)
    for k in a:
        if k.startswith("_"):
            continue
        if a[k].dtype == object:
            assert list(a[k]) == list(b[k]), k
        else:
            np.testing.assert_array_equal(a[k], b[k], k)


def scratch_files():
    return glob.glob(f"/tmp/blockdyn-*-{os.getpid()}*")


def test_simulate_writes_what_the_program_writes(tmp_path):
    traj, summ = tmp_path / "t.csv", tmp_path / "s.json"
    r = blockdyn.simulate(trajectory=traj, json_out=summ, **HOUSNER)
    cli(*blockdyn._args("simulate", dict(HOUSNER, trajectory=tmp_path / "c.csv", json_out=tmp_path / "c.json",
                                         quiet=True)))
    assert read(traj) == read(tmp_path / "c.csv")
    assert read(summ) == read(tmp_path / "c.json")
    assert r.summary == json.loads(read(summ)) and r.summary["impacts"] > 0
    assert_same_columns(r.data, blockdyn.simulate(**HOUSNER).data)  # the arrays of the same run


def test_simulate_figures_leave_no_scratch_file(tmp_path):
    from PIL import Image
    png, gif = tmp_path / "m.png", tmp_path / "m.gif"
    r = blockdyn.simulate(plot=png, animate=gif, animate_frames=9, **HOUSNER)
    assert os.path.getsize(png) > 10000 and os.path.exists(tmp_path / "m.svg")
    with Image.open(gif) as im:
        assert im.n_frames == 9
    assert scratch_files() == [] and sorted(os.listdir(tmp_path)) == ["m.gif", "m.png", "m.svg"]
    assert_same_columns(r.data, blockdyn.simulate(**HOUSNER).data)


def test_assembly_trajectory_is_the_programs(tmp_path):
    a = blockdyn.assembly(trajectory=tmp_path / "a.csv", **TRILITH)
    cli(*blockdyn._args("assembly", dict(TRILITH, trajectory=tmp_path / "c.csv", quiet=True)))
    assert read(tmp_path / "a.csv") == read(tmp_path / "c.csv")
    assert a.summary["impacts"] > 0
    assert_same_columns(a.data, blockdyn.assembly(**TRILITH).data)


def test_bad_file_outputs_name_the_option(tmp_path):
    with pytest.raises(ValueError, match="plot = .* is a directory"):
        blockdyn.simulate(plot=tmp_path, **HOUSNER)
    with pytest.raises(ValueError, match="animate"):
        blockdyn.simulate(animate=tmp_path / "x.avi", **HOUSNER)
    with pytest.raises(ValueError, match="trajectory: files are written by blockdyn.simulate"):
        blockdyn.Simulator(trajectory=tmp_path / "x.csv", **HOUSNER)
    with pytest.raises(ValueError, match="json: the summary is the result's"):
        blockdyn.simulate(json=True, **HOUSNER)
    assert os.listdir(tmp_path) == []


SWEEP = dict(k="1e3:1e5:3", r="0.2,0.3", mu=0.3, t_end=2, metric=["response_type"])


def test_sweep_on_files_is_the_programs_and_resumes(tmp_path):
    out = tmp_path / "s.csv"
    s = blockdyn.sweep(output=out, threads=2, **SWEEP)
    cli(*blockdyn._args("sweep", dict(SWEEP, output=tmp_path / "c.csv", quiet=True)))
    assert read(out) == read(tmp_path / "c.csv")
    assert s["_sidecar"] == json.loads(read(tmp_path / "s.json"))
    assert_same_columns(s, blockdyn.sweep(**SWEEP))  # the in-memory grid
    again = blockdyn.sweep(output=out, resume=True, **SWEEP)  # complete: nothing recomputed
    assert_same_columns(again, s) and read(out) == read(tmp_path / "c.csv")
    with pytest.raises(ValueError, match="exists"):
        blockdyn.sweep(output=out, **SWEEP)
    with pytest.raises(ValueError, match="resume and overwrite: give only one"):
        blockdyn.sweep(output=out, resume=True, overwrite=True, **SWEEP)
    with pytest.raises(ValueError, match="progress = 'sometimes'"):
        blockdyn.sweep(output=tmp_path / "p.csv", progress="sometimes", **SWEEP)
    with pytest.raises(ValueError, match="resume: a file-run option"):
        blockdyn.sweep(resume=True, **SWEEP)


def test_sweep_figure_alone_leaves_only_the_figure(tmp_path):
    png = tmp_path / "s.png"
    s = blockdyn.sweep(plot=png, **SWEEP)
    assert os.path.getsize(png) > 10000
    assert scratch_files() == [] and "s.png" in os.listdir(tmp_path)
    assert not [f for f in os.listdir(tmp_path) if f.endswith((".csv", ".journal"))]
    assert_same_columns(s, blockdyn.sweep(**SWEEP))


def test_map_on_files_is_the_programs(tmp_path):
    opts = dict(k="1e3:1e6:4", inv_r="2:6:3", t_end=5, boundary_points=2, fine_per_decade=0)
    m = blockdyn.map(output=tmp_path / "m.csv", **opts)
    cli(*blockdyn._args("map", dict(opts, output=tmp_path / "c.csv", quiet=True)))
    assert read(tmp_path / "m.csv") == read(tmp_path / "c.csv")
    assert read(tmp_path / "m_boundaries.csv") == read(tmp_path / "c_boundaries.csv")
    mem = blockdyn.map(**opts)
    assert_same_columns(m, mem)
    assert_same_columns(m["_boundaries"], mem["_boundaries"])
    assert m["_boundaries_meta"] == mem["_boundaries_meta"]


def test_figures_from_two_threads_at_once(tmp_path):
    import threading
    results = {}

    def work(i):
        results[i] = blockdyn.sweep(plot=tmp_path / f"s{i}.png", **SWEEP)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert sorted(results) == [0, 1] and scratch_files() == []
    assert all(os.path.getsize(tmp_path / f"s{i}.png") > 10000 for i in range(2))
    assert_same_columns(results[0], results[1])

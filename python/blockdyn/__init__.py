# SPDX-License-Identifier: Apache-2.0
"""blockdyn from Python: nonsmooth dynamics of rigid blocks.

    import blockdyn
    r = blockdyn.simulate(model="housner", width=0.3, height=1.5, w0=0.1, t_end=5)
    r.t, r.state          # NumPy arrays: times, and one row (x, y, w, vx, vy, vw) per output point
    r.events              # list of dicts, as in `blockdyn simulate --json`
    r.summary             # the dict `blockdyn simulate --json` prints
    s = blockdyn.sweep(model="housner", width=0.25, height=1.5, ground_h_pulse="rect",
                       axis=["ground_h_duration=0.1:1:10", "ground_h_amplitude=0.1:1:10"], t_end=8)
    s["overturned"]       # one NumPy column per CSV column

Options are the command line's, with dashes written as underscores (`t_end` for `--t-end`,
`ground_h_amplitude` for `--ground-h-amplitude`); True gives a flag, None or False leaves an
option out, a list repeats it; a record is a file or arrays, `ground_h_record=(t, a)` (s, g).
Every function calls the library from memory (no files, no command line); a run asked to write a
figure or a named output file goes through the command's writers in this process. Either way the
GIL is released and results are identical to the command line's to the last digit. Invalid input raises
ValueError with the program's message (naming the field); other failures RuntimeError.
"""
import csv
import json
import os
import tempfile

import numpy as np

from . import _core

__version__ = _core.__version__
__all__ = ["families", "simulate", "simulate_many", "motion_generate", "motion_info", "limit_analysis", "rocking_spectrum", "fragility", "Simulator", "assembly", "spectrum", "survival", "response_curve", "cycles", "impact_map", "sweep", "map", "run",
           "Simulation", "Assembly", "lyapunov", "chaos_map", "periodic_orbits", "__version__"]

# Where the plot scripts are once installed (share/blockdyn/python beside lib/python3/...).
_here = os.path.dirname(os.path.abspath(__file__))
for _up in (3, 4):
    _cand = os.path.join(_here, *([".."] * _up), "share", "blockdyn", "python")
    if "BLOCKDYN_PYTHON_DIR" not in os.environ and os.path.exists(os.path.join(_cand, "plotkit.py")):
        os.environ["BLOCKDYN_PYTHON_DIR"] = os.path.normpath(_cand)
        break

STATE_COLUMNS = ("x", "y", "w", "vx", "vy", "vw")


def _number(v):
    return repr(float(v)) if isinstance(v, float) else str(v)


def _args(command, options, positional=()):
    args = [command, *[str(p) for p in positional]]
    for key, value in options.items():
        if value is None or value is False:
            continue
        flag = "--" + key.replace("_", "-")
        if value is True:
            args.append(flag)
        elif isinstance(value, (list, tuple)):
            for v in value:
                args += [flag, _number(v)]
        else:
            args += [flag, _number(value)]
    return args


def run(*args):
    """Runs `blockdyn ARGS...` in this process; raises ValueError (invalid input) or RuntimeError."""
    code, message = _core.run_cli([str(a) for a in args])
    if code == 2:
        raise ValueError(message)
    if code != 0:
        raise RuntimeError(message)


def _read_csv(path):
    """{column: NumPy array} (float where every cell is a number or empty, else str)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return {}
    header, body = rows[0], rows[1:]
    cols = {}
    for i, name in enumerate(header):
        cells = [r[i] if i < len(r) else "" for r in body]
        try:
            cols[name] = np.array([float(c) if c != "" else np.nan for c in cells], dtype=float)
        except ValueError:
            cols[name] = np.array(cells, dtype=object)
    return cols


def _state_columns(data):
    """The state columns of the family whose trajectory `data` is (each family registers them)."""
    for cols in sorted({tuple(f["state_columns"]) for f in _core.families()}, key=len, reverse=True):
        if all(c in data for c in cols):
            return cols
    return STATE_COLUMNS


class Simulation:
    """One run: `t`, `state` (rows of the family's state columns: x, y, w, vx, vy, vw for the planar
    families, x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, wy, wz for rigid3d), `mode`, `event` (per
    row), `data` (every trajectory column by name), `events` and `summary` (the JSON of
    `simulate --json`)."""

    def __init__(self, data, summary):
        self.data = data
        self._summary = summary  # a dict, or the JSON text: parsed when first read (most runs never are)
        empty = np.zeros(0)
        self.t = data.get("t", empty)
        self.state_columns = _state_columns(data) if data else STATE_COLUMNS
        self.state = (np.column_stack([data[c] for c in self.state_columns]) if data
                      else np.zeros((0, len(self.state_columns))))
        self.mode = data.get("mode", empty)
        self.event = data.get("event", empty)

    @property
    def summary(self):
        if isinstance(self._summary, str):
            self._summary = json.loads(self._summary)
        return self._summary

    @property
    def events(self):
        return self.summary.get("events", [])

    def __getitem__(self, column):
        return self.data[column]

    def __repr__(self):
        s = self.summary
        return (f"<blockdyn.Simulation model={s.get('model')} status={s.get('status')} "
                f"t_final={s.get('t_final')} rows={len(self.t)} events={len(self.events)}>")


def _with_trajectory(command, positional, options):
    """Runs COMMAND with a trajectory CSV and a JSON summary in a temporary directory; returns
    ({column: array}, summary)."""
    for reserved in ("trajectory", "json", "json_out"):
        if reserved in options:
            raise ValueError(f"{reserved}: set by blockdyn.{command} itself")
    with tempfile.TemporaryDirectory(prefix="blockdyn-py-") as tmp:
        traj = os.path.join(tmp, "trajectory.csv")
        summ = os.path.join(tmp, "summary.json")
        opts = dict(options, trajectory=traj, json_out=summ, quiet=True)
        run(*_args(command, opts, [positional] if positional else []))
        with open(summ) as f:
            summary = json.load(f)
        return _read_csv(traj), summary


# Options that make files (figures): such a run goes through the command line's writers.
_FILE_OPTIONS = ("plot", "animate", "animate_frames")


def _is_samples(value):
    return isinstance(value, (tuple, list)) and len(value) == 2 and not isinstance(value[0], (str, bytes))


def _threads(value, name="threads"):
    """A thread count as the command line takes it: an integer in [0, 1024] (0: all cores);
    ValueError naming the field otherwise."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise ValueError(f"{name} = {value!r} is not an integer")
    if not 0 <= value <= 1024:
        raise ValueError(f"{name} = {value} is out of range: must be in [0, 1024] (0: all cores)")
    return int(value)


def _record_samples(name, value):
    """(t, a) as 1-D float lists; ValueError naming the option for anything else (a 2-D array is
    not flattened)."""
    out = []
    for what, v in zip(("times", "accelerations"), value):
        try:
            arr = np.asarray(v, dtype=float)
        except (TypeError, ValueError) as e:
            raise ValueError(f"--{name}: the record's {what} are not numbers ({e})") from None
        if arr.ndim != 1:
            raise ValueError(f"--{name}: the record's {what} must be a 1-D array, not of shape {arr.shape}")
        out.append(arr.tolist())
    return tuple(out)


def _options(options):
    """The keyword options as the library's (name, value) list: numbers written exactly (repr),
    a record given as (t, a) arrays passed as samples."""
    out = []
    for key, value in options.items():
        if not isinstance(key, str):
            raise ValueError(f"option names are strings: {key!r} is not")
        if value is None or value is False:
            continue
        name = key.replace("_", "-")
        if name == "threads":
            value = _threads(value)
        if (name == "record" or name.endswith("-record")) and _is_samples(value):
            out.append((name, _record_samples(name, value)))
        elif value is True:
            out.append((name, "true"))
        elif isinstance(value, (list, tuple)):
            out += [(name, _number(v)) for v in value]
        else:
            out.append((name, _number(value)))
    return out


def _columns(cols):
    """Text columns as object arrays; a text column with every cell empty reads as NaN numbers, as
    from the CSV."""
    data = {}
    for name, col in cols.items():
        if isinstance(col, list):
            data[name] = (np.full(len(col), np.nan) if all(c == "" for c in col)
                          else np.array(col, dtype=object))
        else:
            data[name] = col
    return data


def _prepared(scenario, options, command="simulate"):
    for reserved in ("trajectory", "json", "json_out"):
        if reserved in options:
            raise ValueError(f"{reserved}: set by blockdyn.{command} itself")
    opts = dict(options)
    if scenario is not None:
        opts["scenario"] = os.fspath(scenario)
    if command == "assembly":
        opts["model"] = "assembly"
    return _core.Prepared(_options(opts), command)


def _simulation(result):
    """A Simulation (its summary parsed when first read), or an Assembly for the assembly family."""
    cols, summary = result
    data = _columns(cols)
    if "theta_0" in data or not data:  # an assembly, or no table to tell by: read the summary now
        return _simulation_of(data, json.loads(summary))
    return Simulation(data, summary)


def _simulation_of(data, summary):
    return Assembly(data, summary) if "blocks" in summary and "theta_0" in data else Simulation(data, summary)


class Simulator:
    """A block's run prepared once (options parsed and validated, a record read once), run as often
    as wanted: `Simulator(model="housner", width=0.3, height=1.5, w0=0.1).run()`."""

    def __init__(self, scenario=None, **options):
        self._prepared = _prepared(scenario, options)

    def run(self, trajectory=True):
        """A Simulation (without the trajectory table when trajectory=False: the summary only)."""
        return _simulation(_core.simulate(self._prepared, trajectory))


def simulate(scenario=None, **options):
    """Runs one block (the options of `blockdyn simulate`, optionally a TOML scenario) and returns a
    Simulation (an Assembly with model="assembly"), from memory. A record may be a file or arrays:
    ground_h_record=(t, a), t in s, a in g."""
    if any(options.get(k) for k in _FILE_OPTIONS):
        return _simulation_of(*_with_trajectory("simulate", scenario, options))
    return _simulation(_core.simulate(_prepared(scenario, options), True))


def simulate_many(runs, threads=1, trajectory=True):
    """Runs a list of option dicts (each as for simulate) on `threads` threads without the GIL; the
    list of Simulations equals that of serial calls, bit for bit."""
    threads = _threads(threads)
    prepared = []
    for options in runs:
        if not isinstance(options, dict):
            raise ValueError(f"runs: each run is a dict of options, not {type(options).__name__}")
        o = dict(options)
        prepared.append(_prepared(o.pop("scenario", None), o))
    return [_simulation(r) for r in _core.simulate_many(prepared, threads, trajectory)]


class Assembly:
    """One assembly run: `t`, `data` (every trajectory column by name: x_b, y_b, theta_b, ... per
    block, px/py/fn/ft/state per contact end, energies), `theta` (rows: time, columns: blocks),
    `events` and `summary` (the JSON of `assembly --json`)."""

    def __init__(self, data, summary):
        self.data = data
        self.summary = summary
        self.t = data["t"]
        nb = len(summary["blocks"])
        self.theta = np.column_stack([data[f"theta_{b}"] for b in range(nb)])
        self.events = summary.get("events", [])

    def __getitem__(self, column):
        return self.data[column]

    def __repr__(self):
        s = self.summary
        return (f"<blockdyn.Assembly preset={s['assembly'].get('preset')} contact={s.get('contact')} "
                f"status={s.get('status')} motion={s.get('motion')} t_final={s.get('t_final')}>")


def assembly(file=None, **options):
    """Runs a block assembly (a preset, e.g. preset="trilith", or an assembly TOML file; the options
    of `blockdyn assembly`) and returns an Assembly with NumPy arrays, from memory."""
    if any(options.get(k) for k in _FILE_OPTIONS):
        return Assembly(*_with_trajectory("assembly", file, options))
    cols, summary = _core.simulate(_prepared(file, options, "assembly"), True)
    return Assembly(_columns(cols), json.loads(summary))


def _grid_summary(command, options):
    """A grid analysis computed in memory on its threads (the runner's rows, no journal): its JSON
    summary, with the table's columns under "table"."""
    for reserved in ("out", "csv", "json", "json_out", "plot", "plot_map", "quiet", "progress", "resume",
                     "overwrite", "progress_interval"):
        if reserved in options:
            raise ValueError(f"{reserved}: set by blockdyn.{command.replace('-', '_')} itself")
    cols, summary, _ = _core.grid_study(command, _options(options))
    j = json.loads(summary)
    j["table"] = _columns(cols)
    return j


def spectrum(**options):
    """Runs `blockdyn spectrum` and returns its JSON summary, with the rows also as arrays under
    "duration" and "min_overturning_amplitude" (NaN where nothing in the scan overturns)."""
    j = _grid_summary("spectrum", options)
    rows = j["rows"]
    j["duration"] = np.array([r["duration"] for r in rows], dtype=float)
    j["min_overturning_amplitude"] = np.array(
        [np.nan if r["min_overturning_amplitude"] is None else r["min_overturning_amplitude"] for r in rows],
        dtype=float)
    return j


def survival(**options):
    """Runs `blockdyn survival` and returns its JSON summary, with arrays "beta", "omega",
    "motion", "t_failure" (NaN without failure) and "max_abs_rotation" over the points."""
    j = _grid_summary("survival", options)
    pts = j["points"]
    j["beta"] = np.array([p["beta"] for p in pts], dtype=float)
    j["omega"] = np.array([p["omega"] for p in pts], dtype=float)
    j["motion"] = np.array([p["motion"] for p in pts], dtype=object)
    j["t_failure"] = np.array([np.nan if p["t_failure"] is None else p["t_failure"] for p in pts], dtype=float)
    j["max_abs_rotation"] = np.array([p["max_abs_rotation"] for p in pts], dtype=float)
    j["cycle"] = np.array([p["cycle"] for p in pts], dtype=object)
    return j


def rocking_spectrum(**options):
    """Runs `blockdyn rocking-spectrum` in memory (record= a file or (t, a) arrays, alpha=,
    p_values= or p_min/p_max/p_points, optionally scales=) and returns its JSON summary with the
    rows also as arrays "p", "scale", "max_abs_rotation_over_alpha", "overturned" (bool)."""
    record = options.get("record")
    if record is not None and not _is_samples(record):
        options["record"] = os.fspath(record)
    j = _grid_summary("rocking-spectrum", options)
    rows = j["rows"]
    for key in ("p", "scale", "max_abs_rotation_over_alpha"):
        j[key] = np.array([r[key] for r in rows], dtype=float)
    j["overturned"] = np.array([r["overturned"] for r in rows], dtype=bool)
    return j


def fragility(**options):
    """Runs `blockdyn fragility` in memory (records= a glob, im=, levels=, the model's options) and
    returns its JSON summary (runs, levels, fit with its 90 % band, curve) with the stripes as
    arrays "level", "fraction" and the curve as "curve_im", "curve_p", "curve_p05", "curve_p95"."""
    j = _grid_summary("fragility", options)
    j["level"] = np.array([lv["im"] for lv in j["levels"]], dtype=float)
    j["fraction"] = np.array([lv["n_overturned"] / lv["n"] for lv in j["levels"]], dtype=float)
    for key in ("im", "p", "p05", "p95"):
        j["curve_" + key] = np.array([c.get(key, np.nan) for c in j["curve"]], dtype=float)
    return j


def response_curve(**options):
    """Runs `blockdyn response-curve` and returns its JSON summary, with arrays "beta", "omega",
    "theta_max_over_alpha", "max_sliding_over_b", "motion", "t_failure" (NaN without failure) and,
    against the friction angle, "phi_s" and "phi_l" over the points."""
    j = _grid_summary("response-curve", options)
    pts = j["points"]
    for key in ("beta", "omega", "theta_max_over_alpha", "max_sliding_over_b", "phi_s", "phi_l"):
        if pts and key in pts[0]:
            j[key] = np.array([p[key] for p in pts], dtype=float)
    j["motion"] = np.array([p["motion"] for p in pts], dtype=object)
    j["t_failure"] = np.array([np.nan if p["t_failure"] is None else p["t_failure"] for p in pts], dtype=float)
    return j


def _harmonic_command(command, tables, options):
    """Runs the study COMMAND from memory; returns its summary with each series of `tables` (the
    names of the command line's CSV outputs) as {column: NumPy array} under its key."""
    for reserved in ("json", "json_out", "out", "poincare", "trace", "plot", "quiet", "progress"):
        if reserved in options:
            raise ValueError(f"{reserved}: set by blockdyn.{command.replace('-', '_')} itself")
    opts = _options(options)
    cols, summary, text, series = _core.study(command, opts, True, list(tables))
    j = json.loads(summary)
    for key in tables:
        j[key] = _columns(series[key])
    return j


def cycles(trace=False, **options):
    """Runs `blockdyn cycles` (stroboscopic samples and (m, n) cycles, 2m impacts per n forcing
    periods) and returns its JSON summary with the strobe samples under "strobe" ({column: array}:
    k, t, x_b, y_b, theta_b, vx_b, vy_b, omega_b per block, cycle) and the analysed block's "t",
    "theta", "omega" at t = k T; with trace=True also the trajectory under "trace"."""
    tables = ["strobe", *(["trace"] if trace else [])]
    j = _harmonic_command("cycles", tables, options)
    b = j["block"]
    j["t"], j["theta"], j["omega"] = (j["strobe"][c] for c in ("t", f"theta_{b}", f"omega_{b}"))
    return j


def impact_map(trace=False, **options):
    """Runs `blockdyn impact-map` and returns its JSON summary with the impacts as arrays "t",
    "phase" ((Omega t + phase) mod 2 pi), "omega_before", "omega_after", the Poincare section under
    "poincare" ({column: array}) and, with trace=True, the trajectory under "trace"."""
    tables = ["impacts", "poincare", *(["trace"] if trace else [])]
    j = _harmonic_command("impact-map", tables, options)
    for c in ("t", "phase", "omega_before", "omega_after"):
        j[c] = j["impacts"].get(c, np.array([], dtype=float))
    return j


def _table_command(command, definition, options):
    """The grid of `sweep` or `map`: in memory on `threads` threads, or, given `output` (or a
    figure), through the command's writers (CSV, sidecar, journal, figure)."""
    if options.get("output") or options.get("plot"):
        with tempfile.TemporaryDirectory(prefix="blockdyn-py-") as tmp:
            out = options.pop("output", None) or os.path.join(tmp, command + ".csv")
            opts = dict(options, output=out, quiet=True)
            run(*_args(command, opts, [definition] if definition else []))
            cols = _read_csv(out)
            side = os.path.splitext(out)[0] + ".json" if out.endswith(".csv") else out + ".json"
            with open(side) as f:
                cols["_sidecar"] = json.load(f)
            if command == "map":
                cols["_boundaries"] = _read_csv(os.path.splitext(out)[0] + "_boundaries.csv")
            return cols
    for reserved in ("resume", "overwrite", "progress", "progress_interval", "dry_run"):
        if reserved in options:
            raise ValueError(f"{reserved}: a file-run option; give output= to run blockdyn.{command} on files")
    options.pop("quiet", None)
    threads = _threads(options.pop("threads", 0) or 0)
    if definition is not None:
        options["definition"] = os.fspath(definition)
    result = getattr(_core, command)(_options(options), threads)
    cols = _columns(result[0])
    cols["_sidecar"] = json.loads(result[1])
    if command == "map":
        cols["_boundaries"] = _columns(result[2])
        cols["_boundaries_meta"] = json.loads(result[3])
    return cols


def sweep(definition=None, **options):
    """Runs `blockdyn sweep` and returns {column: NumPy array}, with the sidecar dict under key
    "_sidecar" (its definition, tolerances, columns). In memory on `threads` threads (0: all
    cores; the rows are the same on any count), or, given `output` or `plot`, on files as the
    command line writes them."""
    return _table_command("sweep", definition, options)


def map(**options):  # noqa: A001 (the command's name)
    """Runs `blockdyn map` (response types over (k, 1/r) with boundaries) and returns its table as
    {column: NumPy array}, "_sidecar", and the boundaries table under "_boundaries" (their meta
    under "_boundaries_meta"). In memory, or on files given `output` or `plot`."""
    return _table_command("map", None, options)


def families():
    """The registered model families, the default first: a list of dicts with "name",
    "description" and what each takes part in ("scenario", "rigid_ground", "sweep", "forced",
    "free_lyapunov")."""
    return _core.families()


def _family(name):
    """The family registered under `name` (None: the default); ValueError naming the choices."""
    fams = _core.families()
    if name is None:
        return fams[0]
    for f in fams:
        if f["name"] == name:
            return f
    raise ValueError(f"model = {name!r} is not one of: " + ", ".join(f["name"] for f in fams))


def lyapunov(**options):
    """Runs `blockdyn lyapunov` (the free Winkler block, or model="housner"|"rigid"|"assembly" under
    a ground motion) and returns its JSON summary with the convergence history as arrays "t",
    "growth", "estimate", and for forced models the two nearby orbits' separation as "twin_t",
    "twin_separation", "twin_predicted"."""
    for reserved in ("csv", "twin_csv", "json", "json_out", "plot"):
        if reserved in options:
            raise ValueError(f"{reserved}: set by blockdyn.lyapunov itself")
    forced = not _family(options.get("model")).get("free_lyapunov")
    tables = ["history", *(["twin"] if forced else [])]
    _, summary, _, series = _core.study("lyapunov", _options(options), True, tables)
    j = json.loads(summary)
    h = _columns(series["history"])
    for k in ("t", "growth", "estimate"):
        j[k] = h.get(k, np.array([], dtype=float))
    if forced:
        tw = _columns(series["twin"])
        for k in ("t", "separation", "predicted"):
            j["twin_" + k] = tw.get(k, np.array([], dtype=float))
    return j


def chaos_map(**options):
    """Runs `blockdyn chaos-map` and returns its JSON summary with one NumPy array per CSV column:
    "beta", "omega", "motion", "exponent" (1/s; -inf superstable, NaN none), "exponent_nondim",
    "exponent_second_half", "status", "impacts", "collapse_mode", "t_failure"."""
    j = _harmonic_command("chaos-map", ["points"], options)
    j.update(j.pop("points"))
    return j


def periodic_orbits(**options):
    """Runs `blockdyn periodic-orbits` and returns its JSON summary with the table's columns as NumPy
    arrays: the orbits (phase, velocity, mu1_re, ..., stable), the branch points of `continue_`
    ("continue" is a Python keyword: pass it as continue_="ks") or the region grid (region=True)."""
    if "continue_" in options:
        options["continue"] = options.pop("continue_")
    j = _harmonic_command("periodic-orbits", ["table"], options)
    j.update(j.pop("table"))
    return j


def motion_generate(out, **options):
    """Writes a suite of synthetic records into the directory `out` (`blockdyn motion generate`:
    model="rezaeian" with arias=, d5_95=, t_mid=, f_mid=, ... or model="pulse" with pulse_pgv=,
    pulse_period=, ...; count=, seed=, threads=) and returns motions.json's dict (per record its
    file and measures, the suite's medians) with "files": the records' paths."""
    j = json.loads(_core.motion_generate(_options(dict(options, out=os.fspath(out)))))
    j["files"] = [os.path.join(os.fspath(out), r["file"]) for r in j["records"]]
    return j


def motion_info(record, **options):
    """A record's intensity measures (`blockdyn motion info`): a dict with pga (g), pgv (m/s), pgd
    (m), arias (m/s), d5_95, t5, t95, t_mid, mean_period (s), ...; with spectrum=True (or periods=
    [...] or period_min/period_max/period_points) also "spectrum" (rows) and the arrays "period",
    "sa" (g), "sd" (m). `record` is a file (PEER .AT2, CSV) or arrays (t in s, a in g)."""
    if not _is_samples(record):
        record = os.fspath(record)
    j = json.loads(_core.motion_info(_options(dict(options, record=record))))
    if "spectrum" in j:
        for key in ("period", "sa", "sd", "t_peak"):
            j[key] = np.array([row[key] for row in j["spectrum"]], dtype=float)
    return j


def limit_analysis(file=None, **options):
    """Static limit analysis (`blockdyn limit-analysis`) of a preset (preset="arch", voussoirs=20,
    thickness_ratio=0.15, ...) or an assembly file: a dict with "lambda" (a_H / g at collapse),
    "status", "mechanism" (per block vx, vy, omega; per interface hinge / sliding / separating /
    closed), "thrust" (per joint: forces, centre of pressure) and, with min_thickness=True (arch),
    "min_thickness_ratio". direction=-1 loads towards +x."""
    if file is not None:
        options["file"] = os.fspath(file)
    return json.loads(_core.limit_analysis(_options(options)))


class StudyResult:
    """A study's results: `table` ({column: NumPy array, or object array of text}), `summary` (the
    dict the command's JSON summary holds), `text` (what the command prints) and `series` (an
    orbit study's tables by name, e.g. response's "swings" and "phase": {column: array})."""

    def __init__(self, table, summary, text, series=None):
        self.table, self.summary, self.text = table, summary, text
        self.series = series or {}

    def __getitem__(self, column):
        """A column of the table, or a series by name."""
        return self.table[column] if column in self.table else self.series[column]

    def __repr__(self):
        return f"StudyResult({self.summary.get('command', '')!r}, columns={list(self.table)})"


def studies():
    """{study name: (description, {option: (default, help)})}: the analyses `blockdyn.study` runs
    (the command line's subcommands of the same names)."""
    return _core.studies()


def study(name, table=True, **options):
    """Runs the study NAME (e.g. "flight-time", "stability-curve", "equilibria") from memory, with
    the command line's options as keywords (a list gives a comma-separated list); returns a
    StudyResult. table=False skips tables the summary does not need (equilibria, bifurcation, the
    orbit studies' series)."""
    opts = []
    for key, value in options.items():
        if value is None or value is False:
            continue
        flag = key.replace("_", "-")
        if value is True:
            opts.append((flag, "true"))
        elif isinstance(value, (list, tuple, np.ndarray)):
            opts.append((flag, ",".join(_number(v) for v in value)))
        else:
            opts.append((flag, _number(value)))
    cols, summary, text, series = _core.study(name, opts, table)
    return StudyResult(_columns(cols), json.loads(summary), text,
                       {k: _columns(v) for k, v in series.items()})


def _study_function(name, description):
    def run_named(**options):
        return study(name, **options)

    run_named.__name__ = name.replace("-", "_")
    run_named.__doc__ = f"{description} (`blockdyn {name}`; see blockdyn.study)."
    return run_named


# A function per study, but for the studies that have their own above (cycles, impact_map: their
# results keep the shape they had).
for _name, (_description, _opts) in _core.studies().items():
    if _name.replace("-", "_") not in globals():
        globals()[_name.replace("-", "_")] = _study_function(_name, _description)
        __all__.append(_name.replace("-", "_"))
__all__ += ["study", "studies", "StudyResult"]

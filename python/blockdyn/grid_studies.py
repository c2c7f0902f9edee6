# SPDX-License-Identifier: Apache-2.0
"""Analyses over a grid of runs: spectra, survival and response maps, fragility, sweeps and maps."""
import json
import os

import numpy as np

from . import _core
from ._marshal import _columns, _is_samples, _options, _threads


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


def _table_command(command, definition, options):
    """The grid of `sweep` or `map`: in memory on `threads` threads, or, given `output` (or a
    figure), on files by the command's writers (CSV, sidecar, journal, figure; resume= and
    overwrite= as on the command line)."""
    options.pop("quiet", None)
    threads = _threads(options.pop("threads", 0) or 0)
    if definition is not None:
        options["definition"] = os.fspath(definition)
    if "dry_run" in options:
        raise ValueError(f"dry_run: a command-line option (`blockdyn {command} --dry-run`)")
    if options.get("output") or options.get("plot"):
        runner = dict(resume=bool(options.pop("resume", False)), overwrite=bool(options.pop("overwrite", False)),
                      progress=str(options.pop("progress", "none")),
                      progress_interval=float(options.pop("progress_interval", 10)))
        if options.get("output"):
            options["output"] = os.fspath(options["output"])
        result = getattr(_core, command + "_files")(_options(options), threads, **runner)
    else:
        for reserved in ("resume", "overwrite", "progress", "progress_interval"):
            if reserved in options:
                raise ValueError(f"{reserved}: a file-run option; give output= to run blockdyn.{command} on files")
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

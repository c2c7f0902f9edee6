# SPDX-License-Identifier: Apache-2.0
"""Analyses of the motion under harmonic forcing and the named studies."""
import json

import numpy as np

from . import _core
from ._marshal import _columns, _number, _options
from .families import _family
from .results import StudyResult


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

# SPDX-License-Identifier: Apache-2.0
"""One run of a block or an assembly, prepared once, run once or many times."""
import json
import os

from . import _core
from ._marshal import _columns, _number, _options, _threads
from .results import Assembly, _simulation, _summary_text

# The files a run writes besides returning its arrays, by the command line's writers.
_FILE_OPTIONS = ("trajectory", "plot", "animate", "animate_frames", "json_out")
_FILE_SET = frozenset(_FILE_OPTIONS)


def _files(options):
    """(the model's options, {output: path} of the files asked for)."""
    files = {}
    for key in _FILE_OPTIONS:
        value = options.get(key)
        if value is not None and value is not False:
            files[key.replace("_", "-")] = _number(value) if key == "animate_frames" else os.fspath(value)
    return {k: v for k, v in options.items() if k not in _FILE_OPTIONS}, files


def _checked_options(options, scenario=None, command="simulate"):
    """The library's option list of a run (its scenario file, if any): no JSON and no files here."""
    if "json" in options:
        raise ValueError("json: the summary is the result's `summary` (json_out= writes it to a file)")
    for key in _FILE_OPTIONS:
        if options.get(key) is not None and options.get(key) is not False:
            raise ValueError(f"{key}: files are written by blockdyn.simulate and blockdyn.assembly, not here")
    opts = dict(options)
    if scenario is not None:
        opts["scenario"] = os.fspath(scenario)
    if command == "assembly":
        opts["model"] = "assembly"
    return _options(opts)


def _prepared(scenario, options, command="simulate"):
    return _core.Prepared(_checked_options(options, scenario, command), command)


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
    if options.keys() & _FILE_SET:
        options, files = _files(options)
        return _simulation(_core.simulate_files(_prepared(scenario, options), files))
    if scenario is None and "json" not in options:  # the common call: no file, nothing to check
        return _simulation(_core.simulate(_core.Prepared(_options(options), "simulate"), True))
    return _simulation(_core.simulate(_prepared(scenario, options), True))


def simulate_many(runs, threads=1, trajectory=True):
    """Runs a list of option dicts (each as for simulate) on `threads` threads without the GIL; the
    list of Simulations equals that of serial calls, bit for bit."""
    threads = _threads(threads)
    option_lists = []
    for options in runs:
        if not isinstance(options, dict):
            raise ValueError(f"runs: each run is a dict of options, not {type(options).__name__}")
        option_lists.append(_checked_options(options))
    # Each run is prepared (parsed, validated, its record read) on the worker thread that runs it.
    return [_simulation(r) for r in _core.simulate_many_options(option_lists, threads, trajectory)]


def assembly(file=None, **options):
    """Runs a block assembly (a preset, e.g. preset="trilith", or an assembly TOML file; the options
    of `blockdyn assembly`) and returns an Assembly with NumPy arrays, from memory."""
    options, files = _files(options)
    prepared = _prepared(file, options, "assembly")
    cols, summary = _core.simulate_files(prepared, files) if files else _core.simulate(prepared, True)
    return Assembly(_columns(cols), json.loads(_summary_text(summary)))

# SPDX-License-Identifier: Apache-2.0
"""One run of a block or an assembly, prepared once, run once or many times."""
import json
import os

from . import _core
from ._command_line import _FILE_OPTIONS, _with_trajectory
from ._marshal import _columns, _options, _threads
from .results import Assembly, _simulation, _simulation_of


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


def assembly(file=None, **options):
    """Runs a block assembly (a preset, e.g. preset="trilith", or an assembly TOML file; the options
    of `blockdyn assembly`) and returns an Assembly with NumPy arrays, from memory."""
    if any(options.get(k) for k in _FILE_OPTIONS):
        return Assembly(*_with_trajectory("assembly", file, options))
    cols, summary = _core.simulate(_prepared(file, options, "assembly"), True)
    return Assembly(_columns(cols), json.loads(summary))

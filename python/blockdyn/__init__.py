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
import os

from . import _core
from ._command_line import _args, run  # noqa: F401 (_args: the tests build command lines with it)
from .families import families
from .grid_studies import fragility, map, response_curve, rocking_spectrum, spectrum, survival, sweep
from .masonry import limit_analysis
from .motion import motion_generate, motion_info
from .orbit_studies import _study_function, chaos_map, cycles, impact_map, lyapunov, periodic_orbits, studies, study
from .results import STATE_COLUMNS, Assembly, Simulation, StudyResult  # noqa: F401 (STATE_COLUMNS: public, as before)
from .simulation import Simulator, assembly, simulate, simulate_many

__version__ = _core.__version__
__all__ = ["families", "simulate", "simulate_many", "motion_generate", "motion_info", "limit_analysis", "rocking_spectrum",
           "fragility", "Simulator", "assembly", "spectrum", "survival", "response_curve", "cycles", "impact_map", "sweep",
           "map", "run", "Simulation", "Assembly", "lyapunov", "chaos_map", "periodic_orbits", "__version__"]

# Where the plot scripts are once installed (share/blockdyn/python beside lib/python3/...).
_here = os.path.dirname(os.path.abspath(__file__))
for _up in (3, 4):
    _cand = os.path.join(_here, *([".."] * _up), "share", "blockdyn", "python")
    if "BLOCKDYN_PYTHON_DIR" not in os.environ and os.path.exists(os.path.join(_cand, "plotkit.py")):
        os.environ["BLOCKDYN_PYTHON_DIR"] = os.path.normpath(_cand)
        break

# A function per study, but for the studies that have their own (cycles, impact_map: their
# results keep the shape they had).
for _name, (_description, _opts) in _core.studies().items():
    if _name.replace("-", "_") not in globals():
        globals()[_name.replace("-", "_")] = _study_function(_name, _description)
        __all__.append(_name.replace("-", "_"))
__all__ += ["study", "studies", "StudyResult"]

# SPDX-License-Identifier: Apache-2.0
"""Runs that write files (figures, named outputs): the command's own writers, in this process."""
import csv
import json
import os
import tempfile

import numpy as np

from . import _core
from ._marshal import _number


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


# Options that make files (figures): such a run goes through the command line's writers.
_FILE_OPTIONS = ("plot", "animate", "animate_frames")


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

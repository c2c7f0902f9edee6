# SPDX-License-Identifier: Apache-2.0
"""What the runs return: a block's Simulation, an Assembly, a StudyResult."""
import json

import numpy as np

from . import _core
from ._marshal import _columns


STATE_COLUMNS = ("x", "y", "w", "vx", "vy", "vw")


_FAMILY_STATE_COLUMNS = []  # the families' state columns, longest first (read once)


def _state_columns(data):
    """The state columns of the family whose trajectory `data` is (each family registers them)."""
    if not _FAMILY_STATE_COLUMNS:
        _FAMILY_STATE_COLUMNS.extend(
            sorted({tuple(f["state_columns"]) for f in _core.families()}, key=len, reverse=True))
    for cols in _FAMILY_STATE_COLUMNS:
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
        self._state_columns = self._state = None  # found and stacked when first read
        self.mode = data.get("mode", empty)
        self.event = data.get("event", empty)

    @property
    def state_columns(self):
        if self._state_columns is None:
            self._state_columns = _state_columns(self.data) if self.data else STATE_COLUMNS
        return self._state_columns

    @property
    def state(self):
        if self._state is None:
            self._state = (np.column_stack([self.data[c] for c in self.state_columns]) if self.data
                           else np.zeros((0, len(self.state_columns))))
        return self._state

    @property
    def summary(self):
        if not isinstance(self._summary, dict):
            self._summary = json.loads(_summary_text(self._summary))
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


def _summary_text(summary):
    """The JSON text of a run's summary: given, or printed by the module when first read."""
    return summary if isinstance(summary, str) else summary.text()


def _simulation(result):
    """A Simulation (its summary printed and parsed when first read), or an Assembly for the
    assembly family (its table has the blocks' columns)."""
    cols, summary = result
    data = _columns(cols)
    if "theta_0" in data:  # an assembly's table, or a block's: the summary tells
        return _simulation_of(data, json.loads(_summary_text(summary)))
    return Simulation(data, summary)


def _simulation_of(data, summary):
    return Assembly(data, summary) if "blocks" in summary and "theta_0" in data else Simulation(data, summary)


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

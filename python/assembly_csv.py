# SPDX-License-Identifier: Apache-2.0
"""Reads the trajectory CSV of `blockdyn assembly` and the block sizes of its JSON summary."""
import csv
import re

import numpy as np


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    cols = {}
    for i, name in enumerate(header):
        vals = [r[i] for r in body]
        if name in ("event",) or name.startswith("state_"):
            cols[name] = np.array(vals, dtype=object)
        else:
            cols[name] = np.array([float(v) if v else np.nan for v in vals])
    nb = len([h for h in header if re.fullmatch(r"theta_\d+", h)])
    npts = len([h for h in header if h.startswith("fn_")])
    return cols, nb, npts

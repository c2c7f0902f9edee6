# SPDX-License-Identifier: Apache-2.0
"""Ground motions: synthetic suites and a record's intensity measures."""
import json
import os

import numpy as np

from . import _core
from ._marshal import _is_samples, _options


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

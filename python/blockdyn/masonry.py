# SPDX-License-Identifier: Apache-2.0
"""Static limit analysis of masonry assemblies."""
import json
import os

from . import _core
from ._marshal import _options


def limit_analysis(file=None, **options):
    """Static limit analysis (`blockdyn limit-analysis`) of a preset (preset="arch", voussoirs=20,
    thickness_ratio=0.15, ...) or an assembly file: a dict with "lambda" (a_H / g at collapse),
    "status", "mechanism" (per block vx, vy, omega; per interface hinge / sliding / separating /
    closed), "thrust" (per joint: forces, centre of pressure) and, with min_thickness=True (arch),
    "min_thickness_ratio". direction=-1 loads towards +x."""
    if file is not None:
        options["file"] = os.fspath(file)
    return json.loads(_core.limit_analysis(_options(options)))

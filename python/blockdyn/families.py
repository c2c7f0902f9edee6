# SPDX-License-Identifier: Apache-2.0
"""The registered model families."""
from . import _core


def families():
    """The registered model families, the default first: a list of dicts with "name",
    "description" and what each takes part in ("scenario", "rigid_ground", "sweep", "forced",
    "free_lyapunov")."""
    return _core.families()


def _family(name):
    """The family registered under `name` (None: the default); ValueError naming the choices."""
    fams = _core.families()
    if name is None:
        return fams[0]
    for f in fams:
        if f["name"] == name:
            return f
    raise ValueError(f"model = {name!r} is not one of: " + ", ".join(f["name"] for f in fams))

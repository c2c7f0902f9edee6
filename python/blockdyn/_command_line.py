# SPDX-License-Identifier: Apache-2.0
"""The command line in this process: `blockdyn.run('simulate', '--model', ...)`."""
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

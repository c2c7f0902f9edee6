# SPDX-License-Identifier: Apache-2.0
"""Python values to the library's options and the library's columns to NumPy arrays."""
import numpy as np


def _number(v):
    return repr(float(v)) if isinstance(v, float) else str(v)


def _is_samples(value):
    return isinstance(value, (tuple, list)) and len(value) == 2 and not isinstance(value[0], (str, bytes))


def _threads(value, name="threads"):
    """A thread count as the command line takes it: an integer in [0, 1024] (0: all cores);
    ValueError naming the field otherwise."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise ValueError(f"{name} = {value!r} is not an integer")
    if not 0 <= value <= 1024:
        raise ValueError(f"{name} = {value} is out of range: must be in [0, 1024] (0: all cores)")
    return int(value)


def _record_samples(name, value):
    """(t, a) as 1-D float lists; ValueError naming the option for anything else (a 2-D array is
    not flattened)."""
    out = []
    for what, v in zip(("times", "accelerations"), value):
        try:
            arr = np.asarray(v, dtype=float)
        except (TypeError, ValueError) as e:
            raise ValueError(f"--{name}: the record's {what} are not numbers ({e})") from None
        if arr.ndim != 1:
            raise ValueError(f"--{name}: the record's {what} must be a 1-D array, not of shape {arr.shape}")
        out.append(arr.tolist())
    return tuple(out)


def _options(options):
    """The keyword options as the library's (name, value) list: numbers written exactly (repr),
    a record given as (t, a) arrays passed as samples."""
    out = []
    for key, value in options.items():
        if not isinstance(key, str):
            raise ValueError(f"option names are strings: {key!r} is not")
        if value is None or value is False:
            continue
        name = key.replace("_", "-")
        if name == "threads":
            value = _threads(value)
        if (name == "record" or name.endswith("-record")) and _is_samples(value):
            out.append((name, _record_samples(name, value)))
        elif value is True:
            out.append((name, "true"))
        elif isinstance(value, (list, tuple)):
            out += [(name, _number(v)) for v in value]
        else:
            out.append((name, _number(value)))
    return out


def _columns(cols):
    """Text columns as object arrays; a text column with every cell empty reads as NaN numbers, as
    from the CSV."""
    if not any(isinstance(col, list) for col in cols.values()):
        return cols  # the module's arrays (text as object arrays) as they are
    data = {}
    for name, col in cols.items():
        if isinstance(col, list):
            data[name] = (np.full(len(col), np.nan) if all(c == "" for c in col)
                          else np.array(col, dtype=object))
        else:
            data[name] = col
    return data

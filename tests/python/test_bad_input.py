# SPDX-License-Identifier: Apache-2.0
"""Bad input from Python is a ValueError naming the field, as the command line's exit 2 is: records
as arrays of the wrong shape, thread counts out of range or not integers, option names that are not
strings, a command that does not exist."""
import numpy as np
import pytest

import blockdyn

HOUSNER = {"model": "housner", "width": 0.3, "height": 1.5, "w0": 0.1, "t_end": 0.2}


@pytest.mark.parametrize("call, words", [
    (lambda: blockdyn.run("nonexistent"), "'nonexistent' is not a blockdyn command"),
    (lambda: blockdyn.simulate_many([HOUSNER], threads=-1), "threads = -1 is out of range"),
    (lambda: blockdyn.simulate_many([HOUSNER], threads=10**30), "threads = 1000000000000000000000000000000"),
    (lambda: blockdyn.simulate_many([HOUSNER], threads=1.5), "threads = 1.5 is not an integer"),
    (lambda: blockdyn.simulate_many([{1: 2}]), "option names are strings"),
    (lambda: blockdyn.simulate_many(["housner"]), "each run is a dict"),
    (lambda: blockdyn.simulate(**HOUSNER, ground_h_record=(np.zeros((2, 3)), np.zeros((2, 3)))),
     "--ground-h-record: the record's times must be a 1-D array"),
    (lambda: blockdyn.motion_info((np.linspace(0, 1, 11).reshape(11, 1), np.zeros(11))),
     "--record: the record's times must be a 1-D array, not of shape (11, 1)"),
    (lambda: blockdyn.motion_info((np.linspace(0, 1, 11), np.zeros((11, 2)))), "accelerations must be a 1-D array"),
    (lambda: blockdyn.spectrum(model="housner", width=0.3, height=1.5, durations=[0.5], threads=-2),
     "threads = -2"),
])
def test_bad_input_is_a_value_error_naming_the_field(call, words):
    with pytest.raises(ValueError) as e:
        call()
    assert words in str(e.value)


def test_threads_zero_means_every_core_and_gives_the_serial_result():
    runs = [dict(HOUSNER, w0=0.05 + 0.01 * k) for k in range(4)]
    a = blockdyn.simulate_many(runs, threads=0)
    b = blockdyn.simulate_many(runs, threads=1)
    for x, y in zip(a, b):
        assert np.array_equal(x.data["w"], y.data["w"])

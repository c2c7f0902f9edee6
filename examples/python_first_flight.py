#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The thesis's Fig. 4.6 family from Python: time to first flight versus the foundation stiffness
k for a slender block (r = 0.1, mu = 0.2) released from half its overturning angle (ic1), one
run per k stopped at the first take-off, coloured by ihor (passages through w = 0 before flight).

    PYTHONPATH=build/python /usr/bin/python3 examples/python_first_flight.py out/first_flight.png

Runs in about 10 s on 2 cores (120 points). The same as
`blockdyn flight-time --ic ic1 --r 0.1 --mu 0.2 --k-min 1e2 --k-max 1e9 --points 120`.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import blockdyn  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "first_flight.png"
s = blockdyn.sweep(k="1e2:1e9:120", r=0.1, mu=0.2, ic="ic1", w0_over_alpha=0.5,
                   stop_at_first_flight=True, t_end=30)
k, t, ihor = s["k"], s["first_flight_time"], s["ihor_at_first_flight"]
flew = ~np.isnan(t)
over = s["status"] == "overturned"
fig, ax = plt.subplots(figsize=(8, 5), constrained_layout=True)
sc = ax.scatter(k[flew], t[flew], c=ihor[flew], cmap="viridis", s=18, label="first flight")
ax.scatter(k[~flew & ~over], np.full((~flew & ~over).sum(), 30.0), marker="x", c="0.5", s=14,
           label="no flight by t = 30")
ax.scatter(k[over], np.full(over.sum(), 30.0), marker="v", c="C3", s=14, label="overturned, no flight")
ax.set_xscale("log")
ax.set_xlabel("k = k_phys a b / (m g)")
ax.set_ylabel("time to first flight (units of sqrt(a/g))")
ax.set_title("time to first flight, r = 0.1, mu = 0.2, ic1 (thesis Fig. 4.6 family), from Python")
fig.colorbar(sc, label="ihor at first flight")
ax.legend(fontsize=8, loc="upper right")
fig.savefig(out, dpi=110)
print(f"wrote {out}: {flew.sum()} of {len(k)} runs fly; lowest k with flight {k[flew].min():.4g}")

#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The thesis's code checks (section 3.3, Figs 3.2-3.11), computed with the blockdyn program.

usage: fig_convergence.py BLOCKDYN OUTDIR [--tiny]

Writes into OUTDIR (PNG + SVG each):
  conv_test1.png            Figs 3.2-3.5: ic1, r = 0.2, mu = 0.2, k = 1e3, 1e4, 1e6, 1e8 (one column
                            each): x - x0, y, w, w' of the Winkler block (R-E) and of the rigid block
                            on rigid ground (R-R, `--model rigid`), up to the first w = 0
  conv_test2.png            Figs 3.6-3.7: ic1 with w0 = 0.8, r = 2, mu = 0.3, k = 1e4, 1e8
  conv_forces_fig3_8.png    Fig 3.8: reactions Rx, Ry of the second test, k = 1e7, 1e8, 1e9
  conv_forces_fig3_9.png    Fig 3.9: the same for k = 1e4, 1e6, 1e8
  vertical_oscillation_mu0.2.png, vertical_oscillation_mu0.png
                            Figs 3.10-3.11: the upright block bouncing (r = 0.5, k = 1e5), every
                            integration step plotted, against the closed form
and prints a JSON summary of the comparisons (the numbers quoted in docs/validation.md).
--tiny: two k values and short windows (for the test that the script runs).
"""
import math
import os
import sys
import tempfile

from plotkit import figure_script_args, legend_outside, np, plt, read_table, save

RE_STYLE = dict(color="C0", lw=1.0)
RR_STYLE = dict(color="k", lw=1.0, ls="--")


class Runs:
    """The R-E (Winkler) and R-R (rigid, `--model rigid` with height 1, g = 1, mass 1: the
    non-dimensional units of the Winkler model) runs of one check, cut at their first w = 0."""

    def __init__(self, cli, tmp):
        self.cli, self.tmp, self.n = cli, tmp, 0

    def _run(self, args, interval, t_end):
        self.n += 1
        path = os.path.join(self.tmp, f"run{self.n}.csv")
        summary = self.cli.json("simulate", *args, "--t-end", t_end, "--trajectory", path,
                                "--output-interval", interval, "--json")
        return read_table(path), summary

    def winkler(self, r, mu, k, w0, interval, t_end):
        args = ["--r", r, "--mu", mu, "--k", k, "--ic", "ic1"] + (["--w0", w0] if w0 is not None else [])
        tr, s = self._run(args, interval, t_end)
        t_stop = next((e["t"] for e in s["events"] if e["kind"] == "w_zero"), t_end)
        return cut(tr, t_stop), s, t_stop

    def rigid(self, r, mu, w0, interval, t_end):
        args = ["--model", "rigid", "--width", r, "--height", 1, "--g", 1, "--mass", 1,
                "--mu-s", mu, "--mu-k", mu, "--w0", w0]
        tr, s = self._run(args, interval, t_end)
        t_stop = next((e["t"] for e in s["events"] if e["kind"] == "impact"), t_end)
        tr = cut(tr, t_stop)
        tr["Rx"] = tr["T_A"] + tr["T_B"]
        tr["Ry"] = tr["N_A"] + tr["N_B"]
        return tr, s, t_stop


def cut(tr, t_stop):
    """The rows up to the first one at t_stop (an impact adds rows after it at the same time)."""
    n = int(np.searchsorted(tr["t"], t_stop * (1 - 1e-13))) + 1
    return {k: v[:n] for k, v in tr.items()}


def slide_times(events, kinds):
    return [e["t"] for e in events if e["kind"] in kinds]


def test_figure(runs, out, title, r, mu, w0, ks, interval):
    """x - x0, y, w, w' of R-E (one column per k) with R-R overlaid; returns the comparison."""
    w0_rr = w0 if w0 is not None else 0.5 * math.atan(r)
    rr, rr_sum, rr_stop = runs.rigid(r, mu, w0_rr, interval, 6)
    rr_slide = slide_times(rr_sum["events"], ("mode",))
    fig, ax = plt.subplots(4, len(ks), figsize=(3.2 * len(ks) + 1.6, 8.5), sharex="col", squeeze=False,
                           constrained_layout=True)
    rows = []
    for j, k in enumerate(ks):
        re, re_sum, re_stop = runs.winkler(r, mu, k, w0, interval, 6)
        both = re["t"] <= min(re_stop, rr_stop)  # R-R interpolated onto the R-E output instants
        dw = float(np.max(np.abs(re["w"][both] - np.interp(re["t"][both], rr["t"], rr["w"]))))
        dx = float(np.max(np.abs(re["x"][both] - re["x"][0]
                                 - np.interp(re["t"][both], rr["t"], rr["x"] - rr["x"][0]))))
        re_slide = [t for t in slide_times(re_sum["events"], ("contact_to_slide", "slide_reversal")) if t < re_stop]
        rows.append(dict(k=k, t_w0_re=re_stop, t_w0_rr=rr_stop, max_dw=dw, max_dx=dx,
                         slide_events_re=re_slide[:2], slide_events_rr=rr_slide[:2]))
        for i, (name, label) in enumerate((("x", "x - x0"), ("y", "y"), ("w", "w"), ("vw", "w'"))):
            a = ax[i, j]
            base_re = re["x"][0] if name == "x" else 0.0
            base_rr = rr["x"][0] if name == "x" else 0.0
            a.plot(re["t"], re[name] - base_re, label="R-E (Winkler)", **RE_STYLE)
            a.plot(rr["t"], rr[name] - base_rr, label="R-R (rigid ground)", **RR_STYLE)
            if j == 0:
                a.set_ylabel(label)
            a.grid(True, lw=0.3)
        ax[0, j].set_title(f"k = {k:.0e}\nmax|dw| = {dw:.1e}, w = 0 at {re_stop:.4f} / {rr_stop:.4f}",
                           fontsize=8)
        ax[-1, j].set_xlabel("t")
    legend_outside(ax[0, -1])
    fig.suptitle(title, fontsize=10)
    save(fig, out)
    return rows


def forces_figure(runs, out, title, ks, interval):
    """Rx, Ry of the second test (R-E per k, R-R dashed), the full run and a zoom from just before
    the slip reversal s_r to the end shown; the oscillation amplitude is half the peak-to-peak
    range of Ry(R-E) - Ry(R-R) over [s_r, end]."""
    r, mu, w0 = 2.0, 0.3, 0.8
    rr, rr_sum, rr_stop = runs.rigid(r, mu, w0, interval, 6)
    s_rr = slide_times(rr_sum["events"], ("mode",))
    # This wide block lands on its other corner at w = 0: the R-E reaction rises steeply just
    # before (that corner enters the springs). The forces are shown up to shortly before it.
    t_show = rr_stop - 0.01
    fig, ax = plt.subplots(3, len(ks), figsize=(3.4 * len(ks) + 1.6, 7.5), squeeze=False,
                           constrained_layout=True)
    rows = []
    for j, k in enumerate(ks):
        re, re_sum, _ = runs.winkler(r, mu, k, w0, interval, 6)
        re = cut(re, t_show)
        rev = slide_times(re_sum["events"], ("slide_reversal",))
        s_r = rev[0] if rev else s_rr[-1]
        after = re["t"] > s_r
        diff = re["Ry"][after] - np.interp(re["t"][after], rr["t"], rr["Ry"])
        amp = float(0.5 * (diff.max() - diff.min())) if after.any() else float("nan")
        rows.append(dict(k=k, s_r=s_r, ry_oscillation_amplitude=amp, window=[s_r, t_show]))
        for i, name in enumerate(("Rx", "Ry")):
            a = ax[i, j]
            a.plot(re["t"], re[name], label="R-E (Winkler)", rasterized=True, **RE_STYLE)
            a.plot(rr["t"][rr["t"] <= t_show], rr[name][rr["t"] <= t_show], label="R-R (rigid ground)",
                   **RR_STYLE)
            a.axvline(s_r, color="C3", lw=0.6, ls=":")
            a.set_ylabel(name if j == 0 else "")
            a.grid(True, lw=0.3)
        win = re["t"] > s_r - 0.01
        ax[2, j].plot(re["t"][win], re["Ry"][win], rasterized=True, **RE_STYLE)
        win_rr = (rr["t"] > s_r - 0.01) & (rr["t"] <= t_show)
        ax[2, j].plot(rr["t"][win_rr], rr["Ry"][win_rr], **RR_STYLE)
        ax[2, j].axvline(s_r, color="C3", lw=0.6, ls=":", label="slip reversal s_r")
        ax[2, j].set_xlabel("t")
        ax[2, j].grid(True, lw=0.3)
        if j == 0:
            ax[2, j].set_ylabel("Ry near s_r")
        ax[0, j].set_title(f"k = {k:.0e}: s_r = {s_r:.6f}\nRy oscillation after s_r: amplitude {amp:.3f}",
                           fontsize=8)
    legend_outside(ax[0, -1])
    legend_outside(ax[2, -1])
    fig.suptitle(title, fontsize=10)
    save(fig, out)
    return rows


def bounce_exact(t, k):
    """Closed form of the upright block released from h = y - 1/2 = -3/k at rest (thesis sec. 3.3):
    (h, h') with contact while h < 0 (h + 1/k = -(2/k) cos(sqrt(k) t)) and free flight above."""
    sk = math.sqrt(k)
    v = math.sqrt(3.0 / k)
    tc = 4.0 * math.pi / (3.0 * sk)  # one contact phase, landing to take-off
    period = tc + 2.0 * v
    s = np.mod(t + 2.0 * math.pi / (3.0 * sk), period)
    contact = s < tc
    th = sk * s - 2.0 * math.pi / 3.0
    tau = s - tc
    h = np.where(contact, -(1.0 + 2.0 * np.cos(th)) / k, v * tau - 0.5 * tau * tau)
    dh = np.where(contact, 2.0 * np.sin(th) / sk, v - tau)
    return h, dh


def vertical_figure(cli, tmp, out, mu, t_end):
    r, k = 0.5, 1e5
    path = os.path.join(tmp, f"bounce_{mu}.csv")
    s = cli.json("simulate", "--r", r, "--mu", mu, "--k", k, "--ic", "custom", "--x0", r / 2, "--w0", 0,
                 "--y0", 0.5 - 3.0 / k, "--t-end", t_end, "--trajectory", path, "--output-interval", 0,
                 "--json")
    tr = read_table(path)
    t = tr["t"]
    h_ex, dh_ex = bounce_exact(t, k)
    tf = np.linspace(0, t_end, 4000)
    hf, dhf = bounce_exact(tf, k)
    dev = float(np.max(np.abs(tr["y"] - 0.5 - h_ex)))
    wmax = float(max(np.max(np.abs(tr["w"])), np.max(np.abs(tr["vw"]))))
    ev = [e for e in s["events"] if e["kind"] in ("takeoff", "landing")]
    fig, ax = plt.subplots(3, 1, figsize=(8.5, 7.5), sharex=True, constrained_layout=True,
                           gridspec_kw=dict(height_ratios=[1, 2.5, 2.5]))
    mode = np.array([0 if m == "flight" else 1 for m in tr["mode"]])
    ax[0].step(t, mode, where="post", color="k", lw=0.8)
    on_springs = "/".join(sorted({m for m in tr["mode"] if m != "flight"}))
    ax[0].set_yticks([0, 1], ["flight", on_springs])
    ax[0].set_ylim(-0.3, 1.3)
    ax[0].set_ylabel("mode")
    ax[1].plot(tf, hf, color="0.6", lw=1.0, label="closed form")
    ax[1].plot(t, tr["y"] - 0.5, "x", color="C0", ms=3.5, label="blockdyn, one mark per step")
    te = [e["t"] for e in ev]
    ax[1].plot(te, [e["state"]["y"] - 0.5 for e in ev], "o", mfc="none", color="C3", ms=6,
               label="take-off / landing (events)")
    ax[1].set_ylabel("y - 1/2")
    ax[2].plot(tf, dhf, color="0.6", lw=1.0)
    ax[2].plot(t, tr["vy"], "x", color="C0", ms=3.5)
    ax[2].set_ylabel("y'")
    ax[2].set_xlabel("t")
    for a in ax:
        a.grid(True, lw=0.3)
    legend_outside(ax[1])
    fig.suptitle(f"Vertical oscillation (thesis Fig {'3.10' if mu > 0 else '3.11'}): r = {r}, k = {k:.0e}, "
                 f"mu = {mu}, y0 = 1/2 - 3/k\n{len(t)} output points (every step), max |y - exact| = {dev:.1e}, "
                 f"max(|w|, |w'|) = {wmax:.1e}, {len(ev)} take-offs/landings", fontsize=9)
    save(fig, out)
    return dict(mu=mu, steps=int(s["steps"]), max_dev_y=dev, max_abs_w_or_vw=wmax, events=len(ev))


def main(argv):
    cli, out, tiny = figure_script_args(argv, __doc__)
    summary = {}
    with tempfile.TemporaryDirectory(prefix="blockdyn-conv-") as tmp:
        runs = Runs(cli, tmp)
        ks1 = [1e3, 1e8] if tiny else [1e3, 1e4, 1e6, 1e8]
        summary["test1"] = test_figure(
            runs, os.path.join(out, "conv_test1.png"),
            "R-E vs R-R, first test (thesis Figs 3.2-3.5): ic1 (w0 = alpha/2), r = 0.2, mu = 0.2, up to w = 0",
            0.2, 0.2, None, ks1, 0.002)
        ks2 = [1e4] if tiny else [1e4, 1e8]
        summary["test2"] = test_figure(
            runs, os.path.join(out, "conv_test2.png"),
            "R-E vs R-R, second test (thesis Figs 3.6-3.7): ic1 with w0 = 0.8, r = 2, mu = 0.3, up to w = 0",
            2.0, 0.3, 0.8, ks2, 0.002)
        fine = 1e-3 if tiny else 2e-5
        summary["forces_3_8"] = forces_figure(
            runs, os.path.join(out, "conv_forces_fig3_8.png"),
            "Reactions, second test (thesis Fig 3.8): r = 2, mu = 0.3, w0 = 0.8", [1e7] if tiny else [1e7, 1e8, 1e9],
            fine)
        summary["forces_3_9"] = forces_figure(
            runs, os.path.join(out, "conv_forces_fig3_9.png"),
            "Reactions, second test (thesis Fig 3.9): r = 2, mu = 0.3, w0 = 0.8", [1e4] if tiny else [1e4, 1e6, 1e8],
            fine)
        t_end = 0.05 if tiny else 0.2
        summary["vertical"] = [vertical_figure(cli, tmp, os.path.join(out, f"vertical_oscillation_mu{mu}.png"),
                                               mu, t_end) for mu in (0.2, 0)]
    print(cli.summary("fig-convergence", "checks", summary))


if __name__ == "__main__":
    main(sys.argv)

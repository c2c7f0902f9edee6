# SPDX-License-Identifier: Apache-2.0
"""Independent SciPy reference for the block on a Winkler foundation (issue 10).

Same model, initial conditions (ic1, ic2), modes and events as blockdyn's winkler model
(docs: /work/shared/spec/winkler-block-model.md), written from the spec with SciPy's DOP853
and a restart at every mode switch.

State (9): x, h = y - 1/2, w, x', y', w', work of friction, work of the non-potential torque,
work of the ground (always 0 here). In contact x and x' are not integrated (derivatives 0);
they follow from w and the pivot abscissa at every segment end, as in blockdyn. Tolerances:
rtol for all, atol * (1, min(1,1/k), 1, 1, min(1,1/sqrt(k)), 1, 1, 1, 1) as blockdyn's
abs_tol_scale.

Counted: "steps" = accepted DOP853 steps summed over the segments (the step that straddles an
event counts, truncated at the event, as in blockdyn); "nfev" = SciPy's right-hand-side
evaluations (event-state recomputations included); "wall_s", "cpu_s" = wall and CPU time of the
integration loop.

Event location (--driver): "sampled" (default) steps scipy.integrate.DOP853 directly and checks
every event function at 4 points per step plus dips (segment_sampled); "solve_ivp" uses
solve_ivp(method='DOP853', events=..., terminal), which compares signs at step ends only and so
misses a brief flight inside one step (segment_solve_ivp). Both recompute the event state by a
fresh integration from the last step start (the straddling step's interpolant is least accurate
there). An event function <= 0 at a restart is ignored until it is positive; 16 zero-duration
events in a row trigger a grazing hold (contact, or slide when the stick margin is falling below
zero), as the spec asks.

Usage: /usr/bin/python3 bench/scipy_reference.py --r 1 --k 1e6 --mu 0.2 --ic ic1 --t-end 30
       [--rtol 1e-10] [--atol 1e-12] [--state x,y,w,vx,vy,vw] [--driver sampled|solve_ivp]
       [--states] [--json-out F]
"""
import argparse
import json
import math
import sys
import time
from collections import Counter

import numpy as np
from scipy.integrate import DOP853, solve_ivp
from scipy.optimize import brentq, minimize_scalar

CONTACT, SLIDE, FLIGHT = "contact", "slide", "flight"
EV_OVERTURN, EV_INVALID, EV_SURFACE, EV_WZERO, EV_FRICTION = range(5)
CHATTER_LIMIT = 16


def sgn(v):
    return int(v > 0) - int(v < 0)


class Winkler:
    def __init__(self, r, k, mu):
        self.r, self.k, self.mu = r, k, mu
        self.inertia = (1.0 + r * r) / 12.0
        self.alpha = math.atan(r)

    # ---- geometry -------------------------------------------------------------------------
    def corners(self, h, w):
        """Heights above the surface of the lowest, other bottom and pivot-side upper corners."""
        s = math.sin(abs(w))
        c = math.cos(w)
        omc = s * s / (1.0 + c)  # 1 - cos w without cancellation
        rs = self.r * s
        return (h + 0.5 * (omc - rs), h + 0.5 * (omc + rs), h + 0.5 * (2.0 - omc - rs)), s, c

    def region(self, h, w):
        """Area, moment about the centre (signed with w), integral of s^2, and the end depths."""
        (y_low, y_oth, y_up), s, c = self.corners(h, w)
        r = self.r
        # envelope for |w|: upper pivot-side corner -> lowest corner -> other bottom corner
        pts = ((-0.5 * (r * c + s), -y_up), (-0.5 * (r * c - s), -y_low), (0.5 * (r * c + s), -y_oth))
        area = mom = sq = 0.0
        for (a, da), (b, db) in zip(pts[:-1], pts[1:]):
            if da <= 0.0 and db <= 0.0:
                continue
            if da < 0.0:
                a, da = a + (b - a) * da / (da - db), 0.0
            elif db < 0.0:
                b, db = a + (b - a) * da / (da - db), 0.0
            L = b - a
            area += 0.5 * L * (da + db)
            mom += L / 6.0 * ((2.0 * a + b) * da + (a + 2.0 * b) * db)
            sq += L / 3.0 * (da * da + da * db + db * db)
        if w < 0.0:
            mom = -mom
        return area, mom, sq, max(0.0, -y_oth), max(0.0, -y_up)

    def arms(self, w, side):
        """A, B of the corner on `side` (+1 lower-left, -1 lower-right)."""
        s, c = math.sin(w), math.cos(w)
        return 0.5 * (self.r * c - side * s), 0.5 * (c + side * self.r * s)

    # ---- forces and right-hand side ----------------------------------------------------------
    def forces(self, mode, z):
        """(Ry, Rx, x'', w'', torque_nonpot, margin, v_corner)."""
        regime, side, fsign, _ = mode
        A, B = self.arms(z[2], side)
        vw = z[5]
        if regime == FLIGHT:
            return 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, z[3] + B * vw
        area, mom, _, far, piv = self.region(z[1], z[2])
        kr = self.k / self.r
        Ry, T = kr * area, kr * mom
        tnp = sgn(z[2]) * kr / 6.0 * (far ** 3 - piv ** 3)
        if regime == CONTACT:
            ww = (T - side * A * B * vw * vw) / (self.inertia + B * B)
            Rx = -B * ww - side * A * vw * vw
            return Ry, Rx, Rx, ww, tnp, self.mu * Ry - abs(Rx), 0.0
        Rx = fsign * self.mu * Ry
        return Ry, Rx, Rx, (T + B * Rx) / self.inertia, tnp, 1.0, z[3] + B * vw

    def rhs(self, mode, z):
        Ry, Rx, ax, ww, tnp, _, vp = self.forces(mode, z)
        ay = Ry - 1.0
        if mode[0] == CONTACT:
            return [0.0, z[4], z[5], 0.0, ay, ww, 0.0, tnp * z[5], 0.0]
        return [z[3], z[4], z[5], ax, ay, ww, Rx * vp, tnp * z[5], 0.0]

    def complete(self, mode, z):
        if mode[0] == CONTACT:
            A, B = self.arms(z[2], mode[1])
            z[0] = mode[3] + mode[1] * A
            z[3] = -B * z[5]
        return z

    def events(self, mode, z):
        regime, side, fsign, _ = mode
        (y_low, y_oth, y_up), _, _ = self.corners(z[1], z[2])
        g = [self.alpha - side * z[2], max(y_oth, y_up),
             y_low if regime == FLIGHT else -y_low, side * z[2], 1.0]
        if regime == CONTACT:
            g[4] = self.forces(mode, z)[5]
        elif regime == SLIDE and self.mu > 0.0:
            g[4] = -fsign * (z[3] + self.arms(z[2], side)[1] * z[5])
        return g

    # ---- modes ------------------------------------------------------------------------------
    def stick_or_slip(self, z, side, slip_sign):
        A, _ = self.arms(z[2], side)
        c = (CONTACT, side, 0, z[0] - side * A)
        f = self.forces(c, self.complete(c, list(z)))
        if f[5] >= 0.0:
            return c
        return (SLIDE, side, slip_sign if slip_sign else sgn(f[1]), 0.0)

    def submerged(self, z, side):
        if self.mu == 0.0:
            return (SLIDE, side, 0, 0.0)
        vp = z[3] + self.arms(z[2], side)[1] * z[5]
        if vp != 0.0:
            return (SLIDE, side, -sgn(vp), 0.0)
        return self.stick_or_slip(z, side, 0)

    def initial_mode(self, z):
        side = sgn(z[2]) or sgn(z[5])
        airborne = self.corners(z[1], z[2])[0][0] > 0.0
        if side == 0:
            probe = (FLIGHT, 1, 0, 0.0) if airborne else self.submerged(z, 1)
            side = sgn(self.rhs(probe, self.complete(probe, list(z)))[5]) or 1
        return (FLIGHT, side, 0, 0.0) if airborne else self.submerged(z, side)

    def transition(self, mode, z, ev):
        """(next mode, kind, stop)."""
        regime, side, fsign, _ = mode
        if ev == EV_OVERTURN:
            return mode, "overturn", True
        if ev == EV_INVALID:
            return mode, "invalid", True
        if ev == EV_SURFACE:
            if regime == FLIGHT:
                return self.submerged(z, side), "landing", False
            return (FLIGHT, side, 0, 0.0), "takeoff", False
        if ev == EV_WZERO:
            if regime == CONTACT:
                return self.stick_or_slip(z, -side, 0), "w_zero", False
            return (regime, -side, fsign, mode[3]), "w_zero", False
        if regime == CONTACT:  # friction
            return (SLIDE, side, sgn(self.forces(mode, z)[1]), 0.0), "contact_to_slide", False
        nxt = self.stick_or_slip(z, side, -fsign)
        return nxt, ("slide_to_contact" if nxt[0] == CONTACT else "slide_reversal"), False

    def step_hint(self, mode):
        return 0.05 if mode[0] == FLIGHT else 0.5 / math.sqrt(max(1.0, self.k))

    def probe(self, mode, z, frac=1e-6):
        """The state a tiny explicit step later (for the slope of an event function)."""
        dt = frac * self.step_hint(mode)
        dz = self.rhs(mode, z)
        return self.complete(mode, [zi + dt * di for zi, di in zip(z, dz)])

    def grazing_hold(self, mode, z):
        """Grazing stop: hold the corner, unless the stick margin is falling below zero."""
        side = mode[1]
        c = (CONTACT, side, 0, z[0] - side * self.arms(z[2], side)[0])
        zc = self.complete(c, list(z))
        f0 = self.forces(c, zc)
        if self.mu > 0.0:
            m1 = self.forces(c, self.probe(c, zc))[5]
            if m1 < 0.0 and m1 < f0[5] and f0[1] != 0.0:
                return (SLIDE, side, sgn(f0[1]), 0.0), "contact_to_slide"
        return c, "grazing_hold"

    # ---- initial conditions -------------------------------------------------------------------
    def rigid_rest_reaction(self, w):
        A, B = self.arms(w, 1)
        I = self.inertia
        aw = -A / (I + A * A + B * B)
        Rx, Ry = -B * aw, 1.0 + A * aw
        if self.mu > 0.0 and self.mu * Ry - abs(Rx) >= 0.0:
            return Ry
        c = sgn(Rx) * self.mu * B - A
        return 1.0 + A * c / (I - A * c)

    def rest_height(self, w, Ry):
        a = abs(w)
        low0 = self.corners(0.0, a)[0][0]
        d = math.sqrt(2.0 * self.r * math.sin(a) * math.cos(a) * Ry / self.k)
        h1 = -low0 - d
        ch = self.corners(h1, a)[0]
        if ch[1] >= 0.0 and ch[2] >= 0.0:
            return h1
        f = lambda h: self.k / self.r * self.region(h, a)[0] - Ry
        hi, lo = -low0, -low0 - 1.0 / self.k
        while f(lo) < 0.0:
            lo = hi - 2.0 * (hi - lo)
        return brentq(f, lo, hi, xtol=1e-300, rtol=4 * np.finfo(float).eps)

    def ic(self, name, w0=None):
        z = [0.0] * 9
        if name == "ic1":
            w0 = 0.5 * self.alpha if w0 is None else w0
            z[2] = w0
            z[1] = self.rest_height(w0, self.rigid_rest_reaction(abs(w0)))
            A = self.arms(abs(w0), 1)[0]
            z[0] = A if w0 > 0 else -A
        else:
            z[1] = -1.0 / self.k
            z[0] = self.r / 2.0
            z[3] = 0.06
            z[4] = 0.0001
            z[5] = 6.0 * z[3] / (1.0 + self.r * self.r)
        return z


class Segment:
    """Result of integrating one mode until its first event or t_end."""
    def __init__(self, t, z, event=None, steps=0, nfev=0, h_last=None, failure=None):
        self.t, self.z, self.event, self.steps, self.nfev = t, z, event, steps, nfev
        self.h_last, self.failure = h_last, failure


def _fresh_to(model, mode, t0, y0, te, rtol, atol_v, hint):
    """State at te by a fresh integration from a step start (not the straddling interpolant)."""
    if te <= t0:
        return np.asarray(y0, dtype=float).tolist(), 0
    s = solve_ivp(lambda tt, y: model.rhs(mode, y.tolist()), (t0, te), np.asarray(y0),
                  method="DOP853", rtol=rtol, atol=atol_v, first_step=min(te - t0, hint))
    return s.y[:, -1].tolist(), s.nfev


def segment_sampled(model, mode, t, z, t_end, rtol, atol_v, first, g0, hold=False):
    """DOP853 steps; each event function is checked at the step end and at 3 interior points
    (cubic Hermite from the step's end values and slopes) and, when falling into the step end,
    just before it; a negative sample or a local minimum of the samples near zero is resolved on the step's DOP853 dense output (brentq; a dip by a
    bounded minimisation). An event function <= 0 at the restart is ignored until it is
    positive (halving towards t finds a brief rise), else it fires at t (zero duration); after a
    grazing hold (hold=True) those functions are only watched again once positive."""
    fun = lambda tt, y: model.rhs(mode, y.tolist())
    st = DOP853(fun, t, np.array(z), t_end, rtol=rtol, atol=atol_v, first_step=first)
    ev = lambda y: model.events(mode, y.tolist())
    n_ev = 5
    armed = [g > 0.0 for g in g0]
    steps, first_step = 0, True
    g_old = g0
    while st.status == "running":
        t0, y0, f0 = st.t, st.y, st.f
        st.step()
        if st.status == "failed":
            return Segment(st.t, st.y.tolist(), steps=steps, nfev=st.nfev, failure="DOP853 step failed")
        steps += 1
        t1, y1, f1 = st.t, st.y, st.f
        h = t1 - t0
        ts = [t0 + h * j / 4.0 for j in range(5)]
        ts[4] = t1

        def hermite(u):  # cubic Hermite interpolant of the step at t0 + u h
            return ((1 + 2 * u) * (1 - u) ** 2 * y0 + u * (1 - u) ** 2 * h * f0
                    + u * u * (3 - 2 * u) * y1 + u * u * (u - 1) * h * f1)

        gs = [g_old] + [ev(hermite(j / 4.0)) for j in (1, 2, 3)] + [ev(y1)]
        end_g = None
        dense = None
        best = None
        for i in range(n_ev):
            col = [g[i] for g in gs]
            if i == EV_FRICTION and col[0] == 1.0 and col[4] == 1.0:
                continue
            lo = None  # bracket [lo, hi] with g(lo) >= 0 > g(hi), or a dip window
            dip = None
            arm = armed[i]
            for j in range(1, 5):
                if not arm and col[j] > 0.0:
                    arm = True
                    continue
                if col[j] < 0.0:
                    if arm:
                        lo = (ts[j - 1], ts[j])
                    elif first_step and j == 1 and not hold:
                        lo = ("halve", ts[1])
                    break
                if arm and j < 4 and col[j] < col[j - 1] and col[j] < col[j + 1] \
                        and col[j] < 100.0 * max(col[j - 1], col[j + 1]) - col[j]:
                    dip = (ts[j - 1], ts[j + 1])
                    break
            if lo is None and dip is None and arm and 0.0 < col[4] < col[3]:
                if end_g is None:  # falling into the step end: is a minimum just before it?
                    end_g = ev(hermite(1.0 - 1e-3 / 4.0))
                if end_g[i] < col[4] and end_g[i] < 100.0 * (col[3] - end_g[i]):
                    dip = (ts[3], t1)
            if lo is None and dip is None:
                continue
            if dense is None:
                dense = st.dense_output()
            gi = lambda tt, i=i: ev(dense(tt))[i]
            root = None
            if lo is not None and lo[0] == "halve":
                a = t0
                for kk in range(1, 60):
                    tt = t0 + math.ldexp(ts[1] - t0, -kk)
                    if tt <= t0:
                        break
                    if gi(tt) > 0.0:
                        a = tt
                        break
                root = t0 if a == t0 else _root(gi, a, ts[1])
            elif lo is not None:
                root = _root(gi, lo[0], lo[1])
            else:
                a = dip[0]
                res = minimize_scalar(gi, bounds=(a, dip[1]), method="bounded",
                                      options={"xatol": 1e-14 * max(1.0, abs(t1))})
                if res.fun < 0.0 and gi(a) >= 0.0:
                    root = _root(gi, a, res.x)
            if root is not None and (best is None or root < best[0]):
                best = (root, i)
        if best is not None:
            te, i = best
            z_ev, nf = _fresh_to(model, mode, t0, y0, te, rtol, atol_v, model.step_hint(mode))
            return Segment(te, model.complete(mode, z_ev), i, steps, st.nfev + nf, h)
        for i in range(n_ev):
            armed[i] = armed[i] or any(g[i] > 0.0 for g in gs[1:])
        g_old, first_step = gs[4], False
    return Segment(st.t, model.complete(mode, st.y.tolist()), None, steps, st.nfev, None)


def _root(g, a, b):
    """Root of g on [a, b] with g(a) >= 0 > g(b); the last time g was not yet negative."""
    ga, gb = g(a), g(b)
    if ga <= 0.0:
        return a
    if gb >= 0.0:
        return None
    return brentq(g, a, b, xtol=1e-15 * max(1.0, abs(b)), rtol=4 * np.finfo(float).eps)


def segment_solve_ivp(model, mode, t, z, t_end, rtol, atol_v, first, g0, hold=False):
    """solve_ivp(DOP853) with terminal events (direction -1): signs are compared at step ends
    only, and an event function <= 0 at the restart is ignored until it is positive."""
    funcs, cache = [], [None, None]

    def g_all(tt, y):
        key = (tt, y[1], y[2], y[3], y[5])
        if cache[0] != key:
            cache[0], cache[1] = key, model.events(mode, y.tolist())
        return cache[1]

    for i in range(5):
        if i == EV_FRICTION and g0[i] == 1.0 and mode[0] != CONTACT:
            continue
        fn = (lambda tt, y, i=i: g_all(tt, y)[i])
        fn.terminal, fn.direction = True, -1
        funcs.append((i, fn))
    sol = solve_ivp(lambda tt, y: model.rhs(mode, y.tolist()), (t, t_end), np.array(z),
                    method="DOP853", rtol=rtol, atol=atol_v, events=[f for _, f in funcs],
                    first_step=first)
    h_last = sol.t[-2] - sol.t[-3] if len(sol.t) >= 3 else None
    if sol.status == -1:
        return Segment(sol.t[-1], sol.y[:, -1].tolist(), failure=sol.message)
    if sol.status == 0:
        return Segment(t_end, model.complete(mode, sol.y[:, -1].tolist()), None, len(sol.t) - 1,
                       sol.nfev, h_last)
    te, j = min((te[0], j) for j, te in enumerate(sol.t_events) if len(te))
    z_ev, nf = _fresh_to(model, mode, sol.t[-2], sol.y[:, -2], te, rtol, atol_v, model.step_hint(mode))
    return Segment(te, model.complete(mode, z_ev), funcs[j][0], len(sol.t) - 1, sol.nfev + nf, h_last)


DRIVERS = {"sampled": segment_sampled, "solve_ivp": segment_solve_ivp}


def simulate(model, z0, t0, t_end, rtol=1e-10, atol=1e-12, mode=None, keep_states=False,
             driver="sampled"):
    """Integrates from (t0, z0) to t_end; returns the result dictionary."""
    k = model.k
    atol_v = atol * np.array([1, min(1.0, 1 / k), 1, 1, min(1.0, 1 / math.sqrt(k)), 1, 1, 1, 1])
    segment = DRIVERS[driver]
    z = list(z0)
    mode = mode or model.initial_mode(z)
    z = model.complete(mode, z)
    ihor = 1 if z[2] == 0.0 else 0
    events, steps, nfev, zero_run = [], 0, 0, 0
    t, h_next = t0, None
    start_mode = mode
    E0 = energy(model, z)
    wall0, cpu0 = time.perf_counter(), time.process_time()
    status = "t_end"

    def record(kind, new_mode):
        e = {"t": t, "kind": kind, "from": mode[0], "to": new_mode[0]}
        if keep_states:  # x, y, w, x', y', w'; energy; energy balance E - E0 - works
            e["state"] = [z[0], z[1] + 0.5] + list(z[2:6])
            e["E"] = energy(model, z)
            e["balance"] = e["E"] - E0 - z[6] - z[7]
        events.append(e)

    while t < t_end:
        g0 = model.events(mode, z)
        hint = model.step_hint(mode)
        first = (t + min(h_next or hint, hint, t_end - t)) - t
        # after a grazing hold the functions at zero are not re-fired at once (hold)
        seg = segment(model, mode, t, z, t_end, rtol, atol_v, first, g0, zero_run < 0)
        steps += seg.steps
        nfev += seg.nfev
        h_next = seg.h_last or h_next
        if seg.failure:
            status = "failure: " + seg.failure
            break
        zero_run = zero_run + 1 if seg.t == t else 0
        t, z = seg.t, seg.z
        if seg.event is None:
            break
        new_mode, kind, stop = model.transition(mode, z, seg.event)
        if kind == "w_zero":
            ihor += 1
        record(kind, new_mode)
        if stop:
            status = kind
            break
        mode = new_mode
        z = model.complete(mode, z)
        if zero_run >= CHATTER_LIMIT:
            new_mode, kind = model.grazing_hold(mode, z)
            record(kind, new_mode)
            mode, zero_run = new_mode, -1
            z = model.complete(mode, z)
    wall, cpu = time.perf_counter() - wall0, time.process_time() - cpu0
    counts = Counter(e["kind"] for e in events)
    first_flight = next((e["t"] for e in events if e["kind"] == "takeoff"), None)
    E = energy(model, z)
    return {"parameters": {"r": model.r, "k": model.k, "mu": model.mu},
            "tolerances": {"method": "scipy DOP853, events: " + driver, "rtol": rtol, "atol": atol},
            "t_start": t0, "t_final": t, "status": status, "initial_mode": start_mode[0],
            "final_mode": mode[0], "final_state": [z[0], z[1] + 0.5] + z[2:6], "final_energy": E,
            "work_friction": z[6], "work_nonpotential": z[7],
            "steps": steps, "nfev": nfev, "wall_s": wall, "cpu_s": cpu, "ihor": ihor,
            "first_flight_time": first_flight, "event_counts": dict(counts), "events": events}


def energy(model, z):
    """Total mechanical energy (zero for the upright block just touching the surface)."""
    sq = model.region(z[1], z[2])[2]
    return (0.5 * (z[3] ** 2 + z[4] ** 2 + model.inertia * z[5] ** 2) + z[1]
            + 0.5 * model.k / model.r * sq)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--r", type=float, default=0.5)
    ap.add_argument("--k", type=float, default=1e5)
    ap.add_argument("--mu", type=float, default=0.2)
    ap.add_argument("--ic", choices=["ic1", "ic2"], default="ic1")
    ap.add_argument("--w0", type=float, help="ic1 release tilt (default alpha/2)")
    ap.add_argument("--state", help="start from x,y,w,vx,vy,vw instead of an ic")
    ap.add_argument("--t0", type=float, default=0.0)
    ap.add_argument("--t-end", type=float, default=10.0)
    ap.add_argument("--rtol", type=float, default=1e-10)
    ap.add_argument("--atol", type=float, default=1e-12)
    ap.add_argument("--driver", choices=sorted(DRIVERS), default="sampled",
                    help="event detection: sampled (4 points per step and dips, default) or "
                    "solve_ivp (solve_ivp's events: signs at step ends only)")
    ap.add_argument("--states", action="store_true", help="include the state at each event")
    ap.add_argument("--json-out", help="write the JSON here (default: stdout)")
    a = ap.parse_args(argv)
    m = Winkler(a.r, a.k, a.mu)
    if a.state:
        s = [float(v) for v in a.state.split(",")]
        z0 = [s[0], s[1] - 0.5, s[2], s[3], s[4], s[5], 0.0, 0.0, 0.0]
    else:
        z0 = m.ic(a.ic, a.w0)
    res = simulate(m, z0, a.t0, a.t_end, a.rtol, a.atol, keep_states=a.states, driver=a.driver)
    res["ic"] = "custom" if a.state else a.ic
    text = json.dumps(res, indent=1)
    if a.json_out:
        with open(a.json_out, "w") as fh:
            fh.write(text + "\n")
    else:
        print(text)


if __name__ == "__main__":
    sys.exit(main())

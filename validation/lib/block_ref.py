"""Reference for a block on a plane with ricochet's TYPE6 normal law and its
incremental (elastic-plastic) friction with the stick damper, written from
docs/theory.md 3.3, 3.5, 5.1 and 7.1; nothing here is read from the engine.

Two coordinates of a block (rotations locked) on a fixed plane: the
penetration p along the inward normal and the displacement x along the
tangential load (the fall line of an incline, the pull on a floor). The
loads are N(t) = m a_n f(t) into the plane and T(t) = m a_t f(t) along x,
f the time function, a table interpolated linearly (as the engine's /FUNCT).

* normal (TYPE6, linear load curve k, Visc c_n): F_n = k p + c_n p',
  m p'' = N(t) - F_n while closed. The contact starts closed (touching at
  zero gap under a load ramped from zero, or penetrating); a release
  (F_n falling through 0) is not modelled and raises.
* friction: F_lim = Sfric + mu F_n. Stick: the applied force is
  F = F_t - c_t x', c_t = 2 sqrt(K_t m) (critical, the plane being fixed),
  dF_t/dt = -K_t x'. Slip: F = F_lim e, e = sign(F_t), dF_t/dt = 0 (the
  radial return in rate form has no component in one dimension).
  m x'' = T(t) + F.
* events: stick -> slip when |F| rises through (1 + 1e-6) F_lim + f_band
  (f_band the absolute tolerance of F_t, 7.1), the state then put on the
  limit along F: F_t := F_lim sign(F); slip -> stick when x' e rises
  through 0, F_t := F_lim e. A sticking state beyond the test at the start
  or after an event slips at once (5.1).

The plastic (slipped) displacement is x_pl = x + F_t/K_t while sticking
(F_t = -K_t (x - x_pl)); at rest under the full load T_end the block sits at
x = x_pl + T_end/K_t.

Two independent solutions: scipy's solve_ivp (Radau or LSODA, event
location on its dense output), and, since the ODE of each mode is linear
with a forcing linear in t on each table segment, the exact flow by the
matrix exponential with the events located by bisection on it
(solve_exact). Their difference is the accuracy of the reference.
Sanity check: under a constant load from the static normal penetration with
f_band = 0 both give the slip onset of the closed form of lib/stick.py
(step_onset, 0.402047789 ms for tan(theta) = 0.5, mu = 0.3) to 1e-18 s.
"""
import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.linalg import expm
from scipy.optimize import brentq

BAND = 1e-6  # RC_SLIP_BAND: stick -> slip at |F| = (1 + BAND) F_lim + f_band


class Block:
    """m [kg], k, cn: normal law; kt: stick stiffness; mu, sfric: limit;
    fband: force band of the slip test [N]; an, at: load accelerations
    [m/s^2] (into the plane, along x); tab: (t, f) points of the time
    function; p0: initial penetration [m] (at rest, F_t = 0, stick)."""

    def __init__(self, m, k, cn, kt, mu, sfric, fband, an, at, tab, p0=0.0):
        self.m, self.k, self.cn, self.kt, self.mu, self.sfric, self.fband = m, k, cn, kt, mu, sfric, fband
        self.ct = 2.0 * math.sqrt(kt * m)
        self.an, self.at = an, at
        self.tx, self.ty = np.asarray(tab[0], float), np.asarray(tab[1], float)
        self.p0 = p0

    # time function (linear interpolation, the end segments extended)
    def seg(self, t):
        """Index k of the table segment [tx[k], tx[k+1]] used at time t."""
        k = int(np.searchsorted(self.tx, t, side="right")) - 1
        return min(max(k, 0), len(self.tx) - 2)

    def f_lin(self, k):
        """f = a + b t on segment k."""
        b = (self.ty[k + 1] - self.ty[k]) / (self.tx[k + 1] - self.tx[k])
        return self.ty[k] - b * self.tx[k], b

    def f(self, t):
        a, b = self.f_lin(self.seg(t))
        return a + b * t

    # forces of state y = [p, p', x, x', F_t]
    def fn(self, y):
        return self.k * y[0] + self.cn * y[1]

    def flim(self, y):
        return self.sfric + self.mu * self.fn(y)

    def force(self, y, slip):
        """Applied tangential force on the block."""
        if slip:
            return self.flim(y) * math.copysign(1.0, y[4])
        return y[4] - self.ct * y[3]

    def slip_fn(self, y):
        """Stick: |F| - ((1 + BAND) F_lim + f_band), slips when rising through 0."""
        return abs(y[4] - self.ct * y[3]) - ((1.0 + BAND) * self.flim(y) + self.fband)

    def stick_fn(self, y):
        """Slip: x' e, sticks when rising through 0."""
        return y[3] * math.copysign(1.0, y[4])

    def rhs(self, t, y, slip):
        f = self.f(t)
        fn = self.fn(y)
        F = self.force(y, slip)
        return [y[1], self.an * f - fn / self.m, y[3], self.at * f + F / self.m, 0.0 if slip else -self.kt * y[3]]

    def matrix(self, k, slip):
        """dz/dt = A z on segment k, z = [p, p', x, x', F_t, t, 1]."""
        a, b = self.f_lin(k)
        m = self.m
        A = np.zeros((7, 7))
        A[0, 1] = 1.0
        A[1, 0], A[1, 1], A[1, 5], A[1, 6] = -self.k / m, -self.cn / m, self.an * b, self.an * a
        A[2, 3] = 1.0
        A[5, 6] = 1.0  # dt/dt = 1
        A[3, 5], A[3, 6] = self.at * b, self.at * a
        if slip:
            return A  # the force depends on sign(F_t): added by the caller
        A[3, 3], A[3, 4] = -self.ct / m, 1.0 / m
        A[4, 3] = -self.kt
        return A

    def to_slip(self, y):
        """stick -> slip: F_t on the limit along the applied force."""
        y = list(y)
        y[4] = self.flim(y) * math.copysign(1.0, y[4] - self.ct * y[3])
        return y

    def to_stick(self, y):
        """slip -> stick: F_t := F_lim e."""
        y = list(y)
        y[4] = self.flim(y) * math.copysign(1.0, y[4])
        return y

    def start(self, y, slip, t, events):
        """State-based decision at the start and after an event (5.1)."""
        if not slip and self.slip_fn(y) > 0:
            events.append((t, "fric_slip"))
            return self.to_slip(y), True
        return y, slip

    def y0(self):
        return [self.p0, 0.0, 0.0, 0.0, 0.0]

    # ---- solve_ivp ---------------------------------------------------------
    def solve(self, tend, method="Radau", rtol=1e-12, atol=None, t_keep=()):
        """Integrate to tend with solve_ivp, restarting at every table point
        and every event. Returns dict(events=[(t, kind)], y=final state,
        slip=final mode, at=[(t, y)] the states at the times t_keep)."""
        if atol is None:
            atol = self.atol()
        y, slip, t = self.y0(), False, 0.0
        events, keep = [], []
        self.before = []
        y, slip = self.start(y, slip, t, events)
        brk = [x for x in self.tx if 0.0 < x < tend] + [tend]
        tk = sorted(t_keep)
        while t < tend:
            t1 = next(x for x in brk if x > t)

            def ev(tt, yy, s=slip):
                return self.stick_fn(yy) if s else self.slip_fn(yy)
            ev.terminal, ev.direction = True, 1.0
            sol = solve_ivp(self.rhs, (t, t1), y, method=method, rtol=rtol, atol=atol, args=(slip,), events=ev,
                            dense_output=True)
            if sol.status < 0:
                raise RuntimeError(sol.message)
            tn = sol.t[-1]
            for x in tk:
                if t <= x <= tn:
                    keep.append((x, sol.sol(x)))
            tk = [x for x in tk if x > tn]
            y = list(sol.y[:, -1])
            if self.fn(y) < 0:
                raise RuntimeError(f"contact released at t = {tn}: not modelled")
            if sol.status == 1:  # event
                tn = sol.t_events[0][0]
                y = list(sol.y_events[0][0])
                self.before.append(list(y))
                if slip:
                    events.append((tn, "fric_stick"))
                    y, slip = self.to_stick(y), False
                else:
                    events.append((tn, "fric_slip"))
                    y, slip = self.to_slip(y), True
                y, slip = self.start(y, slip, tn, events)
            t = tn
        return dict(events=events, y=y, slip=slip, at=keep)

    def atol(self):
        """Absolute tolerances far below every quantity of interest: 1e-14
        of the static normal penetration for p, x; of the load for F_t."""
        load = self.m * max(abs(self.an), abs(self.at), 1e-30)
        ps = load / self.k
        w = math.sqrt(self.k / self.m)
        return [1e-14 * ps, 1e-14 * ps * w, 1e-14 * ps, 1e-14 * ps * w, 1e-14 * load]

    # ---- exact flow --------------------------------------------------------
    def flow(self, k, slip, z, h):
        A = self.matrix(k, slip)
        if slip:
            # F = (Sfric + mu (k p + c_n p')) e, e = sign(F_t), constant in slip
            e = math.copysign(1.0, z[4])
            A = A.copy()
            A[3, 0] += e * self.mu * self.k / self.m
            A[3, 1] += e * self.mu * self.cn / self.m
            A[3, 6] += e * self.sfric / self.m
        return expm(A * h) @ z

    def solve_exact(self, tend, nsample=64, t_keep=()):
        """The same by the exact flow of each segment; a root is searched
        where the event function changes sign between nsample points of a
        segment and located by Brent's method to 1e-15 s relative."""
        y, slip, t = self.y0(), False, 0.0
        events, keep = [], []
        self.before = []
        y, slip = self.start(y, slip, t, events)
        brk = [x for x in self.tx if 0.0 < x < tend] + [tend]
        tk = sorted(t_keep)
        while t < tend:
            t1 = next(x for x in brk if x > t)
            k = self.seg(0.5 * (t + t1))
            z0 = np.array(list(y) + [t, 1.0])
            fev = self.stick_fn if slip else self.slip_fn

            def g(tt):
                return fev(self.flow(k, slip, z0, tt - t)[:5])
            ts = np.linspace(t, t1, nsample + 1)
            gs = [g(x) for x in ts]
            hit = None
            for i in range(nsample):
                if gs[i] <= 0 < gs[i + 1] or (i == 0 and gs[0] < 0 < gs[1]):
                    hit = brentq(g, ts[i], ts[i + 1], xtol=1e-18, rtol=1e-15)
                    break
            tn = hit if hit is not None else t1
            for x in tk:
                if t <= x <= tn:
                    keep.append((x, self.flow(k, slip, z0, x - t)[:5]))
            tk = [x for x in tk if x > tn]
            y = list(self.flow(k, slip, z0, tn - t)[:5])
            if self.fn(y) < 0:
                raise RuntimeError(f"contact released at t = {tn}: not modelled")
            if hit is not None:
                self.before.append(list(y))
                if slip:
                    events.append((tn, "fric_stick"))
                    y, slip = self.to_stick(y), False
                else:
                    events.append((tn, "fric_slip"))
                    y, slip = self.to_slip(y), True
                y, slip = self.start(y, slip, tn, events)
            t = tn
        return dict(events=events, y=y, slip=slip, at=keep)

    def plastic(self, y):
        """Plastic (slipped) displacement of a sticking state: x + F_t/K_t."""
        return y[2] + y[4] / self.kt

    def rates(self, t, y, kind):
        """Rate of the event function through the event kind at (t, y), the
        state just before it: d|F|/dt - (1 + BAND) dF_lim/dt [N/s] for
        fric_slip (in stick), the acceleration along e [m/s^2] for
        fric_stick (in slip)."""
        slip = kind == "fric_stick"
        d = self.rhs(t, y, slip)
        if slip:
            return d[3] * math.copysign(1.0, y[4])
        sgn = math.copysign(1.0, y[4] - self.ct * y[3])
        return sgn * (d[4] - self.ct * d[3]) - (1.0 + BAND) * self.mu * (self.k * d[0] + self.cn * d[1])

    def excess(self, tend, n=20000):
        """Largest |F| - (1 + BAND) F_lim along the stick trajectory with no
        slip allowed (f_band infinite) on [0, tend]: how far the applied
        force rises past the limit [N], and when."""
        fb = self.fband
        self.fband = float("inf")
        ts = np.linspace(0.0, tend, n + 1)[1:]
        r = self.solve_exact(tend, t_keep=list(ts))
        self.fband = fb
        best = max((abs(y[4] - self.ct * y[3]) - (1.0 + BAND) * self.flim(y), t) for t, y in r["at"])
        return best

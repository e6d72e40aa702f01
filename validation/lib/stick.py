"""The stick phase of ricochet's incremental (elastic-plastic) friction law,
written from its description for the validation references; nothing here is
read from the engine. The law is that of docs/theory.md 3.5
with the stick damper of commit aa7c6b5 (docs/theory.md 3.5 still
describes the undamped stick spring).

While sticking, the tangential force that acts is the spring state plus a
critically damped stick damper,

    F = F_t - c_t v_t,   dF_t/dt = -K_t v_t,   c_t = 2 zeta_t sqrt(K_t m_red), zeta_t = 1,

m_red the reduced mass of the pair (a fixed body is infinitely heavy, so a
block on a fixed floor has m_red = m). Stick -> slip when |F| rises through
(1 + BAND) F_lim; the state then takes F returned radially onto the limit.
At the start of a run (and after every event) a sticking contact whose F
already exceeds the limit slips at once.

For one body of mass m on a fixed surface the stick phase is the critically
damped oscillator m x'' + c_t x' + K_t x = P (x the tangential displacement
since the state was zero, P a constant tangential load), w = sqrt(K_t/m):

* launched at v0 with no load (P = 0): x = v0 t e^(-w t),
  F = -m w v0 (2 - w t) e^(-w t), largest at t = 0, where |F| = c_t v0;
* from rest under a step load P: x = (P/K_t) (1 - (1 + w t) e^(-w t)),
  F = -P (1 - (1 - w t) e^(-w t)), rising monotonically to P (1 + e^-2) at
  w t = 2, then back to P without overshooting x = P/K_t;
* released at rest from the state F_t = -F_lim e (the block stopped by a
  slip -> stick switch, no load): x = -(F_lim/K_t) (1 - (1 + w t) e^(-w t))
  along e, F = -F_lim (1 - w t) e^(-w t) e: the block relaxes by F_lim/K_t
  without ringing, |F| <= F_lim.
"""
import math

from scipy.special import lambertw

BAND = 1e-6    # stick -> slip at |F| = (1 + BAND) F_lim (RC_SLIP_BAND, src/model.h)
ZETA_T = 1.0   # damping ratio of the stick spring (critical)


def ct(kt, m_red):
    """Stick damping coefficient c_t = 2 zeta_t sqrt(K_t m_red) [N s/m]."""
    return 2.0 * ZETA_T * math.sqrt(kt * m_red)


def slips_at_launch(kt, m, v0, flim):
    """A contact starting to stick with a zero state while sliding at v0:
    the applied force is the damper's alone, c_t v0; True if it exceeds
    (1 + BAND) F_lim, i.e. the contact slips at t = 0 (the force then only
    falls, so otherwise it never slips)."""
    return ct(kt, m) * v0 > (1 + BAND) * flim


def launch_onset(kt, m, v0, flim):
    """Slip time, displacement and speed of a block launched at v0 on a
    sticking contact with a zero state: (0, 0, v0) when it slips at once.
    Raises if it would not slip at all (no reference here needs that case)."""
    if not slips_at_launch(kt, m, v0, flim):
        raise ValueError("the stick damper does not reach the limit: the block sticks")
    return 0.0, 0.0, v0


def step_onset(kt, m, load, flim):
    """Slip time of a block at rest with a zero state under a step tangential
    load P = load from t = 0: |F| = P (1 - (1 - s) e^(-s)), s = w t, reaches
    r P with r = (1 + BAND) F_lim/P at s = 1 - W((1 - r) e) (W the principal
    branch of Lambert's function, 1 - s = q solving q e^q = (1 - r) e).
    Needs r < 1 + e^-2 (the largest |F|/P, at s = 2)."""
    r = (1 + BAND) * flim / load
    if r >= 1.0 + math.exp(-2.0):
        raise ValueError("the step load never reaches the limit")
    s = 1.0 - lambertw((1.0 - r) * math.e, 0).real
    return s / math.sqrt(kt / m)


def step_stick(kt, m, load, t):
    """Displacement along the load of a block held by the stick spring under a
    step load from rest: (P/K_t) (1 - (1 + w t) e^(-w t))."""
    w = math.sqrt(kt / m)
    return load / kt * (1.0 - (1.0 + w * t) * math.exp(-w * t))


def settle(kt, m, flim, t):
    """Displacement along the former sliding direction after a stop (slip ->
    stick with the state at -F_lim along it, block at rest, no load):
    -(F_lim/K_t) (1 - (1 + w t) e^(-w t)); the speed is
    -(F_lim/m) t e^(-w t)."""
    w = math.sqrt(kt / m)
    return -flim / kt * (1.0 - (1.0 + w * t) * math.exp(-w * t)), -flim / m * t * math.exp(-w * t)

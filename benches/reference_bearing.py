"""An independent NumPy/SciPy implementation of the ball-bearing equations
(PHYSICS.md sections 2-3; Jones-Harris quasi-statics, outer-raceway
control), written from the equations and not from the Rust code. Used by
``benches/bearing_scipy.py`` (timing ratio) and by the pytest suite
(agreement of two independent methods).

Conventions (same as the Rust core): radial load along x, ball j at
psi_j = 2 pi j / Z, displacements from the concentric position with the
groove curvature centres in one plane (ISO/TS 16281):
A1 = dz, A2 = A cos(alpha0) + dx cos(psi), A = (f_i + f_o - 1) D.
Unknowns per ball: X1, X2 (ball centre from the outer groove centre,
axial/radial), delta_i, delta_o; ring unknowns dx, dz.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, fsolve
from scipy.special import ellipe, ellipk

STEEL = {"E": 208e9, "nu": 0.30, "rho": 7830.0}


def reduced_modulus(m1: dict, m2: dict) -> float:
    return 2.0 / ((1 - m1["nu"] ** 2) / m1["E"] + (1 - m2["nu"] ** 2) / m2["E"])


def hertz_k(raceway: str, d: float, dm: float, f: float, alpha: float, ep: float) -> float:
    """Load-deflection constant K (Q = K delta^1.5) with the exact
    ellipticity from F(rho) = ((k^2+1) E - 2 K) / ((k^2-1) E)."""
    gamma = d * math.cos(alpha) / dm
    roll = (2 / d) * gamma / (1 - gamma) if raceway == "inner" else -(2 / d) * gamma / (1 + gamma)
    rho_sum = 4 / d + roll - 1 / (f * d)
    f_rho = (roll + 1 / (f * d)) / rho_sum

    def g(kappa: float) -> float:
        m = 1 - 1 / kappa**2
        kk, ee = ellipk(m), ellipe(m)
        return ((kappa**2 + 1) * ee - 2 * kk) / ((kappa**2 - 1) * ee) - f_rho

    kappa = brentq(g, 1 + 1e-9, 1e4, xtol=1e-14, rtol=1e-14)
    m = 1 - 1 / kappa**2
    kk, ee = ellipk(m), ellipe(m)
    return math.pi * kappa * ep / 3 * math.sqrt(2 * ee / (kk**3 * rho_sum))


class ReferenceBearing:
    def __init__(
        self,
        z=9,
        d=12e-3,
        dm=60e-3,
        fi=0.52,
        fo=0.53,
        pd=0.04e-3,
        ball=STEEL,
        ring=STEEL,
        k_table_deg=None,
    ):
        if k_table_deg is None:
            k_table_deg = np.arange(0.0, 60.01, 0.5)
        self.z, self.d, self.dm, self.fi, self.fo = z, d, dm, fi, fo
        self.a = (fi + fo - 1) * d
        self.alpha0 = math.acos(1 - pd / (2 * self.a))
        self.mass = ball["rho"] * math.pi * d**3 / 6
        self.inertia = ball["rho"] * math.pi * d**5 / 60
        ep = reduced_modulus(ball, ring)
        self._tab = np.radians(k_table_deg)
        self._ki = np.array([hertz_k("inner", d, dm, fi, a, ep) for a in self._tab])
        self._ko = np.array([hertz_k("outer", d, dm, fo, a, ep) for a in self._tab])
        self.psi = 2 * np.pi * np.arange(z) / z

    def k_inner(self, alpha):
        return np.interp(np.abs(alpha), self._tab, self._ki)

    def k_outer(self, alpha):
        return np.interp(np.abs(alpha), self._tab, self._ko)

    # -- high-speed quasi-statics ----------------------------------------
    def residual(self, x, fa, fr, omega_i, gyro=True, centrifugal=True):
        z, d, dm = self.z, self.d, self.dm
        dx, dz = x[0], x[1]
        b = x[2:].reshape(z, 4)
        x1, x2, di, do = b[:, 0], b[:, 1], b[:, 2], b[:, 3]
        a1 = dz * np.ones(z)
        a2 = self.a * math.cos(self.alpha0) + dx * np.cos(self.psi)
        ri = (self.fi - 0.5) * d + di
        ro = (self.fo - 0.5) * d + do
        sin_i, cos_i = (a1 - x1) / ri, (a2 - x2) / ri
        sin_o, cos_o = x1 / ro, x2 / ro
        ai, ao = np.arctan2(sin_i, cos_i), np.arctan2(sin_o, cos_o)
        qi = self.k_inner(ai) * np.clip(di, 0, None) ** 1.5
        qo = self.k_outer(ao) * np.clip(do, 0, None) ** 1.5
        # Outer-raceway control kinematics (Harris): attitude, orbit, spin.
        beta = np.arctan2(sin_o, cos_o + d / dm)
        cb, sb = np.cos(beta), np.sin(beta)
        ratio = (
            (dm / d + cos_o)
            * (cb * cos_i + sb * sin_i)
            / ((dm / d - cos_i) * (cb * cos_o + sb * sin_o))
        )
        wc = omega_i / (1 + ratio)
        wr = wc * (dm / d + cos_o) / (cb * cos_o + sb * sin_o)
        fc = 0.5 * self.mass * dm * wc**2 if centrifugal else 0 * wc
        mg = self.inertia * wr * wc * sb if gyro else 0 * wc
        # The outer-contact friction force that supplies the precession
        # moment dH/dt = +Mg (about the orbit direction) acts on the ball as
        # (2 Mg / D)(+sin a_o radially, -cos a_o axially).
        r = np.empty(4 * z)
        r[0::4] = (a1 - x1) ** 2 + (a2 - x2) ** 2 - ri**2
        r[1::4] = x1**2 + x2**2 - ro**2
        r[2::4] = qi * sin_i - qo * sin_o - 2 * mg / d * cos_o
        r[3::4] = qi * cos_i - qo * cos_o + fc + 2 * mg / d * sin_o
        ring = np.array([fr - np.sum(qi * cos_i * np.cos(self.psi)), fa - np.sum(qi * sin_i)])
        scale = np.empty(4 * z)
        scale[0::4] = d**2
        scale[1::4] = d**2
        scale[2::4] = 1.0
        scale[3::4] = 1.0
        return np.concatenate([ring, r / scale])

    def static_start(self, fa, fr):
        """A start from the rigid-ring thrust solution (balls at the free angle)."""
        z, d = self.z, self.d
        x = np.zeros(2 + 4 * z)
        q = max(fa, 1.0) / (z * math.sin(self.alpha0) + 1e-9)
        ki0, ko0 = self.k_inner(self.alpha0), self.k_outer(self.alpha0)
        kn = 1.0 / (ki0 ** (-2 / 3) + ko0 ** (-2 / 3)) ** 1.5
        delta = (q / kn) ** (2 / 3)
        dz = (self.a + delta) * math.sin(self.alpha0) + 1e-6
        x[1] = dz
        x[0] = 1e-6 * np.sign(fr)
        di = (q / self.k_inner(self.alpha0)) ** (2 / 3)
        do = (q / self.k_outer(self.alpha0)) ** (2 / 3)
        ro = (self.fo - 0.5) * d + do
        for j in range(z):
            sa, ca = math.sin(self.alpha0), math.cos(self.alpha0)
            x[2 + 4 * j : 6 + 4 * j] = [ro * sa, ro * ca, di, do]
        return x

    def solve(self, fa, fr, speed_rpm, gyro=True, centrifugal=True, x0=None):
        omega = speed_rpm * math.pi / 30
        x0 = self.static_start(fa, fr) if x0 is None else x0
        sol, info, ier, msg = fsolve(
            self.residual, x0, args=(fa, fr, omega, gyro, centrifugal), full_output=True, xtol=1e-12
        )
        res = np.max(np.abs(self.residual(sol, fa, fr, omega, gyro, centrifugal)))
        if ier != 1 and res > 1e-6:
            raise RuntimeError(f"fsolve: {msg} (residual {res:.2e})")
        z, d = self.z, self.d
        b = sol[2:].reshape(z, 4)
        a2 = self.a * math.cos(self.alpha0) + sol[0] * np.cos(self.psi)
        ri = (self.fi - 0.5) * d + b[:, 2]
        ro = (self.fo - 0.5) * d + b[:, 3]
        ai = np.arctan2((sol[1] - b[:, 0]) / ri, (a2 - b[:, 1]) / ri)
        ao = np.arctan2(b[:, 0] / ro, b[:, 1] / ro)
        return {
            "dx_m": sol[0],
            "dz_m": sol[1],
            "inner_contact_angle_deg": np.degrees(ai),
            "outer_contact_angle_deg": np.degrees(ao),
            "inner_load_n": self.k_inner(ai) * np.clip(b[:, 2], 0, None) ** 1.5,
            "outer_load_n": self.k_outer(ao) * np.clip(b[:, 3], 0, None) ** 1.5,
            "x": sol,
        }

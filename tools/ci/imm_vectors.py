#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Reference numbers for the IMM and motion-model unit tests.

    python3 tools/ci/imm_vectors.py

Prints the numbers that test/test_imm.c, test/test_motion_ca.c and
test/test_motion_ct.c assert, derived independently of the C code (numpy
only):

  * CA model: F = expm(A T) by its (finite) power series, Q by Gauss-Legendre
    quadrature of the integral of e^{A t} G q G' e^{A' t} over [0, T]
    (exact: the integrand is a polynomial of degree 4).
  * CT model: f(x) in the closed form, its Jacobian by complex-step
    differentiation (exact to round-off; no series, no finite differences).
  * IMM mixing of a 4-state CV and a 6-state CA model: each other model's
    estimate is extended by the target model's own extra components with
    zero cross-covariance, then the textbook full-dimensional mixture
    (ALGORITHMS.md §14.1 CHOICE).
  * IMM-IPDA per-model quantities in the textbook form (Λ_j, μ_j, β_i^j), and
    IMM-IHPDA of a selected measurement from the per-model A^j, C^j.

The C tests split the same quantities through other routes (difference sums,
the model-mixed likelihood, the joint split), so an agreement checks both.
"""
import numpy as np

np.set_printoptions(precision=10)


def fmt(v):
    a = np.atleast_1d(np.asarray(v, dtype=float)).ravel()
    return ", ".join("%.10g" % t for t in a)


def kv(name, v):
    print("%s = {%s}" % (name, fmt(v)))


# --------------------------------------------------------------- CA model
def ca_reference(T, q):
    A3 = np.array([[0.0, 1, 0], [0, 0, 1], [0, 0, 0]])
    G3 = np.array([[0.0], [0], [1]])
    F3 = np.eye(3) + A3 * T + A3 @ A3 * T * T / 2.0  # A3^3 = 0
    nodes, weights = np.polynomial.legendre.leggauss(8)
    Q3 = np.zeros((3, 3))
    for u, w in zip(nodes, weights):
        t = 0.5 * T * (u + 1.0)
        E = np.eye(3) + A3 * t + A3 @ A3 * t * t / 2.0
        Q3 += 0.5 * T * w * (E @ G3 * q @ G3.T @ E.T)
    # interleave to [x y vx vy ax ay]
    F = np.zeros((6, 6)); Q = np.zeros((6, 6))
    for ax in range(2):
        idx = [ax, 2 + ax, 4 + ax]
        F[np.ix_(idx, idx)] = F3
        Q[np.ix_(idx, idx)] = Q3
    return F3, Q3, F, Q


# --------------------------------------------------------------- CT model
def ct_f(x, T):
    px, py, vx, vy, w = x
    s, c = np.sin(w * T), np.cos(w * T)
    return np.array([px + vx * s / w - vy * (1 - c) / w,
                     py + vx * (1 - c) / w + vy * s / w,
                     c * vx - s * vy, s * vx + c * vy, w])


def ct_jacobian(x, T):
    h = 1e-30
    J = np.zeros((5, 5))
    for k in range(5):
        xc = np.array(x, dtype=complex)
        xc[k] += 1j * h
        J[:, k] = np.imag(ct_f(xc, T)) / h
    return J


# --------------------------------------------------------------- IMM mixing
def imm_mix(Pi, mu, xs, Ps):
    r = len(xs)
    cbar = Pi.T @ mu
    mix = Pi * mu[:, None] / cbar[None, :]
    out = []
    for j in range(r):
        nj = len(xs[j])
        xa, Pa = [], []
        for i in range(r):
            xi = np.array(xs[j], dtype=float)
            Pi_ = np.zeros((nj, nj))
            if i == j:
                xi = xs[j].copy(); Pi_ = Ps[j].copy()
            else:  # common part from model i, extras of model j, no cross
                xi[:4] = xs[i][:4]
                Pi_[:4, :4] = Ps[i][:4, :4]
                Pi_[4:, 4:] = Ps[j][4:, 4:]
            xa.append(xi); Pa.append(Pi_)
        x0 = sum(mix[i, j] * xa[i] for i in range(r))
        P0 = sum(mix[i, j] * (Pa[i] + np.outer(xa[i] - x0, xa[i] - x0)) for i in range(r))
        out.append((x0, P0))
    return cbar, mix, out


def main():
    print("# CA model, T = 0.5, q = 3")
    F3, Q3, F, Q = ca_reference(0.5, 3.0)
    kv("ca_F3", F3); kv("ca_Q3", Q3); kv("ca_Q", Q)
    x = np.array([10.0, -20.0, 150.0, 30.0, 4.0, -9.0])
    kv("ca_Fx", F @ x)

    print("\n# CT model")
    for name, xv, T in (("ct_turn", [100.0, 50.0, 150.0, -40.0, 0.25], 1.0),
                        ("ct_slow", [100.0, 50.0, 150.0, -40.0, 0.02], 2.0),
                        ("ct_neg", [-3.0, 7.0, -120.0, 200.0, -0.3], 0.5)):
        xv = np.array(xv)
        kv(name + "_xp", ct_f(xv, T)); kv(name + "_F", ct_jacobian(xv, T))
    # w = 0: the CV model.  To first order in w, x' = x + vx T - vy w T^2/2,
    # y' = y + vx w T^2/2 + vy T, vx' = vx - w T vy, vy' = vy + w T vx:
    # the Jacobian's column 4 is [-vy T^2/2, vx T^2/2, -vy T, vx T].
    T, (px, py, vx, vy) = 2.0, (100.0, 50.0, 150.0, -40.0)
    F0 = np.eye(5); F0[0, 2] = F0[1, 3] = T
    F0[:4, 4] = [-vy * T * T / 2, vx * T * T / 2, -vy * T, vx * T]
    kv("ct_zero_xp", [px + vx * T, py + vy * T, vx, vy, 0.0]); kv("ct_zero_F", F0)

    print("\n# IMM mixing: model 0 CV (4), model 1 CA (6)")
    Pi = np.array([[0.9, 0.1], [0.2, 0.8]])
    mu = np.array([0.7, 0.3])
    x_cv = np.array([1000.0, 2000.0, 150.0, -20.0])
    P_cv = np.array([[30.0, 4, 6, 1], [4, 25, 1, 5], [6, 1, 9, 0.5], [1, 5, 0.5, 8]])
    x_ca = np.array([1003.0, 1996.0, 146.0, -12.0, 8.0, -15.0])
    L = np.array([[6.0, 0, 0, 0, 0, 0], [0.5, 5, 0, 0, 0, 0], [1.5, 0.3, 4, 0, 0, 0],
                  [0.2, 1.1, 0.4, 3.5, 0, 0], [0.3, -0.2, 1.2, 0.1, 2.5, 0],
                  [-0.1, 0.4, 0.2, 1.3, 0.6, 2.2]])
    P_ca = L @ L.T
    kv("mix_P_ca", P_ca)
    cbar, mix, out = imm_mix(Pi, mu, [x_cv, x_ca], [P_cv, P_ca])
    kv("mix_cbar", cbar); kv("mix_mu_ij", mix)
    for j, (x0, P0) in enumerate(out):
        kv("mix_x0_%d" % j, x0); kv("mix_P0_%d" % j, P0)
        print("# min eigenvalue of P0_%d: %.6g" % (j, np.linalg.eigvalsh(P0).min()))
    lam = np.array([0.4, 1.7])
    c = lam @ cbar
    mu_k = lam * cbar / c
    kv("mix_c", c); kv("mix_mu_k", mu_k)
    xc = sum(mu_k[j] * [x_cv, x_ca][j][:4] for j in range(2))
    Pc = sum(mu_k[j] * ([P_cv, P_ca][j][:4, :4] + np.outer([x_cv, x_ca][j][:4] - xc,
                                                             [x_cv, x_ca][j][:4] - xc))
             for j in range(2))
    kv("mix_xc", xc); kv("mix_Pc", Pc)

    print("\n# IMM-IPDA, 2 models, 3 measurements (textbook form)")
    PD, PG = np.array([0.9, 0.9]), 0.99
    p = np.array([[0.02, 0.01], [0.004, 0.006], [0.0005, 0.003]])  # p[i][j] = p_i^j
    lamc = np.array([1e-3, 1e-3, 2e-3])
    cb = np.array([0.78, 0.22])
    Lam = 1 - PD * PG + PD * PG * (p / lamc[:, None]).sum(axis=0)
    c = Lam @ cb
    kv("ipda_Lambda", Lam); kv("ipda_c", c); kv("ipda_mu", Lam * cb / c)
    kv("ipda_beta0_j", (1 - PD * PG) / Lam)
    kv("ipda_beta_j", (PD * PG * p / lamc[:, None] / Lam[None, :]).T)  # [j][i]
    pdm = cb @ PD
    pm = (p * (cb * PD)[None, :]).sum(axis=1) / pdm
    kv("ipda_pd_mix", pdm); kv("ipda_p_mix", pm)

    print("\n# IMM-IHPDA: selected measurement s of rank 1 among m = 3, rho = 1, V_G = 400")
    a = 1.0 / (1.0 + 1.0)
    Pr = (1.0 / (1.0 + a)) * (2.0 / (2.0 + a))  # P_r(1 | 3, rho = 1), ALGORITHMS.md §7.2
    ps, m, VG, lam_s = np.array([0.02, 0.01]), 3, 400.0, 1e-3
    A = PD * PG * m * ps * Pr / lam_s
    C = 1 - PD * PG + PD * PG * (m / (lam_s * VG)) * (1 - Pr)
    Ls = cb @ (A + C)
    kv("ihpda_Pr", Pr); kv("ihpda_p_mix", cb @ (PD * ps) / (cb @ PD)); kv("ihpda_A", A); kv("ihpda_C", C); kv("ihpda_L", Ls)
    kv("ihpda_mu", cb * (A + C) / Ls); kv("ihpda_beta_j", A / (A + C))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""split_vectors.py - reference numbers of the split-target models
(docs/ALGORITHMS.md §14.3), derived independently of src/split/split.c.

numpy only.  A straightforward implementation of the formulas as written
in §14.3: explicit H, H^s, R^s and matrix inverses, the textbook (standard,
not Joseph) forms of the covariance updates, the literal likelihood of
model 5 (with V^-(m_i - 1)) and of model 6 ([S3] eq. 14 with phi! V^-phi),
and the joint events enumerated by brute force (itertools).  test/test_split.c
asserts the numbers this prints:

    python3 tools/ci/split_vectors.py

Library conventions the C code follows and this script states explicitly:
likelihoods are also printed as ratios to V^-m (what src/split/split.c returns);
an undetected target has the factor 1 - PD PG and a detected one PD N with
N untruncated (ALGORITHMS.md §4; PG = 1 gives [S3]'s 1 - PD); an undetected
target's innovation is 0 in nu^s(theta).
"""
import itertools
import math

import numpy as np

GAMMA = -2.0 * math.log(1.0 - 0.99)  # chi-square 0.99, 2 dof: 9.2103...


def gauss(nu, S):
    return math.exp(-0.5 * nu @ np.linalg.solve(S, nu)) / (2.0 * math.pi * math.sqrt(np.linalg.det(S)))


def H_of(n):
    H = np.zeros((2, n))
    H[0, 0] = H[1, 1] = 1.0
    return H


def just_split(xp, Pp, R, z, beta, V):
    """Model 5, §14.3 steps 1 to 6, literally."""
    n = len(xp)
    H = H_of(n)
    S = H @ Pp @ H.T + R
    Si = np.linalg.inv(S)
    W = Pp @ H.T @ Si
    m = len(z)
    order = sorted(range(m), key=lambda j: (-beta[j], j))
    c1, c2 = order[0], order[1]
    cl = []
    for j in range(m):
        if j == c1:
            cl.append(0)
        elif j == c2:
            cl.append(1)
        else:
            d0 = (z[j] - z[c1]) @ Si @ (z[j] - z[c1])
            d1 = (z[j] - z[c2]) @ Si @ (z[j] - z[c2])
            cl.append(1 if d1 < d0 else 0)
    zhat = H @ xp
    nu = [zj - zhat for zj in z]
    bn = [0.0] * m
    xs, Ps_blocks, lik_literal = [], [], 1.0
    IWH = np.eye(n) - W @ H
    Pc = IWH @ Pp                           # standard form
    for h in (0, 1):
        idx = [j for j in range(m) if cl[j] == h]
        bsum = sum(beta[j] for j in idx)
        for j in idx:
            bn[j] = beta[j] / bsum
        nub = sum(bn[j] * nu[j] for j in idx)
        spread = sum(bn[j] * np.outer(nu[j], nu[j]) for j in idx) - np.outer(nub, nub)
        xs.append(xp + W @ nub)
        Ps_blocks.append(Pc + W @ spread @ W.T)
        mi = len(idx)
        lik_literal *= sum(gauss(nu[j], S) for j in idx) / mi * V ** (-(mi - 1))
    P12 = IWH @ Pp @ IWH.T                  # [S3] eq. 12
    Ps = np.block([[Ps_blocks[0], P12], [P12.T, Ps_blocks[1]]])
    return dict(cluster=cl, beta_n=bn, xs=np.concatenate(xs), Ps=Ps, lik_literal=lik_literal,
                lik_ratio=lik_literal * V ** m, S=S, V=V)


def split_events(xps, Pps, R, z, pd, pg, gamma, V, lam=0.0, coupled=False):
    """Model 6: the joint events by brute force, [S3] eq. 14 literally
    (lam = 0); with lam > 0 the parametric form (Poisson clutter of density
    lam: lam^phi in place of phi! V^-phi)."""
    n = len(xps) // 2
    H = H_of(n)
    m = len(z)
    zh, S = [], []
    for t in (0, 1):
        sl = slice(t * n, (t + 1) * n)
        zh.append(H @ xps[sl])
        S.append(H @ Pps[sl, sl] @ H.T + R)
    gated = [[(z[j] - zh[t]) @ np.linalg.solve(S[t], z[j] - zh[t]) <= gamma for j in range(m)]
             for t in (0, 1)]
    events = []
    for j1 in [None] + list(range(m)):
        for j2 in [None] + list(range(m)):
            if j1 is not None and j1 == j2:
                continue
            if (j1 is not None and not gated[0][j1]) or (j2 is not None and not gated[1][j2]):
                continue
            assigned = [(t, j) for t, j in ((0, j1), (1, j2)) if j is not None]
            phi = m - len(assigned)
            w = lam ** phi if lam > 0 else math.factorial(phi) * V ** (-phi)
            if coupled and len(assigned) == 2:
                Hs = np.block([[H, np.zeros((2, n))], [np.zeros((2, n)), H]])
                Ss = Hs @ Pps @ Hs.T + np.block([[R, np.zeros((2, 2))], [np.zeros((2, 2)), R]])
                nu4 = np.concatenate([z[j1] - zh[0], z[j2] - zh[1]])
                w *= math.exp(-0.5 * nu4 @ np.linalg.solve(Ss, nu4)) / (
                    (2.0 * math.pi) ** 2 * math.sqrt(np.linalg.det(Ss)))
            else:
                for t, j in assigned:
                    w *= gauss(z[j] - zh[t], S[t])
            for t, j in ((0, j1), (1, j2)):
                w *= pd if j is not None else (1.0 - pd * pg)
            events.append(((j1, j2), w))
    c = sum(w for _, w in events)
    probs = {e: w / c for e, w in events}
    ratio = c / lam ** m if lam > 0 else c * V ** m / math.factorial(m)
    return probs, c, ratio, zh, S


def split_update(xps, Pps, R, z, probs):
    """Model 6 coupled update, §14.3 with the corrected bracket of eq. 25."""
    n = len(xps) // 2
    H = H_of(n)
    Hs = np.block([[H, np.zeros((2, n))], [np.zeros((2, n)), H]])
    Rs = np.block([[R, np.zeros((2, 2))], [np.zeros((2, 2)), R]])
    Ss = Hs @ Pps @ Hs.T + Rs
    Ws = Pps @ Hs.T @ np.linalg.inv(Ss)
    zhs = Hs @ xps

    def nu_theta(e):
        v = np.zeros(4)
        for t, j in enumerate(e):
            if j is not None:
                v[2 * t:2 * t + 2] = z[j] - zhs[2 * t:2 * t + 2]
        return v

    nus = sum(p * nu_theta(e) for e, p in probs.items())
    bracket = sum(p * np.outer(nu_theta(e), nu_theta(e)) for e, p in probs.items()) - np.outer(nus, nus)
    beta0 = probs.get((None, None), 0.0)
    I = np.eye(2 * n)
    P = beta0 * Pps + (1.0 - beta0) * (I - Ws @ Hs) @ Pps + Ws @ bracket @ Ws.T
    return xps + Ws @ nus, P, beta0


def decouple_d2(xps, Pps, R):
    n = len(xps) // 2
    H = H_of(n)
    S1 = H @ Pps[:n, :n] @ H.T + R
    S2 = H @ Pps[n:, n:] @ H.T + R
    d = H @ xps[:n] - H @ xps[n:]
    return d @ np.linalg.solve(S1 + S2, d)


KNOWN_A, KNOWN_S = 1.25, 0.15  # ALGORITHMS.md §14.3, split_known_speed


def known_split(xp, Pp, R, z, cluster, bn, dv, dt, n_off, V):
    """Model 5's child half for a split of known speed (§14.3, split_known_speed),
    literally: the prior moved across the course, the textbook PDA update
    (beta_0 = 0), the likelihood over (2 n_off) equally likely sides and offsets."""
    n = len(xp)
    H = H_of(n)
    v = np.array(xp[2:4])
    nrm = np.array([-v[1], v[0]]) / np.linalg.norm(v) if np.linalg.norm(v) > 0 else np.array([0.0, 1.0])
    I2 = [j for j in range(len(z)) if cluster[j] == 1]
    I1 = [j for j in range(len(z)) if cluster[j] == 0]
    w = np.array([bn[j] for j in I2]) / sum(bn[j] for j in I2)
    zbar = sum(wj * z[j] for wj, j in zip(w, I2))
    side = 1.0 if (zbar - H @ xp) @ nrm >= 0 else -1.0
    offs = [(KNOWN_A + h) * dv * dt for h in range(n_off)]
    off = min(offs, key=lambda o: np.sum((zbar - H @ xp - side * o * nrm) ** 2))
    xk = np.array(xp, dtype=float)
    xk[0:2] += side * off * nrm
    xk[2:4] += side * dv * nrm
    # across the course: velocity (s dv)^2, position (dv dt)^2/12 + (s dv dt)^2/4, covariance (s dv)^2 dt/2
    sv = (KNOWN_S * dv) ** 2
    Q = np.zeros((n, n))
    N = np.outer(nrm, nrm)
    Q[0:2, 0:2] = ((dv * dt) ** 2 / 12.0 + sv * dt * dt / 4.0) * N
    Q[0:2, 2:4] = Q[2:4, 0:2] = sv * dt / 2.0 * N
    Q[2:4, 2:4] = sv * N
    Pk = Pp + Q
    Sk = H @ Pk @ H.T + R
    Scv = H @ Pp @ H.T + R
    K = Pk @ H.T @ np.linalg.inv(Sk)
    nus = [z[j] - H @ xk for j in I2]
    nub = sum(wj * nu for wj, nu in zip(w, nus))
    spread = sum(wj * np.outer(nu, nu) for wj, nu in zip(w, nus)) - np.outer(nub, nub)
    x2 = xk + K @ nub
    P2 = (np.eye(n) - K @ H) @ Pk + K @ spread @ K.T
    lik = (V / len(I1)) * sum(gauss(z[j] - H @ xp, Scv) for j in I1) * \
          (V / len(I2)) * sum(gauss(nu, Sk) for nu in nus) / (2.0 * n_off)
    return x2, P2, lik


def kalman(xp, Pp, R, z):
    H = H_of(len(xp))
    S = H @ Pp @ H.T + R
    K = Pp @ H.T @ np.linalg.inv(S)
    return xp + K @ (z - H @ xp), (np.eye(len(xp)) - K @ H) @ Pp


# ---- inputs (the same literals are in test/test_split.c) ----
R = np.array([[9.0, 1.5], [1.5, 12.0]])
XP = np.array([100.0, 50.0, 10.0, -5.0])
PP = np.array([[30.0, 2.0, 10.0, 0.0], [2.0, 25.0, 0.0, 8.0], [10.0, 0.0, 9.0, 0.5], [0.0, 8.0, 0.5, 7.0]])
Z5 = [np.array(v) for v in ([104.0, 48.0], [93.0, 57.0], [108.0, 44.0], [97.0, 59.0], [110.0, 53.0])]
B5 = [0.30, 0.22, 0.18, 0.12, 0.08]

XPS = np.array([100.0, 50.0, 10.0, -5.0, 112.0, 47.0, 12.0, -1.0])
P22 = np.array([[28.0, 1.0, 9.0, 0.0], [1.0, 26.0, 0.0, 7.0], [9.0, 0.0, 8.0, 0.3], [0.0, 7.0, 0.3, 6.0]])
P12 = np.array([[12.0, 1.0, 4.0, 0.0], [0.5, 10.0, 0.0, 3.0], [4.0, 0.0, 3.0, 0.2], [0.0, 3.0, 0.1, 2.5]])
PPS = np.block([[PP, P12], [P12.T, P22]])
Z6 = [np.array(v) for v in ([103.0, 49.0], [110.0, 46.0], [106.0, 52.0], [140.0, 80.0])]
PD6, PG6 = 0.9, 0.99


def fmt(v):
    return ", ".join("%.10g" % x for x in np.ravel(v))


def main():
    assert np.all(np.linalg.eigvalsh(PPS) > 0), "stacked prior must be positive definite"
    print("# split_vectors.py: reference numbers of docs/ALGORITHMS.md §14.3 (test/test_split.c)")
    print("gamma = %.16g" % GAMMA)

    H = H_of(4)
    S = H @ PP @ H.T + R
    V5 = math.pi * GAMMA * math.sqrt(np.linalg.det(S))
    r5 = just_split(XP, PP, R, Z5, B5, V5)
    print("\n## model 5: just split")
    print("V = %.10g" % V5)
    print("cluster = {%s}" % ", ".join(str(c) for c in r5["cluster"]))
    print("beta_n = {%s}" % fmt(r5["beta_n"]))
    print("xs = {%s}" % fmt(r5["xs"]))
    print("Ps (8x8, row-major) = {%s}" % fmt(r5["Ps"]))
    ev5 = np.linalg.eigvalsh(r5["Ps"])
    print("eigenvalues of Ps: min %.3g, max %.6g (positive semi-definite, singular:"
          " the halves differ only by W times their innovations)" % (ev5[0], ev5[-1]))
    print("lik literal prod (1/m_i) sum N V^-(m_i-1) = %.10g" % r5["lik_literal"])
    print("lik ratio (literal * V^m) = %.10g" % r5["lik_ratio"])

    print("\n## model 5, a split of known speed (split_known_speed), on model 5's clusters above")
    for dv, n_off in ((5.0, 1), (2.0, 1), (2.0, 2)):
        x2, P2, lk = known_split(XP, PP, R, Z5, r5["cluster"], r5["beta_n"], dv, 1.0, n_off, V5)
        print("dv %g, dt 1, n_off %d:" % (dv, n_off))
        print("  x2 = {%s}" % fmt(x2))
        print("  P2 (4x4) = {%s}" % fmt(P2))
        print("  lik = %.10g" % lk)

    V6 = math.pi * GAMMA * (math.sqrt(np.linalg.det(H @ PP @ H.T + R)) +
                            math.sqrt(np.linalg.det(H @ P22 @ H.T + R)))
    probs, c, ratio, _, _ = split_events(XPS, PPS, R, Z6, PD6, PG6, GAMMA, V6)
    print("\n## model 6: split, pd %.2f pg %.2f" % (PD6, PG6))
    print("V = %.10g" % V6)
    print("events (j1, j2; -1 = undetected), P(theta):")
    for e, p in sorted(probs.items(), key=lambda kv: tuple(-1 if j is None else j for j in kv[0])):
        print("  {%d, %d, %.10g}," % tuple([-1 if j is None else j for j in e] + [p]))
    print("sum P(theta) = %.16g" % sum(probs.values()))
    for t in (0, 1):
        bt = [sum(p for e, p in probs.items() if e[t] == j) for j in range(len(Z6))]
        print("beta[%d] = {%s}, miss = %.10g" % (t, fmt(bt), sum(p for e, p in probs.items() if e[t] is None)))
    print("c literal = %.10g" % c)
    print("lik ratio (c V^m / m!) = %.10g" % ratio)
    xs6, Ps6, beta0 = split_update(XPS, PPS, R, Z6, probs)
    print("beta0 = %.10g" % beta0)
    print("xs = {%s}" % fmt(xs6))
    print("Ps (8x8, row-major) = {%s}" % fmt(Ps6))
    print("min eigenvalue of Ps = %.6g" % min(np.linalg.eigvalsh(Ps6)))

    LAM6 = 2e-4
    probs_p, _, ratio_p, _, _ = split_events(XPS, PPS, R, Z6, PD6, PG6, GAMMA, V6, LAM6)
    print("\n## model 6, parametric: lambda = %g" % LAM6)
    print("events (j1, j2; -1 = undetected), P(theta):")
    for e, p in sorted(probs_p.items(), key=lambda kv: tuple(-1 if j is None else j for j in kv[0])):
        print("  {%d, %d, %.10g}," % tuple([-1 if j is None else j for j in e] + [p]))
    print("lik ratio (c / lambda^m) = %.10g" % ratio_p)

    print("\n## decoupling")
    print("d2 of the model-6 prediction = %.10g" % decouple_d2(XPS, PPS, R))
    xfar = XPS + np.array([0, 0, 0, 0, 60.0, 0, 0, 0])
    print("d2 with target 2 moved +60 in x = %.10g" % decouple_d2(xfar, PPS, R))

    # property: PD = PG = 1, P_12 = 0, one measurement per gate = two Kalman updates
    Pbd = np.block([[PP, np.zeros((4, 4))], [np.zeros((4, 4)), P22]])
    zz = [np.array([103.0, 49.0]), np.array([174.0, 45.0])]
    pr, _, _, _, _ = split_events(xfar, Pbd, R, zz, 1.0, 1.0, GAMMA, V6)
    xs_p, Ps_p, _ = split_update(xfar, Pbd, R, zz, pr)
    x1, P1 = kalman(xfar[:4], PP, R, zz[0])
    x2, P2 = kalman(xfar[4:], P22, R, zz[1])
    print("\n## property: PD = PG = 1, one measurement per target")
    print("events with P > 0: %s" % [(e, p) for e, p in pr.items() if p > 0])
    print("max |stacked - independent| = %.3g" % max(
        np.max(np.abs(xs_p - np.concatenate([x1, x2]))),
        np.max(np.abs(Ps_p - np.block([[P1, np.zeros((4, 4))], [np.zeros((4, 4)), P2]])))))


if __name__ == "__main__":
    main()

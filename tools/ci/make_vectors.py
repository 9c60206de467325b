#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Independent reference computations for docs/ALGORITHMS.md.

Prints docs/TEST_VECTORS.md (Markdown) to stdout. From the repository root:
    python3 tools/ci/make_vectors.py > docs/TEST_VECTORS.md

Only numpy and the Python standard library are used. Every expected number in
docs/TEST_VECTORS.md is produced by this script; nothing is typed by hand.
Where a quantity can be obtained two independent ways (closed form against
numerical integration, greedy against brute force, Joseph against the standard
covariance form, enumeration against dynamic programming) both are computed
and the script asserts that they agree.
"""
import itertools
import math
import sys

import numpy as np

FMT = "%.10g"


# --------------------------------------------------------------------------
# formatting helpers
# --------------------------------------------------------------------------
def f(v):
    return FMT % float(v)


def vec(v):
    return "[" + ", ".join(f(x) for x in np.ravel(v)) + "]"


def mat(M):
    M = np.atleast_2d(M)
    return "[" + "; ".join(", ".join(f(x) for x in row) for row in M) + "]"


OUT = []


def p(s=""):
    OUT.append(s)


def h(title, level=2):
    p()
    p("#" * level + " " + title)
    p()


def kv(name, value):
    if isinstance(value, (np.ndarray, list, tuple)):
        arr = np.asarray(value, dtype=float)
        if arr.ndim == 2:
            p(f"- `{name}` = {mat(arr)}")
        else:
            p(f"- `{name}` = {vec(arr)}")
    elif isinstance(value, (bool, np.bool_)):
        p(f"- `{name}` = {'true' if value else 'false'}")
    elif isinstance(value, (int, np.integer)):
        p(f"- `{name}` = {int(value)}")
    elif isinstance(value, str):
        p(f"- `{name}` = {value}")
    else:
        p(f"- `{name}` = {f(value)}")


def close(a, b, rtol=1e-9, atol=1e-12):
    assert np.allclose(np.asarray(a, float), np.asarray(b, float), rtol=rtol, atol=atol), (a, b)


# --------------------------------------------------------------------------
# models
# --------------------------------------------------------------------------
H = np.array([[1.0, 0, 0, 0], [0, 1.0, 0, 0]])


def cv_F(dt):
    return np.array([[1, 0, dt, 0], [0, 1, 0, dt], [0, 0, 1, 0], [0, 0, 0, 1]], float)


def cv_Q(dt, Sw):
    a, b, c = dt ** 3 / 3.0, dt ** 2 / 2.0, dt
    return Sw * np.array([[a, 0, b, 0], [0, a, 0, b], [b, 0, c, 0], [0, b, 0, c]], float)


def kf_predict(x, P, F, Q):
    xp = F @ x
    Pp = F @ P @ F.T + Q
    return xp, 0.5 * (Pp + Pp.T)


def kf_gain(Pp, R):
    S = H @ Pp @ H.T + R
    S = 0.5 * (S + S.T)
    K = Pp @ H.T @ np.linalg.inv(S)
    return S, K


def joseph(Pp, K, R):
    I = np.eye(Pp.shape[0])
    A = I - K @ H
    P = A @ Pp @ A.T + K @ R @ K.T
    return 0.5 * (P + P.T)


def gate_gamma(PG):
    # chi-square, 2 dof: PG = 1 - exp(-gamma/2)
    g = -2.0 * math.log(1.0 - PG)
    close(chi2_2dof_cdf(g), PG, rtol=1e-12)
    return g


def gauss_legendre(fun, a, b, pieces, order=20):
    """Composite Gauss-Legendre quadrature of fun over [a, b]."""
    xg, wg = np.polynomial.legendre.leggauss(order)
    edges = np.linspace(a, b, pieces + 1)
    total = 0.0
    for lo, hi in zip(edges[:-1], edges[1:]):
        half, mid = 0.5 * (hi - lo), 0.5 * (hi + lo)
        total += half * sum(w * fun(mid + half * x) for x, w in zip(xg, wg))
    return total


def chi2_2dof_cdf(x):
    """P(chi2 with 2 dof <= x), by quadrature of its density exp(-t/2)/2."""
    return gauss_legendre(lambda t: 0.5 * math.exp(-0.5 * t), 0.0, x, 8)


def gate_volume(gamma, S):
    return math.pi * gamma * math.sqrt(np.linalg.det(S))


def maha2(nu, S):
    return float(nu @ np.linalg.solve(S, nu))


def gauss_pdf(nu, S):
    d2 = maha2(nu, S)
    val = math.exp(-0.5 * d2) / (2.0 * math.pi * math.sqrt(np.linalg.det(S)))
    # independent check: whiten with the Cholesky factor of S
    Lc = np.linalg.cholesky(S)
    w = np.linalg.solve(Lc, nu)
    close(val, math.exp(-0.5 * float(w @ w)) / (2.0 * math.pi * Lc[0, 0] * Lc[1, 1]))
    return val


# --------------------------------------------------------------------------
# order statistics
# --------------------------------------------------------------------------
def prank_closed(m, rho):
    """P(rank=l), l=1..m (1 = strongest); product/recurrence form."""
    a = 1.0 / (1.0 + rho)
    P = np.zeros(m)
    p1 = 1.0
    for j in range(1, m):
        p1 *= j / (j + a)
    P[0] = p1
    for l in range(1, m):
        P[l] = P[l - 1] * (l - 1 + a) / l
    return P


def pbarA_paper(m, rho):
    return 1.0 + sum((-1) ** i * math.comb(m - 1, i) / ((i + 1) + i * rho) for i in range(1, m))


def gamma_paper(l, rho):
    if l == 1:
        return 1.0
    num = 1.0
    for j in range(1, l):
        num *= (j - 1) * (1 + rho) + 1
    return num / (math.factorial(l - 1) * (1 + rho) ** (l - 1))


def prank_numint(m, l, rho):
    def integrand(t):
        return ((1 - math.exp(-t)) ** (m - l) * math.exp(-t * (l - 1))
                * math.exp(-t / (1 + rho)) / (1 + rho))
    # the integrand decays at least like exp(-t/(1+rho)); stop where it is below 1e-17
    t_end = 40.0 * (1.0 + rho)
    v = gauss_legendre(integrand, 0.0, t_end, int(4 * t_end))
    return math.comb(m - 1, l - 1) * v


def prank_altsum(m, l, rho):
    s = 0.0
    for i in range(0, m - l + 1):
        s += (-1) ** i * math.comb(m - l, i) / (1 + (i + l - 1) * (1 + rho))
    return math.comb(m - 1, l - 1) * s


def prank_float32(m, rho):
    f32 = np.float32
    a = f32(1) / (f32(1) + f32(rho))
    P = [f32(1)]
    for j in range(1, m):
        P[0] = f32(P[0] * f32(j) / (f32(j) + a))
    for l in range(1, m):
        P.append(f32(P[-1] * (f32(l - 1) + a) / f32(l)))
    return np.array(P, dtype=np.float32)


# --------------------------------------------------------------------------
# IHPDA / IPDA
# --------------------------------------------------------------------------
def ranks_by_intensity(intens, idx):
    """rank 1 = strongest; ties -> lower measurement index ranks stronger."""
    order = sorted(idx, key=lambda j: (-intens[j], j))
    return {j: r + 1 for r, j in enumerate(order)}


def ihpda_candidates(idx, pvals, lams, intens, PD, PG, VG, rho):
    """Return dict j -> (rank, Prank, A, C, L, beta_j, beta_0, delta)."""
    m = len(idx)
    rk = ranks_by_intensity(intens, idx)
    Pr = prank_closed(m, rho)
    out = {}
    for j in idx:
        pr = Pr[rk[j] - 1]
        A = PD * PG * m * pvals[j] * pr / lams[j]
        C = 1.0 - PD * PG + PD * PG * (m / (lams[j] * VG)) * (1.0 - pr)
        L = A + C
        out[j] = dict(rank=rk[j], Prank=pr, A=A, C=C, L=L, beta=A / L, beta0=C / L, delta=1.0 - L)
    return out


def ihpda_select(cands):
    # argmax beta; ties -> stronger rank, then lower index
    return sorted(cands, key=lambda j: (-cands[j]["beta"], cands[j]["rank"], j))[0]


def existence_update(delta, Ppred):
    return (1.0 - delta) * Ppred / (1.0 - delta * Ppred)


def ipda(idx, pvals, lams, PD, PG):
    s = sum(pvals[j] / lams[j] for j in idx)
    L = 1.0 - PD * PG + PD * PG * s
    beta = {j: PD * PG * (pvals[j] / lams[j]) / L for j in idx}
    beta0 = (1.0 - PD * PG) / L
    return L, 1.0 - L, beta, beta0


def pda_update(xp, Pp, K, R, nus, betas, beta0):
    Pc = joseph(Pp, K, R)
    nu_c = sum(b * n for b, n in zip(betas, nus)) if nus else np.zeros(2)
    spread = sum(b * np.outer(n, n) for b, n in zip(betas, nus)) if nus else np.zeros((2, 2))
    spread = spread - np.outer(nu_c, nu_c)
    x = xp + K @ nu_c
    P = beta0 * Pp + (1.0 - beta0) * Pc + K @ spread @ K.T
    return x, 0.5 * (P + P.T)


# --------------------------------------------------------------------------
# assignment
# --------------------------------------------------------------------------
def mmr_static(B):
    """Greedy global max on a fixed matrix; 0 entries = not gated.
    Ties: lowest track index, then lowest measurement index."""
    B = np.asarray(B, float)
    n, m = B.shape
    rows, cols = set(range(n)), set(range(m))
    steps = []
    while True:
        cand = [(-B[i, j], i, j) for i in sorted(rows) for j in sorted(cols) if B[i, j] > 0]
        if not cand:
            break
        _, i, j = min(cand)
        steps.append((i, j, B[i, j]))
        rows.discard(i)
        cols.discard(j)
    return steps


def optimal_bruteforce(B):
    """Lexicographic objective: max #assigned tracks, then max sum of beta.
    Ties: lexicographically smallest assignment vector (none = +inf)."""
    B = np.asarray(B, float)
    n, m = B.shape
    best = None
    options = [[None] + [j for j in range(m) if B[i, j] > 0] for i in range(n)]
    for combo in itertools.product(*options):
        used = [j for j in combo if j is not None]
        if len(used) != len(set(used)):
            continue
        card = len(used)
        tot = sum(B[i, j] for i, j in enumerate(combo) if j is not None)
        keyv = tuple(m + 1 if j is None else j for j in combo)
        cand = (-card, -round(tot, 12), keyv, combo, tot)
        if best is None or cand[:3] < best[:3]:
            best = cand
    return best[3], best[4]


def optimal_dp(B):
    """The solver objective of ALGORITHMS.md §10.2 (weights beta + n + 1 on gated
    pairs, maximised) by dynamic programming over the set of used measurements:
    an independent check of optimal_bruteforce."""
    B = np.asarray(B, float)
    n, m = B.shape
    big = n + 1.0
    best = {0: (0.0, ())}  # used-measurement mask -> (weight, assignment so far)
    for i in range(n):
        nxt = {}
        for mask, (wsum, combo) in best.items():
            opts = [(mask, wsum, combo + (None,))]
            opts += [(mask | (1 << j), wsum + B[i, j] + big, combo + (j,))
                     for j in range(m) if B[i, j] > 0 and not mask & (1 << j)]
            for k, wv, cb in opts:
                if k not in nxt or wv > nxt[k][0] + 1e-12:
                    nxt[k] = (wv, cb)
        best = nxt
    return max(best.values(), key=lambda e: e[0])[1]


# --------------------------------------------------------------------------
# JPDA family
# --------------------------------------------------------------------------
def jpda_events(A, Bmiss):
    """Enumerate feasible joint events. A[t][j] > 0 means gated. Bmiss[t] = miss weight.
    Returns list of (assignment tuple, weight)."""
    A = np.asarray(A, float)
    T, M = A.shape
    opts = [[None] + [j for j in range(M) if A[t, j] > 0] for t in range(T)]
    ev = []
    for combo in itertools.product(*opts):
        used = [j for j in combo if j is not None]
        if len(used) != len(set(used)):
            continue
        w = 1.0
        for t, j in enumerate(combo):
            w *= Bmiss[t] if j is None else A[t, j]
        ev.append((combo, w))
    return ev


def betas_from_events(ev, T, M):
    tot = sum(w for _, w in ev)
    beta = np.zeros((T, M + 1))  # last column = no measurement
    for combo, w in ev:
        for t, j in enumerate(combo):
            beta[t, M if j is None else j] += w / tot
    return beta, tot


def jpda_star_events(ev):
    groups = {}
    for k, (combo, w) in enumerate(ev):
        det = tuple(t for t, j in enumerate(combo) if j is not None)
        meas = tuple(sorted(j for j in combo if j is not None))
        key = (det, meas)
        if key not in groups or w > groups[key][1]:
            groups[key] = (combo, w)
    return list(groups.values())


def cheap_jpda(A, B):
    A = np.asarray(A, float)
    T, M = A.shape
    Tt = A.sum(axis=1)
    Mj = A.sum(axis=0)
    beta = np.zeros((T, M + 1))
    for t in range(T):
        for j in range(M):
            beta[t, j] = A[t, j] / (Tt[t] + Mj[j] - A[t, j] + B) if A[t, j] > 0 else 0.0
        beta[t, M] = B / (Tt[t] + B)
    return beta, Tt, Mj


def suboptimal_jpda(A, B):
    """B may be a scalar or a per-track list."""
    A = np.asarray(A, float)
    T, M = A.shape
    Bt = list(B) if isinstance(B, (list, tuple, np.ndarray)) else [B] * T
    At = [[j for j in range(M) if A[t, j] > 0] for t in range(T)]
    Cj = [[t for t in range(T) if A[t, j] > 0] for j in range(M)]
    Lt = [sorted(set(s for j in At[t] for s in Cj[j]) - {t}) for t in range(T)]

    def N(s, j):
        vals = [A[s, k] for k in At[s] if k != j]
        return max(vals) if vals else 0.0

    D = np.zeros((T, M))
    for t in range(T):
        for j in At[t]:
            D[t, j] = A[t, j] if not Lt[t] else A[t, j] * sum(N(s, j) for s in Lt[t])
    beta = np.zeros((T, M + 1))
    for t in range(T):
        den = Bt[t] + D[t].sum()
        beta[t, :M] = D[t] / den
        beta[t, M] = Bt[t] / den
    Nmat = np.array([[N(s, j) for j in range(M)] for s in range(T)])
    return beta, D, Nmat, At, Cj, Lt


def tv13b_gate_shrink():
    """TV13b: one tracker step of the JPDA family with and without the gate
    shrink of §13.7, end to end: overlap, gates, A and B, events, betas, update."""
    h("TV13b Gate shrink of the adaptive JPDA family (§13.7), one tracker step")
    PD, PG, lam, n_shrink, dist = 0.9, 0.99, 0.01, 3.0, 9.0
    gam = gate_gamma(PG)
    R = np.eye(2)
    xs = [np.array([0.0, 0.0, 0.0, 0.0]), np.array([3.0, 0.0, 0.0, 0.0]), np.array([50.0, 0.0, 0.0, 0.0])]
    P0 = np.eye(4)
    Z = [(-2.2, -1.5), (-1.5, 1.5), (1.2, 0.3), (1.8, -0.2), (3.5, 2.2), (5.2, 0.0), (50.5, 0.5), (52.5, 0.0)]
    p("Inputs: the first frame (no prediction), three seeded tracks (existence 1) with P = I, "
      "measurements in input order z1..z8, meas_sigma = (1, 1), so S = 2 I for every track; "
      "initiate off, merging off.")
    p()
    kv("x1, x2, x3 (positions)", [x[:2] for x in xs]); kv("z", Z)
    kv("PD", PD); kv("PG", PG); kv("clutter_density", lam); kv("gamma", gam)
    kv("adaptive_jpda_distance", dist); kv("adaptive_jpda_shrink", n_shrink)
    # rule 1: overlap on the predicted positions, 9 sigma_m
    T = len(xs)
    over = [any(s_ != t and np.hypot(*(xs[t][:2] - xs[s_][:2])) <= dist * 1.0 for s_ in range(T))
            for t in range(T)]
    assert over == [True, True, False]
    p(f"- overlap (|H x_t - H x_s| <= 9 sigma_m): T1 {over[0]}, T2 {over[1]}, T3 {over[2]}")
    Bmiss = lam * (1.0 - PD * PG) / PD
    kv("B = lambda (1 - PD PG) / PD", Bmiss)
    S, K = kf_gain(P0, R)
    modes = [("jpda", False, "exact"), ("jpda-vg", True, "exact"), ("adaptive-jpda-star", True, "star"),
             ("adaptive-nnjpda", True, "nn"), ("adaptive-jpda", True, "share")]
    for name, shrink, kind in modes:
        gates = []
        for t in range(T):
            g = gam / n_shrink if (shrink and over[t]) else gam
            d2 = [maha2(np.array(z) - xs[t][:2], S) for z in Z]
            for v in d2:   # no pair within 5 % of its gate threshold: float decides the same
                assert abs(v - g) > 0.05 * g
            gates.append([j for j in range(len(Z)) if d2[j] <= g])
        A = np.zeros((T, len(Z)))
        for t in range(T):
            for j in gates[t]:
                A[t, j] = gauss_pdf(np.array(Z[j]) - xs[t][:2], S)
        ev = jpda_events(A, [Bmiss] * T)
        if kind == "star":
            ev = jpda_star_events(ev)
        beta, _ = betas_from_events(ev, T, len(Z))
        M = len(Z)
        p()
        p(f"`{name}`: gates T1 {[j + 1 for j in gates[0]]}, T2 {[j + 1 for j in gates[1]]}, "
          f"T3 {[j + 1 for j in gates[2]]} (measurement numbers); {len(ev)} events of the three tracks together (the clusters factor)"
          + (" kept by JPDA*" if kind == "star" else "") + ":")
        p()
        if kind == "nn":
            steps = mmr_static(beta[:, :M])
            assign = {i: j for i, j, _ in steps}
            p("- NNJPDA assignment on the betas: "
              + ", ".join(f"T{i + 1} -> z{j + 1} (beta {f(v)})" for i, j, v in steps))
        if kind == "share":
            for t in range(T):
                if not over[t]:
                    continue
                shared = False
                for j in gates[t]:
                    nc = sum(1 for s_ in range(T) if over[s_] and j in gates[s_])
                    if nc >= 2:
                        beta[t, j] = 1.0 / nc
                        shared = True
                if shared:
                    tot = beta[t, :M].sum()
                    if tot > 1.0:
                        beta[t, :M] /= tot
                        beta[t, M] = 0.0
                    else:
                        beta[t, M] = 1.0 - tot
        for t in range(T):
            nus = [np.array(Z[j]) - xs[t][:2] for j in gates[t]]
            if kind == "nn":
                j = assign.get(t)
                x, P = pda_update(xs[t], P0, K, R, [np.array(Z[j]) - xs[t][:2]], [1.0], 0.0) \
                    if j is not None else (xs[t], P0)
                p(f"- T{t + 1}: assigned z{j + 1}, x = {vec(x)}, P diagonal = {vec(np.diag(P))}, "
                  f"P[0][1] = {f(P[0, 1])}")
                continue
            x, P = pda_update(xs[t], P0, K, R, nus, [beta[t, j] for j in gates[t]], beta[t, M])
            p(f"- T{t + 1}: beta_0 = {f(beta[t, M])}, beta over its gate = {vec([beta[t, j] for j in gates[t]])}, "
              f"x = {vec(x)}, P diagonal = {vec(np.diag(P))}, P[0][1] = {f(P[0, 1])}")



# ==========================================================================
# main
# ==========================================================================
def main():
    p("# Test vectors for the tracking library (generated)")
    p()
    p("Generated by `tools/ci/make_vectors.py` (numpy and the Python standard library only). "
      "Do not edit by hand: from the repository root, re-run "
      "`python3 tools/ci/make_vectors.py > docs/TEST_VECTORS.md`. Numbers are printed with 10 "
      "significant digits. Compare with 1e-6 relative tolerance and a 1e-9 absolute floor in double "
      "builds, or 1e-4 relative and a 1e-6 absolute floor in float32 builds (ALGORITHMS.md §16). "
      "Matrices are written row-major as `[r11, r12; r21, r22]`. Indices in this file "
      "are 1-based (z1, z2, ... ; T1, T2, ...). State = [x, y, vx, vy], measurement = [x, y].")

    # ---------------------------------------------------------------- TV1
    h("TV1 CV model F and Q (ALGORITHMS.md §2)")
    for dt, Sw in ((1.0, 5.0), (0.25, 5.0)):
        p(f"Inputs: dt = {f(dt)}, Sw = {f(Sw)}")
        p()
        kv("F", cv_F(dt))
        kv("Q", cv_Q(dt, Sw))
        p()

    # ---------------------------------------------------------------- TV2
    h("TV2 Kalman predict + Joseph update (§3)")
    dt, Sw = 1.0, 5.0
    F, Q = cv_F(dt), cv_Q(dt, Sw)
    x0 = np.array([100.0, 50.0, 10.0, -5.0])
    P0 = np.array([[4.0, 1, 1, 0], [1, 4, 0, 1], [1, 0, 1, 0], [0, 1, 0, 1]])
    R = np.array([[1.0, 0.3], [0.3, 2.0]])
    z = np.array([111.5, 44.0])
    p("Inputs:")
    p()
    kv("dt", dt); kv("Sw", Sw); kv("x0 (x_{k-1|k-1})", x0); kv("P0 (P_{k-1|k-1})", P0)
    kv("R", R); kv("z", z)
    xp, Pp = kf_predict(x0, P0, F, Q)
    S, K = kf_gain(Pp, R)
    nu = z - H @ xp
    xu = xp + K @ nu
    Pu = joseph(Pp, K, R)
    Pstd = (np.eye(4) - K @ H) @ Pp
    close(Pu, 0.5 * (Pstd + Pstd.T), rtol=1e-9, atol=1e-10)
    p()
    p("Expected:")
    p()
    kv("x_pred", xp); kv("P_pred", Pp); kv("z_hat = H x_pred", H @ xp); kv("S", S)
    kv("K", K); kv("nu", nu); kv("d2 = nu' S^-1 nu", maha2(nu, S))
    kv("x_upd", xu); kv("P_upd (Joseph)", Pu)
    p()
    p("Check: the standard form (I-KH)P_pred equals the Joseph result to round-off.")

    # ---------------------------------------------------------------- TV3
    h("TV3 Gating, gate volume, Gaussian likelihood (§4)")
    PG = 0.99
    g = gate_gamma(PG)
    zhat = H @ xp
    VG = gate_volume(g, S)
    offs = [np.array([0.8, -0.5]), np.array([-3.5, 2.4]), np.array([5.0, 3.0]),
            np.array([8.0, -7.0]), np.array([9.0, 0.0])]
    p("Inputs: S and z_hat from TV2, PG = 0.99. Candidate measurements z = z_hat + offset:")
    p()
    for i, o in enumerate(offs):
        p(f"- c{i+1}: z = {vec(zhat + o)}  (offset {vec(o)})")
    p()
    p("Expected:")
    p()
    kv("gamma = -2 ln(1-PG)", g)
    kv("V_G = pi * gamma * sqrt(det S)", VG)
    kv("det S", np.linalg.det(S))
    for i, o in enumerate(offs):
        d2 = maha2(o, S)
        inside = d2 <= g
        line = f"- c{i+1}: d2 = {f(d2)}, gated = {'true' if inside else 'false'}"
        if inside:
            N = gauss_pdf(o, S)
            line += f", N(nu;0,S) = {f(N)}, p = N/PG = {f(N / PG)}"
        p(line)

    # ---------------------------------------------------------------- TV4
    h("TV4 Intensity order statistics (§7.2)")
    p("Clutter intensity ~ Exp(1), target intensity ~ Exp(mean 1+rho), m gated measurements "
      "(target + m-1 clutter). `Prank[l]` = P(target has rank l), l = 1 is the strongest. "
      "Closed form a = 1/(1+rho), Prank[1] = prod_{j=1}^{m-1} j/(j+a), "
      "Prank[l+1] = Prank[l]*(l-1+a)/l. `PbarA` and `gamma(l)` are the formulas of [S0] eq. (3); "
      "`gamma(l)*PbarA` reproduces Prank exactly.")
    maxdev_paper = 0.0
    for (m, rho) in [(1, 0.0), (3, 0.0), (3, 3.0), (5, 3.0), (8, 10.0)]:
        Pr = prank_closed(m, rho)
        PA = pbarA_paper(m, rho)
        gam = np.array([gamma_paper(l, rho) for l in range(1, m + 1)])
        num = np.array([prank_numint(m, l, rho) for l in range(1, m + 1)])
        alt = np.array([prank_altsum(m, l, rho) for l in range(1, m + 1)])
        close(Pr, num, rtol=1e-9)
        close(Pr, alt, rtol=1e-9)
        close(Pr, gam * PA, rtol=1e-9)
        close(Pr[-1], 1.0 / (m + (m - 1) * rho), rtol=1e-12)
        close(Pr.sum(), 1.0, rtol=1e-12)
        maxdev_paper = max(maxdev_paper, float(np.max(np.abs(gam * PA - num) / num)))
        p()
        p(f"**m = {m}, rho = {f(rho)}**")
        p()
        kv("PbarA(m) ([S0] alternating sum)", PA)
        kv("gamma(l), l=1..m ([S0] product)", gam)
        kv("Prank[l], l=1..m (closed form)", Pr)
        kv("Prank by numerical integration", num)
        kv("1/(m+(m-1)rho) (= Prank[m])", 1.0 / (m + (m - 1) * rho))
        kv("Prank in float32 (product form)", prank_float32(m, rho).astype(float))
    p()
    assert maxdev_paper < 1e-13, maxdev_paper
    p("Max relative deviation of [S0]'s gamma(l)*PbarA(m) from numerical integration over "
      "these cases: below 1e-13 (double precision round-off and quadrature error only).")
    p()
    from fractions import Fraction

    def exact_frac(m, rho):
        a = Fraction(1) / (1 + Fraction(rho))
        ex = [Fraction(1)]
        for j in range(1, m):
            ex[0] *= Fraction(j) / (j + a)
        for l in range(1, m):
            ex.append(ex[-1] * (l - 1 + a) / l)
        return ex

    def altsum_f32(m, rho):
        f32 = np.float32
        s_ = f32(1)
        for i in range(1, m):
            term = f32(math.comb(m - 1, i)) / (f32(i + 1) + f32(i) * f32(rho))
            s_ = f32(s_ + f32((-1) ** i) * term)
        return float(s_)

    def altsum_f64(m, rho):
        return pbarA_paper(m, rho)

    p()
    p("Precision study (exact rational reference, computed by the generator):")
    p()
    for rho in (0.0, 1.0, 3.0, 10.0, 100.0):
        first32 = first64 = None
        for m in range(1, 129):
            ex = float(exact_frac(m, rho)[0])
            if first32 is None and abs(altsum_f32(m, rho) - ex) / ex > 1e-3:
                first32 = m
            if first64 is None and abs(altsum_f64(m, rho) - ex) / ex > 1e-6:
                first64 = m
        p(f"- rho = {f(rho)}: [S0] alternating sum for PbarA first exceeds 1e-3 relative error at "
          f"m = {first32} in float32, and 1e-6 at m = {first64} in float64")
    for M in (16, 32, 64):
        worst = 0.0
        for rho in (0.0, 0.5, 1.0, 3.0, 10.0, 100.0):
            for m in range(1, M + 1):
                ex = exact_frac(m, rho)
                got = prank_float32(m, rho)
                worst = max(worst, max(abs(float(gv) - float(e)) / float(e) for gv, e in zip(got, ex)))
        p(f"- product/recurrence form in float32, all l, m = 1..{M}, rho in {{0,0.5,1,3,10,100}}: "
          f"worst relative error {'%.3g' % worst}")
    # restricted alternating sums and lgamma form
    w32 = max(abs(altsum_f32(m, rho) - float(exact_frac(m, rho)[0])) / float(exact_frac(m, rho)[0])
              for rho in (0.0, 0.5, 1.0, 3.0, 10.0, 100.0) for m in range(1, 11))
    w64 = max(abs(altsum_f64(m, rho) - float(exact_frac(m, rho)[0])) / float(exact_frac(m, rho)[0])
              for rho in (0.0, 0.5, 1.0, 3.0, 10.0, 100.0) for m in range(1, 31))
    p(f"- [S0] alternating sum restricted to m <= 10 in float32: worst relative error {'%.3g' % w32}; "
      f"restricted to m <= 30 in float64: {'%.3g' % w64}")
    f32 = np.float32
    wl = 0.0
    for rho in (0.0, 0.5, 1.0, 3.0, 10.0, 100.0):
        for m in range(1, 33):
            a32 = f32(1) / (f32(1) + f32(rho))
            ex = exact_frac(m, rho)
            for l in range(1, m + 1):
                v = (f32(math.log(a32)) + f32(math.lgamma(m)) + f32(math.lgamma(l - 1 + float(a32)))
                     - f32(math.lgamma(l)) - f32(math.lgamma(m + float(a32))))
                got = float(f32(np.exp(f32(v))))
                wl = max(wl, abs(got - float(ex[l - 1])) / float(ex[l - 1]))
    p(f"- log-domain (lgamma) form with float32 rounding of each term, m = 1..32: worst relative "
      f"error {'%.3g' % wl}")

    # ---------------------------------------------------------------- TV5
    h("TV5 IHPDA, one track, three gated measurements (§7)")
    PD, PG, lam, rho, Pex = 0.9, 0.99, 0.002, 3.0, 0.6
    g = gate_gamma(PG)
    VG = gate_volume(g, S)
    meas_off = {0: np.array([0.8, -0.5]), 1: np.array([-3.5, 2.4]), 2: np.array([5.0, 3.0])}
    intens = {0: 40.0, 1: 95.0, 2: 60.0}
    Z = {j: zhat + o for j, o in meas_off.items()}
    p("Inputs: track prediction x_pred, P_pred, S, K from TV2 (z_hat = H x_pred), R from TV2.")
    p()
    kv("PD", PD); kv("PG", PG); kv("lambda (clutter density, per unit area)", lam)
    kv("rho (target mean intensity / clutter mean intensity - 1)", rho)
    kv("P(exist | Z^{k-1}) (predicted existence)", Pex)
    for j in range(3):
        p(f"- z{j+1} = {vec(Z[j])}, intensity = {f(intens[j])}")
    idx = [0, 1, 2]
    pv, lams = {}, {}
    for j in idx:
        assert maha2(meas_off[j], S) <= g
        pv[j] = gauss_pdf(meas_off[j], S) / PG
        lams[j] = lam
    cands = ihpda_candidates(idx, pv, lams, intens, PD, PG, VG, rho)
    tv5_p, tv5_vg = [pv[j] for j in idx], VG  # TV15's amplitude row reuses this gate
    s = ihpda_select(cands)
    c = cands[s]
    p()
    p("Expected (per candidate j, m = 3):")
    p()
    kv("gamma", g); kv("V_G", VG)
    for j in idx:
        cj = cands[j]
        p(f"- z{j+1}: d2 = {f(maha2(meas_off[j], S))}, p = {f(pv[j])}, rank = {cj['rank']}, "
          f"Prank = {f(cj['Prank'])}, L = {f(cj['L'])}, beta_j = {f(cj['beta'])}, "
          f"beta_0 = {f(cj['beta0'])}, delta = {f(cj['delta'])}")
    p(f"- selected measurement: z{s+1} (largest beta_j)")
    Pnew = existence_update(c["delta"], Pex)
    kv("P(exist | Z^k) after update", Pnew)
    xs, Ps = pda_update(xp, Pp, K, R, [meas_off[s]], [c["beta"]], c["beta0"])
    kv("x_upd (single-measurement PDA update)", xs)
    kv("P_upd", Ps)
    # m = 0
    p()
    p("Sub-case m = 0 (no gated measurement): delta = PD*PG.")
    p()
    kv("delta", PD * PG)
    kv("P(exist | Z^k)", existence_update(PD * PG, Pex))
    p()
    p("State: x_upd = x_pred, P_upd = P_pred.")
    # equivalence with IPDA for m = 1
    p()
    p("Sub-case m = 1 (only z1 gated): IHPDA must equal IPDA for any rho.")
    p()
    for rr in (0.0, 3.0):
        c1 = ihpda_candidates([0], pv, lams, intens, PD, PG, VG, rr)[0]
        L1, d1, b1, b01 = ipda([0], pv, lams, PD, PG)
        close(c1["L"], L1); close(c1["beta"], b1[0]); close(c1["beta0"], b01)
        p(f"- rho = {f(rr)}: L = {f(c1['L'])}, beta_1 = {f(c1['beta'])}, beta_0 = {f(c1['beta0'])}, "
          f"P(exist|Z^k) = {f(existence_update(c1['delta'], Pex))}")
    # rho = 0 with 3 measurements: IPDA with unselected likelihoods replaced by 1/V_G
    p()
    p("Sub-case rho = 0, m = 3, candidate z1: IHPDA L equals IPDA L with p2, p3 replaced by 1/V_G.")
    c0 = ihpda_candidates(idx, pv, lams, intens, PD, PG, VG, 0.0)[0]
    pv_mod = {0: pv[0], 1: 1.0 / VG, 2: 1.0 / VG}
    Lm, _, _, _ = ipda(idx, pv_mod, lams, PD, PG)
    close(c0["L"], Lm)
    p()
    kv("L (both ways)", Lm)

    # ---------------------------------------------------------------- TV6
    h("TV6 IPDA (all gated measurements) on the TV5 inputs (§6)")
    L, d, b, b0 = ipda(idx, pv, lams, PD, PG)
    kv("L = 1 - delta", L); kv("delta", d)
    kv("beta_1..3", [b[j] for j in idx]); kv("beta_0", b0)
    kv("P(exist | Z^k)", existence_update(d, Pex))
    xi, Pi = pda_update(xp, Pp, K, R, [meas_off[j] for j in idx], [b[j] for j in idx], b0)
    kv("x_upd", xi); kv("P_upd", Pi)
    mhat = 3 - PD * PG * Pex
    p()
    p("Non-parametric clutter density for the same gate (§5.2): lambda_hat = (m - PD*PG*P(exist|Z^{k-1}))/V_G")
    p()
    kv("lambda_hat", mhat / VG)
    lamh = {j: mhat / VG for j in idx}
    Lh, dh, bh, b0h = ipda(idx, pv, lamh, PD, PG)
    kv("IPDA with lambda_hat: delta", dh); kv("beta_1..3", [bh[j] for j in idx]); kv("beta_0", b0h)
    kv("P(exist | Z^k)", existence_update(dh, Pex))

    # ---------------------------------------------------------------- TV7
    h("TV7 Markov chain one existence prediction (§11)")
    for (P, p11, p21) in ((0.9, 0.98, 0.0), (0.9, 0.98, 0.01), (0.1, 0.98, 0.0)):
        p(f"- P_(k-1|k-1) = {f(P)}, p11 = {f(p11)}, p21 = {f(p21)} -> "
          f"P_(k|k-1) = {f(p11 * P + p21 * (1 - P))}")

    # ---------------------------------------------------------------- TV8
    h("TV8 LM clutter density, LM-IPDA and LM-IHPDA with MMR (§8, §10)")
    PD, PG, lam, rho = 0.9, 0.99, 0.002, 3.0
    g = gate_gamma(PG)
    tracks = {
        0: dict(zhat=np.array([0.0, 0.0]), S=np.array([[4.0, 1.0], [1.0, 3.0]]), Pex=0.8),
        1: dict(zhat=np.array([5.0, 1.0]), S=np.array([[3.0, -0.5], [-0.5, 5.0]]), Pex=0.5),
    }
    Zm = {0: np.array([-1.5, 0.5]), 1: np.array([2.4, 0.9]), 2: np.array([6.8, 2.5])}
    It = {0: 50.0, 1: 120.0, 2: 70.0}
    p("Inputs (tracks given directly by predicted measurement z_hat and innovation covariance S):")
    p()
    kv("PD", PD); kv("PG", PG); kv("lambda", lam); kv("rho", rho)
    for t, tr in tracks.items():
        p(f"- T{t+1}: z_hat = {vec(tr['zhat'])}, S = {mat(tr['S'])}, P(exist|Z^{{k-1}}) = {f(tr['Pex'])}")
    for j in Zm:
        p(f"- z{j+1} = {vec(Zm[j])}, intensity = {f(It[j])}")
    G, pvt, VGt = {}, {}, {}
    p()
    p("Expected:")
    p()
    for t, tr in tracks.items():
        VGt[t] = gate_volume(g, tr["S"])
        G[t] = []
        pvt[t] = {}
        for j in Zm:
            nu_ = Zm[j] - tr["zhat"]
            d2 = maha2(nu_, tr["S"])
            if d2 <= g:
                G[t].append(j)
                pvt[t][j] = gauss_pdf(nu_, tr["S"]) / PG
            p(f"- T{t+1}, z{j+1}: d2 = {f(d2)}, gated = {'true' if d2 <= g else 'false'}"
              + (f", p = {f(pvt[t][j])}" if d2 <= g else ""))
        p(f"- T{t+1}: V_G = {f(VGt[t])}, gated set = {{{', '.join('z%d' % (j+1) for j in G[t])}}}")
    assert G == {0: [0, 1], 1: [1, 2]}
    # LM
    Pbar = {t: {} for t in tracks}
    for s_, tr in tracks.items():
        den = sum(pvt[s_][l] / lam for l in G[s_])
        for j in G[s_]:
            Pbar[s_][j] = PD * PG * tr["Pex"] * (pvt[s_][j] / lam) / den
    Sacc = {j: 0.0 for j in Zm}
    for s_ in tracks:
        for j in G[s_]:
            Sacc[j] += pvt[s_][j] * Pbar[s_][j] / (1 - Pbar[s_][j])
    lt = {t: {} for t in tracks}
    for t in tracks:
        for j in G[t]:
            direct = lam + sum(pvt[s_][j] * Pbar[s_][j] / (1 - Pbar[s_][j])
                               for s_ in tracks if s_ != t and j in G[s_])
            viaS = lam + Sacc[j] - pvt[t][j] * Pbar[t][j] / (1 - Pbar[t][j])
            close(direct, viaS)
            lt[t][j] = direct
    for t in tracks:
        for j in G[t]:
            p(f"- Ptilde_j^sigma ([S0]'s Pbar): sigma = T{t+1}, j = z{j+1}: {f(Pbar[t][j])}")
    for j in Zm:
        p(f"- W_j (sum over tracks gating z{j+1} of p*Ptilde/(1-Ptilde)) = {f(Sacc[j])}")
    for t in tracks:
        for j in G[t]:
            p(f"- lambda_tilde for T{t+1}, z{j+1} = {f(lt[t][j])}")
    # LM-IPDA
    p()
    p("LM-IPDA (IPDA with lambda replaced by lambda_tilde):")
    p()
    for t, tr in tracks.items():
        L, d, b, b0 = ipda(G[t], pvt[t], lt[t], PD, PG)
        p(f"- T{t+1}: delta = {f(d)}, beta = {{{', '.join('z%d: %s' % (j+1, f(b[j])) for j in G[t])}}}, "
          f"beta_0 = {f(b0)}, P(exist|Z^k) = {f(existence_update(d, tr['Pex']))}")
    # LM-IHPDA initial betas
    p()
    p("LM-IHPDA initial beta matrix (each track ranks its own gated set by intensity):")
    p()
    cand0 = {}
    for t in tracks:
        cand0[t] = ihpda_candidates(G[t], pvt[t], lt[t], It, PD, PG, VGt[t], rho)
        for j in G[t]:
            cj = cand0[t][j]
            p(f"- T{t+1}, z{j+1}: m = {len(G[t])}, rank = {cj['rank']}, Prank = {f(cj['Prank'])}, "
              f"beta = {f(cj['beta'])}, beta_0 = {f(cj['beta0'])}, delta = {f(cj['delta'])}")
    # MMR with recomputation
    p()
    p("MMR with recomputation (§10.1):")
    p()
    free = set(Zm)
    assigned = {}
    it = 0
    while True:
        best = None
        for t in sorted(tracks):
            if t in assigned:
                continue
            av = [j for j in G[t] if j in free]
            if not av:
                continue
            cands = ihpda_candidates(av, pvt[t], lt[t], It, PD, PG, VGt[t], rho)
            for j in sorted(av):
                key = (-cands[j]["beta"], t, j)
                if best is None or key < best[0]:
                    best = (key, t, j, cands[j]["beta"], len(av))
        if best is None:
            break
        it += 1
        _, t, j, bv, mm = best
        p(f"- iteration {it}: global max beta = {f(bv)} at (T{t+1}, z{j+1}) with m = {mm}; "
          f"assign z{j+1} -> T{t+1}")
        assigned[t] = j
        free.discard(j)
    p()
    p("Final recomputation (each track's gated set minus measurements assigned to other tracks):")
    p()
    for t, tr in tracks.items():
        others = {assigned[u] for u in assigned if u != t}
        av = [j for j in G[t] if j not in others]
        if t in assigned:
            cands = ihpda_candidates(av, pvt[t], lt[t], It, PD, PG, VGt[t], rho)
            cj = cands[assigned[t]]
            p(f"- T{t+1}: assigned z{assigned[t]+1}, m = {len(av)}, rank = {cj['rank']}, "
              f"Prank = {f(cj['Prank'])}, beta = {f(cj['beta'])}, beta_0 = {f(cj['beta0'])}, "
              f"delta = {f(cj['delta'])}, P(exist|Z^k) = {f(existence_update(cj['delta'], tr['Pex']))}")
        else:
            p(f"- T{t+1}: no measurement, delta = PD*PG = {f(PD * PG)}, "
              f"P(exist|Z^k) = {f(existence_update(PD * PG, tr['Pex']))}")
    # optimal 2D on the initial matrix
    Bm = np.zeros((2, 3))
    for t in tracks:
        for j in G[t]:
            Bm[t, j] = cand0[t][j]["beta"]
    opt, tot = optimal_bruteforce(Bm)
    assert opt == optimal_dp(Bm)
    p()
    p("Optimal 2D assignment on the initial LM-IHPDA beta matrix (§10.2): "
      + ", ".join(f"T{t+1} -> z{j+1}" for t, j in enumerate(opt) if j is not None)
      + f", sum of beta = {f(tot)} (MMR sum on the same initial matrix = "
      + f"{f(sum(Bm[t, j] for t, j in assigned.items()))}). Final recomputation for the optimal result:")
    p()
    asg = {t: j for t, j in enumerate(opt) if j is not None}
    for t, tr in tracks.items():
        others = {asg[u] for u in asg if u != t}
        av = [j for j in G[t] if j not in others]
        cands = ihpda_candidates(av, pvt[t], lt[t], It, PD, PG, VGt[t], rho)
        cj = cands[asg[t]]
        p(f"- T{t+1}: assigned z{asg[t]+1}, m = {len(av)}, rank = {cj['rank']}, "
          f"Prank = {f(cj['Prank'])}, beta = {f(cj['beta'])}, beta_0 = {f(cj['beta0'])}, "
          f"delta = {f(cj['delta'])}, P(exist|Z^k) = {f(existence_update(cj['delta'], tr['Pex']))}")

    # ---------------------------------------------------------------- TV8c
    h("TV8c LM density over all tracks: lm-ipda-all, [S4]'s LM-IPDAF (§8.3)")
    PD, PG, lam = 0.9, 0.99, 1e-6
    g = gate_gamma(PG)
    tracks = {
        0: dict(zhat=np.array([0.0, 0.0]), S=np.array([[1.0, 0.2], [0.2, 0.8]]), Pex=0.9),
        1: dict(zhat=np.array([4.0, 0.5]), S=np.array([[1.2, -0.1], [-0.1, 1.0]]), Pex=0.6),
        2: dict(zhat=np.array([20.0, 20.0]), S=np.array([[1.0, 0.0], [0.0, 1.0]]), Pex=0.5),
    }
    Zm = {0: np.array([0.3, -0.2]), 1: np.array([2.0, 0.3]), 2: np.array([4.8, 1.0]), 3: np.array([20.5, 19.8])}
    p("Inputs (tracks by z_hat and S, as TV8; T3 is far from the others):")
    p()
    kv("PD", PD); kv("PG", PG); kv("lambda", lam)
    for t, tr in tracks.items():
        p(f"- T{t+1}: z_hat = {vec(tr['zhat'])}, S = {mat(tr['S'])}, P(exist|Z^{{k-1}}) = {f(tr['Pex'])}")
    for j in Zm:
        p(f"- z{j+1} = {vec(Zm[j])}")
    # p of every (track, measurement), untruncated; G from the gate test
    pu = {t: {j: gauss_pdf(Zm[j] - tr["zhat"], tr["S"]) / PG for j in Zm} for t, tr in tracks.items()}
    G = {t: [j for j in Zm if maha2(Zm[j] - tr["zhat"], tr["S"]) <= g] for t, tr in tracks.items()}
    assert G == {0: [0, 1], 1: [1, 2], 2: [3]}
    tot = {t: sum(pu[t][l] for l in G[t]) for t in tracks}

    def w_of(s_, j, truncated):
        """w_j^s of §8.1 (truncated: 0 outside G^s) or §8.3 (P~ over G^s and j)."""
        if j in G[s_]:
            pt = PD * PG * tracks[s_]["Pex"] * pu[s_][j] / tot[s_]
        elif truncated:
            return 0.0
        else:
            pt = PD * PG * tracks[s_]["Pex"] * pu[s_][j] / (tot[s_] + pu[s_][j])
        return pu[s_][j] * pt / (1.0 - pt)

    p()
    p("Expected: the terms of the tracks that do not gate a measurement that some gate holds:")
    p()
    for s_ in tracks:
        for j in Zm:
            if j not in G[s_] and any(j in G[t] for t in tracks):
                p(f"- T{s_+1}, z{j+1}: d2 = {f(maha2(Zm[j] - tracks[s_]['zhat'], tracks[s_]['S']))}, "
                  f"p (untruncated) = {f(pu[s_][j])}, w = {f(w_of(s_, j, False))}")
    lt_c, lt_a = {}, {}
    for t in tracks:
        for j in G[t]:
            # cluster form: the truncated sum over every other track is §8.2's (§8.1)
            lt_c[(t, j)] = lam + sum(w_of(s_, j, True) for s_ in tracks if s_ != t)
            direct = lam + sum(w_of(s_, j, False) for s_ in tracks if s_ != t)
            out_j = sum(w_of(s_, j, False) for s_ in tracks if j not in G[s_])
            close(direct, lt_c[(t, j)] + out_j)          # §8.3's decomposition
            lt_a[(t, j)] = direct
            p(f"- T{t+1}, z{j+1}: lambda_tilde lm-ipda = {f(lt_c[(t, j)])} ({f(lt_c[(t, j)] / lam)} lambda), "
              f"lm-ipda-all = {f(lt_a[(t, j)])} ({f(lt_a[(t, j)] / lam)} lambda)")
    p()
    p("LM-IPDA with the all-tracks density (lm-ipda-all):")
    p()
    for t, tr in tracks.items():
        L, d, b, b0 = ipda(G[t], pu[t], {j: lt_a[(t, j)] for j in G[t]}, PD, PG)
        p(f"- T{t+1}: delta = {f(d)}, beta = {{{', '.join('z%d: %s' % (j+1, f(b[j])) for j in G[t])}}}, "
          f"beta_0 = {f(b0)}, P(exist|Z^k) = {f(existence_update(d, tr['Pex']))}")

    # ---------------------------------------------------------------- TV8b
    h("TV8b Cluster formation (§9)")
    gates = {0: [0, 1], 1: [1, 2], 2: [3], 3: [3], 4: []}
    nmeas = 5
    p("Input gating lists ([S0] Fig. 1 / Table 2 pattern plus an isolated track T5 and a "
      "measurement z5 gated by nobody):")
    p()
    for t, g_ in gates.items():
        p(f"- T{t+1}: {{{', '.join('z%d' % (j+1) for j in g_)}}}")
    parent = list(range(len(gates)))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    owner = {}
    for t in sorted(gates):
        for j in gates[t]:
            if j in owner:
                ra, rb = find(owner[j]), find(t)
                if ra != rb:
                    parent[max(ra, rb)] = min(ra, rb)
            else:
                owner[j] = t
    clusters = {}
    for t in sorted(gates):
        clusters.setdefault(find(t), []).append(t)
    p()
    p("Expected clusters (ordered by smallest track index):")
    p()
    for k, (root, ts) in enumerate(sorted(clusters.items())):
        ms = sorted({j for t in ts for j in gates[t]})
        p(f"- cluster {k+1}: tracks {{{', '.join('T%d' % (t+1) for t in ts)}}}, "
          f"measurements {{{', '.join('z%d' % (j+1) for j in ms)}}}")
    ungated = [j for j in range(nmeas) if j not in owner]
    p(f"- measurements in no gate: {{{', '.join('z%d' % (j+1) for j in ungated)}}}")

    # ---------------------------------------------------------------- TV9
    h("TV9 MMR (static matrix) vs optimal 2D assignment (§10)")
    B = np.array([[0.70, 0.60, 0.00, 0.10],
                  [0.65, 0.05, 0.00, 0.20],
                  [0.00, 0.55, 0.50, 0.00]])
    p("Input beta matrix (rows T1..T3, columns z1..z4; 0 = not gated). Both T1 and T2 have "
      "their row maximum on z1 (conflict). No recomputation (pure greedy on fixed values):")
    p()
    kv("B", B)
    steps = mmr_static(B)
    p()
    p("Expected MMR (global maximum, remove row and column, repeat; ties -> lowest track, then "
      "lowest measurement index):")
    p()
    for k, (i, j, v) in enumerate(steps):
        p(f"- step {k+1}: T{i+1} -> z{j+1} (beta = {f(v)})")
    p(f"- total = {f(sum(v for _, _, v in steps))}")
    opt, tot = optimal_bruteforce(B)
    assert opt == optimal_dp(B)
    p()
    p("Expected optimal 2D assignment (max number of assigned tracks, then max sum of beta):")
    p()
    p("- " + ", ".join(f"T{t+1} -> z{j+1}" for t, j in enumerate(opt) if j is not None)
      + f"; total = {f(tot)}")
    # tie case
    Bt = np.array([[0.5, 0.5], [0.5, 0.2]])
    st = mmr_static(Bt)
    p()
    p("Tie-break case: B = " + mat(Bt) + " -> MMR: "
      + ", ".join(f"T{i+1} -> z{j+1}" for i, j, _ in st)
      + " (three entries equal 0.5; lowest track index, then lowest measurement index wins).")

    # ---------------------------------------------------------------- TV10
    h("TV10 Two-point differencing initiation (§12.1)")
    for (za, zb, dT, Rr, Vmax) in ((np.array([100.0, 200.0]), np.array([130.0, 190.0]), 1.0,
                                    np.diag([1.0, 1.0]), 60.0),
                                   (np.array([10.0, 20.0]), np.array([14.0, 17.0]), 0.5,
                                    np.diag([4.0, 9.0]), 12.0),
                                   (np.array([100.0, 200.0]), np.array([150.0, 240.0]), 1.0,
                                    np.diag([1.0, 1.0]), 60.0)):
        dist = float(np.linalg.norm(zb - za))
        ok = dist <= Vmax * dT
        p(f"Inputs: z_(k-1) = {vec(za)}, z_k = {vec(zb)}, dT = {f(dT)}, R = {mat(Rr)}, Vmax = {f(Vmax)}")
        p()
        kv("|z_k - z_(k-1)|", dist); kv("Vmax*dT", Vmax * dT); kv("initiate", ok)
        if ok:
            x22 = np.array([zb[0], zb[1], (zb[0] - za[0]) / dT, (zb[1] - za[1]) / dT])
            P22 = np.block([[Rr, Rr / dT], [Rr / dT, 2 * Rr / dT ** 2]])
            kv("x_{2|2}", x22); kv("P_{2|2}", P22)
        p()

    # ---------------------------------------------------------------- TV11
    h("TV11 Track merge test (§12.3)")
    cases = [
        (np.array([100.0, 50.0, 10.0, -5.0]), np.diag([1.0, 1.0, 0.5, 0.5]),
         np.array([100.6, 49.7, 10.3, -5.2]), np.diag([2.0, 2.0, 1.0, 1.0])),
        (np.array([100.0, 50.0, 10.0, -5.0]), np.diag([1.0, 1.0, 0.5, 0.5]),
         np.array([101.5, 49.0, 10.3, -5.2]), np.diag([2.0, 2.0, 1.0, 1.0])),
    ]
    for k, (xa, Pa, xb, Pb) in enumerate(cases):
        dv = xa - xb
        d2 = float(dv @ np.linalg.solve(Pa + Pb, dv))
        merge = d2 < 1.0
        p(f"Case {k+1}: x_a = {vec(xa)}, P_a = {mat(Pa)}, x_b = {vec(xb)}, P_b = {mat(Pb)}, t_merge = 1")
        p()
        kv("d2 = (x_a-x_b)'(P_a+P_b)^-1(x_a-x_b)", d2); kv("merge (d2 < t_merge)", merge)
        if merge:
            ta, tb = np.trace(Pa[:2, :2]), np.trace(Pb[:2, :2])
            p(f"- survivor: track {'a' if ta <= tb else 'b'} (trace of position covariance "
              f"{f(min(ta, tb))} < {f(max(ta, tb))})")
        p()

    # ---------------------------------------------------------------- TV12
    h("TV12 Intensity-based initial gate f(I) (§12.2)")

    def fI(I):
        f1 = -0.0007 * I * I + 0.5072 * I + 39.70
        f2 = -0.0001 * I * I + 0.2097 * I + 57.25
        if I <= 150:
            return f1, f1, f2, None
        if I > 250:
            return f2, f1, f2, None
        w1 = -0.01 * I + 2.5
        return w1 * f1 + (1 - w1) * f2, f1, f2, w1

    for I in (0.0, 100.0, 150.0, 200.0, 250.0, 1000.0):
        val, f1, f2, w1 = fI(I)
        sig = val / 3.0
        line = (f"- I = {f(I)}: f1 = {f(f1)}, f2 = {f(f2)}" + (f", w1 = {f(w1)}" if w1 is not None else "")
                + f", f(I) = {f(val)}; sigma_P (sqrt(gamma)=3) = {f(sig)}, sigma_P^2 = {f(sig**2)}")
        p(line)
    Ipk = 0.2097 / 0.0002
    p()
    p("Library extension (not in [S2]): clamp I to [0, I_peak] with I_peak = 0.2097/0.0002 = "
      f"{f(Ipk)} where f2 is maximal; f(I_peak) = {f(fI(Ipk)[0])}; raw [S2] f(2000) = {f(fI(2000.0)[0])}, "
      f"clamped f(2000) = {f(fI(Ipk)[0])}.")
    p()
    p("Gate with sigma_P (§12.2): for I = 200, R = diag(1,1), gamma = 9: S0 = diag(sigma_P^2+1, sigma_P^2+1), "
      "pair accepted if d' S0^-1 d <= gamma; equivalent radius:")
    val = fI(200.0)[0]
    sg = val / 3.0
    p()
    kv("radius = sqrt(gamma*(sigma_P^2+1))", math.sqrt(9.0 * (sg ** 2 + 1.0)))
    p()
    p("Maximum pixel motion, [S2] eq. (3)-(4): d = 340*Mach/fr, dx = atan(d/R)/IFOV. "
      "Inputs Mach = 2, fr = 4 Hz, IFOV = 0.3 mrad:")
    p()
    d = 340.0 * 2.0 / 4.0
    kv("d [m/frame]", d)
    for Rng in (3000.0, 10000.0, 17000.0):
        p(f"- R = {f(Rng)} m: dx = {f(math.atan(d / Rng) / 0.3e-3)} pixel/frame")

    # ---------------------------------------------------------------- TV13
    h("TV13 JPDA family on the [S1] two-track / three-measurement example (§13)")
    A = np.array([[0.50, 0.30, 0.00],
                  [0.00, 0.40, 0.20]])
    Bb = 0.10
    p("Inputs: A[t][j] (rows T1, T2; columns z1..z3; A13 = A21 = 0 = not gated), B = 0.1 "
      "(same B for both tracks).")
    p()
    kv("A", A); kv("B", Bb)
    cb, Tt, Mj = cheap_jpda(A, Bb)
    p()
    p("Cheap JPDA (Fitzgerald numerator/denominator, Blair beta_t0); raw values, "
      "row sums are not 1:")
    p()
    kv("T_t (row sums)", Tt); kv("M_j (column sums)", Mj)
    for t in range(2):
        p(f"- T{t+1}: beta_t0 = {f(cb[t, 3])}, beta_t1..t3 = {vec(cb[t, :3])}, row sum = {f(cb[t].sum())}, "
          f"row-normalised = {vec(cb[t] / cb[t].sum())} (order z1, z2, z3, none)")
    sb, D, Nm, At, Cj, Lt = suboptimal_jpda(A, Bb)
    p()
    p("Suboptimal JPDA (Roecker form as given in [S1]):")
    p()
    p("- A_1 = {z1, z2}, A_2 = {z2, z3}; C_1 = {T1}, C_2 = {T1, T2}, C_3 = {T2}; L_1 = {T2}, L_2 = {T1}")
    assert At == [[0, 1], [1, 2]] and Cj == [[0], [0, 1], [1]] and Lt == [[1], [0]]
    kv("N[s][j] = max_{k in A_s, k != j} A[s][k]", Nm)
    kv("D", D)
    for t in range(2):
        p(f"- T{t+1}: beta_t0 = {f(sb[t, 3])}, beta_t1..t3 = {vec(sb[t, :3])}, row sum = {f(sb[t].sum())}")
    # library default for Suboptimal JPDA: per-track B_t = B * sum_{s in L_t} max_{k in A_s} A_sk
    Bdef = [Bb * sum(max(A[s_, k] for k in At[s_]) for s_ in Lt[t]) if Lt[t] else Bb for t in range(2)]
    sbd, _, _, _, _, _ = suboptimal_jpda(A, Bdef)
    p("- Library default B_t = B * sum_{s in L_t} max_{k in A_s} A[s][k] (§13.4): "
      f"B_1 = {f(Bdef[0])}, B_2 = {f(Bdef[1])}")
    for t in range(2):
        p(f"  - T{t+1}: beta_t0 = {f(sbd[t, 3])}, beta_t1..t3 = {vec(sbd[t, :3])}")
    ev = jpda_events(A, [Bb, Bb])
    eb, tot = betas_from_events(ev, 2, 3)
    p()
    p(f"Exact JPDA (event weight = product of A over assigned pairs x B per undetected track); "
      f"{len(ev)} feasible events, total weight = {f(tot)}:")
    p()
    for combo, w in ev:
        p(f"- event (T1->{'none' if combo[0] is None else 'z%d' % (combo[0]+1)}, "
          f"T2->{'none' if combo[1] is None else 'z%d' % (combo[1]+1)}): weight = {f(w)}")
    for t in range(2):
        p(f"- T{t+1}: beta_t0 = {f(eb[t, 3])}, beta_t1..t3 = {vec(eb[t, :3])}")
    evs = jpda_star_events(ev)
    assert len(evs) == len(ev)
    p("- JPDA* on this example prunes nothing (no two events use the same measurement set for the "
      "same detected tracks), so JPDA* = JPDA here.")
    # NNJPDA
    Bj = eb[:, :3]
    st = mmr_static(Bj)
    p("- NNJPDA (greedy on the exact JPDA betas, threshold 0): "
      + ", ".join(f"T{i+1} -> z{j+1} (beta {f(v)})" for i, j, v in st))

    # 2x2 JPDA*
    p()
    p("JPDA* two-track / two-measurement case (both measurements gated by both tracks):")
    A2 = np.array([[0.5, 0.4], [0.45, 0.3]])
    B2 = 0.1
    p()
    kv("A", A2); kv("B", B2)
    ev2 = jpda_events(A2, [B2, B2])
    b2, tot2 = betas_from_events(ev2, 2, 2)
    ev2s = jpda_star_events(ev2)
    b2s, tot2s = betas_from_events(ev2s, 2, 2)
    p(f"- JPDA ({len(ev2)} events): T1 beta_t0 = {f(b2[0, 2])}, beta_t1..t2 = {vec(b2[0, :2])}; "
      f"T2 beta_t0 = {f(b2[1, 2])}, beta_t1..t2 = {vec(b2[1, :2])}")
    p(f"- JPDA* ({len(ev2s)} events kept; (T1->z1,T2->z2) weight {f(A2[0,0]*A2[1,1])} is pruned in favour of "
      f"(T1->z2,T2->z1) weight {f(A2[0,1]*A2[1,0])}): T1 beta_t0 = {f(b2s[0, 2])}, "
      f"beta_t1..t2 = {vec(b2s[0, :2])}; T2 beta_t0 = {f(b2s[1, 2])}, beta_t1..t2 = {vec(b2s[1, :2])}")
    sb2, D2, N2, _, _, _ = suboptimal_jpda(A2, B2)
    p(f"- Suboptimal JPDA: T1 beta = {vec(sb2[0])}; T2 beta = {vec(sb2[1])} (order z1, z2, none); "
      "with B = 0 it reproduces exact JPDA with PD = 1 and no clutter:")
    sb20, _, _, _, _, _ = suboptimal_jpda(A2, 0.0)
    ev20 = [(c_, w) for c_, w in jpda_events(A2, [0.0, 0.0]) if w > 0]
    b20, _ = betas_from_events(ev20, 2, 2)
    close(sb20, b20)
    p(f"  B = 0: T1 beta = {vec(sb20[0, :2])}, T2 beta = {vec(sb20[1, :2])}")

    # N tracks / N measurements, all likelihoods equal, B = 0 ([S1] claims)
    p()
    p("[S1] claim check, N tracks and N measurements, all A equal (= 1), B = 0:")
    p()
    for Nn in (2, 3, 4):
        Aeq = np.ones((Nn, Nn))
        cbN, _, _ = cheap_jpda(Aeq, 0.0)
        sbN, _, _, _, _, _ = suboptimal_jpda(Aeq, 0.0)
        evN = [(c_, w) for c_, w in jpda_events(Aeq, [0.0] * Nn) if w > 0]
        ebN, _ = betas_from_events(evN, Nn, Nn)
        p(f"- N = {Nn}: Cheap JPDA beta_tj = {f(cbN[0, 0])} (= 1/(2N-1) = {f(1.0 / (2 * Nn - 1))}), "
          f"Suboptimal JPDA beta_tj = {f(sbN[0, 0])}, exact JPDA beta_tj = {f(ebN[0, 0])} (= 1/N)")
    p()
    p("Number of feasible joint events, n tracks and m measurements all mutually gated: "
      "sum_k C(n,k) C(m,k) k! (equals the [S0] Table 1 expression; [S1] eq. (1) left side):")
    p()
    for (nn, mm) in ((2, 3), (3, 3), (3, 6), (4, 6)):
        cnt = sum(math.comb(nn, k) * math.comb(mm, k) * math.factorial(k) for k in range(0, min(nn, mm) + 1))
        if mm >= nn:
            t1 = sum(math.factorial(nn) // math.factorial(i) * math.comb(mm, nn - i) for i in range(0, nn + 1))
        else:
            t1 = sum(math.factorial(mm) // math.factorial(i) * math.comb(nn, mm - i) for i in range(0, nn + 1))
        lhs = 1 + sum(math.comb(nn, k) * math.prod(range(mm - (nn - 1 - k), mm + 1)) for k in range(0, nn))
        brute = len(jpda_events(np.ones((nn, mm)), [1.0] * nn))
        assert cnt == t1 == lhs == brute, (nn, mm, cnt, t1, lhs, brute)
        onetoone = math.perm(mm, nn) if mm >= nn else None
        p(f"- n = {nn}, m = {mm}: {cnt} events"
          + (f"; one-to-one events with every track assigned ([S0] eq. 11, mPn) = {onetoone}" if onetoone else ""))

    # JIPDA
    p()
    p("JIPDA (existence-aware exact enumeration, §13.2) on the [S1] gating structure; "
      "the likelihood ratios p_tj/lambda_j are given directly:")
    PD, PG = 0.9, 0.99
    lamJ = 1.0
    pr = np.array([[0.50, 0.30, 0.0], [0.0, 0.40, 0.20]])  # p_tj / lambda (dimensionless)
    Pe = [0.8, 0.5]
    p()
    kv("p_tj/lambda_j", pr); kv("P(exist|Z^{k-1})", Pe); kv("PD", PD); kv("PG", PG)
    T_, M_ = pr.shape
    # JIPDA weights (§13.2): detected PD*PG*Pbar_t*p_tj/lambda_j, missed 1 - PD*PG*Pbar_t
    AJ = np.array([[PD * PG * Pe[t] * pr[t, j] for j in range(M_)] for t in range(T_)])
    evJ = jpda_events(AJ, [1 - PD * PG * Pe[t] for t in range(T_)])
    totJ = sum(w for _, w in evJ)
    for t in range(T_):
        pj = {j: sum(w for c_, w in evJ if c_[t] == j) / totJ for j in range(M_)}
        p0 = sum(w for c_, w in evJ if c_[t] is None) / totJ
        q = (1 - PD * PG) * Pe[t] / (1 - PD * PG * Pe[t])
        Pexist = sum(pj.values()) + p0 * q
        b_ = {j: pj[j] / Pexist for j in range(M_)}
        b0_ = p0 * q / Pexist
        p(f"- T{t+1}: P(exist|Z^k) = {f(Pexist)}, beta_0 = {f(b0_)}, beta_1..3 = "
          f"{vec([b_[j] for j in range(M_)])}")

    tv13b_gate_shrink()

    # ---------------------------------------------------------------- TV14
    h("TV14 IMM mixing and combination (§14)")
    Pi = np.array([[0.95, 0.05], [0.10, 0.90]])
    mu = np.array([0.8, 0.2])
    x1 = np.array([100.0, 50.0, 10.0, -5.0]); x2 = np.array([101.0, 49.0, 12.0, -4.0])
    P1 = np.diag([2.0, 2.0, 1.0, 1.0]); P2 = np.diag([4.0, 4.0, 3.0, 3.0])
    Lam = np.array([0.01, 0.03])
    p("Inputs: two modes, Markov matrix Pi[i][j] = P(mode j at k | mode i at k-1).")
    p()
    kv("Pi", Pi); kv("mu_{k-1}", mu); kv("x1", x1); kv("P1", P1); kv("x2", x2); kv("P2", P2)
    kv("mode likelihoods Lambda_j (after mode-matched filtering; used for the mode update only)", Lam)
    cbar = Pi.T @ mu
    mix = (Pi * mu[:, None]) / cbar[None, :]  # mix[i, j] = mu_{i|j}
    xs_ = [x1, x2]; Ps_ = [P1, P2]
    p()
    p("Expected:")
    p()
    kv("cbar_j = sum_i Pi[i][j] mu_i", cbar)
    kv("mu_{i|j} (row i, column j)", mix)
    for j in range(2):
        x0j = sum(mix[i, j] * xs_[i] for i in range(2))
        P0j = sum(mix[i, j] * (Ps_[i] + np.outer(xs_[i] - x0j, xs_[i] - x0j)) for i in range(2))
        kv(f"x0_{j+1} (mixed)", x0j); kv(f"P0_{j+1} (mixed)", P0j)
    c = float(Lam @ cbar)
    mu_new = Lam * cbar / c
    kv("c = sum_j Lambda_j cbar_j", c); kv("mu_k", mu_new)
    p()
    p("Combination example using the mode-conditioned *inputs* x1, P1, x2, P2 as if they were the "
      "updated estimates, with weights mu_k:")
    xc = mu_new[0] * x1 + mu_new[1] * x2
    Pc = sum(mu_new[i] * (Ps_[i] + np.outer(xs_[i] - xc, xs_[i] - xc)) for i in range(2))
    p()
    kv("x_combined", xc); kv("P_combined", Pc)
    p()
    p("No-overlap test of the split model (§14.3) for z_hat1 = [0,0], z_hat2 = [6,2], "
      "S1 = S2 = diag(2,2), c = chi2_2(0.99):")
    p()
    dz = np.array([-6.0, -2.0]); Ssum = np.diag([4.0, 4.0])
    c99 = gate_gamma(0.99)  # the 0.99 quantile of chi-square with 2 dof
    kv("statistic", maha2(dz, Ssum)); kv("c", c99)
    kv("separated (statistic >= c)", maha2(dz, Ssum) >= c99)

    # ---------------------------------------------------------------- TV15
    h("TV15 Amplitude likelihood ratio and the amplitude row (§7.6, library extension)")
    rho15 = 3.0

    def g_plain(a, rho):
        return math.exp(min(a * rho / (1.0 + rho), 30.0)) / (1.0 + rho)

    def g_eta(a, rho, eta):
        g = g_plain(a, rho)
        return g / (1.0 - eta + eta * g)

    astar = (1.0 + rho15) * math.log(1.0 + rho15) / rho15
    p("Inputs: rho = 3 (target amplitude Exp(mean 4), clutter Exp(mean 1)); amplitudes a below; "
      "the exponent a rho/(1+rho) is clamped at 30.")
    p()
    kv("rho", rho15)
    kv("break-even amplitude a* = (1+rho) ln(1+rho)/rho (g = 1)", astar)
    p()
    p("Expected g(a) = exp(a rho/(1+rho))/(1+rho) (eta = 0) and g_eta = g/(1 - eta + eta g):")
    p()
    for a in (0.0, 1.0, 2.0, 4.0, 10.0, 50.0):
        p(f"- a = {f(a)}: g = {f(g_plain(a, rho15))}, g_0.5 = {f(g_eta(a, rho15, 0.5))}, "
          f"g_0.1 = {f(g_eta(a, rho15, 0.1))}")
    close(g_plain(astar, rho15), 1.0)
    # E_clutter[g] = 1: integral of g(a) e^-a = e^(-a/(1+rho))/(1+rho) over a >= 0 (without the
    # clamp; the tail beyond a = 400 is e^-100)
    ecl = gauss_legendre(lambda t: math.exp(t * rho15 / (1.0 + rho15) - t) / (1.0 + rho15), 0.0, 400.0, 400)
    kv("E_clutter[g] without the clamp (numerical integral over [0, 400], must be 1)", ecl)
    close(ecl, 1.0, rtol=1e-7)
    p()
    p("Amplitude row on the TV5 gate (p_j, V_G, PD, PG, lambda of TV5) with amplitudes a = [0.5, 3, 1.5] "
      "instead of TV5's intensities, eta = 0.5: p'_j = p_j g_j, A_j = PD PG p'_j / lambda, "
      "C_j = 1 - PD PG + PD PG (sum_{i != j} g_i)/(lambda V_G), L_j = A_j + C_j, beta_j = A_j / L_j; "
      "existence from P^ = 0.6.")
    p()
    amps = [0.5, 3.0, 1.5]
    p5 = [tv5_p[j] for j in range(3)]
    gj = [g_eta(a, rho15, 0.5) for a in amps]
    G = sum(gj)
    pdpg = 0.9 * 0.99
    for j in range(3):
        A = pdpg * p5[j] * gj[j] / 0.002
        C = 1.0 - pdpg + pdpg * (G - gj[j]) / (0.002 * tv5_vg)
        L = A + C
        p(f"- z{j + 1}: a = {f(amps[j])}, g_0.5 = {f(gj[j])}, A = {f(A)}, C = {f(C)}, L = {f(L)}, "
          f"beta_j = {f(A / L)}, P(exist|Z^k) = {f(L * 0.6 / (1.0 - 0.6 + L * 0.6))}")
    p()
    p("With g = 1 for every candidate (no amplitude, or rho = 0) the row is TV5's rank row with rho = 0 "
      "(P_r = 1/m); with m = 1 it is IPDA (§6).")

    sys.stdout.write("\n".join(OUT) + "\n")


if __name__ == "__main__":
    main()

# SPDX-License-Identifier: BSD-3-Clause
"""Exact linear assignment without scipy.

``linear_assignment(cost)`` solves min sum cost[i, pi(i)] over one-to-one
assignments that cover the smaller side of a rectangular matrix (the
Hungarian method with potentials, shortest augmenting paths, O(n^2 m); the
inner loop over columns is vectorised with numpy).  ``brute_force`` is the
O(m!/(m-n)!) reference used by the tests.
"""

from __future__ import annotations

import itertools

import numpy as np

__all__ = ["linear_assignment", "brute_force"]


def linear_assignment(cost) -> list[tuple[int, int]]:
    """Minimum-cost assignment; returns sorted (row, col) pairs.

    Every row is assigned when rows <= cols, every column otherwise.
    ``cost`` must be finite (use a large number for forbidden pairs).
    Ties are broken deterministically (lowest column index first).
    """
    c = np.asarray(cost, dtype=float)
    if c.ndim != 2:
        raise ValueError("cost must be a 2-D matrix")
    if c.size and not np.all(np.isfinite(c)):
        raise ValueError("cost must be finite")
    n, m = c.shape
    if n == 0 or m == 0:
        return []
    transposed = n > m
    if transposed:
        c = c.T
        n, m = m, n
    INF = np.inf
    u = np.zeros(n + 1)
    v = np.zeros(m + 1)
    p = np.zeros(m + 1, dtype=int)  # p[j]: row (1-based) assigned to column j, 0 = none
    way = np.zeros(m + 1, dtype=int)
    for i in range(1, n + 1):
        p[0] = i
        j0 = 0
        minv = np.full(m + 1, INF)
        used = np.zeros(m + 1, dtype=bool)
        while True:
            used[j0] = True
            i0 = p[j0]
            free = ~used[1:]
            cur = c[i0 - 1] - u[i0] - v[1:]
            better = free & (cur < minv[1:])
            mv = minv[1:]
            mv[better] = cur[better]
            wy = way[1:]
            wy[better] = j0
            cand = np.where(free, mv, INF)
            j1 = int(np.argmin(cand)) + 1
            delta = cand[j1 - 1]
            ui = np.nonzero(used)[0]
            u[p[ui]] += delta
            v[ui] -= delta
            mv[free] -= delta
            j0 = j1
            if p[j0] == 0:
                break
        while True:
            j1 = way[j0]
            p[j0] = p[j1]
            j0 = j1
            if j0 == 0:
                break
    pairs = [(int(p[j]) - 1, j - 1) for j in range(1, m + 1) if p[j] != 0]
    if transposed:
        pairs = [(b, a) for a, b in pairs]
    return sorted(pairs)


def brute_force(cost) -> tuple[float, list[tuple[int, int]]]:
    """Exhaustive minimum (total, pairs) covering the smaller side; for tests only."""
    c = np.asarray(cost, dtype=float)
    n, m = c.shape
    if n == 0 or m == 0:
        return 0.0, []
    best = (np.inf, [])
    if n <= m:
        for cols in itertools.permutations(range(m), n):
            tot = sum(c[i, j] for i, j in enumerate(cols))
            if tot < best[0]:
                best = (tot, [(i, j) for i, j in enumerate(cols)])
    else:
        for rows in itertools.permutations(range(n), m):
            tot = sum(c[i, j] for j, i in enumerate(rows))
            if tot < best[0]:
                best = (tot, sorted((i, j) for j, i in enumerate(rows)))
    return float(best[0]), best[1]

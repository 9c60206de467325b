# SPDX-License-Identifier: BSD-3-Clause
"""The reference tracker: one frame of ALGORITHMS.md §15, in numpy double.

Written from docs/ALGORITHMS.md (section numbers below) and the public
behaviour notes of README.md ("Limits and overflow rules"), not from src/.
Plain loops and dense matrices: clarity over speed.

Where the spec once left a choice open and the result depends on it, the
choice is marked "SPEC GAP"; docs/ALGORITHMS.md now states each as a [CHOICE]
(python/tests/test_differential.py's SPEC_GAPS_DOCUMENTED gives the sections).

Every decision taken on a computed number (gate test, argmax, velocity gate,
merge test, thresholds) also records, in Tracker.near_ties, when the two
sides are closer than TIE_REL relative: there two correct double-precision
implementations may legitimately decide differently.
"""

import math
from collections import Counter
from dataclasses import dataclass, field

import numpy as np

MODES = ("lm-ihpda", "ihpda", "lm-ipda", "ipda", "lm-ipda-all")
# The JPDA family modes the reference models (§13.1, §13.5, §13.6, §13.7):
# name -> (the betas, the §13.7 gate shrink, the §13.7 equal share).
JPDA_MODES = {
    "jpda": ("exact", False, False), "nnjpda": ("nn", False, False), "jpda-star": ("star", False, False),
    "adaptive-jpda": ("exact", True, True), "jpda-vg": ("exact", True, False),
    "adaptive-nnjpda": ("nn", True, False), "adaptive-jpda-star": ("star", True, False),
}

# Compile-time bounds of the default configuration (include/mtt/config.h).
MAX_TRACKS = 128
MAX_MEAS = 256
MAX_GATED = 32
MAX_PAIRS = 1024
MAX_MERGE_PAIRS = 2 * MAX_TRACKS
MAX_JPDA_TRACKS = 8       # exact JPDA per cluster (§16); beyond: Cheap JPDA (§13.1)
MAX_JPDA_MEAS = 32
MAX_JPDA_EVENTS = 2048

TIE_REL = 1e-9


@dataclass
class Params:
    """The docs/FORMATS.md settings that the reference models (same names, same defaults)."""
    association: str = "lm-ihpda"
    process_psd: float = 5.0
    meas_sigma: tuple = (1.0, 1.0)
    pd: float = 0.9
    pg: float = 0.999
    clutter_density: float = 0.0
    snr_rho: float = 0.0
    markov_p11: float = 0.98
    markov_p21: float = 0.0
    existence_init: float = 0.1
    confirm_threshold: float = 0.995
    terminate_threshold: float = 0.01
    merge_threshold: float = 1.0
    initiate: bool = True
    vmax: float = 60.0
    init_gate: str = "vmax"
    intensity_f1: tuple = (-0.0007, 0.5072, 39.70)
    intensity_f2: tuple = (-0.0001, 0.2097, 57.25)
    intensity_blend: tuple = (150.0, 250.0)
    adaptive_jpda_distance: float = 9.0
    adaptive_jpda_shrink: float = 3.0
    nnjpda_threshold: float = 0.0

    def check(self):
        if self.association not in MODES and self.association not in JPDA_MODES:
            raise ValueError(f"association {self.association!r} is not modelled by mtt_ref")
        if not 0.0 < self.pd <= 1.0 or not 0.0 < self.pg < 1.0:
            raise ValueError("pd / pg out of range")
        if self.init_gate not in ("vmax", "intensity"):
            raise ValueError("init_gate")


@dataclass
class Track:
    id: int
    x: np.ndarray
    P: np.ndarray
    existence: float
    confirmed: bool = False
    age: int = 0
    meas: int = -1          # input index of the measurement used this frame, or -1
    born: bool = False      # born in the current frame (no gate yet)
    dead: bool = False
    # per-frame scratch
    fr: dict = field(default_factory=dict)


def rank_probabilities(m, rho):
    """P_r(l | m, rho), l = 1..m (ALGORITHMS.md §7.2, the normative product form)."""
    a = 1.0 / (1.0 + rho)
    p1 = 1.0
    for j in range(1, m):
        p1 *= j / (j + a)
    pr = [p1]
    for l in range(1, m):
        pr.append(pr[-1] * (l - 1 + a) / l)
    return pr


def two_point_cov(sx, sy, dt):
    """[[R, R/dt], [R/dt, 2R/dt^2]] with R = diag(sx^2, sy^2) (ALGORITHMS.md §12.1)."""
    R = np.diag([sx * sx, sy * sy])
    P = np.zeros((4, 4))
    P[:2, :2] = R
    P[:2, 2:] = R / dt
    P[2:, :2] = R / dt
    P[2:, 2:] = 2.0 * R / (dt * dt)
    return P


def _sym(P):
    return 0.5 * (P + P.T)


class Tracker:
    def __init__(self, params):
        params.check()
        self.par = params
        p = params
        self.gamma = -2.0 * math.log(1.0 - p.pg)                       # §4
        self.R = np.diag([p.meas_sigma[0] ** 2, p.meas_sigma[1] ** 2])
        self.H = np.zeros((2, 4))
        self.H[0, 0] = self.H[1, 1] = 1.0
        self.time = None
        self.dt_last = 0.0
        self.next_id = 0
        self.tracks = []          # ascending id
        self.prev_unused = None   # U_{k-1}: list of (x, y, amp, input index), or None before frame 1
        self.near_ties = []       # decisions closer than TIE_REL (see module doc)
        self.exact_ties = []      # decisions on two equal numbers (tie rules)
        self.events = Counter()   # which paths ran (the test prints the totals)
        self.frame = -1

    # ------------------------------------------------------------------ API
    def add_track(self, x, P):
        """A seeded track: confirmed, existence 1 (docs/FORMATS.md initial_tracks)."""
        t = Track(self.next_id, np.array(x, float), _sym(np.array(P, float).reshape(4, 4)), 1.0,
                  confirmed=True)
        self.next_id += 1
        self.tracks.append(t)
        return t.id

    def _tie(self, what, a, b):
        if a == b:
            # an exact tie: the spec's tie rule decides, if both sides compute it exactly
            self.exact_ties.append(f"frame {self.frame}: {what}: {a!r}")
        elif abs(a - b) <= TIE_REL * max(abs(a), abs(b)):
            self.near_ties.append(f"frame {self.frame}: {what}: {a!r} vs {b!r}")

    def step(self, t, meas):
        """One frame. meas: list of (x, y, amplitude or None), in any order (stored canonically)."""
        p = self.par
        self.frame += 1
        if self.time is not None and not t > self.time:
            raise ValueError("time must increase")
        first = self.time is None
        dt = None if first else t - self.time
        self.time = t

        # --- validation and the MTT_MAX_MEAS cap (README "Limits") ----------
        ms = []
        for i, (mx, my, ma) in enumerate(meas):
            if not (math.isfinite(mx) and math.isfinite(my)):
                self.events["bad detection skipped"] += 1
                continue
            if ma is not None and not (math.isfinite(ma) and ma >= 0.0):
                self.events["bad detection skipped"] += 1
                continue
            ms.append((mx, my, ma, i))
        # the canonical order (ALGORITHMS.md §15): x, y, no amplitude before one, the
        # amplitude, the input index only between equal detections
        def canon(m):
            return (m[0], m[1], m[2] is not None, m[2] if m[2] is not None else 0.0, m[3])
        if len(ms) > MAX_MEAS:
            self.events["measurement cap"] += 1
            # strongest amplitudes stay; no amplitude ranks below any; the canonical order breaks ties
            order = sorted(range(len(ms)), key=lambda k: (ms[k][2] is None,
                                                          -(ms[k][2] or 0.0), canon(ms[k])))
            ms = [ms[k] for k in order[:MAX_MEAS]]
        ms.sort(key=canon)
        nm = len(ms)
        Z = np.array([[m[0], m[1]] for m in ms]).reshape(nm, 2)

        for tr in self.tracks:
            tr.born = False
            tr.meas = -1
            tr.fr = {}

        # --- 1. predict (§2, §3, §11).  SPEC GAP: the first frame predicts nothing
        # (README "Other limits"), not even the existence
        for tr in self.tracks:
            if first:
                xp, Pp, ep = tr.x.copy(), tr.P.copy(), tr.existence
            else:
                F = np.eye(4)
                F[0, 2] = F[1, 3] = dt
                q = p.process_psd
                Q = np.zeros((4, 4))
                Q[0, 0] = Q[1, 1] = q * dt ** 3 / 3.0
                Q[0, 2] = Q[2, 0] = Q[1, 3] = Q[3, 1] = q * dt ** 2 / 2.0
                Q[2, 2] = Q[3, 3] = q * dt
                xp = F @ tr.x
                Pp = _sym(F @ tr.P @ F.T + Q)
                ep = p.markov_p11 * tr.existence + p.markov_p21 * (1.0 - tr.existence)
                tr.age += 1              # SPEC GAP: "frames since birth" counts predictions
            tr.fr.update(xp=xp, Pp=Pp, ep=ep)

        # --- §13.7 rules 1 and 2: overlapping tracks gate with gamma / n -----
        jp = JPDA_MODES.get(p.association)
        if jp is not None and jp[1]:
            dmax = p.adaptive_jpda_distance * max(p.meas_sigma)
            for tr in self.tracks:
                tr.fr["shrink"] = False
            for a_i, a in enumerate(self.tracks):
                for b in self.tracks[a_i + 1:]:
                    d = math.hypot(*(a.fr["xp"][:2] - b.fr["xp"][:2]))
                    self._tie(f"overlap {a.id},{b.id}", d, dmax)
                    if d <= dmax:
                        a.fr["shrink"] = b.fr["shrink"] = True
            self.events["gate shrink"] += sum(tr.fr["shrink"] for tr in self.tracks)

        # --- 2. gate (§4), with the MTT_MAX_GATED cap (§7.2) -----------------
        for tr in self.tracks:
            f = tr.fr
            gamma = self.gamma / p.adaptive_jpda_shrink if f.get("shrink") else self.gamma
            S = f["Pp"][:2, :2] + self.R
            s11, s12, s22 = S[0, 0], 0.5 * (S[0, 1] + S[1, 0]), S[1, 1]
            det = s11 * s22 - s12 * s12
            if not (math.isfinite(det) and det > 0.0):
                tr.dead = True                     # §3: numerically invalid, delete
                continue
            Si = np.array([[s22, -s12], [-s12, s11]]) / det
            f["S"], f["Si"], f["det"] = S, Si, det
            f["VG"] = math.pi * gamma * math.sqrt(det)
            f["K"] = f["Pp"] @ self.H.T @ Si
            gated = []
            NU = Z - f["xp"][:2]
            D2 = np.einsum("ji,ik,jk->j", NU, Si, NU)
            for j in np.flatnonzero(D2 <= gamma * (1.0 + 2.0 * TIE_REL)):
                j = int(j)
                d2 = float(NU[j] @ Si @ NU[j])
                self._tie(f"gate d2 track {tr.id} meas {j}", d2, gamma)
                if d2 <= gamma:
                    gated.append((d2, j))
            if len(gated) > MAX_GATED:
                self.events["gate cap"] += 1
                # SPEC GAP: equal d^2 at the cap; the lower measurement index stays
                gated.sort()
                self._tie(f"gate cap track {tr.id}", gated[MAX_GATED - 1][0], gated[MAX_GATED][0])
                gated = sorted(gated[:MAX_GATED], key=lambda g: g[1])
            f["G"] = [j for _, j in gated]
            f["d2"] = {j: d2 for d2, j in gated}
            f["nu"] = {j: Z[j] - f["xp"][:2] for j in f["G"]}
            norm = 2.0 * math.pi * math.sqrt(det) * p.pg
            f["p"] = {j: math.exp(-0.5 * f["d2"][j]) / norm for j in f["G"]}
            # §7.1: any gated measurement without amplitude -> rho = 0 for this track
        live = [tr for tr in self.tracks if not tr.dead]
        # MTT_MAX_PAIRS (README "Limits"; not in the spec): the least likely pairs of
        # the frame (lowest p) are dropped.  SPEC GAP: equal p; the later track and
        # measurement go first.
        pairs = [(tr.fr["p"][j], tr.id, j, tr) for tr in live for j in tr.fr["G"]]
        if len(pairs) > MAX_PAIRS:
            self.events["pairs cap"] += 1
            pairs.sort(key=lambda q: (q[0], -q[1], -q[2]))
            n_drop = len(pairs) - MAX_PAIRS
            self._tie("pairs cap", pairs[n_drop - 1][0], pairs[n_drop][0])
            for _, _, j, tr in pairs[:n_drop]:
                tr.fr["G"].remove(j)
        for tr in live:
            f = tr.fr
            f["all_amp"] = all(ms[j][2] is not None for j in f["G"])
            if not f["all_amp"] and p.snr_rho > 0.0:
                self.events["rho off (missing amplitude)"] += 1

        # --- clutter density (§5): known, or the per-track estimate (§5.2) --
        for tr in live:
            f = tr.fr
            m = len(f["G"])
            if p.clutter_density > 0.0:
                f["lam"] = p.clutter_density
            elif m > 0:
                f["lam"] = (m - p.pd * p.pg * f["ep"]) / f["VG"]
            else:
                f["lam"] = None

        # --- clusters (§9) ----------------------------------------------------
        parent = {tr.id: tr.id for tr in live}

        def find(a):
            while parent[a] != a:
                parent[a] = parent[parent[a]]
                a = parent[a]
            return a
        gaters = [[] for _ in range(nm)]
        for tr in live:
            for j in tr.fr["G"]:
                gaters[j].append(tr)
        for j in range(nm):
            for tr in gaters[j][1:]:
                ra, rb = find(gaters[j][0].id), find(tr.id)
                if ra != rb:
                    parent[max(ra, rb)] = min(ra, rb)
        cluster = {tr.id: find(tr.id) for tr in live}

        # --- 4. LM densities (§8.2) ----------------------------------------
        lm = p.association.startswith("lm-")
        for tr in live:
            f = tr.fr
            f["lamt"] = {j: f["lam"] for j in f["G"]}
        if lm:
            W = [0.0] * nm
            w = {}
            for tr in live:                                   # pass 1
                f = tr.fr
                if not f["G"]:
                    continue
                # uniform lambda (known, or this track's estimate) cancels in P~ (§8.1, §5.2)
                tot = sum(f["p"][j] for j in f["G"])
                for j in f["G"]:
                    pt = p.pd * p.pg * f["ep"] * f["p"][j] / tot
                    w[(tr.id, j)] = f["p"][j] * pt / (1.0 - pt)
                    W[j] += w[(tr.id, j)]
            for tr in live:                                   # pass 2
                f = tr.fr
                for j in f["G"]:
                    f["lamt"][j] = f["lam"] + max(0.0, W[j] - w[(tr.id, j)])
                    if len(gaters[j]) > 1:
                        self.events["LM pair shared"] += 1
                    direct = sum(w[(s.id, j)] for s in gaters[j] if s is not tr)
                    if abs(direct - (W[j] - w[(tr.id, j)])) > 1e-10 * f["lamt"][j]:
                        self.near_ties.append(f"frame {self.frame}: LM cancellation track {tr.id} meas {j}")
        if p.association == "lm-ipda-all":
            # §8.3: every track that does not gate j adds its untruncated Gaussian's term.
            # SPEC GAP: P~'s sum runs over the track's gate and j
            out = [0.0] * nm
            for s in live:
                fs = s.fr
                tot = sum(fs["p"][l] for l in fs["G"])
                norm = 2.0 * math.pi * math.sqrt(fs["det"]) * p.pg
                for j in range(nm):
                    if not gaters[j] or j in fs["G"]:
                        continue
                    nu = Z[j] - fs["xp"][:2]
                    pj = math.exp(-0.5 * float(nu @ fs["Si"] @ nu)) / norm
                    if pj > 0.0:
                        # the quotient first: pj / (tot + pj) <= 1 even when pj is subnormal
                        pt = min(p.pd * p.pg * fs["ep"] * (pj / (tot + pj)), 1.0 - 1e-6)
                        out[j] += pj * pt / (1.0 - pt)
            for tr in live:
                f = tr.fr
                for j in f["G"]:
                    if out[j] > 0.0:
                        self.events["LM outside the gates"] += 1
                    f["lamt"][j] += out[j]

        # --- 5-7. association, assignment, update ---------------------------
        used = [False] * nm
        mode = p.association
        if mode in ("lm-ihpda", "ihpda"):
            assigned = {}                       # track id -> measurement index
            if mode == "lm-ihpda":
                assigned = self._mmr(live, nm, cluster, ms)
            else:
                for tr in live:
                    if tr.fr["G"]:
                        row = self._ihpda_row(tr, tr.fr["G"], ms)
                        assigned[tr.id] = self._select_74(tr, row)
            owner = {j: tid for tid, j in assigned.items()}
            for tr in live:
                f = tr.fr
                if tr.id in assigned:
                    j = assigned[tr.id]
                    if mode == "lm-ihpda":       # §10.3 final recomputation
                        Gf = [l for l in f["G"] if owner.get(l, tr.id) == tr.id]
                        if len(Gf) < len(f["G"]):
                            self.events["final recomputation, smaller G_f"] += 1
                        row = self._ihpda_row(tr, Gf, ms)
                    else:
                        row = self._ihpda_row(tr, f["G"], ms)
                    beta, beta0, L = row["beta"][j], row["beta0"][j], row["L"][j]
                    self._update(tr, L, [(j, beta)], beta0)
                    tr.meas = ms[j][3]
                    used[j] = True
                else:
                    if f["G"]:
                        self.events["gate taken by others (m = 0)"] += 1
                    self._update(tr, 1.0 - p.pd * p.pg, [], 1.0)
        elif jp is not None:                    # the JPDA family (§13)
            self._jpda_frame(live, cluster, jp, used, ms)
        else:                                   # lm-ipda, ipda, lm-ipda-all (§6)
            for tr in live:
                f = tr.fr
                for j in f["G"]:
                    used[j] = True
                if not f["G"]:
                    self._update(tr, 1.0 - p.pd * p.pg, [], 1.0)
                    continue
                lam_ratio = {j: f["p"][j] / f["lamt"][j] for j in f["G"]}
                Lam = sum(lam_ratio[j] for j in f["G"])
                L = 1.0 - p.pd * p.pg + p.pd * p.pg * Lam
                betas = [(j, p.pd * p.pg * lam_ratio[j] / L) for j in f["G"]]
                beta0 = (1.0 - p.pd * p.pg) / L
                self._update(tr, L, betas, beta0)
                # SPEC GAP: the view's "measurement used" in IPDA is the largest beta
                # (equal beta: the lower index)
                jb = max(betas, key=lambda q: (q[1], -q[0]))
                for j, b in betas:
                    if j != jb[0]:
                        self._tie(f"ipda meas track {tr.id}", b, jb[1])
                tr.meas = ms[jb[0]][3]

        # --- 8.1 initiation (§12.1, §12.2) --------------------------------------
        unused = [ms[j] for j in range(nm) if not used[j]]
        started_now = set()
        if p.initiate and self.prev_unused is not None and dt is not None:
            n_live = len(live)
            for zk in unused:                   # SPEC GAP: pair order, U_k outer
                for zp in self.prev_unused:
                    if not self._init_gate(zp, zk, dt):
                        continue
                    if n_live >= MAX_TRACKS:
                        self.events["birth dropped (table full)"] += 1
                        continue
                    x = np.array([zk[0], zk[1], (zk[0] - zp[0]) / dt, (zk[1] - zp[1]) / dt])
                    P = two_point_cov(p.meas_sigma[0], p.meas_sigma[1], dt)
                    # SPEC GAP (docs/ROBUSTNESS.md F6, not in §12.1): the two-point velocity
                    # variance is capped at vmax^2 by scaling the velocity rows and columns
                    vv = max(P[2, 2], P[3, 3])
                    if vv > p.vmax * p.vmax:
                        c = p.vmax / math.sqrt(vv)
                        P[2:, :] *= c
                        P[:, 2:] *= c
                        self.events["birth velocity cap"] += 1
                    nt = Track(self.next_id, x, P, p.existence_init, born=True)
                    self.next_id += 1
                    self.tracks.append(nt)
                    n_live += 1
                    self.events["birth"] += 1
                    started_now.add(zk[3])
        self.prev_unused = [z for z in unused if z[3] not in started_now]

        # --- 8.2 merging (§12.3) ---------------------------------------------------
        if p.merge_threshold > 0.0:
            cand = []
            for a_i, a in enumerate(live):
                for b in live[a_i + 1:]:
                    if cluster[a.id] != cluster[b.id]:
                        continue
                    dx = a.x - b.x
                    d2 = float(dx @ np.linalg.solve(a.P + b.P, dx))
                    self._tie(f"merge test {a.id},{b.id}", d2, p.merge_threshold)
                    if d2 < p.merge_threshold:
                        cand.append((d2, a.id, b.id, a, b))
            cand.sort(key=lambda c: (c[0], c[1], c[2]))
            if len(cand) > MAX_MERGE_PAIRS:
                # README "Limits": candidates with the largest d^2 are dropped
                self.events["merge candidates cap"] += 1
                self._tie("merge cap", cand[MAX_MERGE_PAIRS - 1][0], cand[MAX_MERGE_PAIRS][0])
                cand = cand[:MAX_MERGE_PAIRS]
            for k in range(len(cand) - 1):
                if set(cand[k][1:3]) & set(cand[k + 1][1:3]):
                    self._tie("merge order", cand[k][0], cand[k + 1][0])
            for d2, _, _, a, b in cand:
                if a.dead or b.dead:
                    continue
                ta, tb = a.P[0, 0] + a.P[1, 1], b.P[0, 0] + b.P[1, 1]
                self._tie(f"merge survivor trace {a.id},{b.id}", ta, tb)
                if ta != tb:
                    keep = a if ta < tb else b
                elif a.existence != b.existence:
                    keep = a if a.existence > b.existence else b
                else:
                    keep = a if a.id < b.id else b
                gone = b if keep is a else a
                keep.existence = max(a.existence, b.existence)
                keep.confirmed = a.confirmed or b.confirmed
                gone.dead = True
                self.events["merge"] += 1

        # --- 8.3 delete (existence, lost), then confirm (§12.4) ------------------
        # lost: position variance beyond (vmax dT)^2, dT the longer of this
        # frame's interval and the last one's; not born this frame; never
        # with terminate_threshold 0
        reach = max(dt or 0.0, self.dt_last) * p.vmax
        for tr in self.tracks:
            if tr.dead:
                continue
            self._tie(f"terminate track {tr.id}", tr.existence, p.terminate_threshold)
            self._tie(f"confirm track {tr.id}", tr.existence, p.confirm_threshold)
            lost = False
            if not tr.born and reach > 0.0 and p.terminate_threshold > 0.0:
                pv = max(tr.P[0, 0], tr.P[1, 1])
                self._tie(f"lost track {tr.id}", pv, reach * reach)
                lost = pv > reach * reach
            if tr.existence < p.terminate_threshold or lost:
                tr.dead = True
                self.events["delete"] += 1
            elif tr.existence >= p.confirm_threshold:
                self.events["confirm"] += not tr.confirmed
                tr.confirmed = True
        self.tracks = [tr for tr in self.tracks if not tr.dead]
        self.dt_last = dt or 0.0
        return self.tracks

    # ------------------------------------------------------------------ stages
    def _ihpda_row(self, tr, cands, ms):
        """β_j, β_{0,j}, L_j of §7.3 over the candidate set `cands` (ascending index)."""
        p = self.par
        f = tr.fr
        m = len(cands)
        rho = p.snr_rho if f["all_amp"] else 0.0
        # §7.1: rank 1 is the strongest; equal intensity -> the lower index ranks stronger
        order = sorted(cands, key=lambda j: (-(ms[j][2] if ms[j][2] is not None else 0.0), j))
        rank = {j: r + 1 for r, j in enumerate(order)}
        if rho > 0.0 and len({ms[j][2] for j in cands}) < m:
            self.events["equal amplitudes ranked by index"] += 1
        pr = rank_probabilities(m, rho)
        pdpg = p.pd * p.pg
        row = {"beta": {}, "beta0": {}, "L": {}, "rank": rank}
        for j in cands:
            lam = f["lamt"][j]
            P_r = pr[rank[j] - 1]
            A = pdpg * m * f["p"][j] * P_r / lam
            C = 1.0 - pdpg + pdpg * (m / (lam * f["VG"])) * (1.0 - P_r)
            L = A + C
            row["beta"][j], row["beta0"][j], row["L"][j] = A / L, C / L, L
        return row

    def _select_74(self, tr, row):
        """§7.4: argmax β; ties: the smaller rank, then the lower index."""
        best = None
        for j, b in row["beta"].items():
            key = (b, -row["rank"][j], -j)
            if best is None or key > best[0]:
                if best is not None:
                    self._tie(f"ihpda select track {tr.id}", b, best[0][0])
                best = (key, j)
            else:
                self._tie(f"ihpda select track {tr.id}", b, best[0][0])
        return best[1]

    def _mmr(self, live, nm, cluster, ms):
        """§10.1 MMR with recomputation; returns {track id: measurement index}."""
        free = [True] * nm
        U = [tr for tr in live if tr.fr["G"]]
        assigned = {}
        rows = {}                              # track id -> candidates of its current row
        while True:
            cands = []
            for tr in U:
                if tr.id not in rows:
                    A = [j for j in tr.fr["G"] if free[j]]
                    row = self._ihpda_row(tr, A, ms) if A else None
                    rows[tr.id] = [(row["beta"][j], tr, j) for j in A]
                cands.extend(rows[tr.id])
            if not cands:
                break
            # global maximum; ties: lowest track index (= ascending id, §15), then lowest measurement
            best = max(cands, key=lambda c: (c[0], -c[1].id, -c[2]))
            for c in cands:
                if c is not best and cluster[c[1].id] == cluster[best[1].id]:
                    self._tie(f"mmr argmax ({best[1].id},{best[2]}) vs ({c[1].id},{c[2]})",
                              best[0], c[0])
            _, tr, j = best
            if any(c[2] == j and c[1] is not tr for c in cands):
                self.events["MMR contested measurement"] += 1
            assigned[tr.id] = j
            free[j] = False
            U = [u for u in U if u is not tr]
            # only the rows that had j in their gate change (§10.1): recompute those
            for u in U:
                if j in u.fr["G"]:
                    rows.pop(u.id, None)
        return assigned

    def _jpda_frame(self, live, cluster, jp, used, ms):
        """§13: per cluster the betas of the mode, existence by §6 (§13.2 CHOICE), update §13.8."""
        p = self.par
        kind, _, share = jp
        pdpg = p.pd * p.pg
        groups = {}
        for tr in live:
            groups.setdefault(cluster[tr.id], []).append(tr)
        for trs in groups.values():
            if len(trs) == 1 and not trs[0].fr["G"]:
                rows = {trs[0].id: (1.0, {})}          # empty gate: the m = 0 update
            else:
                rows = self._jpda_rows(trs, kind)
            if share:
                self._share(trs, rows)
            assigned = self._nn_assign(trs, rows) if kind == "nn" else None
            for tr in trs:
                f = tr.fr
                L = 1.0 - pdpg + pdpg * sum(f["p"][j] / f["lam"] for j in f["G"])
                beta0, beta = rows[tr.id]
                if assigned is not None:
                    j = assigned.get(tr.id)
                    if j is None:
                        self._update(tr, L, [], 1.0)
                    else:
                        self._update(tr, L, [(j, 1.0)], 0.0)
                        tr.meas = ms[j][3]
                        used[j] = True
                    continue
                for j in f["G"]:
                    used[j] = True
                if not f["G"]:
                    self._update(tr, L, [], 1.0)
                    continue
                betas = [(j, beta[j]) for j in f["G"]]
                self._update(tr, L, betas, beta0)
                jb = max(betas, key=lambda q: (q[1], -q[0]))   # §6 "Reported measurement"
                for j, b in betas:
                    if j != jb[0]:
                        self._tie(f"jpda meas track {tr.id}", b, jb[1])
                tr.meas = ms[jb[0]][3]

    def _jpda_rows(self, trs, kind):
        """{track id: (beta_0, {j: beta_j})} of one cluster: exact JPDA (§13.1) or JPDA*
        (§13.6) by enumeration, or Cheap JPDA normalised past the bounds (§13.1 CHOICE)."""
        p = self.par
        A = {tr.id: {j: p.pg * tr.fr["p"][j] for j in tr.fr["G"]} for tr in trs}   # N(nu; 0, S)
        B = {tr.id: tr.fr["lam"] * (1.0 - p.pd * p.pg) / p.pd for tr in trs}
        A0, B0 = dict(A), dict(B)
        # each row over its largest entry: the same probabilities, no underflow
        for tr in trs:
            big = max([B[tr.id]] + list(A[tr.id].values()))
            big = big if big > 0.0 else 1.0
            B[tr.id] /= big
            A[tr.id] = {j: a / big for j, a in A[tr.id].items()}
        n_meas = len({j for tr in trs for j in tr.fr["G"]})
        events = []

        class Over(Exception):
            pass

        def walk(k, used, combo, w):
            if k == len(trs):
                if len(events) >= MAX_JPDA_EVENTS:
                    raise Over
                events.append((tuple(combo), w))
                return
            tr = trs[k]
            walk(k + 1, used, combo + [None], w * B[tr.id])        # "none" first
            for j in tr.fr["G"]:                                    # then ascending
                if j not in used:
                    walk(k + 1, used | {j}, combo + [j], w * A[tr.id][j])
        try:
            if len(trs) > MAX_JPDA_TRACKS or n_meas > MAX_JPDA_MEAS:
                raise Over
            walk(0, frozenset(), [], 1.0)
        except Over:
            self.events["jpda fallback (Cheap JPDA)"] += 1
            return self._cheap(trs, A0, B0)
        if kind == "star":
            best = {}
            for combo, w in events:
                key = (tuple(c is not None for c in combo), frozenset(c for c in combo if c is not None))
                if key in best:
                    self._tie("jpda-star group", w, best[key][1])
                if key not in best or w > best[key][1]:
                    best[key] = (combo, w)
            if len(best) < len(events):
                self.events["jpda-star pruned"] += 1
            events = list(best.values())
        W = sum(w for _, w in events)
        rows = {}
        for k, tr in enumerate(trs):
            if not W > 0.0:
                rows[tr.id] = (1.0, {j: 0.0 for j in tr.fr["G"]})
                continue
            beta = {j: 0.0 for j in tr.fr["G"]}
            b0 = 0.0
            for combo, w in events:
                if combo[k] is None:
                    b0 += w
                else:
                    beta[combo[k]] += w
            rows[tr.id] = (b0 / W, {j: b / W for j, b in beta.items()})
        return rows

    def _cheap(self, trs, A, B):
        """Cheap JPDA (§13.3), rows normalised."""
        Mj = {}
        for tr in trs:
            for j, a in A[tr.id].items():
                Mj[j] = Mj.get(j, 0.0) + a
        rows = {}
        for tr in trs:
            T = sum(A[tr.id].values())
            if not tr.fr["G"]:
                rows[tr.id] = (1.0, {})
                continue
            b0 = B[tr.id] / (T + B[tr.id])
            beta = {j: a / (T + Mj[j] - a + B[tr.id]) for j, a in A[tr.id].items()}
            tot = b0 + sum(beta.values())
            rows[tr.id] = (b0 / tot, {j: b / tot for j, b in beta.items()}) if tot > 0.0 else (b0, beta)
        return rows

    def _share(self, trs, rows):
        """§13.7 rule 3: beta = 1/N_c(j) for a measurement gated by N_c >= 2 overlapping tracks."""
        for tr in trs:
            if not tr.fr.get("shrink"):
                continue
            b0, beta = rows[tr.id]
            shared = False
            for j in tr.fr["G"]:
                nc = sum(1 for s in trs if s.fr.get("shrink") and j in s.fr["G"])
                if nc >= 2:
                    beta[j] = 1.0 / nc
                    shared = True
            if not shared:
                continue
            tot = sum(beta.values())
            if tot > 1.0:
                rows[tr.id] = (0.0, {j: b / tot for j, b in beta.items()})
            else:
                rows[tr.id] = (1.0 - tot, beta)
            self.events["adaptive equal share"] += 1

    def _nn_assign(self, trs, rows):
        """§13.5: static MMR on the betas (beta >= nnjpda_threshold and > 0); ties: the lower
        track, then the lower measurement.  Returns {track id: measurement}."""
        thr = self.par.nnjpda_threshold
        cands = [(b, tr, j) for tr in trs for j, b in rows[tr.id][1].items() if b >= thr and b > 0.0]
        assigned, taken = {}, set()
        while True:
            live = [c for c in cands if c[1].id not in assigned and c[2] not in taken]
            if not live:
                return assigned
            best = max(live, key=lambda c: (c[0], -c[1].id, -c[2]))
            for c in live:
                if c is not best:
                    self._tie(f"nnjpda argmax ({best[1].id},{best[2]}) vs ({c[1].id},{c[2]})", best[0], c[0])
            assigned[best[1].id] = best[2]
            taken.add(best[2])

    def _update(self, tr, L, betas, beta0):
        """Existence (§6 L form, §7.4) and the PDA / single-measurement state update (§6, §7.4)."""
        f = tr.fr
        ep = f["ep"]
        e = L * ep / (1.0 - ep + L * ep)
        tr.existence = min(1.0, max(0.0, e))
        if not betas:
            tr.x, tr.P = f["xp"], f["Pp"]
            return
        K, Pp = f["K"], f["Pp"]
        IKH = np.eye(4) - K @ self.H
        Pc = IKH @ Pp @ IKH.T + K @ self.R @ K.T
        nuc = sum(b * f["nu"][j] for j, b in betas)
        spread = sum(b * np.outer(f["nu"][j], f["nu"][j]) for j, b in betas) - np.outer(nuc, nuc)
        tr.x = f["xp"] + K @ nuc
        tr.P = _sym(beta0 * Pp + (1.0 - beta0) * Pc + K @ spread @ K.T)

    def _init_gate(self, zp, zk, dt):
        """§12.1 velocity circle, or the §12.2 intensity gate (falls back to vmax without amplitude)."""
        p = self.par
        dx, dy = zk[0] - zp[0], zk[1] - zp[1]
        if p.init_gate == "intensity" and zp[2] is not None:
            # §12.2 clamps I at 1048.5, the peak of the default f2, so that f does not
            # decrease (and turn negative) above it.  SPEC GAP: with configured
            # coefficients the bound is read as the peak of the configured f2,
            # -a1 / (2 a2), and there is none when a2 >= 0 (f2 does not peak).
            a2, a1 = p.intensity_f2[0], p.intensity_f2[1]
            i_max = -a1 / (2.0 * a2) if a2 < 0.0 else math.inf
            if zp[2] > i_max:
                self.events["intensity gate clamp"] += 1
            I = min(max(zp[2], 0.0), i_max)
            lo, hi = p.intensity_blend

            def poly(c):
                return c[0] * I * I + c[1] * I + c[2]
            if I <= lo:
                fI = poly(p.intensity_f1)
            elif I > hi:
                fI = poly(p.intensity_f2)
            else:
                w1 = (hi - I) / (hi - lo)
                fI = w1 * poly(p.intensity_f1) + (1.0 - w1) * poly(p.intensity_f2)
            sp2 = (fI * fI) / self.gamma
            S0 = np.diag([sp2, sp2]) + self.R
            d = np.array([dx, dy])
            d2 = float(d @ np.linalg.solve(S0, d))
            self._tie("intensity init gate", d2, self.gamma)
            self.events["intensity gate " + ("pass" if d2 <= self.gamma else "reject")] += 1
            return d2 <= self.gamma
        if p.init_gate == "intensity":
            self.events["intensity gate without amplitude: vmax"] += 1
        r = math.hypot(dx, dy)
        self._tie("vmax gate", r, p.vmax * dt)
        return r <= p.vmax * dt

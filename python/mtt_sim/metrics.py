# SPDX-License-Identifier: BSD-3-Clause
"""Scoring: pure functions on numpy arrays (no I/O, no global state).

Conventions used throughout
---------------------------
* Distances are Euclidean distances between 2-D positions (x, y) in the
  scenario's length unit; velocities are not scored.
* Only **confirmed** tracks are scored (tentative tracks are counted, never
  matched), as in seeds 000 and 004 which report confirmed tracks.
* **Per-scan matching rule** (:func:`match`), used for confirmed true/false
  tracks, RMSE and the seeded-track outcome inputs: at each scan
  independently, a one-to-one assignment between targets present in the
  field and confirmed tracks that (1) has the largest possible number of
  pairs whose distance is <= the association distance ``d_a`` and (2) among
  those, the smallest total distance.  Pairs farther than ``d_a`` are never
  matched.  It is computed exactly by ``scipy.optimize.linear_sum_assignment``
  on a cost matrix that makes (1) dominate (2) (:func:`match`).
* A **confirmed true track** at a scan is a confirmed track matched to a
  target by that rule; every other confirmed track at that scan is a
  **confirmed false track**.  So a second track on an already followed
  target is false, and at most one true track per target is counted (seed
  004 Table 1 counts at most 3 per run).
* **Position RMSE per target** at scan k over runs: sqrt(mean of the squared
  distance between the target and its matched confirmed track), over the
  runs where the target was matched at k.  Unmatched scans are not errors;
  they show up in the confirmed-true count instead.
* **GOSPA** (Rahmathullah, Garcia-Fernandez, Svensson 2017) with p = 1,
  alpha = 2 and cut-off c, per scan, exact assignment.
* **CLEAR-MOT** (Bernardin and Stiefelhagen 2008) with match threshold
  ``d_a``, by TrackEval's ``CLEAR``; see :func:`clear_mot` for the exact
  correspondence rule and the similarity that makes it the rule above.
* **HOTA** (Luiten et al. 2021) by TrackEval's ``HOTA``, similarity
  max(0, 1 - d / d_a) (:func:`hota`); runs combine as TrackEval combines
  sequences (:func:`hota_combine`).
* **Split outcome** (:func:`split_outcome`, scenarios with ``splits``): the
  child's confirmation delay is, per split, the first scan k >= the split
  scan at which confirmed tracks are matched by the per-scan rule to both
  the child and its parent target (two tracks: while one track covers both,
  the child is not counted as tracked), minus the split scan (None if it
  never happens).  A **false
  split** is a track with a parent (the tracks file's ``parent`` column,
  ``split`` = true) that is not matched to a split child target at any of
  its first 3 scans.
* **RMSE on straight legs and in turns** (:func:`rmse_legs`, scenarios with
  manoeuvres): the same squared errors pooled over two disjoint sets of
  (target, scan): the scans inside a target's manoeuvre windows
  (``scenario.manoeuvre_windows``: scans k0 + 1 .. k0 + n of a turn from
  scan k0 lasting n scans) and all the others.
"""

from __future__ import annotations

import math

import numpy as np

from scipy.optimize import linear_sum_assignment
from trackeval.metrics import CLEAR, HOTA

__all__ = [
    "distances", "assignment", "match", "confirmed_true_false", "gospa", "clear_mot", "hota", "hota_combine", "HOTA_FIELDS",
    "seeded_outcome", "counts_per_scan", "time_per_frame", "frames", "score_run",
    "turn_mask", "rmse_legs", "split_outcome",
]


def distances(a_xy, b_xy) -> np.ndarray:
    """Matrix D[i, j] = |a_i - b_j| (Euclidean) for (n, 2) and (m, 2) arrays."""
    a = np.asarray(a_xy, float).reshape(-1, 2)
    b = np.asarray(b_xy, float).reshape(-1, 2)
    return np.sqrt(((a[:, None, :] - b[None, :, :]) ** 2).sum(axis=2))


def assignment(cost) -> list[tuple[int, int]]:
    """Minimum-cost one-to-one assignment of a finite (n, m) cost matrix.

    ``scipy.optimize.linear_sum_assignment``: covers the smaller side; returns
    the (row, col) pairs sorted by row ([] for an empty matrix).
    """
    c = np.asarray(cost, dtype=float)
    if c.size == 0:
        return []
    rows, cols = linear_sum_assignment(c)
    return list(zip(rows.tolist(), cols.tolist()))


def match(truth_xy, track_xy, cutoff: float, dist=None) -> list[tuple[int, int]]:
    """Per-scan matching rule (module docstring): pairs (truth index, track index).

    Maximum number of pairs with distance <= cutoff, then minimum total
    distance.  Implemented as one assignment on the cost d if d <= cutoff
    else BIG, with BIG larger than any possible sum of admissible costs, and
    the BIG pairs dropped afterwards.
    """
    d = distances(truth_xy, track_xy) if dist is None else np.asarray(dist, float)
    n, m = d.shape
    if n == 0 or m == 0:
        return []
    ok = d <= cutoff
    if not ok.any():
        return []
    big = (min(n, m) + 1) * cutoff + 1.0
    cost = np.where(ok, d, big)
    return [(i, j) for i, j in assignment(cost) if ok[i, j]]


def confirmed_true_false(truth_xy, conf_xy, cutoff: float) -> tuple[int, int]:
    """(confirmed true, confirmed false) track counts at one scan (module rule)."""
    n_conf = len(np.asarray(conf_xy).reshape(-1, 2))
    nt = len(match(truth_xy, conf_xy, cutoff))
    return nt, n_conf - nt


def gospa(truth_xy, est_xy, c: float, p: float = 1.0, alpha: float = 2.0) -> dict:
    """GOSPA distance between a truth set X and an estimate set Y at one scan.

    d = [ min over assignments gamma of  sum_{(i,j) in gamma} d(x_i, y_j)^p
          + c^p / alpha * (|X| + |Y| - 2 |gamma|) ]^(1/p)
    where only pairs with d(x_i, y_j) < c may be assigned (alpha = 2; other
    alpha are not supported).  Computed exactly: assign the smaller set
    fully with cost min(d, c)^p (a pair at d >= c then costs c^p, which is
    exactly one missed plus one false target at c^p / 2 each).

    Returns dict: gospa, loc (sum of d^p over real pairs), missed / false
    (their c^p/2 terms), n_missed, n_false, n_assigned.
    """
    if alpha != 2.0:
        raise ValueError("only alpha = 2 is supported")
    X = np.asarray(truth_xy, float).reshape(-1, 2)
    Y = np.asarray(est_xy, float).reshape(-1, 2)
    nx, ny = len(X), len(Y)
    half = c ** p / 2.0
    real = []
    if nx and ny:
        d = distances(X, Y)
        cost = np.minimum(d, c) ** p
        real = [(i, j) for i, j in assignment(cost) if d[i, j] < c]
        loc = float(sum(d[i, j] ** p for i, j in real))
    else:
        loc = 0.0
    na = len(real)
    missed = half * (nx - na)
    false = half * (ny - na)
    return {"gospa": (loc + missed + false) ** (1.0 / p), "loc": loc, "missed": missed, "false": false,
            "n_missed": nx - na, "n_false": ny - na, "n_assigned": na}


def _sequence(frame_list, similarity, transpose: bool = False) -> dict:
    """TrackEval's data of one sequence (``eval_sequence``) from :func:`frames`' tuples.

    Ids become 0-based indices; ``similarity(d)`` maps the per-scan distance
    matrix (targets x tracks) to the similarity matrix; ``transpose``
    exchanges the roles of targets and tracks."""
    gt_ids, tr_ids, sims = [], [], []
    for g, gxy, h, hxy in frame_list:
        gt_ids.append(np.asarray(g, int).ravel())
        tr_ids.append(np.asarray(h, int).ravel())
        sims.append(similarity(distances(gxy, hxy)))
    if transpose:
        gt_ids, tr_ids, sims = tr_ids, gt_ids, [m.T for m in sims]
    data = {"num_timesteps": len(sims), "similarity_scores": sims}
    for key, ids in (("gt", gt_ids), ("tracker", tr_ids)):
        allids = np.concatenate(ids) if ids else np.zeros(0, int)
        uniq = np.unique(allids)
        data[f"{key}_ids"] = [np.searchsorted(uniq, i) for i in ids]
        data[f"num_{key}_ids"] = len(uniq)
        data[f"num_{key}_dets"] = len(allids)
    return data


def clear_mot(frame_list, cutoff: float) -> dict:
    """CLEAR-MOT over a sequence of scans, by TrackEval's ``CLEAR``.

    ``frame_list``: a list of (gt_ids, gt_xy, hyp_ids, hyp_xy) per scan
    (hypotheses = confirmed tracks).  TrackEval's correspondence rule per
    scan (``trackeval.metrics.CLEAR.eval_sequence``):

    1. a (target, track) pair matched at the previous scan is kept if both
       are present and still within ``cutoff`` (a scan without any target
       or without any track is skipped: the pairs of the scan before it
       carry over);
    2. the remaining targets and tracks are matched by the largest total
       similarity among pairs at or above its threshold;
    3. an **ID switch** is counted for each matched target whose track is
       not the one it was last matched to (at any earlier scan);
    4. misses FN = unmatched targets, false positives FP = unmatched tracks.

    The similarity handed to it is s = 1 - d / (L cutoff) for d <= cutoff
    (0 beyond), threshold 1 - 1/L, with L = 2 + the largest min(targets,
    tracks) of a scan: a pair is admissible iff d <= cutoff, one more pair
    always outweighs any change of the others' similarity, and among
    matchings of as many pairs the largest total similarity is the least
    total distance.  So step 2 is the rule of :func:`match`, and the match
    distances come back from TrackEval's ``MOTP_sum`` = sum of s.

    A **track swap** is counted for each track matched to a target other
    than the one it was last matched to: an identity that moved from one
    target to another, i.e. the ID switches of the same ``CLEAR`` with the
    roles of targets and tracks exchanged.  A target lost and re-acquired by
    a new track is an ID switch but no swap.

    MOTA = 1 - (FN + FP + IDSW) / GT (NaN if no GT); MOTP = mean distance of
    the matched pairs (NaN if none).  Returns gt, matches, fn, fp, idsw,
    swaps, dist (the sum of the matched distances), mota, motp.
    """
    frame_list = list(frame_list)
    cutoff = float(cutoff)
    L = 2.0 + max((min(len(f[0]), len(f[2])) for f in frame_list), default=0)
    scale = L * cutoff

    def similarity(d):
        return np.where(d <= cutoff, 1.0 - d / scale, 0.0)

    config = {"THRESHOLD": 1.0 - 1.0 / L, "PRINT_CONFIG": False}
    r = CLEAR(dict(config)).eval_sequence(_sequence(frame_list, similarity))
    rs = CLEAR(dict(config)).eval_sequence(_sequence(frame_list, similarity, transpose=True))
    gt = int(r["CLR_TP"] + r["CLR_FN"])
    matches = int(r["CLR_TP"])
    fn, fp, idsw = int(r["CLR_FN"]), int(r["CLR_FP"]), int(r["IDSW"])
    dist = float((matches - r["MOTP_sum"]) * scale)
    return {
        "gt": gt, "matches": matches, "fn": fn, "fp": fp, "idsw": idsw, "swaps": int(rs["IDSW"]),
        "dist": dist,
        "mota": (1.0 - (fn + fp + idsw) / gt) if gt else math.nan,
        "motp": (dist / matches) if matches else math.nan,
    }


HOTA_FIELDS = ("HOTA_TP", "HOTA_FN", "HOTA_FP", "AssA", "AssRe", "AssPr", "LocA")


def hota(frame_list, cutoff: float) -> dict:
    """HOTA (Luiten et al. 2021) of a sequence of scans, by TrackEval's ``HOTA``.

    The similarity of a target and a track at distance d is
    max(0, 1 - d / cutoff): 1 on the target, 0 at ``cutoff`` and beyond.
    TrackEval evaluates it at the thresholds alpha = 0.05, 0.10, ..., 0.95
    (a pair matches at alpha when its similarity is >= alpha, i.e. d <=
    (1 - alpha) cutoff) and averages over them.  Returns TrackEval's
    per-alpha arrays of :data:`HOTA_FIELDS` (what
    ``HOTA.combine_sequences`` needs to combine runs) and the means over
    alpha ``hota``, ``deta``, ``assa``, ``loca``.
    """
    res = HOTA().eval_sequence(_sequence(list(frame_list), lambda d: np.maximum(0.0, 1.0 - d / float(cutoff))))
    return hota_summary(res)


def hota_summary(res: dict) -> dict:
    """The arrays of :data:`HOTA_FIELDS` and the alpha means of TrackEval's HOTA result ``res``."""
    out = {k: np.asarray(res[k], float) for k in HOTA_FIELDS}
    out.update(hota=float(np.mean(res["HOTA"])), deta=float(np.mean(res["DetA"])),
               assa=float(np.mean(res["AssA"])), loca=float(np.mean(res["LocA"])))
    return out


def hota_combine(per_run) -> dict:
    """HOTA over several runs: TrackEval's ``HOTA.combine_sequences`` with each run a sequence.

    ``per_run``: a list of :func:`hota` results (in run order)."""
    res = HOTA().combine_sequences({i: {k: np.asarray(r[k], float) for k in HOTA_FIELDS}
                                    for i, r in enumerate(per_run)})
    return hota_summary(res)


def seeded_outcome(seeded_targets, truth_ids, truth_xy, track_ids, track_xy, cutoff: float) -> dict:
    """Coalescence-or-switch outcome of one run, for seeded (initial) tracks.

    Seeded track number i (track id i, from ``initial_tracks`` entry i)
    belongs to target ``seeded_targets[i]``.  At the evaluation scan (the
    caller passes the targets present and the live tracks of that scan,
    tentative or confirmed):

    * each live seeded track is **on** the target nearest to its position,
      if that distance is <= ``cutoff``;
    * it is **lost** if it is not alive (deleted or merged away) or no
      target lies within ``cutoff``.

    The run is classified with three flags, not exclusive:

    * ``coalescence``: some target has two or more seeded tracks on it;
    * ``switch``: some seeded track is on a target other than its own;
    * ``lost``: some seeded track is lost.

    ``failed`` = coalescence or switch or lost, i.e. "at the end some seeded
    track is not on its own target"; the coalescence-or-switch rate of a
    Monte Carlo set is the fraction of runs with ``failed`` (the lost part is
    also reported separately).  A seeded track whose own target has left the
    field counts as lost or switched, so scenarios evaluate while every
    seeded target is present.
    """
    truth_ids = [int(a) for a in truth_ids]
    tx = np.asarray(truth_xy, float).reshape(-1, 2)
    alive = {int(t): np.asarray(p, float) for t, p in zip(track_ids, np.asarray(track_xy, float).reshape(-1, 2))}
    on: list[int | None] = []
    for i, _g in enumerate(seeded_targets):
        if i not in alive or not truth_ids:
            on.append(None)
            continue
        dd = np.hypot(*(tx - alive[i]).T)
        j = int(np.argmin(dd))
        on.append(truth_ids[j] if dd[j] <= cutoff else None)
    assigned = [a for a in on if a is not None]
    coalescence = len(assigned) != len(set(assigned))
    switch = any(a is not None and a != int(g) for a, g in zip(on, seeded_targets))
    lost = any(a is None for a in on)
    return {"on": on, "coalescence": coalescence, "switch": switch, "lost": lost,
            "failed": coalescence or switch or lost}


def turn_mask(windows, nscan: int) -> np.ndarray:
    """Boolean array over scans 0..nscan-1: True inside any (first, last) window (inclusive)."""
    mask = np.zeros(nscan, bool)
    for first, last in windows:
        mask[max(int(first), 0):min(int(last), nscan - 1) + 1] = True
    return mask


def rmse_legs(sq_sums: dict, windows: dict, nscan: int) -> dict:
    """Position RMSE split into straight legs and turns.

    ``sq_sums``: {target id: (sum of squared errors per scan, number of
    matched runs per scan)} (arrays of length nscan, as the Monte Carlo
    aggregate keeps them); ``windows``: {target id: [(first, last), ...]}
    manoeuvre windows (a target without an entry is straight throughout).
    Returns {"straight": rmse, "turn": rmse, "straight_n": count,
    "turn_n": count}; an RMSE over no matched scan is NaN.
    """
    acc = {"straight": [0.0, 0.0], "turn": [0.0, 0.0]}
    for tid, (ss, cc) in sq_sums.items():
        ss = np.asarray(ss, float)
        cc = np.asarray(cc, float)
        m = turn_mask(windows.get(int(tid), ()), nscan)
        acc["turn"][0] += float(ss[m].sum())
        acc["turn"][1] += float(cc[m].sum())
        acc["straight"][0] += float(ss[~m].sum())
        acc["straight"][1] += float(cc[~m].sum())
    out = {}
    for k, (s, c) in acc.items():
        out[k] = math.sqrt(s / c) if c else math.nan
        out[k + "_n"] = int(c)
    return out


def counts_per_scan(track_scan, track_confirmed, nscan: int) -> tuple[np.ndarray, np.ndarray]:
    """(tentative, confirmed) numbers of live tracks at each scan 0..nscan-1."""
    s = np.asarray(track_scan, int)
    c = np.asarray(track_confirmed, bool)
    conf = np.bincount(s[c], minlength=nscan)[:nscan]
    tent = np.bincount(s[~c], minlength=nscan)[:nscan]
    return tent, conf


def time_per_frame(elapsed_s: float, nscan: int) -> float:
    """Wall time of one mtt-track call divided by its number of scans (seconds).

    The runner measures ``elapsed_s`` around the whole subprocess, so it
    includes process start-up and file parsing: an upper bound on the
    tracker's own cost per frame.
    """
    return elapsed_s / nscan if nscan > 0 else math.nan


def _slices(scan, nscan):
    scan = np.asarray(scan, int)
    order = np.argsort(scan, kind="stable")
    bounds = np.searchsorted(scan[order], np.arange(nscan + 1))
    return order, bounds


def frames(truth: dict, tracks: dict, nscan: int, confirmed_only: bool = True):
    """Per-scan (truth ids, truth xy, track ids, track xy) tuples, k = 0..nscan-1."""
    to, tb = _slices(truth["scan"], nscan)
    keep = np.asarray(tracks["confirmed"], bool) if confirmed_only else np.ones(len(tracks["scan"]), bool)
    kidx = np.nonzero(keep)[0]
    ro, rb = _slices(np.asarray(tracks["scan"], int)[kidx], nscan)
    out = []
    for k in range(nscan):
        ti = to[tb[k]:tb[k + 1]]
        ri = kidx[ro[rb[k]:rb[k + 1]]]
        out.append((np.asarray(truth["target"])[ti],
                    np.column_stack([np.asarray(truth["x"])[ti], np.asarray(truth["y"])[ti]]),
                    np.asarray(tracks["track"])[ri],
                    np.column_stack([np.asarray(tracks["x"])[ri], np.asarray(tracks["y"])[ri]])))
    return out


def split_outcome(splits, fr, tracks: dict, match_distance: float, window: int = 3) -> dict:
    """Split outcome of one run (module docstring).

    ``splits``: [(child target id, parent target id, split scan)]; ``fr``: :func:`frames` of
    the confirmed tracks; ``tracks``: the tracks table (its ``parent``
    column, -1 for none, when the tracker ran with split = true);
    matching as :func:`match` with ``match_distance``.  Returns
    {"delays": [scans from the split to the child's confirmation, or None],
    "spawned": tracks with a parent, "false_splits": those not matched to a
    split's parent or child within their first ``window`` scans}.
    """
    children = {int(c): (int(p), int(k)) for c, p, k in splits}
    delays = {c: None for c in children}
    matched_split = {}  # track id -> scans at which it is matched to a split's parent or child
    for k, (gid, gxy, hid, hxy) in enumerate(fr):
        d = distances(gxy, hxy)
        pairs = match(None, None, match_distance, dist=d) if len(gid) and len(hxy) else []
        covered = {int(gid[i]) for i, _ in pairs}
        for i, j in pairs:
            t = int(gid[i])
            if t in children and k >= children[t][1]:
                if delays[t] is None and children[t][0] in covered:
                    delays[t] = k - children[t][1]
            if any(t in (c, pk[0]) and k >= pk[1] for c, pk in children.items()):
                matched_split.setdefault(int(hid[j]), []).append(k)
    spawned, false = 0, 0
    if "parent" in tracks and len(tracks["scan"]):
        par = np.asarray(tracks["parent"], int)
        ids = np.asarray(tracks["track"], int)
        scan = np.asarray(tracks["scan"], int)
        for tid in np.unique(ids[par >= 0]):
            spawned += 1
            born = int(scan[ids == tid].min())
            if not any(born <= k < born + window for k in matched_split.get(int(tid), [])):
                false += 1
    return {"delays": [delays[c] for c in children], "spawned": spawned, "false_splits": false}


def score_run(truth: dict, tracks: dict, nscan: int, match_distance: float, gospa_c: float,
              seeded_targets=(), eval_scan: int = -1, splits=()) -> dict:
    """All per-run metrics of one run (tables as in csvio).

    Returns per-scan arrays (length nscan): n_truth, n_tentative,
    n_confirmed, conf_true, conf_false, gospa, gospa_loc, gospa_missed,
    gospa_false; ``sq_err``: {target id: array of squared position
    errors of its matched confirmed track, NaN where unmatched}; ``mot``:
    the CLEAR-MOT totals (:func:`clear_mot`); ``hota``: :func:`hota` with
    the match distance; ``seeded``: :func:`seeded_outcome` at
    ``eval_scan`` (negative counts from the end), or None without seeded
    tracks.
    """
    fr = frames(truth, tracks, nscan, confirmed_only=True)
    tent, conf = counts_per_scan(tracks["scan"], tracks["confirmed"], nscan)
    out = {k: np.zeros(nscan) for k in ("gospa", "gospa_loc", "gospa_missed", "gospa_false")}
    n_truth = np.zeros(nscan, int)
    ct = np.zeros(nscan, int)
    cf = np.zeros(nscan, int)
    sq = {int(t): np.full(nscan, np.nan) for t in np.unique(np.asarray(truth["target"], int))}
    for k, (gid, gxy, _hid, hxy) in enumerate(fr):
        n_truth[k] = len(gid)
        d = distances(gxy, hxy)
        pairs = match(None, None, match_distance, dist=d) if len(gid) and len(hxy) else []
        ct[k] = len(pairs)
        cf[k] = len(hxy) - len(pairs)
        for i, j in pairs:
            sq[int(gid[i])][k] = d[i, j] ** 2
        g = gospa(gxy, hxy, gospa_c)
        out["gospa"][k] = g["gospa"]
        out["gospa_loc"][k] = g["loc"]
        out["gospa_missed"][k] = g["missed"]
        out["gospa_false"][k] = g["false"]
    mot = clear_mot(fr, match_distance)
    hot = hota(fr, match_distance)
    seeded = None
    if seeded_targets:
        k = eval_scan if eval_scan >= 0 else nscan + eval_scan
        allfr = frames(truth, tracks, nscan, confirmed_only=False)[k]
        seeded = seeded_outcome(list(seeded_targets), allfr[0], allfr[1], allfr[2], allfr[3], match_distance)
        seeded["eval_scan"] = int(k)
    split = None
    if splits or "parent" in tracks:
        split = split_outcome(splits, fr, tracks, match_distance)
    out.update({
        "split": split,
        "n_truth": n_truth, "n_tentative": tent, "n_confirmed": conf, "conf_true": ct, "conf_false": cf,
        "sq_err": sq,
        "mot": {k: mot[k] for k in ("gt", "matches", "fn", "fp", "idsw", "swaps", "dist", "mota", "motp")},
        "hota": hot,
        "seeded": seeded,
    })
    return out

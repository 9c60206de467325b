# SPDX-License-Identifier: BSD-3-Clause
"""Metrics on small cases whose answers are worked out by hand in the comments."""

import itertools
import math
import os
import sys
import unittest

import numpy as np

from mtt_sim import csvio, mc, metrics, report


def _brute_match(d, cutoff):
    """Exhaustive per-scan rule: (number of pairs within cutoff, least total distance) over all
    one-to-one partial matchings of the pairs within cutoff."""
    n, m = d.shape
    best = (0, 0.0)

    def rec(i, used, k, tot):
        nonlocal best
        if i == n:
            if k > best[0] or (k == best[0] and tot < best[1]):
                best = (k, tot)
            return
        rec(i + 1, used, k, tot)
        for j in range(m):
            if j not in used and d[i, j] <= cutoff:
                rec(i + 1, used | {j}, k + 1, tot + d[i, j])

    rec(0, frozenset(), 0, 0.0)
    return best


class TestAssignment(unittest.TestCase):
    def test_assignment_matches_brute_force(self):
        # scipy's assignment against every one-to-one cover of the smaller side
        rng = np.random.default_rng(12345)
        for trial in range(300):
            n, m = (int(v) for v in rng.integers(1, 6, 2))
            c = rng.integers(0, 9, (n, m)).astype(float) if trial % 2 else rng.random((n, m)) * 10
            pairs = metrics.assignment(c)
            if n <= m:
                best = min(sum(c[i, j] for i, j in enumerate(p)) for p in itertools.permutations(range(m), n))
            else:
                best = min(sum(c[i, j] for j, i in enumerate(p)) for p in itertools.permutations(range(n), m))
            self.assertAlmostEqual(sum(c[i, j] for i, j in pairs), best, places=9)
            self.assertEqual(len(pairs), min(n, m))
            self.assertEqual(len({i for i, _ in pairs}), len(pairs))
            self.assertEqual(len({j for _, j in pairs}), len(pairs))

    def test_match_rule_matches_brute_force(self):
        # the per-scan rule: most pairs within the cutoff, then least total distance
        rng = np.random.default_rng(2029)
        for trial in range(300):
            n, m = (int(v) for v in rng.integers(1, 6, 2))
            a = rng.random((n, 2)) * 10
            b = rng.random((m, 2)) * 10
            cutoff = float(rng.choice([1.0, 2.5, 4.0]))
            d = metrics.distances(a, b)
            pairs = metrics.match(a, b, cutoff)
            k, tot = _brute_match(d, cutoff)
            self.assertEqual(len(pairs), k)
            self.assertAlmostEqual(sum(d[i, j] for i, j in pairs), tot, places=9)
            self.assertTrue(all(d[i, j] <= cutoff for i, j in pairs))

    def test_hand_3x3(self):
        # cost rows = workers, cols = jobs.  Candidates:
        #   (0,1)+(1,0)+(2,2) = 1 + 2 + 2 = 5   <- optimum
        #   (0,0)+(1,1)+(2,2) = 4 + 4 + 2 = 10, (0,2)+(1,0)+(2,1) = 8 + 2 + 6 = 16, ...
        c = [[4, 1, 8], [2, 4, 7], [9, 6, 2]]
        self.assertEqual(metrics.assignment(c), [(0, 1), (1, 0), (2, 2)])

    def test_empty_and_rectangular(self):
        self.assertEqual(metrics.assignment(np.zeros((0, 3))), [])
        # 3 rows, 1 column: the column goes to the cheapest row (row 2, cost 0.5)
        self.assertEqual(metrics.assignment([[3.0], [1.0], [0.5]]), [(2, 0)])


class TestGospa(unittest.TestCase):
    def test_one_missed(self):
        # X = {(0,0), (10,0)}, Y = {(1,0)}, c = 5, p = 1, alpha = 2.
        # Best: (0,0)-(1,0) at d = 1 (< c); (10,0) is missed: c/2 = 2.5.
        # GOSPA = 1 + 2.5 = 3.5 (loc 1, missed 2.5, false 0).
        g = metrics.gospa([[0, 0], [10, 0]], [[1, 0]], c=5)
        self.assertAlmostEqual(g["gospa"], 3.5)
        self.assertAlmostEqual(g["loc"], 1.0)
        self.assertAlmostEqual(g["missed"], 2.5)
        self.assertAlmostEqual(g["false"], 0.0)
        self.assertEqual((g["n_missed"], g["n_false"]), (1, 0))

    def test_beyond_cutoff_is_missed_plus_false(self):
        # X = {(0,0)}, Y = {(6,0)}, c = 5: d = 6 >= c, so no real pair:
        # one missed (2.5) + one false (2.5) = 5 = c.
        g = metrics.gospa([[0, 0]], [[6, 0]], c=5)
        self.assertAlmostEqual(g["gospa"], 5.0)
        self.assertEqual((g["n_missed"], g["n_false"], g["n_assigned"]), (1, 1, 0))

    def test_optimal_not_greedy(self):
        # X = {(0,0), (4,0)}, Y = {(3,0), (1,0)}, c = 10.
        # Straight pairs: |0-1| + |4-3| = 2; crossed: |0-3| + |4-1| = 6.  GOSPA = 2.
        g = metrics.gospa([[0, 0], [4, 0]], [[3, 0], [1, 0]], c=10)
        self.assertAlmostEqual(g["gospa"], 2.0)

    def test_empty_sets(self):
        # both empty: 0.  X empty, |Y| = 3, c = 5: 3 false * 2.5 = 7.5.
        self.assertEqual(metrics.gospa(np.zeros((0, 2)), np.zeros((0, 2)), c=5)["gospa"], 0.0)
        self.assertAlmostEqual(metrics.gospa(np.zeros((0, 2)), [[0, 0], [1, 1], [2, 2]], c=5)["gospa"], 7.5)
        # |X| = 2, Y empty, c = 4: 2 missed * 2 = 4.
        self.assertAlmostEqual(metrics.gospa([[0, 0], [9, 9]], np.zeros((0, 2)), c=4)["gospa"], 4.0)

    def test_two_targets_one_estimate_between(self):
        # X = {(0,0), (4,0)}, Y = {(2,0)}, c = 3: either pair has d = 2 < 3.
        # GOSPA = 2 (loc) + 1.5 (one missed) = 3.5.
        self.assertAlmostEqual(metrics.gospa([[0, 0], [4, 0]], [[2, 0]], c=3)["gospa"], 3.5)

    def test_p2(self):
        # p = 2: X = {(0,0)}, Y = {(3,4)}, c = 10: d = 5, GOSPA = sqrt(25) = 5.
        self.assertAlmostEqual(metrics.gospa([[0, 0]], [[3, 4]], c=10, p=2)["gospa"], 5.0)


class TestConfirmedTrue(unittest.TestCase):
    def test_counting(self):
        # targets (0,0), (10,0); confirmed tracks (0.5,0), (1,0), (30,0); d_a = 2.
        # target 0 can take (0.5,0) or (1,0) (one-to-one: one of them), target 1
        # has nothing within 2 (nearest 9 away).  True 1, false 2.
        self.assertEqual(metrics.confirmed_true_false([[0, 0], [10, 0]], [[0.5, 0], [1, 0], [30, 0]], 2.0), (1, 2))

    def test_maximum_cardinality(self):
        # A = (0,0), B = (3,0); P = (1.5,0), Q = (-1.6,0); d_a = 2.
        # Distances: A-P 1.5, B-P 1.5, A-Q 1.6, B-Q 4.6 (not allowed).
        # Nearest-first would give A-P and leave B unmatched (1 pair); the rule
        # maximises the number of pairs first: A-Q + B-P = 2 pairs.  True 2, false 0.
        pairs = metrics.match([[0, 0], [3, 0]], [[1.5, 0], [-1.6, 0]], 2.0)
        self.assertEqual(sorted(pairs), [(0, 1), (1, 0)])
        self.assertEqual(metrics.confirmed_true_false([[0, 0], [3, 0]], [[1.5, 0], [-1.6, 0]], 2.0), (2, 0))

    def test_two_tracks_one_target(self):
        # one target, two confirmed tracks on it: one true, one false.
        self.assertEqual(metrics.confirmed_true_false([[5, 5]], [[5, 5.1], [5.2, 5]], 1.0), (1, 1))

    def test_score_run_counts(self):
        # 2 scans. Scan 0: target 0 at (0,0), confirmed track 7 at (0,1), tentative track 8.
        # Scan 1: target 0 at (1,0), confirmed tracks 7 at (1,3) and 9 at (1,0.5); d_a = 2.
        # conf_true = [1, 1] (scan 1: track 9, distance 0.5), conf_false = [0, 1],
        # tentative = [1, 0], confirmed = [1, 2]; sq_err = [1, 0.25].
        truth = {"scan": np.array([0, 1]), "target": np.array([0, 0]),
                 "x": np.array([0.0, 1.0]), "y": np.array([0.0, 0.0])}
        tracks = {"scan": np.array([0, 0, 1, 1]), "track": np.array([7, 8, 7, 9]),
                  "confirmed": np.array([True, False, True, True]),
                  "x": np.array([0.0, 50.0, 1.0, 1.0]), "y": np.array([1.0, 50.0, 3.0, 0.5])}
        sc = metrics.score_run(truth, tracks, 2, match_distance=2.0, gospa_c=2.0)
        self.assertEqual(sc["conf_true"].tolist(), [1, 1])
        self.assertEqual(sc["conf_false"].tolist(), [0, 1])
        self.assertEqual(sc["n_tentative"].tolist(), [1, 0])
        self.assertEqual(sc["n_confirmed"].tolist(), [1, 2])
        np.testing.assert_allclose(sc["sq_err"][0], [1.0, 0.25])
        # GOSPA scan 1 (c = 2): pair target-track 9 at 0.5, track 7 false (1): 1.5.
        self.assertAlmostEqual(sc["gospa"][1], 1.5)


class TestClearMot(unittest.TestCase):
    def test_hand_sequence(self):
        # threshold 2.  Targets 1 and 2; tracks a, b, c, d (ids 10, 11, 12, 13).
        # k0: 1@(0,0) 2@(10,0); a@(0,0) b@(10,0)      -> 1-a, 2-b. FN 0 FP 0 SW 0
        # k1: 1@(1,0) 2@(9,0);  a@(9,0) b@(1,0)       -> old pairs now 8 apart, dropped;
        #     new 1-b, 2-a; 1 was last on a, 2 on b    -> SW 2
        # k2: 1@(2,0) 2@(8,0);  b@(2,0)               -> 1-b kept; 2 missed: FN 1
        # k3: 1@(3,0) 2@(7,0);  b@(3,0) c@(7,0) d@(50,0)
        #     1-b kept; 2-c new, 2 last on a          -> SW 1; d false: FP 1
        # GT = 8, FN = 1, FP = 1, SW = 3 -> MOTA = 1 - 5/8 = 0.375; 7 matches at distance 0.
        fr = [
            ([1, 2], [[0, 0], [10, 0]], [10, 11], [[0, 0], [10, 0]]),
            ([1, 2], [[1, 0], [9, 0]], [10, 11], [[9, 0], [1, 0]]),
            ([1, 2], [[2, 0], [8, 0]], [11], [[2, 0]]),
            ([1, 2], [[3, 0], [7, 0]], [11, 12, 13], [[3, 0], [7, 0], [50, 0]]),
        ]
        r = metrics.clear_mot(fr, 2.0)
        self.assertEqual((r["gt"], r["fn"], r["fp"], r["idsw"], r["matches"]), (8, 1, 1, 3, 7))
        self.assertAlmostEqual(r["mota"], 0.375)
        self.assertAlmostEqual(r["motp"], 0.0)
        # track swaps: a and b each move to the other target at k1 (2); c
        # re-acquires target 2 at k3 as a new track: an ID switch, no swap.
        self.assertEqual(r["swaps"], 2)

    def test_swap_back_counts_twice(self):
        # threshold 1.  Track 7 follows target 1, then target 2, then 1 again:
        # two swaps, but no ID switch: each target is only ever on track 7.
        fr = [([1, 2], [[0, 0], [5, 0]], [7], [[0, 0]]),
              ([1, 2], [[0, 0], [5, 0]], [7], [[5, 0]]),
              ([1, 2], [[0, 0], [5, 0]], [7], [[0, 0]])]
        r = metrics.clear_mot(fr, 1.0)
        self.assertEqual((r["swaps"], r["idsw"]), (2, 0))

    def test_keeps_previous_correspondence(self):
        # threshold 3.  k0: target 1@(0,0), track a@(0,0) -> 1-a.
        # k1: target 1@(0,0); a@(2,0), b@(0,0).  The optimum alone would pick b
        # (distance 0) but a is still within 3, so 1-a is kept: no switch, b false.
        # MOTA = 1 - (0 + 1 + 0)/2 = 0.5, MOTP = (0 + 2)/2 = 1.
        fr = [([1], [[0, 0]], [5], [[0, 0]]), ([1], [[0, 0]], [5, 6], [[2, 0], [0, 0]])]
        r = metrics.clear_mot(fr, 3.0)
        self.assertEqual((r["idsw"], r["fp"]), (0, 1))
        self.assertAlmostEqual(r["mota"], 0.5)
        self.assertAlmostEqual(r["motp"], 1.0)


    def test_most_pairs_then_least_distance(self):
        # threshold 2, one scan: A = (0,0), B = (3,0); P = (1.5,0), Q = (-1.6,0)
        # (TestConfirmedTrue.test_maximum_cardinality): the two pairs A-Q, B-P
        # (1.6 + 1.5 = 3.1), not the nearest A-P alone.  MOTP = 3.1 / 2 = 1.55.
        r = metrics.clear_mot([([1, 2], [[0, 0], [3, 0]], [5, 6], [[1.5, 0], [-1.6, 0]])], 2.0)
        self.assertEqual((r["matches"], r["fn"], r["fp"]), (2, 0, 0))
        self.assertAlmostEqual(r["dist"], 3.1, places=12)
        self.assertAlmostEqual(r["motp"], 1.55, places=12)

    def test_matches_reference_rule(self):
        # TrackEval's CLEAR with the similarity of metrics.clear_mot against the rule
        # of its docstring written out (_reference_clear_mot) on random sequences.
        rng = np.random.default_rng(7)
        for trial in range(60):
            nscan, cutoff = int(rng.integers(5, 25)), float(rng.choice([1.0, 2.0, 3.0]))
            pos = rng.random((4, 2)) * 6
            fr = []
            for _ in range(nscan):
                pos += rng.normal(0, 0.5, pos.shape)
                g = [t for t in range(4) if rng.random() < 0.9]
                h = [int(x) for x in rng.choice(8, int(rng.integers(0, 6)), replace=False)]
                hxy = pos[rng.integers(0, 4, len(h))] + rng.normal(0, 1.0, (len(h), 2))
                fr.append((g, pos[g], h, hxy.reshape(-1, 2)))
            r, ref = metrics.clear_mot(fr, cutoff), _reference_clear_mot(fr, cutoff)
            for k in ("gt", "matches", "fn", "fp", "idsw", "swaps"):
                self.assertEqual(r[k], ref[k], (trial, k))
            self.assertAlmostEqual(r["dist"], ref["dist"], delta=1e-9 * max(1.0, ref["dist"]))

    def test_pairs_carry_over_an_empty_scan(self):
        # threshold 3.  k0: 1-a.  k1: no track.  k2: a 2 away and b on the target: 1-a is
        # kept (the pairs of k0 carry over k1), no switch, b false.
        fr = [([1], [[0, 0]], [5], [[0, 0]]), ([1], [[0, 0]], [], np.zeros((0, 2))),
              ([1], [[0, 0]], [5, 6], [[2, 0], [0, 0]])]
        r = metrics.clear_mot(fr, 3.0)
        self.assertEqual((r["matches"], r["fn"], r["fp"], r["idsw"]), (2, 1, 1, 0))
        self.assertAlmostEqual(r["dist"], 2.0, places=12)


def _reference_clear_mot(fr, cutoff):
    """The correspondence rule of metrics.clear_mot, written out: previous-scan pairs kept
    within cutoff (a scan without targets or without tracks leaves them as they were), the
    rest by metrics.match; ID switches against the last track of each target, swaps against
    the last target of each track."""
    prev, last, last_target = {}, {}, {}
    out = {"gt": 0, "matches": 0, "fn": 0, "fp": 0, "idsw": 0, "swaps": 0, "dist": 0.0}
    for gid, gxy, hid, hxy in fr:
        d = metrics.distances(gxy, hxy)
        col = {h: j for j, h in enumerate(hid)}
        cur = {g: prev[g] for i, g in enumerate(gid) if prev.get(g) in col and d[i, col[prev[g]]] <= cutoff}
        rg = [i for i, g in enumerate(gid) if g not in cur]
        rh = [j for j, h in enumerate(hid) if h not in cur.values()]
        if rg and rh:
            for a, b in metrics.match(None, None, cutoff, dist=d[np.ix_(rg, rh)]):
                g, h = gid[rg[a]], hid[rh[b]]
                out["idsw"] += int(g in last and last[g] != h)
                cur[g] = h
        for g, h in cur.items():
            out["dist"] += d[gid.index(g), col[h]]
            out["swaps"] += int(last_target.get(h, g) != g)
            last_target[h] = g
        out["gt"] += len(gid)
        out["matches"] += len(cur)
        out["fn"] += len(gid) - len(cur)
        out["fp"] += len(hid) - len(cur)
        if gid and hid:
            prev = cur
        last.update(cur)
    return out


class TestHota(unittest.TestCase):
    # TrackEval's thresholds: alpha = 0.05, 0.10, ..., 0.95 (19); similarity 1 - d / cutoff.
    def test_perfect(self):
        # one target, one track on it at every scan: every alpha matches, HOTA = DetA = AssA = 1.
        fr = [([1], [[k, 0]], [9], [[k, 0]]) for k in range(4)]
        h = metrics.hota(fr, 2.0)
        self.assertAlmostEqual(h["hota"], 1.0)
        self.assertAlmostEqual(h["deta"], 1.0)
        self.assertAlmostEqual(h["assa"], 1.0)
        self.assertEqual(h["HOTA_TP"].tolist(), [4.0] * 19)

    def test_id_switch_halves_assa(self):
        # target 1 is followed by track 8 at scans 0-1 and by track 9 at scans 2-3, exactly.
        # DetA = 1; each pair's association IoU is 2 / (2 + 2 + 0) = 0.5, so AssA = 0.5 and
        # HOTA = sqrt(1 * 0.5) = 0.70711.
        fr = [([1], [[k, 0]], [8 if k < 2 else 9], [[k, 0]]) for k in range(4)]
        h = metrics.hota(fr, 2.0)
        self.assertAlmostEqual(h["deta"], 1.0)
        self.assertAlmostEqual(h["assa"], 0.5)
        self.assertAlmostEqual(h["hota"], math.sqrt(0.5))

    def test_localisation_thresholds(self):
        # the track 0.98 away with cutoff 2: similarity 0.51, a match for the 10 alphas
        # 0.05 .. 0.50 only.  HOTA = 10/19 = 0.52632; LocA = 0.51 at those alphas and 1
        # (TrackEval's value without a match) at the 9 others: (10 * 0.51 + 9) / 19.
        # A second run with the track on the target combines (TrackEval's
        # combine_sequences) to TP 8, FN 0, FP 0 at the 10 alphas and TP 4, FN 4, FP 4 at
        # the others: DetA = (10 * 1 + 9 * 4/12) / 19 = 0.68421.
        far = [([1], [[k, 0]], [9], [[k, 0.98]]) for k in range(4)]
        h = metrics.hota(far, 2.0)
        self.assertAlmostEqual(h["hota"], 10 / 19)
        self.assertAlmostEqual(h["loca"], (10 * 0.51 + 9) / 19)
        both = metrics.hota_combine([h, metrics.hota([([1], [[k, 0]], [9], [[k, 0]]) for k in range(4)], 2.0)])
        self.assertAlmostEqual(both["deta"], (10 + 9 * 4 / 12) / 19)

    def test_empty(self):
        # no track at all: every target detection is a miss, HOTA 0.
        h = metrics.hota([([1], [[0, 0]], [], np.zeros((0, 2)))], 1.0)
        self.assertEqual(h["HOTA_FN"].tolist(), [1.0] * 19)
        self.assertAlmostEqual(h["hota"], 0.0)


class TestSeededOutcome(unittest.TestCase):
    T_IDS = [0, 1, 2]
    T_XY = [[0, 0], [0, 3], [0, 6]]

    def outcome(self, tracks):
        ids = list(tracks)
        xy = [tracks[i] for i in ids]
        return metrics.seeded_outcome([0, 1, 2], self.T_IDS, self.T_XY, ids, xy, cutoff=1.0)

    def test_all_on_own(self):
        # nearest targets: 0 -> 0 (0.1), 1 -> 1 (0), 2 -> 2 (0.2): nothing wrong.
        r = self.outcome({0: [0, 0.1], 1: [0, 3], 2: [0, 6.2]})
        self.assertEqual(r["on"], [0, 1, 2])
        self.assertFalse(r["failed"])

    def test_coalescence(self):
        # tracks 0 and 1 both nearest to target 0 (0 and 0.2 away): coalescence;
        # track 1 is on target 0, not its own 1, so the switch flag is also set.
        r = self.outcome({0: [0, 0], 1: [0, 0.2], 2: [0, 6]})
        self.assertEqual(r["on"], [0, 0, 2])
        self.assertTrue(r["coalescence"])
        self.assertTrue(r["switch"])
        self.assertFalse(r["lost"])
        self.assertTrue(r["failed"])

    def test_switch(self):
        # tracks 0 and 1 exchanged targets: switch without coalescence.
        r = self.outcome({0: [0, 3], 1: [0, 0], 2: [0, 6]})
        self.assertEqual(r["on"], [1, 0, 2])
        self.assertTrue(r["switch"])
        self.assertFalse(r["coalescence"])
        self.assertTrue(r["failed"])

    def test_lost(self):
        # track 2 deleted -> lost; track 2 present but 3 away from everything -> lost.
        r = self.outcome({0: [0, 0], 1: [0, 3]})
        self.assertEqual(r["on"], [0, 1, None])
        self.assertTrue(r["lost"] and r["failed"])
        self.assertFalse(r["switch"] or r["coalescence"])
        r = self.outcome({0: [0, 0], 1: [0, 3], 2: [0, 9]})
        self.assertTrue(r["lost"] and r["failed"])

    def test_score_run_uses_last_scan_and_tentative(self):
        # one target 0, seeded track 0.  Scan 0: on target; scan 1 (last): the
        # track is 5 away (> cutoff 1) -> lost at the evaluation scan.
        truth = {"scan": np.array([0, 1]), "target": np.array([0, 0]),
                 "x": np.array([0.0, 1.0]), "y": np.array([0.0, 0.0])}
        tracks = {"scan": np.array([0, 1]), "track": np.array([0, 0]), "confirmed": np.array([True, True]),
                  "x": np.array([0.0, 6.0]), "y": np.array([0.0, 0.0])}
        sc = metrics.score_run(truth, tracks, 2, 1.0, 1.0, seeded_targets=[0])
        self.assertTrue(sc["seeded"]["lost"])
        self.assertEqual(sc["seeded"]["eval_scan"], 1)
        sc = metrics.score_run(truth, tracks, 2, 1.0, 1.0, seeded_targets=[0], eval_scan=0)
        self.assertFalse(sc["seeded"]["failed"])


class TestCountsAndTime(unittest.TestCase):
    def test_counts(self):
        # scans 0,0,1,2,2,2 with confirmed F,T,T,F,F,T over 4 scans:
        # tentative [1,0,2,0], confirmed [1,1,1,0]
        t, c = metrics.counts_per_scan([0, 0, 1, 2, 2, 2], [0, 1, 1, 0, 0, 1], 4)
        self.assertEqual(t.tolist(), [1, 0, 2, 0])
        self.assertEqual(c.tolist(), [1, 1, 1, 0])

    def test_time_per_frame(self):
        self.assertAlmostEqual(metrics.time_per_frame(0.5, 100), 0.005)


class TestRmseLegs(unittest.TestCase):
    def test_turn_mask(self):
        m = metrics.turn_mask([(1, 2), (5, 5)], 7)
        self.assertEqual(m.tolist(), [False, True, True, False, False, True, False])
        # windows beyond the run are clipped
        self.assertEqual(metrics.turn_mask([(5, 9)], 6).tolist(), [False] * 5 + [True])

    def test_split(self):
        # target 0 turns in scans 1-2: squared errors 1, 4, 9, - (scan 3 unmatched);
        # target 1 has no manoeuvre: 16 at scan 0.
        # straight: (1 + 16) / 2 -> sqrt(8.5); turn: (4 + 9) / 2 -> sqrt(6.5).
        sq = {0: (np.array([1.0, 4.0, 9.0, 0.0]), np.array([1, 1, 1, 0])),
              1: (np.array([16.0, 0.0, 0.0, 0.0]), np.array([1, 0, 0, 0]))}
        r = metrics.rmse_legs(sq, {0: [(1, 2)]}, 4)
        self.assertAlmostEqual(r["straight"], math.sqrt(8.5))
        self.assertAlmostEqual(r["turn"], math.sqrt(6.5))
        self.assertEqual((r["straight_n"], r["turn_n"]), (2, 2))
        # no window at all: everything is straight, the turn RMSE is NaN
        r = metrics.rmse_legs(sq, {}, 4)
        self.assertAlmostEqual(r["straight"], math.sqrt(30.0 / 4))
        self.assertTrue(math.isnan(r["turn"]))

    def test_report_rows_only_with_manoeuvres(self):
        # One target at (0, 0) for 3 scans, one confirmed track 3 m off at scans
        # 0 and 2 and 4 m off at scan 1 (the turn window): straight RMSE 3, turn 4.
        truth = {"scan": np.array([0, 1, 2]), "target": np.array([0, 0, 0]),
                 "x": np.zeros(3), "y": np.zeros(3)}
        tracks = {"scan": np.array([0, 1, 2]), "track": np.array([5, 5, 5]), "confirmed": np.ones(3, bool),
                  "x": np.array([3.0, 4.0, 3.0]), "y": np.zeros(3)}
        sc = metrics.score_run(truth, tracks, 3, 10.0, 10.0)
        res = {"ok": True, "run": 0, "seed": 0, "score": sc, "time_per_frame": 0.001}
        summaries = {}
        for name, windows in (("turns", {0: [(1, 1)]}), ("straight", None)):
            agg = mc.Aggregate(3, windows)
            agg.add(res)
            summaries[name] = {"modes": ["m"], "results": {"m": agg.result()}, "metrics": {"gospa_c": 10.0}}
        tot = summaries["turns"]["results"]["m"]["totals"]
        self.assertAlmostEqual(tot["rmse_straight"], 3.0)
        self.assertAlmostEqual(tot["rmse_turn"], 4.0)
        self.assertNotIn("rmse_turn", summaries["straight"]["results"]["m"]["totals"])
        self.assertIn("in turns", report.table_summary(summaries["turns"]))
        self.assertNotIn("in turns", report.table_summary(summaries["straight"]))


class TestSplitOutcome(unittest.TestCase):
    # Target 0 at x = 0 for scans 0..5; target 1 splits off it at scan 2 and
    # is at x = 0, 30, 60, 90 at scans 2..5.  Track 7 follows target 0
    # throughout; track 9 (parent 7) starts at scan 4 on target 1; track 11
    # (parent 7) starts at scan 3 at x = 500, on nothing.
    def case(self):
        truth = {"scan": np.array([0, 1, 2, 3, 4, 5, 2, 3, 4, 5]),
                 "target": np.array([0] * 6 + [1] * 4),
                 "x": np.array([0.0] * 6 + [0.0, 30.0, 60.0, 90.0]), "y": np.zeros(10)}
        tracks = {"scan": np.array([0, 1, 2, 3, 4, 5, 4, 5, 3, 4]),
                  "track": np.array([7] * 6 + [9, 9, 11, 11]), "confirmed": np.ones(10, bool),
                  "x": np.array([0.0] * 6 + [61.0, 92.0, 500.0, 510.0]), "y": np.zeros(10),
                  "parent": np.array([-1] * 6 + [7, 7, 7, 7])}
        return truth, tracks

    def test_delay_and_false_splits(self):
        truth, tracks = self.case()
        fr = metrics.frames(truth, tracks, 6)
        out = metrics.split_outcome([(1, 0, 2)], fr, tracks, 10.0)
        # scan 2: track 7 is matched to one of the two (both at x = 0), not
        # both; scan 3: target 1 is 30 away from track 7, unmatched; scan 4:
        # track 9 on target 1 and track 7 on target 0: delay 4 - 2 = 2
        self.assertEqual(out["delays"], [2])
        self.assertEqual(out["spawned"], 2)
        self.assertEqual(out["false_splits"], 1)  # track 11: 500 away from both

    def test_never_and_no_parent_column(self):
        truth, tracks = self.case()
        del tracks["parent"]
        keep = tracks["track"] != 9
        tracks = {k: v[keep] for k, v in tracks.items()}
        out = metrics.split_outcome([(1, 0, 2)], metrics.frames(truth, tracks, 6), tracks, 10.0)
        self.assertEqual(out, {"delays": [None], "spawned": 0, "false_splits": 0})

    def test_tracks_file_columns(self):
        head = csvio.TRACKS_HEADER + ",mu_0,mu_1,p_split,parent\n"
        t = csvio.parse_tracks(head + "3,3,0,confirmed,1,2,3,4,0.9,1,0,1,0.5,0.5,0.25,\n"
                               "3,3,4,confirmed,1,2,3,4,0.9,1,0,1,1,0,0,0\n")
        self.assertEqual(t["mu"].shape, (2, 2))
        self.assertEqual(list(t["p_split"]), [0.25, 0.0])
        self.assertEqual(list(t["parent"]), [-1, 0])
        with self.assertRaises(csvio.FormatError):  # p_split without parent
            csvio.parse_tracks(csvio.TRACKS_HEADER + ",mu_0,mu_1,p_split\n")

    def test_aggregate_quantiles(self):
        # delays 1, 2, 3, 8 and one child never confirmed: median 3, 90th
        # percentile (inverted cdf over 5) the never one, within 3 scans 3 of 5
        agg = mc.Aggregate(6)
        truth, tracks = self.case()
        sc = metrics.score_run(truth, tracks, 6, 10.0, 10.0, splits=[(1, 0, 2)])
        for d in ([1], [2], [3], [8], [None]):
            sc = dict(sc, split={"delays": d, "spawned": 1, "false_splits": 0})
            agg.add({"ok": True, "run": 1, "seed": 1, "score": sc, "time_per_frame": 0.001})
        sp = agg.result()["totals"]["split"]
        self.assertEqual(sp["delay_median"], 3.0)
        self.assertIsNone(sp["delay_p90"])  # infinite: printed as '-'
        self.assertAlmostEqual(sp["within3"], 0.6)
        self.assertEqual(sp["never"], 1)


if __name__ == "__main__":
    unittest.main()

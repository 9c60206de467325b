# SPDX-License-Identifier: BSD-3-Clause
"""mtt_ref: an independent reference of mtt's per-frame pipeline (numpy, double).

Written from docs/ALGORITHMS.md and docs/FORMATS.md only, never from src/:
it exists so that python/tests/test_differential.py can compare the C
library, frame by frame, with the documented equations.

    from mtt_ref import Params, Tracker
    trk = Tracker(Params(association="lm-ihpda", clutter_density=1e-3))
    trk.add_track([0, 0, 1, 0], P)              # seeded: confirmed, existence 1
    trk.step(0.0, [(0.1, -0.2, 2.5), (4.0, 1.0, None)])   # (x, y, amplitude or None)
    for t in trk.tracks: print(t.id, t.confirmed, t.x, t.P, t.existence)

Modes: lm-ihpda, ihpda, lm-ipda, ipda (ALGORITHMS.md §15.1).
"""

from .tracker import Params, Track, Tracker, rank_probabilities, two_point_cov  # noqa: F401
from .scene import Scene, read_scene, write_scene, parse_driver_output  # noqa: F401

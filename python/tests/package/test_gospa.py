# SPDX-License-Identifier: BSD-3-Clause
"""mtt_sim.metrics.gospa against Stone Soup's GOSPAMetric on seeded random sets.

Both compute GOSPA with alpha = 2 and no further normalisation: d = (sum of
d^p over the assigned pairs + c^p / 2 per missed and per false point)^(1/p),
a pair assignable only at a distance below c (Stone Soup:
GOSPAMetric.compute_gospa_metric, its cost matrix min(d, c), its "missed" and
"false" the c^p / 2 terms, as ours).  Every part must agree to 1e-9 relative."""

import datetime

import numpy as np
import pytest

from conftest import missing

try:
    import stonesoup  # noqa: F401
except ImportError:  # pragma: no cover - CI installs the extra
    stonesoup = None

T0 = datetime.datetime(2024, 1, 1)


def stonesoup_gospa(truth_xy, est_xy, c, p):
    from stonesoup.measures import Euclidean
    from stonesoup.metricgenerator.ospametric import GOSPAMetric
    from stonesoup.types.state import State

    def states(xy):
        return [State(np.array([[x], [y]]), timestamp=T0) for x, y in xy]

    m, _ = GOSPAMetric(c=c, p=p, measure=Euclidean()).compute_gospa_metric(states(est_xy), states(truth_xy))
    return m.value


@pytest.mark.parametrize("p", [1, 2])
@pytest.mark.parametrize("c", [0.5, 2.0, 5.0, 30.0])
def test_gospa_equals_stonesoup(c, p):
    if stonesoup is None:
        missing("stonesoup not installed (pip install .[stonesoup])")
    from mtt_sim import metrics

    rng = np.random.default_rng(int(c * 10) + 1000 * p)
    seen = {"pairs": 0, "missed": 0, "false": 0}
    for trial in range(150):
        nx, ny = rng.integers(0, 9, 2)
        X = rng.random((nx, 2)) * 20
        # half the estimates near a target, the rest anywhere
        Y = rng.random((ny, 2)) * 20
        if nx:
            near = rng.random(ny) < 0.5
            Y[near] = X[rng.integers(0, nx, near.sum())] + rng.normal(0, c / 2, (near.sum(), 2))
        ours = metrics.gospa(X, Y, c=c, p=p)
        if nx == 0 and ny == 0:  # Stone Soup needs one state for the time stamp
            assert ours["gospa"] == 0.0
            continue
        ss = stonesoup_gospa(X, Y, c, p)
        for a, b in (("gospa", "distance"), ("loc", "localisation"), ("missed", "missed"), ("false", "false")):
            assert ours[a] == pytest.approx(float(ss[b]), rel=1e-9, abs=1e-12), (trial, nx, ny, a)
        seen["pairs"] += ours["n_assigned"]
        seen["missed"] += ours["n_missed"]
        seen["false"] += ours["n_false"]
    # every part of the metric was exercised
    assert min(seen.values()) > 20, seen

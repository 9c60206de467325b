# SPDX-License-Identifier: BSD-3-Clause
"""mtt_sim: scenario generation, scoring and Monte Carlo harness for mtt.

Host-side only (Python 3.11, numpy, scipy, TrackEval, matplotlib).  Modules:

- ``scenario``  load and validate scenario JSON files (schema: scenarios/README.md)
- ``gen``       draw one run (truth, detections) from a scenario and a seed; its command
- ``csvio``     read and write the CSV / JSON files of docs/FORMATS.md
- ``metrics``   pure scoring functions (matching, GOSPA, CLEAR-MOT and HOTA by TrackEval, RMSE, ...)
- ``mc``        Monte Carlo runner around the tracker (in-process or ``mtt-track``); its command
- ``report``    text tables in the papers' formats
- ``plot``      matplotlib (Agg) figures; its command
"""

__all__ = ["scenario", "gen", "csvio", "metrics", "mc", "report", "plot"]

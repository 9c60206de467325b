# SPDX-License-Identifier: BSD-3-Clause
"""mtt: the bounded multi-target tracker (LM-IHPDA and the IPDA / JPDA families) in Python.

The C library runs in-process (extension module ``mtt._core``); this package
adds numpy in and out:

- :class:`mtt.Tracker`  ``Tracker(settings=None)``, ``step(time, detections)``,
  ``tracks``, ``stats``
- :class:`mtt.Track`    ``id``, ``confirmed``, ``state``, ``covar``, ``existence``, ``age``
- ``mtt.stonesoup``     ``MttTracker``, a Stone Soup tracker (``pip install mtt[stonesoup]``)

``mtt.REAL`` says which arithmetic the library was built with ("float", as
mtt-track's default build, or "double").  docs/PYTHON.md has the examples.
"""

from . import _core
from .settings import SettingsError
from .tracker import Track, Tracker

__version__ = _core.VERSION
REAL = _core.REAL
MAX_TRACKS = _core.MAX_TRACKS
MAX_MEAS = _core.MAX_MEAS

__all__ = ["Tracker", "Track", "SettingsError", "__version__", "REAL", "MAX_TRACKS", "MAX_MEAS"]

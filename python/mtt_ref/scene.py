# SPDX-License-Identifier: BSD-3-Clause
"""The differential scene format, shared by mtt_ref and test/differential/driver.c.

A scene is plain text, one item per line ('#' starts a comment line):

    param <key> <value> [<value>]      a docs/FORMATS.md setting, nested keys dotted
                                       (meas_sigma takes two values, intensity_gate.f1
                                       and .f2 three, intensity_gate.blend two;
                                       association / init_gate take a name;
                                       initiate takes 0 or 1)
    track x y vx vy p00 p01 ... p33    a seeded track (16 covariance values, row-major)
    frame <time> <n>                   a frame with n detections, then n lines:
    <x> <y> <amplitude | ->            '-' means no amplitude

Numbers are written with repr(), so the C reader (strtod) sees the same doubles.

The driver prints, after each frame, `frame <k> <n>` and one line per live track
in ascending id:

    T id confirmed x0 x1 x2 x3 P00 ... P33 existence age meas
"""

from dataclasses import dataclass, field

import numpy as np

from .tracker import Params, Tracker

_VECTOR = {"meas_sigma": 2, "intensity_gate.f1": 3, "intensity_gate.f2": 3, "intensity_gate.blend": 2}
# settings keys (docs/FORMATS.md, nested ones dotted) -> Params fields
_FIELD = {"intensity_gate.f1": "intensity_f1", "intensity_gate.f2": "intensity_f2",
          "intensity_gate.blend": "intensity_blend"}
_NAMES = {"association", "init_gate"}


@dataclass
class Scene:
    params: dict = field(default_factory=dict)   # docs/FORMATS.md name -> value
    tracks: list = field(default_factory=list)   # (x[4], P[16])
    frames: list = field(default_factory=list)   # (time, [(x, y, amp or None)])

    def make_params(self):
        kw = {}
        for k, v in self.params.items():
            kw[_FIELD.get(k, k)] = tuple(v) if k in _VECTOR else v
        if "initiate" in kw:
            kw["initiate"] = bool(kw["initiate"])
        return Params(**kw)

    def run_reference(self):
        """Run mtt_ref over the scene: returns (frames, near_ties), frames as parse_driver_output."""
        trk = Tracker(self.make_params())
        for x, P in self.tracks:
            trk.add_track(x, np.array(P).reshape(4, 4))
        out = []
        for t, dets in self.frames:
            trk.step(t, dets)
            out.append([(tr.id, int(tr.confirmed), tr.x.copy(), tr.P.copy(), tr.existence,
                         tr.age, tr.meas) for tr in trk.tracks])
        self.events = trk.events
        self.exact_ties = trk.exact_ties
        return out, trk.near_ties + trk.exact_ties


def _num(v):
    return repr(float(v))


def write_scene(scene, path=None):
    lines = ["# mtt differential scene"]
    for k, v in scene.params.items():
        if k in _VECTOR:
            lines.append(f"param {k} " + " ".join(_num(a) for a in v))
        elif k in _NAMES:
            lines.append(f"param {k} {v}")
        elif isinstance(v, bool):
            lines.append(f"param {k} {int(v)}")
        else:
            lines.append(f"param {k} {_num(v)}")
    for x, P in scene.tracks:
        lines.append("track " + " ".join(_num(a) for a in list(x) + list(np.ravel(P))))
    for t, dets in scene.frames:
        lines.append(f"frame {_num(t)} {len(dets)}")
        for d in dets:
            a = "-" if d[2] is None else _num(d[2])
            lines.append(f"{_num(d[0])} {_num(d[1])} {a}")
    text = "\n".join(lines) + "\n"
    if path is not None:
        with open(path, "w") as fh:
            fh.write(text)
    return text


def read_scene(text):
    sc = Scene()
    lines = [ln.split() for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    i = 0
    while i < len(lines):
        w = lines[i]
        i += 1
        if w[0] == "param":
            k = w[1]
            if k in _VECTOR:
                sc.params[k] = [float(a) for a in w[2:]]
            elif k in _NAMES:
                sc.params[k] = w[2]
            elif k == "initiate":
                sc.params[k] = bool(int(w[2]))
            else:
                sc.params[k] = float(w[2])
        elif w[0] == "track":
            v = [float(a) for a in w[1:]]
            sc.tracks.append((v[:4], v[4:20]))
        elif w[0] == "frame":
            t, n = float(w[1]), int(w[2])
            dets = []
            for d in lines[i:i + n]:
                dets.append((float(d[0]), float(d[1]), None if d[2] == "-" else float(d[2])))
            i += n
            sc.frames.append((t, dets))
        else:
            raise ValueError(f"scene: unknown line {' '.join(w)!r}")
    return sc


def parse_driver_output(text):
    """-> list per frame of (id, confirmed, x[4], P[4x4], existence, age, meas)."""
    frames = []
    for ln in text.splitlines():
        w = ln.split()
        if not w:
            continue
        if w[0] == "frame":
            frames.append([])
        elif w[0] == "T":
            v = [float(a) for a in w[3:24]]
            frames[-1].append((int(w[1]), int(w[2]), np.array(v[:4]), np.array(v[4:20]).reshape(4, 4),
                               v[20], int(w[24]), int(w[25])))
    return frames

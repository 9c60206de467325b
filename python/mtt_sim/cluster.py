# SPDX-License-Identifier: BSD-3-Clause
"""A real Dask cluster on this machine: `dask scheduler` and N `dask worker` processes.

    with LocalDaskCluster(workers=2) as addr:      # tcp://127.0.0.1:PORT
        mtt_sim.mc.monte_carlo(scn, modes, runs, exe, scheduler=addr)

The processes are the commands of a real cluster (dask[distributed]'s
`dask` command), started with this Python and PYTHONPATH so that the
workers import this mtt_sim, each worker with one process and one thread
(`--nworkers 1 --nthreads 1`), no dashboards, on 127.0.0.1 with a port the
scheduler picks (`--port 0`, read back from its --scheduler-file).  Leaving
the block stops them (terminate, then kill after 10 s) and removes their
directory.  Used by python/tests/test_tune.py and tools/bench/mc_throughput.py.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

__all__ = ["LocalDaskCluster"]

PYTHON_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class LocalDaskCluster:
    def __init__(self, workers: int = 2, timeout: float = 60.0):
        self.workers = workers
        self.timeout = timeout
        self.procs: list[subprocess.Popen] = []
        self.dir = None
        self.address = None

    def _spawn(self, args, name):
        log = open(os.path.join(self.dir, name + ".log"), "w")
        env = dict(os.environ, PYTHONPATH=os.pathsep.join(
            [PYTHON_DIR] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]))
        # `python -m dask` is the `dask` command of this Python
        p = subprocess.Popen([sys.executable, "-m", *args], stdout=log, stderr=subprocess.STDOUT, env=env,
                             cwd=self.dir, stdin=subprocess.DEVNULL)
        log.close()
        self.procs.append(p)
        return p

    def __enter__(self) -> str:
        from distributed import Client

        self.dir = tempfile.mkdtemp(prefix="mtt_dask_")
        sfile = os.path.join(self.dir, "scheduler.json")
        try:
            self._spawn(["dask", "scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                         "--scheduler-file", sfile], "scheduler")
            t_end = time.monotonic() + self.timeout
            while not os.path.isfile(sfile) or not os.path.getsize(sfile):
                if time.monotonic() > t_end or self.procs[0].poll() is not None:
                    raise RuntimeError(f"dask scheduler did not start: {self.log('scheduler')}")
                time.sleep(0.1)
            time.sleep(0.1)  # the file is written whole, once
            with open(sfile, encoding="utf-8") as f:
                self.address = json.load(f)["address"]
            for i in range(self.workers):
                self._spawn(["dask", "worker", self.address, "--nworkers", "1", "--nthreads", "1",
                             "--no-dashboard", "--name", f"w{i}", "--local-directory",
                             os.path.join(self.dir, f"w{i}")], f"worker{i}")
            with Client(self.address, timeout="30s") as c:
                c.wait_for_workers(self.workers, timeout=self.timeout)
        except BaseException:
            self.__exit__(None, None, None)
            raise
        return self.address

    def log(self, name: str) -> str:
        try:
            with open(os.path.join(self.dir, name + ".log"), encoding="utf-8") as f:
                return f.read()[-2000:]
        except OSError:
            return ""

    def __exit__(self, *exc):
        for p in reversed(self.procs):  # the workers first, then the scheduler
            if p.poll() is None:
                p.terminate()
        for p in self.procs:
            try:
                p.wait(10)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
        self.procs = []
        if self.dir:
            shutil.rmtree(self.dir, ignore_errors=True)
        return False

#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Tune tracker settings on Monte Carlo runs of scenarios with Optuna.

    PYTHONPATH=python python3 -m mtt_sim.tune --scenario scenarios/crossing3.json \\
        --space process_psd=log:0.1:1000 --space pd=0.7:0.99 --trials 30 --runs 20 \\
        --out out/tune --holdout-seed0 1000

Each trial sets the tuned keys in every scenario's "tracker" object and runs
Monte Carlo runs SEED0 .. SEED0+RUNS-1 of each scenario (mtt_sim.mc, the
same seeds in every trial); its value is the objective (minimised) of the
summary's totals, the mean over the scenarios.

--space KEY=SPEC (repeatable), KEY a tracker key (a dotted path reaches into
  it: imm_models.1.process_psd), SPEC one of
    LO:HI            uniform float          pd=0.7:0.99
    log:LO:HI        log-uniform float      process_psd=log:0.1:1000
    int:LO:HI        integer                n_max=int:2:8
    choice:A,B,...   one of JSON values     association=choice:"lm-ipda","lm-ihpda"
--space-file F.json: a JSON object {KEY: SPEC string, or [LO, HI], or
  {"low": LO, "high": HI, "log": true, "int": false}, or {"choices": [..]}};
  --space entries replace the file's.
--objective: a weighted sum of numeric totals of the summary, e.g.
  'gospa_mean+50*idsw_per_run' or '-100*mota+rmse_all' (default gospa_mean;
  names: gospa_mean, idsw_per_run, swaps_per_run, confirmed_false_per_scan,
  confirmed_true_fraction, mota, motp, rmse_all, ...; a dotted name reaches
  into a total: split.delay_median).  A trial whose runs fail is FAIL.

Search: TPE (--sampler tpe, default) or random, seeded (--seed); the sampler
of the n-th counted trial is seeded with (SEED, n), so the trials are a
function of the seed and the finished trials alone.  Pruning (MedianPruner,
5 startup trials; --no-prune turns it off): the runs of a trial go in
--chunks chunks, the objective of the runs so far is reported after each
chunk and a trial worse than the median of the completed ones at that
chunk stops.  The study is stored in SQLite (--storage, default
OUT/study.db; a URL with :// is any Optuna RDB storage) under --study:
running the same command again continues it up to --trials finished trials
(a trial interrupted by Ctrl-C is marked FAIL and does not count).

Engine (--scheduler): local (default): one trial at a time, its runs on
--jobs local processes.  tcp://HOST:8786, a running Dask scheduler: the
trials are Dask tasks, in batches of as many trials as the cluster has
worker threads, each running its runs serially; the client asks Optuna for
a batch, each task prunes against the trials finished before its batch
(a private copy of them), and the client tells the results in trial order.
So a serial study is reproducible, and a study on W worker threads is
reproducible for the same W; the first 10 trials (TPE's random start-up,
pruning not yet active) are the same as the serial ones, later ones differ
as TPE sees batches.  The storage is used by the client only.

Writes OUT/best_settings.json (the first scenario's tracker settings with
the tuned keys replaced: a settings file for mtt-track --config; with
several scenarios also OUT/best_settings.<scenario>.json each), OUT/best.json
(value, parameters, trial counts, held-out figures), and the plots
OUT/history.png, OUT/importances.png (with 2 or more keys) and
OUT/slice_<key>.png (the objective against each key).  Scenario files and
the library's defaults are never written.  --holdout-seed0 N runs the best
settings and the scenarios' own settings (with --set applied) on seeds
N .. N+HOLDOUT_RUNS-1, which must not overlap the tuning seeds, and prints
both.  Exit status 0, 1 if no trial completed, 2 on bad arguments.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import sys
import time

from . import mc
from . import scenario as scnmod

__all__ = ["parse_space_item", "parse_space_file", "parse_objective", "objective_value", "with_params",
           "evaluate_trial", "tune", "main"]

# ------------------------------------------------------------------ search space


class SpaceError(ValueError):
    pass


_UNUM = r"(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?"
_NUM = r"[+-]?" + _UNUM


def _spec(key: str, spec, where: str):
    """(key, spec as a dict) from a SPEC string / list / dict; raises SpaceError naming ``where``."""
    def bad(msg):
        raise SpaceError(f"{where}: {msg}")

    if not re.fullmatch(r"[A-Za-z_]\w*(\.\w+)*", key or ""):
        bad(f"'{key}' is not a tracker key (letters, digits, _, dots)")
    if isinstance(spec, list):
        if len(spec) != 2:
            bad(f"{key}: [LO, HI] expected, not {spec!r}")
        spec = {"low": spec[0], "high": spec[1]}
    if isinstance(spec, str):
        s = spec.strip()
        if s.startswith("choice:"):
            try:
                choices = json.loads("[" + s[7:] + "]")
            except json.JSONDecodeError:
                bad(f"{key}: choice:A,B,... needs JSON values (strings in double quotes), not '{s[7:]}'")
            spec = {"choices": choices}
        else:
            parts = s.split(":")
            kind = parts[0] if parts[0] in ("log", "int") else "float"
            nums = parts[1:] if kind != "float" else parts
            if len(nums) != 2 or not all(re.fullmatch(_NUM, x.strip()) for x in nums):
                bad(f"{key}: '{s}' is not LO:HI, log:LO:HI, int:LO:HI or choice:A,B,...")
            spec = {"low": float(nums[0]), "high": float(nums[1]), "log": kind == "log", "int": kind == "int"}
    if not isinstance(spec, dict):
        bad(f"{key}: a SPEC string, [LO, HI] or an object expected, not {spec!r}")
    if "choices" in spec:
        if not isinstance(spec["choices"], list) or not spec["choices"]:
            bad(f"{key}: choices must be a non-empty list")
        return {"choices": spec["choices"]}
    try:
        lo, hi = float(spec["low"]), float(spec["high"])
    except (KeyError, TypeError, ValueError):
        bad(f"{key}: low and high numbers expected in {spec!r}")
    log, is_int = bool(spec.get("log", False)), bool(spec.get("int", False))
    if not (math.isfinite(lo) and math.isfinite(hi)) or lo >= hi:
        bad(f"{key}: LO must be below HI ({lo:g} >= {hi:g})")
    if log and lo <= 0:
        bad(f"{key}: log:LO:HI needs LO > 0")
    if is_int and (lo != int(lo) or hi != int(hi)):
        bad(f"{key}: int:LO:HI needs integers")
    return {"low": lo, "high": hi, "log": log, "int": is_int}


def parse_space_item(item: str) -> tuple[str, dict]:
    """KEY=SPEC of --space as (key, spec); SpaceError names --space."""
    if "=" not in item:
        raise SpaceError(f"--space '{item}': KEY=SPEC expected (process_psd=log:0.1:1000)")
    key, spec = item.split("=", 1)
    return key.strip(), _spec(key.strip(), spec, f"--space '{item}'")


def parse_space_file(path: str) -> dict:
    try:
        with open(path, encoding="utf-8") as f:
            raw = json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        raise SpaceError(f"--space-file {path}: {e}") from None
    if not isinstance(raw, dict) or not raw:
        raise SpaceError(f"--space-file {path}: a non-empty JSON object {{KEY: SPEC}} expected")
    return {k: _spec(k, v, f"--space-file {path}") for k, v in raw.items()}


def distributions(space: dict) -> dict:
    import optuna.distributions as od

    out = {}
    for k, s in space.items():
        if "choices" in s:
            out[k] = od.CategoricalDistribution([json.dumps(c) if isinstance(c, (list, dict)) else c
                                                 for c in s["choices"]])
        elif s["int"]:
            out[k] = od.IntDistribution(int(s["low"]), int(s["high"]), log=s["log"])
        else:
            out[k] = od.FloatDistribution(s["low"], s["high"], log=s["log"])
    return out


def with_params(scn: dict, params: dict) -> dict:
    """A copy of the scenario with tracker.KEY = value for each tuned key (dotted keys reach in)."""
    s = json.loads(json.dumps(scn))
    scnmod.apply_overrides(s, [f"tracker.{k}={json.dumps(v)}" for k, v in params.items()], scn.get("_source", ""))
    return s


# ------------------------------------------------------------------ objective


class ObjectiveError(ValueError):
    pass


def parse_objective(text: str) -> list[tuple[float, str]]:
    """'gospa_mean+50*idsw_per_run' -> [(1.0, 'gospa_mean'), (50.0, 'idsw_per_run')]."""
    term = re.compile(rf"\s*([+-])?\s*(?:({_UNUM})\s*\*\s*)?([A-Za-z_]\w*(?:\.\w+)*)(?:\s*\*\s*({_UNUM}))?\s*")
    pos, terms = 0, []
    while pos < len(text):
        m = term.match(text, pos)
        if not m or m.end() == pos or (terms and not m.group(1)):
            raise ObjectiveError(f"--objective '{text}': cannot read it at '{text[pos:]}' "
                                 "(a weighted sum such as gospa_mean+50*idsw_per_run)")
        c = float(m.group(2) or 1.0) * float(m.group(4) or 1.0) * (-1.0 if m.group(1) == "-" else 1.0)
        terms.append((c, m.group(3)))
        pos = m.end()
    if not terms:
        raise ObjectiveError("--objective: empty")
    return terms


def objective_value(terms, totals: dict) -> float:
    """The weighted sum of the totals; NaN when a total is undefined (None); ObjectiveError for a bad name."""
    v = 0.0
    for c, name in terms:
        x = totals
        for part in name.split("."):
            if not isinstance(x, dict) or part not in x:
                raise ObjectiveError(f"--objective: '{name}' is not a total of the summary "
                                     f"(totals: {', '.join(sorted(k for k in totals if not isinstance(totals[k], dict)))})")
            x = x[part]
        if x is None:
            return math.nan
        if isinstance(x, (dict, list, bool)) or not isinstance(x, (int, float)):
            raise ObjectiveError(f"--objective: '{name}' is not a number")
        v += c * float(x)
    return v


# ------------------------------------------------------------------ one trial


def evaluate(scns, params: dict, terms, runs: int, seed0: int, exe: str, jobs: int, timeout: float,
             scheduler=None, chunks: int = 1, on_chunk=None) -> dict:
    """Monte Carlo of every scenario with ``params``; returns {"value", "values" (after each chunk),
    "stopped", "totals" (per scenario), "runs_failed"}.  ``on_chunk(k, value)`` returning True stops
    after chunk k (pruning)."""
    chunks = max(1, min(chunks, runs))
    bounds = [round(runs * k / chunks) for k in range(chunks + 1)]
    items = []
    for scn in scns:
        s = with_params(scn, params)
        mode = scnmod.tracker_value(s, "association")
        items.append((s, mode, {mode: mc.Aggregate(int(s["scans"]["count"]), scnmod.manoeuvre_windows(s))}))
    values, totals, failed = [], [], 0
    for k in range(chunks):
        totals, failed = [], 0
        for s, mode, aggs in items:
            r = mc.monte_carlo(s, [mode], bounds[k + 1] - bounds[k], exe, jobs, seed0, timeout=timeout,
                               progress=None, scheduler=scheduler, first_run=bounds[k], aggregates=aggs)
            res = r["results"][mode]
            totals.append(res["totals"])
            failed += res["runs_failed"]
        value = math.nan if failed else sum(objective_value(terms, t) for t in totals) / len(totals)
        values.append(value)
        if not math.isfinite(value):
            break
        if k < chunks - 1 and on_chunk is not None and on_chunk(k, value):
            return {"value": value, "values": values, "stopped": True, "totals": totals, "runs_failed": failed}
    return {"value": values[-1], "values": values, "stopped": False, "totals": totals, "runs_failed": failed}


def evaluate_trial(task: dict) -> dict:
    """One trial, where it runs (this process or a Dask worker): the runs of task["params"],
    pruned by MedianPruner against task["finished"] (the FrozenTrials finished before it) in a
    private in-memory study."""
    import optuna

    optuna.logging.set_verbosity(optuna.logging.WARNING)
    pruner = (optuna.pruners.MedianPruner(n_startup_trials=task["prune_startup"]) if task["prune"]
              else optuna.pruners.NopPruner())
    mirror = optuna.create_study(direction="minimize", pruner=pruner, sampler=optuna.samplers.RandomSampler(0))
    mirror.add_trials(task["finished"])
    mirror.enqueue_trial(task["params"])
    trial = mirror.ask(distributions(task["space"]))

    def on_chunk(k, value):
        trial.report(value, k)
        return trial.should_prune()

    t0 = time.monotonic()
    out = evaluate(task["scenarios"], trial.params, task["terms"], task["runs"], task["seed0"], task["exe"],
                   task["jobs"], task["timeout"], None, task["chunks"], on_chunk)
    out["elapsed"] = time.monotonic() - t0
    out.pop("totals")
    return out


# ------------------------------------------------------------------ the study


def _storage_url(storage: str) -> str:
    if "://" in storage:
        return storage
    os.makedirs(os.path.dirname(os.path.abspath(storage)), exist_ok=True)
    return "sqlite:///" + os.path.abspath(storage)


def _sampler(kind: str, seed: int, n: int):
    import optuna

    s = (seed * 1_000_003 + n) % (2 ** 32)  # the n-th counted trial's own seed
    return optuna.samplers.TPESampler(seed=s) if kind == "tpe" else optuna.samplers.RandomSampler(seed=s)


def _counted(study):
    from optuna.trial import TrialState

    return [t for t in study.get_trials(deepcopy=False)
            if t.state in (TrialState.COMPLETE, TrialState.PRUNED)
            or (t.state == TrialState.FAIL and not t.user_attrs.get("interrupted"))]


def _progress(done, total, best, last, t0, stream):
    el = time.monotonic() - t0
    stream.write(f"\r[trial {done}/{total}] last {last}, best {best:.4g}, {el:.0f} s   ")
    stream.flush()


def tune(scns, space: dict, terms, trials: int, runs: int, seed0: int, exe: str, jobs: int = 1,
         timeout: float = 600.0, storage: str = "out/tune/study.db", study_name: str = "tune", seed: int = 0,
         sampler: str = "tpe", prune: bool = True, chunks: int = 4, scheduler=None, progress=sys.stderr,
         config: dict | None = None):
    """Run (or continue) the study up to ``trials`` counted trials; returns the optuna Study."""
    import optuna
    from optuna.trial import TrialState

    optuna.logging.set_verbosity(optuna.logging.WARNING)
    study = optuna.create_study(storage=_storage_url(storage), study_name=study_name, direction="minimize",
                                load_if_exists=True)
    if config is not None:
        old = study.user_attrs.get("config")
        if old is None:
            study.set_user_attr("config", config)
        elif old != config:
            diff = sorted(k for k in set(old) | set(config) if old.get(k) != config.get(k))
            raise ValueError(f"--study {study_name} in {storage} was made with other "
                             f"{', '.join(diff)}: give another --study or --storage")
    for t in study.get_trials(deepcopy=False, states=(TrialState.RUNNING, TrialState.WAITING)):
        study._storage.set_trial_user_attr(t._trial_id, "interrupted", True)  # left by a stopped run
        study.tell(t.number, state=TrialState.FAIL, skip_if_finished=True)
    dists = distributions(space)
    client, owned = (None, False) if scheduler in (None, "local") else mc.dask_client(scheduler)
    batch = 1 if client is None else max(1, sum(client.nthreads().values()))
    t0 = time.monotonic()
    try:
        while True:
            n = len(_counted(study))
            if n >= trials:
                break
            finished = [t for t in study.get_trials(deepcopy=True)
                        if t.state in (TrialState.COMPLETE, TrialState.PRUNED)]
            asked = []
            for i in range(min(batch, trials - n)):
                study.sampler = _sampler(sampler, seed, n + i)
                asked.append(study.ask(dists))
            tasks = [{"scenarios": scns, "params": tr.params, "space": space, "terms": terms, "runs": runs,
                      "seed0": seed0, "exe": exe, "jobs": jobs if client is None else 1, "timeout": timeout,
                      "chunks": chunks, "prune": prune, "prune_startup": 5, "finished": finished}
                     for tr in asked]
            try:
                if client is None:
                    outs = [evaluate_trial(tasks[0])]
                else:
                    outs = client.gather([client.submit(evaluate_trial, tk, pure=False) for tk in tasks])
            except KeyboardInterrupt:
                for tr in asked:
                    study._storage.set_trial_user_attr(tr._trial_id, "interrupted", True)
                    study.tell(tr, state=TrialState.FAIL)
                raise
            for tr, out in zip(asked, outs):  # in trial order
                for k, v in enumerate(out["values"]):
                    if math.isfinite(v):
                        tr.report(v, k)
                tr.set_user_attr("runs_failed", out["runs_failed"])
                tr.set_user_attr("seconds", round(out["elapsed"], 3))
                if not math.isfinite(out["value"]):
                    study.tell(tr, state=TrialState.FAIL)
                    last = "failed"
                elif out["stopped"]:
                    study.tell(tr, state=TrialState.PRUNED)
                    last = f"pruned at {out['value']:.4g}"
                else:
                    study.tell(tr, out["value"])
                    last = f"{out['value']:.4g}"
                if progress is not None:
                    done = [t for t in study.get_trials(deepcopy=False, states=(TrialState.COMPLETE,))]
                    best = min((t.value for t in done), default=math.nan)
                    _progress(len(_counted(study)), trials, best, last, t0, progress)
    finally:
        if owned:
            client.close()
        if progress is not None:
            progress.write("\n")
            progress.flush()
    return study


# ------------------------------------------------------------------ outputs


def plots(study, keys, out: str) -> list[str]:
    """history.png, importances.png (>= 2 keys), slice_<key>.png; returns the paths written."""
    import warnings

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from optuna.visualization import matplotlib as vm

    paths = []

    def save(ax, name):
        fig = (ax.flat[0] if hasattr(ax, "flat") else ax).figure
        fig.set_size_inches(7, 4.5)
        fig.tight_layout()
        p = os.path.join(out, name)
        fig.savefig(p, dpi=90)
        plt.close(fig)
        paths.append(p)

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # optuna's "experimental" warnings
        save(vm.plot_optimization_history(study), "history.png")
        if len(keys) >= 2:
            save(vm.plot_param_importances(study), "importances.png")
        for k in keys:
            save(vm.plot_slice(study, params=[k]), f"slice_{k.replace('.', '_')}.png")
    return paths


def _holdout_row(name, scns, params, terms, runs, seed0, exe, jobs, timeout, scheduler):
    r = evaluate(scns, params, terms, runs, seed0, exe, jobs, timeout, scheduler)
    g = sum(t["gospa_mean"] for t in r["totals"]) / len(r["totals"]) if r["totals"] else math.nan
    idsw = sum(t["idsw_per_run"] for t in r["totals"]) / len(r["totals"]) if r["totals"] else math.nan
    return {"row": name, "objective": r["value"], "gospa_mean": g, "idsw_per_run": idsw,
            "runs_failed": r["runs_failed"], "per_scenario": r["totals"]}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    mc.add_run_arguments(ap, scenarios=True, runs=20, per="scenario in each trial")
    mc.add_scheduler_argument(ap)
    ap.add_argument("--space", action="append", default=[], metavar="KEY=SPEC", type=str,
                    help="a tuned tracker key and its range (repeatable; see above)")
    ap.add_argument("--space-file", metavar="F.json", help="JSON object of KEY: SPEC (see above)")
    ap.add_argument("--objective", default="gospa_mean", help="weighted sum of totals to minimise (default gospa_mean)")
    ap.add_argument("--trials", type=int, default=30, help="finished trials of the study (default 30)")
    ap.add_argument("--chunks", type=int, default=4, help="pruning steps per trial: the runs go in this many "
                    "chunks (default 4)")
    ap.add_argument("--no-prune", action="store_true", help="no pruning (every trial runs all its runs)")
    ap.add_argument("--sampler", choices=("tpe", "random"), default="tpe", help="Optuna sampler (default tpe)")
    ap.add_argument("--seed", type=int, default=0, help="the sampler's seed (default 0)")
    ap.add_argument("--storage", help="SQLite file of the study, or an Optuna storage URL (default OUT/study.db)")
    ap.add_argument("--study", default="tune", help="study name in the storage (default tune)")
    ap.add_argument("--holdout-seed0", type=int, metavar="N",
                    help="evaluate the best and the scenarios' own settings on seeds N.. (outside the tuning seeds)")
    ap.add_argument("--holdout-runs", type=int, metavar="R", help="runs per scenario of the held-out check (default --runs)")
    ap.add_argument("--mtt-track", dest="mtt_track", help="mtt-track binary (as mtt_sim.mc)")
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds allowed per mtt-track call")
    ap.add_argument("--no-plots", action="store_true", help="skip the PNG figures")
    a = ap.parse_args(argv)
    if a.runs < 1 or a.jobs < 1 or a.trials < 1 or a.chunks < 1:
        ap.error("--runs, --jobs, --trials and --chunks must be >= 1")
    bad = mc.check_scheduler(a.scheduler)
    if bad:
        ap.error(bad)
    try:
        space = parse_space_file(a.space_file) if a.space_file else {}
        for item in a.space:
            k, s = parse_space_item(item)
            space[k] = s
        if not space:
            raise SpaceError("--space: no key to tune (give --space KEY=SPEC or --space-file)")
        terms = parse_objective(a.objective)
    except (SpaceError, ObjectiveError) as e:
        ap.error(str(e))
    hruns = a.holdout_runs or a.runs
    if a.holdout_seed0 is not None and a.holdout_seed0 < a.seed0 + a.runs and a.seed0 < a.holdout_seed0 + hruns:
        ap.error(f"--holdout-seed0: seeds {a.holdout_seed0}..{a.holdout_seed0 + hruns - 1} overlap the tuning "
                 f"seeds {a.seed0}..{a.seed0 + a.runs - 1}")
    try:
        scns = [scnmod.load(f, a.set) for f in a.scenario]
        for s in scns:
            with_params(s, {k: 0 for k in space})  # a key that cannot be set fails here
    except (scnmod.ScenarioError, OSError) as e:
        print(f"tune.py: {e}", file=sys.stderr)
        return 2
    exe = mc.find_tracker("auto", a.mtt_track)
    if exe is None:
        print("tune.py: no mtt-track binary (give --mtt-track, set MTT_TRACK or build build/host-float)",
              file=sys.stderr)
        return 2
    os.makedirs(a.out, exist_ok=True)
    storage = a.storage or os.path.join(a.out, "study.db")
    config = {"scenarios": [os.path.abspath(f) for f in a.scenario], "set": a.set, "space": space,
              "objective": a.objective, "runs": a.runs, "seed0": a.seed0, "chunks": a.chunks,
              "prune": not a.no_prune, "sampler": a.sampler, "seed": a.seed}
    try:
        study = tune(scns, space, terms, a.trials, a.runs, a.seed0, exe, a.jobs, a.timeout, storage, a.study,
                     a.seed, a.sampler, not a.no_prune, a.chunks, a.scheduler, config=config)
    except ObjectiveError as e:
        print(f"tune.py: {e}", file=sys.stderr)
        return 2
    except ValueError as e:
        print(f"tune.py: {e}", file=sys.stderr)
        return 2
    from optuna.trial import TrialState

    states = [t.state for t in study.get_trials(deepcopy=False)]
    counts = {s.name.lower(): states.count(s) for s in (TrialState.COMPLETE, TrialState.PRUNED, TrialState.FAIL)}
    if not counts["complete"]:
        print(f"tune.py: no trial completed ({counts})", file=sys.stderr)
        return 1
    best = study.best_trial
    params = {k: (json.loads(v) if isinstance(v, str) and v[:1] in "[{" else v) for k, v in best.params.items()}
    written = []
    for i, s in enumerate(scns):
        settings = scnmod.tracker_settings(with_params(s, params))
        names = (["best_settings.json"] if i == 0 else []) + ([f"best_settings.{s['name']}.json"] if len(scns) > 1 else [])
        for name in names:
            with open(os.path.join(a.out, name), "w", encoding="utf-8") as f:
                json.dump(settings, f, indent=2)
                f.write("\n")
            written.append(name)
    result = {"study": a.study, "storage": storage, "objective": a.objective, "best_trial": best.number,
              "best_value": best.value, "best_params": params, "trials": counts,
              "tuning_seeds": [a.seed0, a.seed0 + a.runs - 1]}
    print(f"best trial {best.number}: {a.objective} = {best.value:.6g} over {a.runs} runs per scenario "
          f"(seeds {a.seed0}..{a.seed0 + a.runs - 1}); trials {counts}")
    for k, v in params.items():
        print(f"  {k} = {v}")
    print("settings: " + ", ".join(os.path.join(a.out, w) for w in written))
    if a.holdout_seed0 is not None:
        rows = [_holdout_row("scenario file", scns, {}, terms, hruns, a.holdout_seed0, exe, a.jobs, a.timeout,
                             a.scheduler),
                _holdout_row(f"best (trial {best.number})", scns, params, terms, hruns, a.holdout_seed0, exe,
                             a.jobs, a.timeout, a.scheduler)]
        print(f"held-out seeds {a.holdout_seed0}..{a.holdout_seed0 + hruns - 1} ({hruns} runs per scenario):")
        print(f"  {'settings':20s} {'objective':>10s} {'gospa_mean':>10s} {'idsw/run':>9s}")
        for r in rows:
            print(f"  {r['row']:20s} {r['objective']:10.4f} {r['gospa_mean']:10.4f} {r['idsw_per_run']:9.3f}")
        result["holdout"] = {"seeds": [a.holdout_seed0, a.holdout_seed0 + hruns - 1],
                             "rows": [{k: v for k, v in r.items() if k != "per_scenario"} for r in rows]}
    with open(os.path.join(a.out, "best.json"), "w", encoding="utf-8") as f:
        json.dump(mc._nan_to_none(result), f, indent=1)
        f.write("\n")
    if not a.no_plots:
        paths = plots(study, list(space), a.out)
        print("plots: " + ", ".join(os.path.relpath(p, a.out) for p in paths))
    return 0


if __name__ == "__main__":
    sys.exit(main())

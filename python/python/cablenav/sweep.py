"""Sweeping candidate anchor layouts: one machine with ``concurrent.futures``, a cluster with Dask.

A designer sizing a cable robot moves its anchors (the cables' base points on the frame) and
asks, for every candidate layout, which share of each required trajectory stays feasible —
exactly, not at samples. This module is the worked example of doing that at scale:

1. :func:`layouts` makes ``count`` candidate designs from a base scenario, each anchor moved by a
   seeded random offset (design 0 is the base itself), so a sweep is reproducible;
2. :func:`evaluate` verifies every trajectory of one design with :func:`cablenav.verify` and
   summarises it (feasible share of t, infeasible sections, first infeasible t, uncertain
   sections) — a plain function of plain data, so it ships to threads, processes and Dask
   workers alike;
3. :func:`run_serial`, :func:`run_threads` (``concurrent.futures.ThreadPoolExecutor``: the core
   releases the GIL, so threads use every core) and :func:`run_dask` (``dask.distributed``: the
   same function mapped over a cluster — a ``LocalCluster`` here, a ``SSHCluster``, a Kubernetes
   or a Slurm cluster for a sweep that outgrows one machine) return the same list, in design order;
4. :func:`rank` orders the designs by their mean feasible share.

From the command line (the repository root)::

    python -m cablenav.sweep static/scenarios/cdpr7-box.json --designs 300 --workers 2
    python -m cablenav.sweep static/scenarios/cdpr7-box.json --designs 300 --dask 2
    python -m cablenav.sweep static/scenarios/cdpr7-box.json --dask tcp://scheduler:8786

From Python::

    import json
    from cablenav import sweep
    base = json.load(open("static/scenarios/cdpr7-box.json"))
    designs = sweep.layouts(base, 300, spread=0.4, seed=1)
    results = sweep.run_threads(designs)
    for score, name in sweep.rank(results)[:5]:
        print(f"{name}: {score:.3f}")

    from dask.distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        assert sweep.run_dask(designs, client) == results
"""

from __future__ import annotations

import argparse
import copy
import json
import random
import time
from concurrent.futures import ThreadPoolExecutor
from typing import Any, Dict, List, Optional, Tuple

import cablenav


def layouts(base: Dict[str, Any], count: int, spread: float = 0.4, seed: int = 0) -> List[Dict[str, Any]]:
    """``count`` candidate designs of ``base``: every cable's base anchor moved by an offset drawn
    uniformly from [-spread, spread] in each coordinate (metres), seeded by ``seed`` so the same
    arguments give the same designs. Design 0 is ``base`` unchanged; designs are named
    ``layout-0000``, ``layout-0001``, …"""
    rng = random.Random(seed)
    designs = []
    for k in range(count):
        design = copy.deepcopy(base)
        design["name"] = f"layout-{k:04d}"
        if k > 0:
            for cable in design["robot"]["cables"]:
                cable["base"] = [round(c + rng.uniform(-spread, spread), 6) for c in cable["base"]]
        designs.append(design)
    return designs


def _length(intervals: List[List[float]]) -> float:
    return sum(hi - lo for lo, hi in intervals)


def evaluate(design: Dict[str, Any]) -> Dict[str, Any]:
    """Verifies every trajectory of one design exactly and summarises it.

    Returns ``{"name", "score", "trajectories": {name: {"feasible_share", "infeasible_sections",
    "first_infeasible_t", "uncertain_sections"}}}`` where ``score`` is the mean feasible share of
    t ∈ [0, 1] over the trajectories; a design the core rejects (an anchor moved onto another,
    say) gets ``{"name", "score": 0.0, "error": {"field", "reason"}}`` instead of stopping the sweep.
    """
    try:
        summary = {}
        for trajectory in design["trajectories"]:
            report = cablenav.verify(design, trajectory["name"])
            infeasible = report["infeasible"]
            summary[trajectory["name"]] = {
                "feasible_share": _length(report["feasible"]),
                "infeasible_sections": len(infeasible),
                "first_infeasible_t": infeasible[0][0] if infeasible else None,
                "uncertain_sections": len(report["uncertain"]),
            }
    except cablenav.ScenarioError as e:
        return {"name": design.get("name"), "score": 0.0, "error": {"field": e.field, "reason": e.reason}}
    score = sum(s["feasible_share"] for s in summary.values()) / max(len(summary), 1)
    return {"name": design.get("name"), "score": score, "trajectories": summary}


def run_serial(designs: List[Dict[str, Any]]) -> List[Dict[str, Any]]:
    """:func:`evaluate` on each design in turn: the reference the parallel runs must equal."""
    return [evaluate(d) for d in designs]


def run_threads(designs: List[Dict[str, Any]], workers: Optional[int] = None) -> List[Dict[str, Any]]:
    """:func:`evaluate` on a ``ThreadPoolExecutor`` with ``workers`` threads (default: Python's
    choice from the CPU count). The core runs without the GIL, so the threads run in parallel."""
    with ThreadPoolExecutor(max_workers=workers) as pool:
        return list(pool.map(evaluate, designs))


def run_dask(designs: List[Dict[str, Any]], client: Any, batch: int = 25) -> List[Dict[str, Any]]:
    """:func:`evaluate` on a Dask cluster through ``client`` (a ``dask.distributed.Client``), in
    batches of ``batch`` designs per task (one task per design would spend more time scheduling
    than verifying); results in design order."""
    chunks = [designs[i : i + batch] for i in range(0, len(designs), batch)]
    futures = client.map(run_serial, chunks, pure=False)
    return [r for chunk in client.gather(futures) for r in chunk]


def rank(results: List[Dict[str, Any]]) -> List[Tuple[float, str]]:
    """(score, name) of every design, best first (ties by name)."""
    return sorted(((r["score"], r["name"]) for r in results), key=lambda sn: (-sn[0], sn[1]))


def main(argv: Optional[List[str]] = None) -> None:
    """``python -m cablenav.sweep``: sweep a scenario's anchor layouts and print the best."""
    parser = argparse.ArgumentParser(prog="python -m cablenav.sweep", description=__doc__.split("\n")[0])
    parser.add_argument("scenario", help="a cablenav-scenario/1 JSON file whose anchors are varied")
    parser.add_argument("--designs", type=int, default=300, help="candidate layouts (default 300)")
    parser.add_argument("--spread", type=float, default=0.4, help="largest anchor offset per coordinate, metres")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--workers", type=int, default=None, help="threads on this machine")
    parser.add_argument("--dask", metavar="N|ADDRESS", help="run on a LocalCluster of N workers, or on the scheduler at ADDRESS")
    parser.add_argument("--top", type=int, default=10, help="designs to print")
    args = parser.parse_args(argv)
    with open(args.scenario) as f:
        designs = layouts(json.load(f), args.designs, args.spread, args.seed)
    start = time.perf_counter()
    if args.dask is None:
        results, where = run_threads(designs, args.workers), "threads"
    else:
        from dask.distributed import Client, LocalCluster

        if args.dask.isdigit():
            with LocalCluster(n_workers=int(args.dask), threads_per_worker=1) as cluster, Client(cluster) as client:
                results = run_dask(designs, client)
        else:
            with Client(args.dask) as client:
                results = run_dask(designs, client)
        where = f"dask {args.dask}"
    seconds = time.perf_counter() - start
    trajectories = len(designs[0]["trajectories"]) if designs else 0
    print(f"{len(designs)} designs × {trajectories} trajectories verified exactly in {seconds:.2f} s ({where})")
    for score, name in rank(results)[: args.top]:
        print(f"  {name}  mean feasible share {score:.4f}")


if __name__ == "__main__":
    main()

"""Parameter sweeps over a scenario, serially or on a Dask cluster.

    import eoir.sweep as sweep
    tasks = sweep.tasks("scenarios/validation/valid_sens_snr_access.json",
                        grid={"Sensor1.f_number": [2.0, 3.5],
                              "Satellite2.temperature_K": [250.0, 300.0]},
                        outputs=[sweep.Report("EOIR Sensor-to-Target Metrics", "Sensor1",
                                              target="Satellite2",
                                              elements=["Signal to Noise Ratio"])],
                        stop="2010-12-08T23:00:00Z", step_s=600)
    serial = sweep.run_serial(tasks)
    from distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster, Client(cluster) as client:
        parallel = sweep.run_dask(tasks, client)
    assert parallel == serial

A grid maps "OBJECT.PROPERTY" to the values to try; tasks() makes one task
per point of the Cartesian product (in the grid's order, the last key
varying fastest). run_task() (what a worker runs) loads the scenario with
eoir.Scenario (the CLI's own scenario code) in a fresh engine with the
task's seed and one thread, sets the point's properties, and at each time of
the scenario (or of start/stop/step_s) pushes the states and evaluates the
outputs:

- Report(group, sensor, target=None, elements=None): data-provider values
  (scalars only) at each time;
- Truth(sensor): renders the sensor and keeps the per-frame truth (object,
  FITS pixel, RA/Dec, range, SNR) at each time.

Results are plain dicts of Python numbers (picklable, comparable): {"index",
"point": {key: value}, "times": [...], "outputs": [{"kind", ..., "values":
[...per time...]}]}. Every task builds its own engine, so a task's result
does not depend on where or in which order it runs: a Dask run returns
exactly what a serial run does.
"""

from __future__ import annotations

import itertools
import os
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Sequence


@dataclass(frozen=True)
class Report:
    """Scalar data-provider elements of a group (all scalars if elements is None)."""
    group: str
    sensor: str
    target: Optional[str] = None
    elements: Optional[Sequence[str]] = None


@dataclass(frozen=True)
class Truth:
    """Render the sensor at each time and keep its per-frame truth."""
    sensor: str


@dataclass(frozen=True)
class Task:
    index: int
    scenario: str
    point: Dict[str, Any]
    outputs: Sequence[Any]
    start: Optional[str] = None
    stop: Optional[str] = None
    step_s: Optional[float] = None
    seed: int = 1
    threads: int = 1
    extra: Dict[str, Any] = field(default_factory=dict)


def _split(key: str):
    obj, sep, prop = key.rpartition(".")
    if not sep or not obj or not prop:
        raise ValueError(f"grid key {key!r}: expected 'OBJECT.PROPERTY'")
    return obj, prop


def tasks(scenario, grid: Dict[str, Sequence[Any]], outputs: Sequence[Any], start=None, stop=None,
          step_s: Optional[float] = None, seed: int = 1) -> List[Task]:
    """One Task per point of the grid's Cartesian product (see the module)."""
    if not outputs:
        raise ValueError("outputs: give at least one Report or Truth")
    for o in outputs:
        if not isinstance(o, (Report, Truth)):
            raise TypeError(f"outputs: {o!r} is not an eoir.sweep.Report or Truth")
    keys = list(grid)
    for k in keys:
        _split(k)
        if len(grid[k]) == 0:
            raise ValueError(f"grid[{k!r}]: no values")
    path = os.path.abspath(os.fspath(scenario))
    points = itertools.product(*(list(grid[k]) for k in keys))
    return [Task(i, path, dict(zip(keys, values)), tuple(outputs), start, stop, step_s, seed)
            for i, values in enumerate(points)]


def _number(x):
    return float(x) if isinstance(x, (int, float)) and not isinstance(x, bool) else x


def run_task(task: Task) -> Dict[str, Any]:
    """Runs one task in this process (a fresh engine) and returns its result."""
    from .scenario import Scenario  # imported here: workers import eoir lazily
    from .engine import provider_elements
    with Scenario.load(task.scenario, seed=task.seed, threads=task.threads) as sc:
        for key, value in task.point.items():
            obj, prop = _split(key)
            sc.engine.set(obj, prop, value)
        times = sc.times(task.start, task.stop, task.step_s)
        results = []
        for o in task.outputs:
            if isinstance(o, Report):
                names = list(o.elements) if o.elements is not None else [
                    e["name"] for e in provider_elements(o.group) if e["type"] != "curve"]
                results.append({"kind": "report", "group": o.group, "sensor": o.sensor, "target": o.target,
                                "elements": names, "values": []})
            else:
                results.append({"kind": "truth", "sensor": o.sensor, "values": []})
        for t in times:
            sc.set_time(t)
            for o, r in zip(task.outputs, results):
                if isinstance(o, Report):
                    r["values"].append([_number(sc.engine.provider(o.group, e, o.sensor, o.target))
                                        for e in r["elements"]])
                else:
                    sc.engine.render(o.sensor)
                    r["values"].append(sc.truth(o.sensor))
        return {"index": task.index, "point": dict(task.point), "times": times, "outputs": results}


def run_serial(task_list: Sequence[Task]) -> List[Dict[str, Any]]:
    """Every task, one after the other, in this process."""
    return [run_task(t) for t in task_list]


def run_dask(task_list: Sequence[Task], client) -> List[Dict[str, Any]]:
    """Every task on a dask.distributed Client (one Dask task each, pure=False
    so that none is skipped as a duplicate), results in the tasks' order."""
    futures = client.map(run_task, list(task_list), pure=False)
    return client.gather(futures)

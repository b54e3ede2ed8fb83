"""Tutorial "A parameter sweep on a Dask cluster", with what each output costs.

Sweeps the radius and the temperature of the spec 7.8 sensor's target
over a scenario (2 x 2 points, 5 time steps each) on a local Dask cluster of
two worker processes, asks for two kinds of output, and times each kind
alone in the same run:

- Report: data-provider values at each time step (no image is rendered);
- Truth: the per-frame truth, which renders the sensor's frame at each time
  step: a whole image per step.

Writes OUT/sweep.csv (one row per point and time) and OUT/sweep_costs.csv
(seconds per task of each output, serial, measured in this run); OUT
defaults to docs/tutorials/results:

    /usr/bin/python3 docs/tutorials/sweep.py [--out OUT]
"""
import argparse
import csv
import os
import time

import eoir.sweep as sweep

HERE = os.path.dirname(os.path.abspath(__file__))
SCENARIO = os.path.join(HERE, "..", "..", "scenarios", "validation", "valid_sens_snr_access.json")
GRID = {"Satellite2.dimensions_m": [[1.0], [2.0]], "Satellite2.temperature_K": [250.0, 300.0]}
SPAN = {"stop": "2010-12-08T22:40:00Z", "step_s": 600}  # from the scenario's start: 5 time steps
REPORT = sweep.Report("EOIR Sensor-to-Target Metrics", "Sensor1", target="Satellite2",
                      elements=["Signal to Noise Ratio", "Range to Target"])
TRUTH = sweep.Truth("Sensor1")


def seconds_per_task(outputs):
    """Runs the grid serially with these outputs only: seconds per task."""
    tasks = sweep.tasks(SCENARIO, grid=GRID, outputs=outputs, **SPAN)
    t0 = time.perf_counter()
    sweep.run_serial(tasks)
    return (time.perf_counter() - t0) / len(tasks)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(HERE, "results"))
    out = parser.parse_args().out
    os.makedirs(out, exist_ok=True)

    # One task per point of the grid (4); each builds its own engine from the scenario.
    tasks = sweep.tasks(SCENARIO, grid=GRID, outputs=[REPORT], **SPAN)

    from distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        results = sweep.run_dask(tasks, client)
    # A task's result does not depend on where it ran: the same as a serial run.
    assert results == sweep.run_serial(tasks)

    with open(os.path.join(out, "sweep.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["radius_m", "temperature_K", "time", "snr", "range_km"])
        for r in results:
            report = r["outputs"][0]  # values: one list per time, in the order of report["elements"]
            for t, values in zip(r["times"], report["values"]):
                named = dict(zip(report["elements"], values))
                writer.writerow([r["point"]["Satellite2.dimensions_m"][0], r["point"]["Satellite2.temperature_K"], t,
                                 f"{named['Signal to Noise Ratio']:.6g}", f"{named['Range to Target']:.6g}"])

    # What each output costs, serially, on this machine, in this run.
    report_s, truth_s = seconds_per_task([REPORT]), seconds_per_task([TRUTH])
    with open(os.path.join(out, "sweep_costs.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["output", "seconds_per_task", "frames_rendered_per_task"])
        writer.writerow(["Report", f"{report_s:.3f}", 0])
        writer.writerow(["Truth", f"{truth_s:.3f}", len(results[0]["times"])])
    print(f"Report: {report_s:.3f} s per task; Truth: {truth_s:.3f} s per task "
          f"({len(results[0]['times'])} frames rendered)")


if __name__ == "__main__":
    main()

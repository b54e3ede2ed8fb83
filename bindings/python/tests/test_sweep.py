"""eoir.sweep: a scenario and a parameter grid become tasks; run on a Dask
LocalCluster of two worker processes they give exactly the serial results,
and the grid's values reach the engine (the SNR grows with the target's
temperature and falls with a narrower band)."""
import os

import pytest

import eoir.sweep as sweep

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
SCENARIO = os.path.join(ROOT, "scenarios", "validation", "valid_sens_snr_access.json")


def make_tasks():
    return sweep.tasks(
        SCENARIO,
        grid={"Sensor1.band_high_um": [12.0, 10.0], "Satellite2.temperature_K": [250.0, 300.0, 350.0]},
        outputs=[sweep.Report("EOIR Sensor-to-Target Metrics", "Sensor1", target="Satellite2",
                              elements=["Signal to Noise Ratio", "Range to Target"]),
                 sweep.Truth("Sensor1")],
        start="2010-12-08T22:15:00Z", stop="2010-12-08T22:25:00Z", step_s=300)


def test_tasks_from_a_grid():
    tasks = make_tasks()
    assert [t.point for t in tasks[:2]] == [{"Sensor1.band_high_um": 12.0, "Satellite2.temperature_K": 250.0},
                                           {"Sensor1.band_high_um": 12.0, "Satellite2.temperature_K": 300.0}]
    assert len(tasks) == 6 and [t.index for t in tasks] == list(range(6))
    with pytest.raises(ValueError, match="OBJECT.PROPERTY"):
        sweep.tasks(SCENARIO, {"f_number": [1]}, [sweep.Truth("Sensor1")])


def test_dask_local_cluster_equals_serial():
    import distributed  # Debian python3-distributed (.ci/setup): a missing one fails, not skips
    tasks = make_tasks()
    serial = sweep.run_serial(tasks)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  host="127.0.0.1", silence_logs=40) as cluster, \
            distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        parallel = sweep.run_dask(tasks, client)
        pids = set(client.run(os.getpid).values())
    assert len(pids) == 2 and os.getpid() not in pids
    assert parallel == serial
    # the grid reaches the engine: at 22:20 the target is in the field
    snr = {(r["point"]["Sensor1.band_high_um"], r["point"]["Satellite2.temperature_K"]):
           r["outputs"][0]["values"][1][0] for r in serial}
    assert snr[(12.0, 250.0)] < snr[(12.0, 300.0)] < snr[(12.0, 350.0)]
    assert snr[(10.0, 300.0)] < snr[(12.0, 300.0)]  # a narrower band collects less
    assert serial[0]["times"] == ["2010-12-08T22:15:00Z", "2010-12-08T22:20:00Z", "2010-12-08T22:25:00Z"]
    truth = serial[0]["outputs"][1]["values"][1]
    assert [t["object"] for t in truth] == ["Satellite2"] and truth[0]["ra_deg"] is not None

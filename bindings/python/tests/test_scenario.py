"""eoir.Scenario: scenario files through the CLI's own code (libeoir_host).

- the states Scenario.set_time pushes are those `eoir save-state` saves at
  the same time, bit for bit, for every motion model (fixed geodetic, Kepler,
  ephemeris, tle) and pointing (nadir, target);
- Scenario.times() are the CLI's run times; bad files raise naming the field;
- FITS through astropy: the header is the CLI's, the pixels those of
  `eoir run`, and the WCS maps the truth RA/Dec to the truth pixel;
- eoir.tle_state agrees with python3-sgp4 (TEME) within 1 m.
"""
import json
import math
import os
import subprocess
import warnings

import numpy as np
import pytest

import eoir

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
CLI_DATA = os.path.join(ROOT, "tests", "cli", "data")
EOIR_CLI = os.environ.get("EOIR_CLI", os.path.join(ROOT, "build", "bin", "eoir"))
ISS = ("1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927",
       "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537")


def cli(*args):
    r = subprocess.run([EOIR_CLI, *args], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    return r


@pytest.fixture
def motion_scenario(tmp_path):
    """motion_models.json plus a satellite on a TLE pointing at another."""
    doc = json.load(open(os.path.join(CLI_DATA, "motion_models.json")))
    doc["start"], doc["stop"] = "2010-08-25T18:00:00Z", "2010-08-25T18:10:00Z"
    doc["objects"].append({"name": "Iss", "kind": "satellite",
                           "motion": {"type": "tle", "line1": ISS[0], "line2": ISS[1]},
                           "attitude": {"type": "target", "target": "Leo"}})
    path = tmp_path / "motion.json"
    path.write_text(json.dumps(doc))
    return str(path)


def test_states_are_the_clis(motion_scenario, tmp_path):
    times = ["2010-08-25T18:00:00Z", "2010-08-25T18:07:30Z"]
    with eoir.Scenario.load(motion_scenario) as sc:
        assert {o["motion"] for o in sc.objects} == {"ephemeris", "kepler", "fixed_geodetic", "tle"}
        for t in times:
            sc.set_time(t)
            scd = tmp_path / "cli.scd"
            cli("save-state", motion_scenario, "--out", str(scd), "--time", t)
            saved = {o["name"]: o for o in json.load(open(scd))["objects"]}
            py = tmp_path / "py.scd"
            sc.engine.save(str(py))
            mine = {o["name"]: o for o in json.load(open(py))["objects"]}
            assert mine.keys() == saved.keys()
            for name, o in saved.items():
                assert mine[name].get("state") == o.get("state"), (t, name)
            assert "state" in mine["Iss"] and "state" in mine["Leo"]


def test_times_and_description():
    with eoir.Scenario.load(os.path.join(ROOT, "scenarios", "demo", "default.json"), seed=3) as sc:
        assert sc.times() == [f"2010-08-25T18:0{m}:00Z" for m in range(6)]
        assert sc.times(stop="2010-08-25T18:02:30Z", step_s=120) == [
            "2010-08-25T18:00:00Z", "2010-08-25T18:02:00Z", "2010-08-25T18:02:30Z"]
        assert [s["name"] for s in sc.sensors] == ["Sensor1", "WideLWIR", "Inspector"]
        assert sc.engine.time_iso().startswith("2010-08-25T18:00:00")


def test_bad_scenario_names_the_field():
    with pytest.raises(eoir.CorruptFileError, match=r"perigee_inside_earth.json: objects\[0\]\.motion: perigee"):
        eoir.Scenario.load(os.path.join(CLI_DATA, "perigee_inside_earth.json"))
    with pytest.raises(eoir.CorruptFileError, match=r"duplicate key 'f_number'"):
        eoir.Scenario.load(os.path.join(CLI_DATA, "duplicate_key.json"))


def test_fits_through_astropy_match_the_cli(tmp_path):
    from astropy.io import fits
    from astropy.wcs import WCS
    scenario = os.path.join(CLI_DATA, "wcs_targets.json")
    out = tmp_path / "run"
    cli("run", scenario, "--out", str(out), "--stop", "2010-08-25T18:00:00Z", "--quiet")
    with eoir.Scenario.load(scenario) as sc:
        sc.set_time(sc.start)
        sc.engine.render("Cam")
        path = tmp_path / "py.fits"
        sc.write_fits("Cam", "sensor_mean", path)
        truth = sc.truth("Cam")
    with fits.open(path) as mine, fits.open(out / "Cam_0000_mean_electrons.fits") as theirs:
        assert mine[0].verify_checksum() == 1
        np.testing.assert_array_equal(mine[0].data, theirs[0].data)
        for key in ("DATE-OBS", "DATE-BEG", "DATE-AVG", "DATE-END", "BUNIT", "CTYPE1", "CTYPE2", "RADESYS",
                    "TIMESYS", "TREFPOS", "SENSOR", "IMAGTYPE"):
            assert mine[0].header[key] == theirs[0].header[key], key
        # numbers: astropy writes 16 significant digits, cfitsio 15-17
        for key in ("CRVAL1", "CRVAL2", "CRPIX1", "CRPIX2", "CD1_1", "CD1_2", "CD2_1", "CD2_2", "EXPTIME", "MJD-OBS",
                    "MJD-AVG", "OBSGEO-X", "OBSGEO-Y", "OBSGEO-Z", "OBSJ2K-X", "OBSJ2KVX", "GAIN"):
            assert mine[0].header[key] == pytest.approx(theirs[0].header[key], rel=1e-14, abs=1e-300), key
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            # wcslib fills in OBSGEO-L/B/H from OBSGEO-X/Y/Z and says so (astropy issue #10365)
            warnings.filterwarnings("ignore", message=r".*'obsfix' made the change 'Set OBSGEO-L")
            w = WCS(mine[0].header)
    assert truth == json.load(open(out / "Cam_0000_truth.json"))
    assert len(truth) == 3
    for t in truth:
        x, y = w.world_to_pixel_values(t["ra_deg"], t["dec_deg"])
        assert math.hypot(x + 1 - t["x_fits"], y + 1 - t["y_fits"]) < 0.05


def test_tle_state_matches_python_sgp4():
    from sgp4.api import Satrec, jday
    sat = Satrec.twoline2rv(*ISS)
    for y, mo, d, h, mi, sec in ((2008, 9, 20, 12, 25, 40.0), (2008, 9, 21, 3, 0, 0.5), (2008, 9, 27, 0, 0, 0.0)):
        iso = f"{y:04d}-{mo:02d}-{d:02d}T{h:02d}:{mi:02d}:{sec:06.3f}Z"
        s = eoir.tle_state(*ISS, iso)
        e, r, v = sat.sgp4(*jday(y, mo, d, h, mi, sec))
        assert e == 0
        assert math.dist(s["teme_position_km"], r) * 1e3 < 1.0, iso
        assert math.dist(s["teme_velocity_km_s"], v) * 1e3 < 1e-3, iso
        # J2000 is TEME rotated: same length, a different direction
        assert abs(np.linalg.norm(s["position_m"]) - np.linalg.norm(r) * 1e3) < 1e-3
        assert math.dist(s["position_m"], np.array(r) * 1e3) > 1e3
    with pytest.raises(eoir.OutOfRangeError, match="line 2 checksum"):
        eoir.tle_state(ISS[0], ISS[1][:-1] + "0", "2008-09-20T12:00:00Z")

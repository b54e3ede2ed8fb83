"""Arguments the C ABI cannot carry as given are refused before the call
(issue 25 item 9): a NUL would cut a C string (Engine.save("/tmp/x\\0y.scd")
wrote /tmp/x), threads of 2**32 wrapped to 0 (all cores); and every call
that takes a time takes the documented forms, (jd1, jd2, scale) included
(provider_series refused them). A scenario's files lie in its folder unless
allowed (issue 25 item 10)."""
import datetime
import json

import pytest

import eoir

STATIC = ("EOIR Sensor Optics", "Ensquared Energy", "Sensor")


def test_nul_in_a_path_is_refused_naming_it(engine, tmp_path):
    engine.add_object("satellite", "Sat")
    engine.add_sensor("Cam", "Sat")
    for path in (str(tmp_path / "x\0y.scd"), bytes(tmp_path / "x\0y.scd")):
        with pytest.raises(ValueError, match="path: contains a NUL"):
            engine.save(path)
    assert not (tmp_path / "x").exists()
    for call in (engine.load, lambda p: engine.save_sensor("Cam", p), lambda p: engine.load_sensor("Cam", p)):
        with pytest.raises(ValueError, match="path: contains a NUL"):
            call(str(tmp_path / "x\0y"))
    with pytest.raises(ValueError, match="path: contains a NUL"):
        eoir.Scenario.load(str(tmp_path / "x\0y.json"))


def test_nul_in_a_name_or_string_is_refused_naming_it(engine):
    with pytest.raises(ValueError, match="name: contains a NUL"):
        engine.add_object("satellite", "Sat\0ellite")
    assert "Sat" not in engine
    engine.add_object("satellite", "Sat")
    with pytest.raises(ValueError, match="value: contains a NUL"):
        engine.set("Sat", "material", "gold_mli\0")
    with pytest.raises(ValueError, match="prop: contains a NUL"):
        engine.set("Sat", b"material\0x", "gold_mli")
    with pytest.raises(ValueError, match="parent: contains a NUL"):
        engine.add_sensor("Cam", "Sat\0")
    with pytest.raises(ValueError, match="time: contains a NUL"):
        engine.set_time("2010-08-25T18:00:00Z\0junk")


@pytest.mark.parametrize("threads", [2**32, 2**32 + 1, 1025, -1])
def test_threads_out_of_range_are_refused(threads, tmp_path):
    with pytest.raises(ValueError, match=r"threads: must be in \[0, 1024\]"):
        eoir.Engine(threads=threads)
    with pytest.raises(ValueError, match=r"threads: must be in \[0, 1024\]"):
        eoir.Scenario.load(str(tmp_path / "none.json"), threads=threads)


def test_threads_limits_are_accepted():
    for threads in (0, 1024):
        with eoir.Engine(threads=threads) as e:
            assert not e.closed


def test_provider_series_takes_every_documented_time(table3):
    iso = ["2010-08-25T18:00:00Z", "2010-08-25T18:01:00Z"]
    expected = list(table3.provider_series(*STATIC, iso))
    julian = [eoir.time_from_iso(t) for t in iso]  # (jd1, jd2, "utc")
    assert list(table3.provider_series(*STATIC, julian)) == expected
    assert list(table3.provider_series(*STATIC, [(j[0], j[1]) for j in julian])) == expected
    dates = [datetime.datetime(2010, 8, 25, 18, m, tzinfo=datetime.timezone.utc) for m in (0, 1)]
    assert list(table3.provider_series(*STATIC, dates)) == expected
    assert list(table3.provider_series(*STATIC, (t for t in iso))) == expected
    assert table3.time_iso().startswith("2010-08-25T18:01:00")


def test_scenario_files_outside_its_folder_need_leave(tmp_path):
    catalogue = tmp_path / "stars.csv"
    catalogue.write_text("id,ra_deg,dec_deg,pm_ra_mas_yr,pm_dec_mas_yr,parallax_mas,v_mag,b_v\n"
                         "vega,279.234735,38.783689,200.94,286.23,130.23,0.03,0.00\n")
    folder = tmp_path / "scenarios"
    folder.mkdir()
    doc = {"format": "eoir-scenario", "version": 1, "name": "paths", "start": "2010-08-25T18:00:00Z",
           "stars": {"properties": {"catalog_file": "../stars.csv"}}}
    path = folder / "paths.json"
    path.write_text(json.dumps(doc))
    with pytest.raises(eoir.CorruptFileError, match=r"stars\.properties\.catalog_file: '\.\./stars\.csv' lies "
                                                    r"outside the scenario's folder"):
        eoir.Scenario.load(str(path))
    with eoir.Scenario.load(str(path), allow_paths_outside=True) as sc:
        assert sc.engine.get("Stars", "catalog_file").endswith("stars.csv")

"""Hosts that feel native (issue 24 item 5): Engine.point_at and
Engine.track really point (the target lands at the image centre, (N - 1) / 2
in 0-based pixels, within a pixel, read from truth), the truth fields of
Engine and Scenario agree, the named constants mirror eoir.h, the package
is typed, and a Python without numpy gets an ImportError that says what
works."""

import inspect
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

import eoir

T0 = "2010-08-25T18:00:00Z"
N = 64
FOV_DEG = 0.5
SOURCE = Path(__file__).resolve().parents[3]
CLI_DATA = SOURCE / "tests" / "cli" / "data"


def centre_offset(row):
    """Distance in pixels of a truth row from the image centre, both ways."""
    c = (N - 1) / 2
    return math.hypot(row["pixel_x"] - c, row["pixel_y"] - c)


def build(engine, target_velocity=(0.0, 0.0, 0.0)):
    """A camera on a GEO platform (identity attitude: looking along J2000 +z)
    and a 2 m sphere 100 km away along +y, 90 deg off that boresight."""
    engine.set_time(T0)
    engine.add_object(eoir.Kind.SATELLITE, "Host")
    engine.set("Host", "shape", "none")
    engine.set_state("Host", position=(42164e3, 0.0, 0.0))
    engine.add_object(eoir.Kind.SATELLITE, "Tgt")
    engine.set("Tgt", "shape", "sphere")
    engine.set("Tgt", "dimensions_m", [2.0])
    engine.set_state("Tgt", position=(42164e3, 100e3, 0.0), velocity=target_velocity)
    engine.add_sensor("Cam", "Host")
    for name, value in dict(horizontal_pixels=N, vertical_pixels=N, horizontal_fov_deg=FOV_DEG,
                            vertical_fov_deg=FOV_DEG, band_low_um=0.45, band_high_um=0.9,
                            noise_enabled=False).items():
        engine.set("Cam", name, value)
    return engine


def target_row(engine):
    rows = [t for t in engine.truth("Cam") if t["object"] == "Tgt"]
    return rows[0] if rows else None


def test_point_at_puts_the_target_at_the_centre(engine):
    build(engine)
    engine.render("Cam")
    assert target_row(engine) is None  # not pointed: the target is 90 deg off the boresight
    engine.point_at("Cam", "Tgt")
    engine.render("Cam")
    row = target_row(engine)
    print(f"point_at: Tgt at ({row['pixel_x']:.4f}, {row['pixel_y']:.4f}), FITS ({row['x_fits']}, {row['y_fits']})")
    assert centre_offset(row) < 1.0
    # the FITS pixel of the centre of a 64-pixel image: (64 + 1) / 2
    assert row["x_fits"] == pytest.approx((N + 1) / 2, abs=1.0)
    assert row["y_fits"] == pytest.approx((N + 1) / 2, abs=1.0)


def test_track_keeps_the_target_at_the_centre_as_time_steps(engine):
    # The target crosses at 1 km/s: 10 s move it 10 km, 5.7 deg at 100 km,
    # over ten fields' widths.
    build(engine, target_velocity=(0.0, 0.0, 1000.0))
    engine.track("Cam", "Tgt")
    assert engine.tracks() == {"Cam": "Tgt"}
    offsets = []
    for k in range(4):
        engine.set_time(f"2010-08-25T18:00:{10 * k:02d}Z")
        engine.render("Cam")
        row = target_row(engine)
        assert row is not None, k
        offsets.append(centre_offset(row))
    print("track: offsets from the centre (px)", [f"{o:.4f}" for o in offsets])
    assert max(offsets) < 1.0
    # Pointed once only (at 18:00:30), the sensor turns on at that moment's
    # rate, 9.17 mrad/s, while the line of sight's rate falls: at 18:00:40
    # the target is atan(0.4) - atan(0.3) - 0.0917 rad = 0.154 deg, 19.75 px
    # (pixels of 2 tan(0.25 deg) / 64 in the tangent plane)
    # from the centre.
    engine.track("Cam", None)
    assert engine.tracks() == {}
    engine.set_time("2010-08-25T18:00:40Z")
    engine.render("Cam")
    row = target_row(engine)
    print(f"untracked: {centre_offset(row):.2f} px from the centre")
    assert centre_offset(row) == pytest.approx(19.75, abs=0.5)


def test_snr_at_a_time_follows_a_track(engine):
    # The SNR is 0 outside the field: pointed once, the target has left it
    # 60 s later (the sensor turned on at the first rate, 10 mrad/s: 0.6 rad
    # - atan(0.6) = 3.4 deg off in a 0.5 deg field); tracked, it is in the
    # middle.
    build(engine, target_velocity=(0.0, 0.0, 1000.0))
    engine.point_at("Cam", "Tgt")
    assert engine.snr("Cam", "Tgt", time="2010-08-25T18:01:00Z") == 0.0
    engine.set_time(T0)
    engine.track("Cam", "Tgt")
    assert engine.snr("Cam", "Tgt", time="2010-08-25T18:01:00Z") > 0.0


def test_track_follows_states_the_host_pushes(engine):
    # The host pushes the target's state after set_time (a state that the
    # velocity would not give): the render points at the pushed state.
    build(engine)
    engine.track("Cam", "Tgt")
    engine.set_time("2010-08-25T18:01:00Z")
    engine.set_state("Tgt", position=(42164e3, 100e3, 30e3))  # 16.7 deg away from the last pointing
    engine.render("Cam")
    row = target_row(engine)
    assert row is not None and centre_offset(row) < 1.0


def test_point_at_or_a_sensor_state_ends_a_track(engine):
    build(engine)
    engine.track("Cam", "Tgt")
    engine.point_at("Cam", "Tgt")
    assert engine.tracks() == {}
    engine.track("Cam", "Tgt")
    engine.set_state("Cam", position=(42164e3, 0.0, 0.0))
    assert engine.tracks() == {}
    engine.track("Cam", "Tgt")
    engine.remove("Tgt")
    assert engine.tracks() == {}


def test_track_refuses_what_point_at_refuses(engine):
    build(engine)
    with pytest.raises(eoir.NotAllowedError):
        engine.track("Cam", "Host")  # the sensor's parent
    with pytest.raises(eoir.UnknownNameError):
        engine.track("Cam", "Nobody")
    assert engine.tracks() == {}


def test_track_on_a_scenario_engine():
    # wcs_targets.json points its camera at a fixed RA/Dec; a track on
    # sc.engine takes over after each sc.set_time.
    with eoir.Scenario.load(CLI_DATA / "wcs_targets.json") as sc:
        sc.engine.track("Cam", "TargetB")
        for t in sc.times():
            sc.set_time(t)
            sc.engine.render("Cam")
            (row,) = [r for r in sc.engine.truth("Cam") if r["object"] == "TargetB"]
            w = sc.engine.image_info("Cam", "sensor_electrons")["width"]
            assert math.hypot(row["pixel_x"] - (w - 1) / 2, row["pixel_y"] - (w - 1) / 2) < 1.0, t


def test_engine_and_scenario_truth_have_the_same_fields():
    with eoir.Scenario.load(CLI_DATA / "wcs_targets.json") as sc:
        sc.set_time(sc.start)
        sc.engine.render("Cam")
        from_file = sc.truth("Cam")
        from_engine = sc.engine.truth("Cam")
    assert len(from_file) == len(from_engine) == 3
    for f, e in zip(from_file, from_engine):
        assert set(e) == set(eoir.TRUTH_FIELDS)
        assert set(f) <= set(e), set(f) - set(e)
        for key, value in f.items():
            if isinstance(value, str) or isinstance(value, bool):
                assert e[key] == value, key
            elif isinstance(value, list):
                assert e[key] == pytest.approx(tuple(value), rel=1e-12, abs=1e-9), key
            else:
                assert e[key] == pytest.approx(value, rel=1e-12, abs=1e-9), key


def header_enum(name):
    """{NAME: value} of an enum of eoir.h, read from the header itself."""
    text = (SOURCE / "capi" / "include" / "eoir" / "eoir.h").read_text()
    body = re.search(r"typedef enum %s \{(.*?)\} %s;" % (name, name), text, re.S).group(1)
    return {k: int(v) for k, v in re.findall(r"EOIR_(\w+)\s*=\s*(-?\d+)", body)}


@pytest.mark.parametrize("enum_name, cls", [("eoir_object_kind", eoir.Kind), ("eoir_frame", eoir.Frame),
                                            ("eoir_time_scale", eoir.TimeScale),
                                            ("eoir_image_kind", eoir.ImageKind)])
def test_named_constants_mirror_the_header(enum_name, cls):
    expected = header_enum(enum_name)
    assert expected, enum_name
    prefix = {"Kind": "KIND_", "Frame": "FRAME_", "TimeScale": "TIME_", "ImageKind": "IMAGE_"}[cls.__name__]
    got = {prefix + m.name: int(m) for m in cls}
    assert got == expected
    for name, value in expected.items():
        assert getattr(eoir, name) == value and getattr(eoir, name) is cls[name[len(prefix):]]


def test_named_constants_are_taken_wherever_names_are(engine):
    engine.set_time(T0)
    engine.add_object(eoir.KIND_SATELLITE, "Sat")
    engine.set_state("Sat", position=(0.0, 0.0, 35786e3), frame=eoir.Frame.GEODETIC)
    assert engine.objects()[-1] == ("Sat", "satellite")
    lat_lon_h = engine.get_state("Sat", eoir.FRAME_GEODETIC)["position"]
    assert lat_lon_h == pytest.approx([0.0, 0.0, 35786e3], abs=1e-3)
    assert engine.get_time(eoir.TimeScale.UTC)[2] == "utc"


def test_the_package_is_typed():
    package = Path(eoir.__file__).parent
    assert (package / "py.typed").is_file()
    assert 'eoir = ["py.typed"]' in (package.parent / "pyproject.toml").read_text()
    missing = []
    for cls in (eoir.Engine, eoir.Scenario):
        for name, fn in inspect.getmembers(cls, inspect.isfunction):
            if name.startswith("_") and name not in ("__init__", "__enter__"):
                continue
            sig = inspect.signature(fn)
            if sig.return_annotation is inspect.Signature.empty:
                missing.append(f"{cls.__name__}.{name} -> ?")
            for p in list(sig.parameters.values())[1:]:
                if p.annotation is inspect.Parameter.empty and p.kind not in (p.VAR_POSITIONAL,):
                    missing.append(f"{cls.__name__}.{name}({p.name})")
    for name in ("version", "version_string", "time_to_iso", "time_from_iso", "tle_state",
                 "heading_pitch_roll_quaternion", "provider_groups", "provider_elements"):
        sig = inspect.signature(getattr(eoir, name))
        if sig.return_annotation is inspect.Signature.empty or any(
                p.annotation is inspect.Parameter.empty for p in sig.parameters.values()):
            missing.append(name)
    assert missing == []


def test_a_python_without_numpy_is_told_what_works():
    # -S: no site-packages, so Debian's numpy (dist-packages) is not found,
    # as in a venv made without --system-site-packages.
    package_dir = Path(eoir.__file__).resolve().parents[1]
    out = subprocess.run([sys.executable, "-S", "-c", f"import sys; sys.path.insert(0, {str(package_dir)!r}); "
                          "import eoir"], capture_output=True, text=True,
                         env={k: v for k, v in os.environ.items() if k != "PYTHONPATH"})
    assert out.returncode != 0
    message = out.stderr.strip().splitlines()[-1]
    print(message)
    assert message.startswith("ImportError: eoir needs numpy")
    assert sys.executable in message
    assert "/usr/bin/python3" in message and "--system-site-packages" in message


def test_version_is_the_package_version():
    from eoir import _version
    assert eoir.__version__ == _version.__version__ == eoir.version_string()

#!/usr/bin/env python3
"""05 - a ground telescope tracking a satellite through the atmosphere.

A site is a place on the Earth (latitude, longitude, height) that carries
sensors. Here a telescope at Kitt Peak follows a satellite 550 km up across
the twilight sky with Engine.track, which points it again at every time
step, so the satellite stays in the middle of the image while the sky moves.
The Earth's atmosphere is on: the sky glows, the satellite is dimmed by the
air along the line of sight and raised by the refraction. Tracking aims at
the satellite's true (geometric) place, so the image shows it above the
centre by the refraction, about 1 arcmin at 40 deg elevation.

    python3 examples/05_ground_telescope.py [OUTPUT_DIR]

Makes telescope_NN.png (one per time step) and telescope_track.csv (time,
azimuth, elevation, air mass, pixel and SNR of the satellite).
"""

import math

import example_output as out

import numpy as np

import eoir

folder = out.output_dir()
N = 96
PIXEL_ARCSEC = 0.3 * 3600 / N
times = ["2010-08-25T02:45:00Z", "2010-08-25T02:45:10Z", "2010-08-25T02:45:20Z"]   # the Sun 10 deg down

with eoir.Engine(seed=1) as engine:
    engine.set_time(times[0])
    engine.add_object(eoir.Kind.CENTRAL_BODY, "Earth")
    engine.set("Earth", "atmosphere", "simple")              # US Standard 1976, rural aerosols

    engine.add_object(eoir.Kind.SITE, "KittPeak")
    for name, value in {"latitude_deg": 31.9583, "longitude_deg": -111.5967, "height_m": 2096.0}.items():
        engine.set("KittPeak", name, value)
    engine.add_sensor("Scope", "KittPeak")
    for name, value in {"horizontal_pixels": N, "vertical_pixels": N, "horizontal_fov_deg": 0.3,
                        "vertical_fov_deg": 0.3, "band_low_um": 0.45, "band_high_um": 0.9,
                        "integration_time_ms": 50.0}.items():
        engine.set("Scope", name, value)

    # The satellite, a 2 m sphere: placed 550 km above a point south-east of
    # the site (away from the set Sun, so its lit side faces us), then moving
    # east at 7.6 km/s (an Earth-fixed state; the engine moves it along its
    # velocity between the states the host pushes).
    engine.add_object(eoir.Kind.SATELLITE, "Sat")
    engine.set("Sat", "shape", "sphere")
    engine.set("Sat", "dimensions_m", [2.0])
    engine.set("Sat", "material", "white_thermal_control")   # a new object is a black gray body
    engine.set_state("Sat", position=(29.0, -108.0, 550e3), frame=eoir.FRAME_GEODETIC)
    r = engine.get_state("Sat", eoir.FRAME_EARTH_FIXED)["position"]
    east = np.cross([0.0, 0.0, 1.0], r)
    engine.set_state("Sat", position=r, velocity=7600.0 * east / np.linalg.norm(east), frame=eoir.FRAME_EARTH_FIXED)

    engine.track("Scope", "Sat")                              # point_at now and at every time step
    rows = []
    for i, time in enumerate(times):
        engine.set_time(time)
        engine.render("Scope")
        (sat,) = [t for t in engine.truth("Scope") if t["object"] == "Sat"]
        rows.append({"time": time, **sat})
        png = folder / f"telescope_{i:02d}.png"
        out.write_png(png, engine.image("Scope", "sensor_display"))
        out.made(png, f"{time}: Sat at azimuth {sat['azimuth_deg']:.2f}, elevation {sat['elevation_deg']:.2f} deg, "
                      f"air mass {sat['air_mass']:.2f}, SNR {sat['snr']:.0f}")

out.write_csv(folder / "telescope_track.csv", rows,
              ["time", "azimuth_deg", "elevation_deg", "air_mass", "pixel_x", "pixel_y", "snr", "range_m"])
out.made(folder / "telescope_track.csv", f"{len(rows)} time steps")

# Tracked: in the centre column in every frame, and raised above the centre
# row by the refraction: Bennett's formula, R = 1.02' / tan(h + 10.3 / (h +
# 5.11)), scaled by the air's pressure and temperature at 2096 m (US 1976:
# 794 hPa, 274.5 K), (P / 1010) (283 / T) = 0.811, within a pixel; while
# the satellite crossed many fields' widths of sky.
for row in rows:
    h = row["elevation_deg"]
    bennett_px = 0.811 * 60 * 1.02 / math.tan(math.radians(h + 10.3 / (h + 5.11))) / PIXEL_ARCSEC
    raised_px = (N - 1) / 2 - row["pixel_y"]
    print(f"{row['time']}: raised {raised_px:.2f} px by the refraction (Bennett: {bennett_px:.2f} px)")
    out.check(abs(row["pixel_x"] - (N - 1) / 2) < 1 and abs(raised_px - bennett_px) < 1,
              f"{row['time']}: Sat at ({row['pixel_x']:.2f}, {row['pixel_y']:.2f}), not where tracking puts it")
    out.check(row["snr"] > 5, f"{row['time']}: SNR {row['snr']:.1f}: the satellite is not seen")
moved = abs(rows[-1]["azimuth_deg"] - rows[0]["azimuth_deg"]) + abs(rows[-1]["elevation_deg"] - rows[0]["elevation_deg"])
out.check(moved > 0.3, f"the satellite moved only {moved:.2f} deg")

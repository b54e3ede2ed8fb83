#!/usr/bin/env python3
"""01 - your first frame.

The smallest complete program: one engine, two satellites in GEO and a
camera on one of them pointed at the other; render one 64 x 64 frame, read
its images and its truth (where each object landed), and write them.

    python3 examples/01_first_frame.py [OUTPUT_DIR]

Makes first_frame_electrons.fits (the sensor's electrons, astropy),
first_frame.png (the display image) and first_frame_truth.csv.
"""

import example_output as out  # the output folder, PNG and CSV writers

import numpy as np
from astropy.io import fits

import eoir

folder = out.output_dir()

# An engine holds a universe (the Sun from the start) at a time; threads=0
# uses every core, seed fixes the noise.
with eoir.Engine(threads=0, seed=1) as engine:
    engine.set_time("2010-08-25T18:00:00Z")

    # Objects are added by kind and name, then moved by pushing states:
    # J2000 position in metres (and velocity in m/s, attitude...).
    engine.add_object(eoir.Kind.SATELLITE, "Observer")
    engine.set("Observer", "shape", "none")           # a bare platform: nothing of it in view
    engine.set_state("Observer", position=(42164e3, 0.0, 0.0))

    # The neighbour, a 3 x 2 x 2 m box in gold foil, 30 km away on the side
    # away from the Sun, so that we see its sunlit faces. get_state reads an
    # object's state: here the Sun's J2000 position.
    sun = engine.get_state("Sun")["position"]
    away = -sun / np.linalg.norm(sun)
    engine.add_object(eoir.Kind.SATELLITE, "Neighbour")
    engine.set("Neighbour", "shape", "box")
    engine.set("Neighbour", "dimensions_m", [3.0, 2.0, 2.0])
    engine.set("Neighbour", "material", "gold_mli")
    engine.set_state("Neighbour", position=np.array([42164e3, 0.0, 0.0]) + 30e3 * away + (0.0, 0.0, 5e3))

    # A sensor rides on a parent object. Properties have types and units in
    # their names (eoir.Engine.properties("Camera") lists them all).
    engine.add_sensor("Camera", "Observer")
    for name, value in {"horizontal_pixels": 64, "vertical_pixels": 64,
                        "horizontal_fov_deg": 0.1, "vertical_fov_deg": 0.1,
                        "band_low_um": 0.45, "band_high_um": 0.9,
                        "integration_time_ms": 100.0}.items():
        engine.set("Camera", name, value)

    # Point the boresight (body +z) at the neighbour; render at the engine time.
    engine.point_at("Camera", "Neighbour")
    engine.render("Camera")

    electrons = engine.image("Camera", "sensor_electrons")   # (rows, columns), row 0 at the top
    display = engine.image("Camera", "sensor_display")       # uint8, the sensor's stretch
    truth = engine.truth("Camera")                           # one dict per object in the field

fits.PrimaryHDU(np.flipud(electrons).astype(np.float32)).writeto(  # FITS row 1 is the bottom row
    folder / "first_frame_electrons.fits", overwrite=True)
out.made(folder / "first_frame_electrons.fits", f"{electrons.shape[1]} x {electrons.shape[0]} electrons, "
         f"total {electrons.sum():.4g} e-")
out.write_png(folder / "first_frame.png", display)
out.made(folder / "first_frame.png", "the display image")
out.write_csv(folder / "first_frame_truth.csv", truth,
              ["object", "pixel_x", "pixel_y", "x_fits", "y_fits", "range_m", "snr", "point_source"])
out.made(folder / "first_frame_truth.csv", f"{len(truth)} object(s)")

# The neighbour sits at the image centre, (64 - 1) / 2 in 0-based pixels.
(row,) = truth
print(f"{row['object']}: pixel ({row['pixel_x']:.2f}, {row['pixel_y']:.2f}), range {row['range_m'] / 1e3:.2f} km, "
      f"SNR {row['snr']:.1f}")
out.check(abs(row["pixel_x"] - 31.5) < 1 and abs(row["pixel_y"] - 31.5) < 1, "the neighbour is off centre")
out.check(row["snr"] > 10, f"SNR {row['snr']:.1f}: the neighbour is not seen")

#!/usr/bin/env python3
"""04 - the Earth from GEO, in the visible and the thermal infrared.

Two cameras on one geostationary satellite, both pointed at the Earth's
centre with Engine.point_at: a visible one (0.45-0.75 um) with the Earth in
bitmap mode (land cover and coastlines) and a thermal one (8-12 um) seeing
the Earth's own emission. The Earth is a central body: add it by name.

    python3 examples/04_earth_from_geo.py [OUTPUT_DIR]

Makes earth_visible.png, earth_thermal.png, earth_radiance.fits (both
cameras' scene radiance, one HDU each) and earth_rows.csv (the middle row
of both in W/(cm^2 sr)).
"""

import math

import example_output as out

import numpy as np
from astropy.io import fits

import eoir

folder = out.output_dir()
N = 128

with eoir.Engine(seed=1) as engine:
    engine.set_time("2010-08-25T15:00:00Z")
    engine.add_object(eoir.Kind.CENTRAL_BODY, "Earth")     # central bodies are named: Earth, Moon, Mars...

    # A GEO satellite over the Atlantic (longitude 25 W), placed by latitude,
    # longitude and height (eoir.FRAME_GEODETIC) instead of J2000 metres.
    engine.add_object(eoir.Kind.SATELLITE, "Geo")
    engine.set("Geo", "shape", "none")
    engine.set_state("Geo", position=(0.0, -25.0, 35786e3), frame=eoir.FRAME_GEODETIC)

    # The Earth spans 17.4 deg from GEO: a 19 deg field holds it whole.
    bands = {"Visible": (0.45, 0.75), "Thermal": (8.0, 12.0)}
    for sensor, (low_um, high_um) in bands.items():
        engine.add_sensor(sensor, "Geo")
        for name, value in {"horizontal_pixels": N, "vertical_pixels": N, "horizontal_fov_deg": 19.0,
                            "vertical_fov_deg": 19.0, "band_low_um": low_um, "band_high_um": high_um,
                            "noise_enabled": False, "saturation_enabled": False}.items():
            engine.set(sensor, name, value)
        engine.point_at(sensor, "Earth")
    engine.set("Visible", "scene_mode", "bitmap")          # land cover and coasts (a fidelity knob)

    hdus = [fits.PrimaryHDU()]
    rows = {}
    for sensor in bands:
        engine.render(sensor)
        radiance = engine.image(sensor, "scene_radiance")   # the scene before the optics, W/(cm^2 sr)
        hdus.append(fits.ImageHDU(np.flipud(radiance).astype(np.float32), name=sensor.upper()))
        rows[sensor] = radiance[radiance.shape[0] // 2]
        png = folder / f"earth_{sensor.lower()}.png"
        mean = engine.image(sensor, "sensor_mean")            # electrons through the optics (the OTF)
        if sensor == "Visible":
            out.write_png(png, out.stretch(mean, 0.0, 99.9))       # asinh: the glint and the dark sea
        else:
            out.write_png(png, out.stretch(mean, 12.0, 100.0, 0))  # linear over the disc: cold clouds dark
        out.made(png, f"{sensor} ({bands[sensor][0]}-{bands[sensor][1]} um): mean radiance of the scene "
                      f"{radiance.mean():.3g} W/(cm^2 sr), brightest {radiance.max():.3g}")

fits.HDUList(hdus).writeto(folder / "earth_radiance.fits", overwrite=True)
out.made(folder / "earth_radiance.fits", "scene radiance, one HDU per camera")
out.write_csv(folder / "earth_rows.csv",
              [{"column": i, "visible": v, "thermal": t} for i, (v, t) in enumerate(zip(*rows.values()))],
              ["column", "visible", "thermal"])
out.made(folder / "earth_rows.csv", "the middle row of both cameras")

# Along the middle row the disc spans the Earth's angular diameter from GEO,
# 2 asin(6378 / 42164) = 17.4 deg: tan(8.70 deg) / tan(9.5 deg) = 91 % of the
# columns (pixels are uniform in the tangent of the angle).
expected = math.tan(math.asin(6378.137 / 42164.0)) / math.tan(math.radians(9.5))
thermal = rows["Thermal"]
on_disc = np.count_nonzero(thermal > 0.5 * thermal.max()) / thermal.size
print(f"thermal middle row: {on_disc:.1%} of the columns on the disc, expected {expected:.1%}")
out.check(abs(on_disc - expected) < 0.03, "the thermal disc is not the Earth's size")

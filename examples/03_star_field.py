#!/usr/bin/env python3
"""03 - a surveillance star field, from a scenario file.

Scenario files (JSON, schemas/scenario.schema.json) describe objects, their
motion, sensors and their pointing; eoir.Scenario loads one through the CLI's
own code. This one (scenarios/demo/star_field.json) has a GEO camera track a
communications satellite 2000 km ahead among the Hipparcos/Tycho-2 stars.
We shrink the camera to 256 x 256 pixels over 1.5 deg (seconds, not tens of
seconds), render the first frame, and write it as `eoir run` would: a FITS
file with the astrometric TAN WCS (ready for astrometry.net or SExtractor)
and the truth of every star and object in the field.

    python3 examples/03_star_field.py [OUTPUT_DIR]

Makes star_field.fits, star_field.png and star_field_truth.csv.
"""

import example_output as out

import eoir

folder = out.output_dir()
scenario = out.SOURCE_DIR / "scenarios" / "demo" / "star_field.json"

with eoir.Scenario.load(scenario, seed=1) as sc:
    print(f"{sc.name}: {sc.description[:100]}...")
    # sc.engine is an eoir.Engine over the scenario's engine: any property
    # can be changed after loading.
    for name, value in {"horizontal_pixels": 256, "vertical_pixels": 256,
                        "horizontal_fov_deg": 1.5, "vertical_fov_deg": 1.5}.items():
        sc.engine.set("SkyCam", name, value)

    sc.set_time(sc.start)              # every object's state and the camera's pointing (a "target" pointing)
    sc.engine.render("SkyCam")

    sc.write_fits("SkyCam", "sensor_electrons", folder / "star_field.fits")   # astropy, with the WCS
    out.made(folder / "star_field.fits", "electrons with the astrometric WCS, DATE-OBS, EXPTIME")
    out.write_png(folder / "star_field.png", out.stretch(sc.engine.image("SkyCam", "sensor_mean")))
    out.made(folder / "star_field.png", "the mean electrons, asinh stretch")

    truth = sc.truth("SkyCam")         # as `eoir run` writes it: FITS pixels, RA/Dec, V...
    out.write_csv(folder / "star_field_truth.csv", truth,
                  ["object", "kind", "x_fits", "y_fits", "ra_deg", "dec_deg", "v_mag", "snr"])
    stars = [t for t in truth if t["kind"] == "star"]
    out.made(folder / "star_field_truth.csv", f"{len(stars)} stars and {len(truth) - len(stars)} object(s)")

brightest = min(stars, key=lambda t: t["v_mag"])
print(f"brightest star {brightest['object']}: V = {brightest['v_mag']:.2f} at FITS pixel "
      f"({brightest['x_fits']:.1f}, {brightest['y_fits']:.1f})")
(target,) = [t for t in truth if t["object"] == "GeoComsat"]
print(f"GeoComsat at FITS pixel ({target['x_fits']:.2f}, {target['y_fits']:.2f}), SNR {target['snr']:.0f}")
# The tracked satellite sits at the centre: FITS pixel (256 + 1) / 2.
out.check(abs(target["x_fits"] - 128.5) < 1 and abs(target["y_fits"] - 128.5) < 1, "the target is off centre")
out.check(len(stars) >= 5, f"only {len(stars)} stars in 1.5 deg")

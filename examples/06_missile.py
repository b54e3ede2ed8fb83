#!/usr/bin/env python3
"""06 - a missile boost seen from GEO in the mid-wave infrared.

Reuses the scenario of scenarios/demo/missile_demo.py
(scenarios/demo/results/missile_boost.json): a staring 3-5 um camera on a
GEO satellite over 25 W watches a two-stage missile launched at local
midnight from 5 N 30 W; its plumes (0.99 of a black body) outshine the
night Earth. The camera is shrunk to 128 x 128 pixels over its 1 deg.

    python3 examples/06_missile.py [OUTPUT_DIR]

Makes missile_NN.png (one per time step) and missile_truth.csv (time,
pixel, irradiance and SNR of the missile).
"""

import example_output as out

import eoir

folder = out.output_dir()
scenario = out.SOURCE_DIR / "scenarios" / "demo" / "results" / "missile_boost.json"

with eoir.Scenario.load(scenario, seed=1) as sc:
    print(f"{sc.name}: {sc.description[:110]}...")
    sc.engine.set("Stare", "horizontal_pixels", 128)
    sc.engine.set("Stare", "vertical_pixels", 128)
    rows = []
    for i, time in enumerate(sc.times(step_s=60.0)):          # the scenario's span, every 60 s
        sc.set_time(time)
        sc.engine.render("Stare")
        missile = [t for t in sc.engine.truth("Stare") if t["object"] == "Missile1"]
        png = folder / f"missile_{i:02d}.png"
        out.write_png(png, out.stretch(sc.engine.image("Stare", "sensor_mean"), 50.0, 100.0, 1000.0))
        if missile:
            m = missile[0]
            rows.append({"time": time, **m})
            out.made(png, f"{time}: Missile1 at FITS pixel ({m['x_fits']:.1f}, {m['y_fits']:.1f}), "
                          f"{m['effective_irradiance']:.3g} W/cm^2, SNR {m['snr']:.0f}")
        else:
            out.made(png, f"{time}: Missile1 outside the field")

out.write_csv(folder / "missile_truth.csv", rows,
              ["time", "x_fits", "y_fits", "effective_irradiance", "snr", "range_m"])
out.made(folder / "missile_truth.csv", f"{len(rows)} frames with the missile")
out.check(len(rows) >= 2 and max(r["snr"] for r in rows) > 10, "the missile's boost is not seen")

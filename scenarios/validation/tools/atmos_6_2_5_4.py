#!/usr/bin/python3
"""Spec 6.2.5.4 (Atmosphere - MODTRAN 4 comparison): eq. 9's components at
the sensor per spectral interval, written as CSV and plotted as the spec's
figures show them (total radiance, path thermal, path scatter, ground
reflected, ground emitted, transmittance), for the three bands of step 5.

usage: atmos_6_2_5_4.py [--eoir EXE] [--out-dir DIR]
  EXE: the eoir program (default $EOIR_EXE, else build/bin/eoir)
  DIR: where to write (default scenarios/validation/results)

For each sensor of scenarios/validation/v_atmos_test3.json it runs, from the
repository root,

  eoir pick scenarios/validation/v_atmos_test3.json --sensor NAME --x 1 --y 1 \\
       --space pixel --format json

and the same pick of a copy whose Earth is at 0 K, which leaves the light
the surface reflects: ground emitted = surface(288.15 K) - surface(0 K),
ground reflected = surface(0 K), each times T_out at the sensor (MODTRAN's
GRND EMIS and GRND RFLT). DownWelling is off in the scenario (single
scatter, ERRATA 4.1.5.3), so the surface reflects the direct Sun only.

Writes into DIR: atmos_6_2_5_4.csv (one row per interval of the three bands;
radiances in W/(cm^2 sr um)) and atmos_6_2_5_4_<band>.png (one figure per
band, 2 x 3 panels).
"""
import argparse
import copy
import csv
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
SCENARIO = os.path.join("scenarios", "validation", "v_atmos_test3.json")
# (sensor, file suffix, title) of spec 6.2.5.4 step 5 a-c.
BANDS = (("Sensor_0p3_1um", "0p3_1um", "0.3-1.0 um, 700 intervals"),
         ("Sensor_1_4um", "1_4um", "1.0-4.0 um, 600 intervals"),
         ("Sensor_4_28um", "4_28um", "4.0-28.0 um, 600 intervals"))
CENTRE = ["--x", "1", "--y", "1", "--space", "pixel"]
RADIANCE_UNIT = "W/(cm^2 sr um)"
COLUMNS = ("sensor", "wavelength_um", "total", "path_thermal", "path_scatter", "ground_reflected", "ground_emitted",
           "transmittance", "surface", "surface_reflected", "downwelling")


def pick(exe, scenario, sensor):
    cmd = [exe, "pick", scenario, "--sensor", sensor, *CENTRE, "--format", "json"]
    print("$ " + " ".join(cmd), file=sys.stderr)
    r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"eoir pick failed (exit {r.returncode}):\n{r.stderr}")
    return json.loads(r.stdout)


def components(hot, cold):
    """Eq. 9's components at the sensor from the picks of the 288.15 K and the
    0 K Earth (same geometry, same path)."""
    c, k = hot["columns"], cold["columns"]
    assert c["wavelength_um"] == k["wavelength_um"] and c["transmittance"] == k["transmittance"]
    T = np.array(c["transmittance"])
    surface, surface_reflected = np.array(c["surface"]), np.array(k["surface"])
    return {
        "wavelength_um": np.array(c["wavelength_um"]),
        "total": np.array(c["at_sensor"]),
        "path_thermal": np.array(c["path_thermal"]),
        "path_scatter": np.array(c["path_scatter"]),
        "ground_reflected": surface_reflected * T,
        "ground_emitted": (surface - surface_reflected) * T,
        "transmittance": T,
        "surface": surface,
        "surface_reflected": surface_reflected,
        "downwelling": np.array(c["downwelling"]),
    }


def run_all(exe):
    """{sensor: (components, the 288.15 K pick's header)} for the three bands."""
    doc = json.load(open(os.path.join(ROOT, SCENARIO)))
    cold = copy.deepcopy(doc)
    cold["central_bodies"][0]["properties"]["temperature_K"] = 0.0
    cold["description"] = "Spec 6.2.5.4 with the Earth at 0 K: only reflected light leaves it (atmos_6_2_5_4.py)."
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        cold_file = os.path.join(tmp, "v_atmos_test3_0K.json")
        with open(cold_file, "w") as f:
            json.dump(cold, f)
        for sensor, _, _ in BANDS:
            hot = pick(exe, SCENARIO, sensor)
            out[sensor] = (components(hot, pick(exe, cold_file, sensor)), hot)
    return out


def write_csv(path, results):
    with open(path + ".tmp", "w", newline="") as f:
        f.write("# Spec 6.2.5.4 components at the sensor, eoir pick of scenarios/validation/v_atmos_test3.json "
                "(pixel 1, 1); radiances in " + RADIANCE_UNIT + ", transmittance T_out 1;\n"
                "# total = (surface_reflected + ground emission) * T + path_thermal + path_scatter; "
                "ground_* are at the sensor (times T)\n")
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for sensor, (c, _) in results.items():
            for i in range(len(c["wavelength_um"])):
                w.writerow([sensor] + ["%.10g" % c[k][i] for k in COLUMNS[1:]])
    os.replace(path + ".tmp", path)


def plot(path, title, c, header):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    wl = c["wavelength_um"]
    panels = (("total", "Total radiance"), ("path_thermal", "Path thermal"), ("path_scatter", "Path scatter"),
              ("ground_reflected", "Ground reflected"), ("ground_emitted", "Ground emitted"),
              ("transmittance", "Transmittance (T_out)"))
    fig, axes = plt.subplots(2, 3, figsize=(15, 7.5), dpi=90, sharex=True)
    for ax, (key, name) in zip(axes.flat, panels):
        ax.plot(wl, c[key], color="tab:blue", lw=0.8)
        ax.set_title(name, fontsize=10)
        ax.set_ylabel("T_out" if key == "transmittance" else "radiance [" + RADIANCE_UNIT + "]", fontsize=8)
        ax.ticklabel_format(axis="y", style="sci", scilimits=(-2, 3))
        if c[key].max() > 0:  # (the ground's emission below 1 um is 0 to double precision)
            ax.set_ylim(0, 1.05 * c[key].max())
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("wavelength [um]")
    axes[1][2].set_ylim(0, 1)
    fig.suptitle("Spec 6.2.5.4, %s: US76, rural aerosol, 23 km visibility, single scatter, 80 %% Lambertian "
                 "surface at 288.15 K\nnadir view from 500 km, Sun at the zenith (%.4f N, %.4f E, %s); "
                 "band radiance at the sensor %.4g W/(cm^2 sr)"
                 % (title, header["latitude_deg"], header["longitude_deg"], header["time"],
                    header["effective_radiance_W_cm2_sr"]), fontsize=10)
    fig.tight_layout()
    fig.savefig(path + ".tmp.png")
    plt.close(fig)
    os.replace(path + ".tmp.png", path)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--eoir", default=os.environ.get("EOIR_EXE", os.path.join(ROOT, "build", "bin", "eoir")))
    p.add_argument("--out-dir", default=os.path.join(ROOT, "scenarios", "validation", "results"))
    a = p.parse_args()
    os.makedirs(a.out_dir, exist_ok=True)
    results = run_all(os.path.abspath(a.eoir))
    write_csv(os.path.join(a.out_dir, "atmos_6_2_5_4.csv"), results)
    for sensor, suffix, title in BANDS:
        c, header = results[sensor]
        plot(os.path.join(a.out_dir, "atmos_6_2_5_4_%s.png" % suffix), title, c, header)
        i = int(np.argmin(abs(c["wavelength_um"] - 0.55))) if sensor == BANDS[0][0] else None
        print("%s: effective radiance %.5g W/(cm^2 sr)%s" % (
            sensor, header["effective_radiance_W_cm2_sr"],
            "" if i is None else ", T_out(%.4f um) %.4f" % (c["wavelength_um"][i], c["transmittance"][i])),
            file=sys.stderr)
    print("wrote atmos_6_2_5_4.csv and 3 figures into " + a.out_dir, file=sys.stderr)


if __name__ == "__main__":
    main()

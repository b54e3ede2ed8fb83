#!/usr/bin/env python3
"""Spec 6.2.5.4 (Atmosphere - MODTRAN 4 comparison) as a validation run:
scenarios/validation/tools/atmos_6_2_5_4.py picks the subsolar point of
scenarios/validation/v_atmos_test3.json (nadir view from 500 km, Sun at the
zenith, day 93, US76, rural aerosol at 23 km, single scatter, 80 %
Lambertian gray surface at 288.15 K; 0.3-1 um in 700 intervals, 1-4 um in
600, 4-28 um in 600) and writes the components as CSV and figures. Checked
against values that do not come from the engine:

 1. Eq. 9 (spec 4.1.5.3): total = ground reflected + ground emitted + path
    thermal + path scatter in every interval, 1e-8 (the CSV's 10 digits).
 2. T_out at 0.55 um (mean of the two 1 nm intervals at 0.549-0.551 um)
    against LOWTRAN 7's vertical US76 column: 0.882 without aerosol (issue
    20 item 9, the issue's run of the public code) times exp(-0.324), the
    rural 23 km aerosol's vertical optical depth at 0.55 um (LOWTRAN 7, as
    tests/atmosphere Aerosol.*): 0.638 +- 0.02 (the issue's tolerance).
 3. What the surface reflects is the direct Sun only (DownWelling off,
    ERRATA 4.1.5.3): rho / pi x E-490 (the published table, read from
    pyspectral's file) / d^2 (d by ERFA) x T_sun, with T_sun = T_out (Sun
    at the zenith and nadir view: the same vertical column), in bins of 10
    intervals where T_out > 0.3, 0.3-28 um: 0.3 % (spec 6.2.4.1's tolerance
    on the Sun's band irradiance; the engine puts the Sun at its distance
    from the surface point, 1 Earth radius nearer: +8.5e-5).
 4. What it emits is (1 - rho) B(lambda, 288.15 K) (spec 4.1.4.1:
    emissivity = 1 - SRF), B the interval mean of Planck's law, 3-28 um:
    0.1 % (the midpoint rule's departure from the interval mean is at most
    dlambda^2 / 24 |B''/B| = 7e-4 at 4 um in 0.04 um intervals).
 5. Path thermal (Schwarzschild): below (1 - T) B(lambda, 288.15 K) in
    every interval (no US76 air below 86 km is warmer than the ground:
    US76 Table I), and where the path is opaque (T_out < 0.01) a black
    body at a temperature between the coldest and warmest US76 air,
    186.87-288.15 K.
 6. Path scatter in the visible: sunlight (E-490 falls from 0.45 to 0.9 um)
    times a scattering optical depth that falls with wavelength (Rayleigh
    lambda^-4, rural aerosol): its 50 nm means decrease from 0.45 to 0.9 um.

The spec's own figures (MODTRAN 4 against EOIR) did not survive its
conversion from PDF (ERRATA: "figures are missing"), so no read-off values
are compared.

usage: check_atmos_6_2_5_4.py EOIR_EXE E490_FILE WORK_DIR
"""
import csv
import os
import subprocess
import sys

import erfa
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
TOOL = os.path.join(ROOT, "scenarios", "validation", "tools", "atmos_6_2_5_4.py")
BANDS = {"Sensor_0p3_1um": (0.3, 1.0, 700), "Sensor_1_4um": (1.0, 4.0, 600), "Sensor_4_28um": (4.0, 28.0, 600)}
REFLECTANCE, SURFACE_K = 0.8, 288.15
EPOCH = (2010, 4, 3, 12, 3, 19.0)  # the scenario's time
C1, C2 = 1.191042972e4, 14387.7688  # Planck: W um^4 / (cm^2 sr), um K
US76_COLDEST_K, US76_WARMEST_K = 186.87, 288.15  # 0-86 km (US76 Table I: 84.852 km and the ground)


def planck(wl_um, T):
    return C1 / wl_um ** 5 / np.expm1(C2 / (wl_um * T))


def interval_mean(f, lo, hi, n=64):
    x = np.linspace(lo, hi, n + 1)
    return np.trapz(f(x), x) / (hi - lo)


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    header, out = rows[0], {}
    for r in rows[1:]:
        out.setdefault(r[0], []).append([float(v) for v in r[1:]])
    return {s: {k: np.array(v)[:, i] for i, k in enumerate(header[1:])} for s, v in out.items()}


def sun_distance_au():
    d1, d2 = erfa.dtf2d("UTC", *EPOCH)
    t1, t2 = erfa.taitt(*erfa.utctai(d1, d2))
    pvh, _ = erfa.epv00(t1, t2)
    return float(np.linalg.norm(pvh[0]))


def main():
    exe, e490_file, work = sys.argv[1:4]
    r = subprocess.run([sys.executable, TOOL, "--eoir", exe, "--out-dir", work], capture_output=True, text=True)
    print(r.stderr)
    if r.returncode != 0:
        sys.exit(f"FAILED: {TOOL} exit {r.returncode}")
    for suffix in ("0p3_1um", "1_4um", "4_28um"):
        png = os.path.join(work, f"atmos_6_2_5_4_{suffix}.png")
        assert os.path.getsize(png) > 10000, png
    data = read_csv(os.path.join(work, "atmos_6_2_5_4.csv"))
    e490 = np.loadtxt(e490_file)  # um, W/(m^2 um) at 1 au
    sun_scale = 1e-4 / sun_distance_au() ** 2
    failures = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            failures.append(what)

    for sensor, (lo, hi, n) in BANDS.items():
        c = data[sensor]
        wl, T = c["wavelength_um"], c["transmittance"]
        assert len(wl) == n, (sensor, len(wl))
        edges = lo + (hi - lo) * np.arange(n + 1) / n
        # 1. The components sum to the total.
        parts = c["ground_reflected"] + c["ground_emitted"] + c["path_thermal"] + c["path_scatter"]
        worst = np.max(np.abs(parts - c["total"]) / np.maximum(np.abs(c["total"]), 1e-300))
        check(worst < 1e-8, f"{sensor}: total = sum of components, worst {worst:.1e} (1e-8)")
        # 3. Reflected: rho/pi E-490 / d^2 T_sun, T_sun = T_out.
        sun = np.array([interval_mean(lambda x: np.interp(x, e490[:, 0], e490[:, 1]), edges[i], edges[i + 1])
                        for i in range(n)]) * sun_scale
        expect = REFLECTANCE / np.pi * sun * T
        ratios = [c["surface_reflected"][k:k + 10].sum() / expect[k:k + 10].sum()
                  for k in range(0, n, 10) if T[k:k + 10].min() > 0.3]
        if ratios:
            check(max(abs(np.array(ratios) - 1)) < 3e-3,
                  f"{sensor}: reflected / (rho/pi E-490 T_sun) in {len(ratios)} bins {min(ratios):.5f}-"
                  f"{max(ratios):.5f} (0.3 %)")
        # 4. Emitted: (1 - rho) B(288.15 K), where it is more than 1e-3 of the reflected light.
        emitted = c["surface"] - c["surface_reflected"]
        planck_mean = np.array([interval_mean(lambda x: planck(x, SURFACE_K), edges[i], edges[i + 1])
                                for i in range(n)])
        m = wl >= 3.0
        if m.any():
            q = emitted[m] / ((1 - REFLECTANCE) * planck_mean[m])
            check(max(abs(q - 1)) < 1e-3, f"{sensor}: emitted / (1 - rho) B(288.15 K), 3-28 um, {q.min():.5f}-"
                  f"{q.max():.5f} (0.1 %)")
        # 5. Path thermal: Schwarzschild bounds.
        L = c["path_thermal"]
        check(np.all(L <= (1 - T) * planck(wl, US76_WARMEST_K) * (1 + 1e-6)),
              f"{sensor}: path thermal <= (1 - T) B(288.15 K) in every interval")
        opaque = T < 0.01
        if opaque.any() and wl.min() >= 1.0:
            tb = C2 / (wl[opaque] * np.log1p(C1 / (wl[opaque] ** 5 * L[opaque])))
            check(tb.min() >= US76_COLDEST_K and tb.max() <= US76_WARMEST_K,
                  f"{sensor}: {opaque.sum()} opaque intervals emit at {tb.min():.1f}-{tb.max():.1f} K "
                  f"(US76 air {US76_COLDEST_K}-{US76_WARMEST_K} K)")
            at15 = np.argmin(abs(wl - 14.99))
            if abs(wl[at15] - 14.99) < 0.05:
                print(f"     CO2 band centre {wl[at15]:.2f} um: T_out {T[at15]:.1e}, path brightness "
                      f"{C2 / (wl[at15] * np.log1p(C1 / (wl[at15] ** 5 * L[at15]))):.1f} K")

    vis = data["Sensor_0p3_1um"]
    # 2. T_out at 0.55 um against LOWTRAN 7.
    wl, T = vis["wavelength_um"], vis["transmittance"]
    t055 = T[(wl > 0.549) & (wl < 0.551)].mean()
    lowtran = 0.882 * np.exp(-0.324)
    check(abs(t055 - lowtran) < 0.02, f"T_out(0.55 um) {t055:.4f} vs LOWTRAN 7 {lowtran:.4f} (+-0.02)")
    # 6. Scatter falls with wavelength in the visible.
    means = [vis["path_scatter"][(wl > a) & (wl < a + 0.05)].mean() for a in np.arange(0.45, 0.9, 0.05)]
    check(all(a > b for a, b in zip(means, means[1:])),
          "path scatter's 50 nm means fall from 0.45 to 0.9 um: " + ", ".join(f"{m:.3g}" for m in means))
    if failures:
        sys.exit("FAILED: " + "; ".join(failures))
    print("passed")


if __name__ == "__main__":
    main()

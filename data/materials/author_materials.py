#!/usr/bin/env python3
"""Writes the authored satellite/vehicle material files into
data/materials/authored/ (committed; CMake copies them into the data folder).
Run by hand after changing a parameter here:

    /usr/bin/python3 data/materials/author_materials.py \
        --e490 /usr/lib/python3/dist-packages/pyspectral/data/e490_00a.dat

Two kinds of material:
 * metals: normal-incidence Fresnel reflectance R = |(N-1)/(N+1)|^2 of the
   Lorentz-Drude dielectric function of Rakic et al., Appl. Opt. 37, 5271
   (1998), parameters as transcribed in github.com/polyanskiy/refractiveindex.info-scripts
   (scripts/"Rakic 1998 - Au|Ag|Al (LD model).py", commit 11e9266533b5710e64b23e832d8d28c8558a61ce);
 * coatings and MLI outer layers: no measured spectrum was available, so the
   SRF is a two-level (solar / thermal-IR) curve whose levels are solved so
   that the E-490-weighted solar absorptance and the 300 K Planck-weighted
   emittance over 0.28-28 um equal published alpha_s / epsilon values.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import eoir_materials as em  # noqa: E402

HC_EV_UM = 1.23984198  # eV um

RAKIC_SCRIPTS = ("Rakic et al., Appl. Opt. 37, 5271-5283 (1998), Lorentz-Drude model; parameters from "
                 "https://github.com/polyanskiy/refractiveindex.info-scripts path 'scripts/Rakic 1998 - {m} (LD model).py' "
                 "commit 11e9266533b5710e64b23e832d8d28c8558a61ce")

# (omega_p eV, [(f, Gamma eV, omega eV)], first entry is the Drude term with omega = 0)
RAKIC_LD = {
    "Au": (9.03, [(0.760, 0.053, 0.0), (0.024, 0.241, 0.415), (0.010, 0.345, 0.830),
                  (0.071, 0.870, 2.969), (0.601, 2.494, 4.304), (4.384, 2.214, 13.32)]),
    "Ag": (9.01, [(0.845, 0.048, 0.0), (0.065, 3.886, 0.816), (0.124, 0.452, 4.481),
                  (0.011, 0.065, 8.185), (0.840, 0.916, 9.083), (5.646, 2.419, 20.29)]),
    "Al": (14.98, [(0.523, 0.047, 0.0), (0.227, 0.333, 0.162), (0.050, 0.312, 1.544),
                   (0.166, 1.351, 1.808), (0.030, 3.382, 3.473)]),
}
RAKIC_VALID_UM = {"Au": (0.248, 6.2), "Ag": (0.248, 12.4), "Al": (0.062, 248.0)}


def rakic_epsilon(metal, wl_um):
    wp, terms = RAKIC_LD[metal]
    w = HC_EV_UM / wl_um
    f0, g0, _ = terms[0]
    eps = 1 - f0 * wp ** 2 / (w * (w + 1j * g0))
    for f, g, w0 in terms[1:]:
        eps = eps + f * wp ** 2 / ((w0 ** 2 - w ** 2) - 1j * w * g)
    return eps


def normal_reflectance(eps):
    n = np.sqrt(eps)
    return np.abs((n - 1) / (n + 1)) ** 2


def smoothstep(x, x0, x1):
    t = np.clip((x - x0) / (x1 - x0), 0.0, 1.0)
    return t * t * (3 - 2 * t)


def two_level(grid, solar_w, ir_w, alpha_s, eps_h, ir_from, ir_to, solar_shape=None):
    """SRF = Rs * shape(l) * (1 - t(l)) + Rir * t(l); t rises from 0 at ir_from
    to 1 at ir_to (log-wavelength smoothstep). Rs, Rir solved from alpha, eps."""
    t = smoothstep(np.log(grid), np.log(ir_from), np.log(ir_to))
    shape = np.ones_like(grid) if solar_shape is None else solar_shape
    a = shape * (1 - t)
    b = t
    m = np.array([[em.band_mean(grid, a, solar_w), em.band_mean(grid, b, solar_w)],
                  [em.band_mean(grid, a, ir_w), em.band_mean(grid, b, ir_w)]])
    rs, rir = np.linalg.solve(m, [1 - alpha_s, 1 - eps_h])
    srf = rs * a + rir * b
    if srf.min() < -1e-9 or srf.max() > 1 + 1e-9:
        raise SystemExit(f"two-level fit out of [0,1]: Rs={rs:.3f} Rir={rir:.3f}")
    return np.clip(srf, 0, 1), rs, rir


def ramp(grid, x0, x1, low, high=1.0):
    """Relative solar shape: `low` below x0 rising smoothly to `high` at x1."""
    return low + (high - low) * smoothstep(grid, x0, x1)


GILMORE = ("D. G. Gilmore (ed.), Spacecraft Thermal Control Handbook, Vol. I, 2nd ed., "
           "The Aerospace Press 2002, thermo-optical property tables (typical beginning-of-life values)")
FIT_NOTE = ("SRF synthesised, not measured: two reflectance levels (solar, thermal IR) joined by a smooth step, "
            "solved so that 1 - <SRF> weighted by the ASTM E-490 spectrum (0.28-28 um) equals alpha_s and "
            "1 - <SRF> weighted by a 300 K Planck curve (0.28-28 um) equals epsilon; shape features stated per file")

# name: (alpha_s, epsilon, ir_from, ir_to, solar shape builder or None, description, source, shape note, brdf)
COATINGS = {
    "black_thermal_control": (
        0.95, 0.87, 2.0, 4.0, None,
        "Black thermal-control paint (Z306-type black polyurethane): alpha_s 0.95, epsilon 0.87.",
        "alpha_s = 0.95, epsilon = 0.87 for Aeroglaze Z306 black polyurethane, " + GILMORE,
        "flat solar level",
        {"k0": 0.9, "k1": 0.5, "alpha": 2.0, "beta": 2.0,
         "reason": "matte paint: nearly Lambertian, weak broad lobes"}),
    "white_thermal_control": (
        0.17, 0.92, 1.8, 3.5, lambda g: ramp(g, 0.36, 0.41, 0.08),
        "White thermal-control paint (Z93-type zinc oxide / potassium silicate): alpha_s 0.17, epsilon 0.92.",
        "alpha_s = 0.17, epsilon = 0.92 for Z93 (ZnO in potassium silicate), " + GILMORE,
        "ZnO absorption edge: solar level x0.08 below 0.36 um rising to x1 at 0.41 um",
        {"k0": 0.95, "k1": 0.5, "alpha": 2.0, "beta": 2.0,
         "reason": "matte paint: nearly Lambertian"}),
    "gold_mli": (
        0.38, 0.67, 3.0, 6.0, lambda g: ramp(g, 0.45, 0.62, 0.15),
        "Gold-coloured MLI blanket outer layer: aluminised polyimide (Kapton, 25 um) with the polyimide side out; "
        "the polyimide absorption edge near 0.5 um gives the gold colour. alpha_s 0.38, epsilon 0.67.",
        "alpha_s = 0.38, epsilon = 0.67 for 1 mil aluminised Kapton, Kapton side out, " + GILMORE,
        "polyimide edge: solar level x0.15 below 0.45 um rising to x1 at 0.62 um; IR step 3-6 um where polyimide becomes opaque",
        {"k0": 0.3, "k1": 0.1, "alpha": 8.0, "beta": 4.0,
         "reason": "crinkled film: glossy but faceted, so a broad forward lobe plus a diffuse part"}),
    "aluminum_mli": (
        0.12, 0.04, 3.0, 6.0, None,
        "Aluminium-coloured MLI blanket outer layer: vapour-deposited aluminium facing out. alpha_s 0.12, epsilon 0.04.",
        "alpha_s = 0.12, epsilon = 0.04: mid-range of the tabulated values for vapour-deposited aluminium "
        "(alpha_s 0.08-0.17, epsilon 0.03-0.05), " + GILMORE,
        "flat solar and IR levels",
        {"k0": 0.2, "k1": 0.1, "alpha": 10.0, "beta": 4.0,
         "reason": "crinkled metallised film: strong but broadened specular lobe"}),
    "silver_mli": (
        0.08, 0.78, 6.0, 9.0, lambda g: ramp(g, 0.31, 0.36, 0.25),
        "Silver MLI / radiator outer layer: silvered FEP Teflon (second-surface mirror, 127 um FEP). alpha_s 0.08, epsilon 0.78.",
        "alpha_s = 0.08, epsilon = 0.78 for 5 mil silvered FEP Teflon, " + GILMORE,
        "silver plasma edge: solar level x0.25 below 0.31 um rising to x1 at 0.36 um; FEP transparent to ~6 um, opaque from ~9 um (C-F bands)",
        {"k0": 0.15, "k1": 0.05, "alpha": 20.0, "beta": 5.0,
         "reason": "second-surface mirror: mostly specular"}),
    "solar_panel": (
        0.80, 0.82, 2.5, 5.0, lambda g: ramp(g, 1.05, 1.20, 0.35),
        "Solar array front face: silicon cells under cover glass. alpha_s 0.80, epsilon 0.82.",
        "alpha_s = 0.80, epsilon = 0.82: typical values for silicon cells with cover glass "
        "(tabulated alpha_s 0.75-0.82, epsilon 0.80-0.85), " + GILMORE,
        "silicon band gap: solar level x0.35 below 1.05 um (cells absorb) rising to x1 at 1.2 um (sub-band-gap light reflected)",
        {"k0": 0.2, "k1": 0.05, "alpha": 40.0, "beta": 5.0,
         "reason": "cover glass: sharp specular glint over a dark diffuse cell"}),
}

METALS = {
    "aluminum": ("Al", "Aluminium, bare (vehicle skin). SRF = normal-incidence reflectance of evaporated aluminium "
                       "from its optical constants; the same SRF as burnished_aluminum, with a rougher BRDF.",
                 {"k0": 0.3, "k1": 0.1, "alpha": 10.0, "beta": 5.0,
                  "reason": "unpolished metal sheet: broad specular lobe plus a diffuse part"}),
    "burnished_aluminum": ("Al", "Burnished (polished) aluminium. SRF = normal-incidence reflectance of evaporated "
                                 "aluminium from its optical constants (an upper bound for polished bulk metal).",
                           {"k0": 0.05, "k1": 0.05, "alpha": 60.0, "beta": 5.0,
                            "reason": "polished metal: nearly mirror-like, sharp forward lobe"}),
    "gold": ("Au", "Gold (vapour-deposited or plated). SRF = normal-incidence reflectance from optical constants.",
             {"k0": 0.1, "k1": 0.05, "alpha": 30.0, "beta": 5.0,
              "reason": "smooth metal coating: specular"}),
    "silver": ("Ag", "Silver (vapour-deposited or plated). SRF = normal-incidence reflectance from optical constants.",
               {"k0": 0.1, "k1": 0.05, "alpha": 30.0, "beta": 5.0,
                "reason": "smooth metal coating: specular"}),
}


def read_e490(path):
    rows = [tuple(map(float, l.split()[:2])) for l in open(path) if l.strip() and not l.startswith("#")]
    a = np.array(rows)
    return a[:, 0], a[:, 1]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--e490", default="/usr/lib/python3/dist-packages/pyspectral/data/e490_00a.dat")
    p.add_argument("--output-dir", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "authored"))
    args = p.parse_args()

    grid = em.common_grid()
    w, e = read_e490(args.e490)
    solar_w = np.interp(grid, w, e)
    ir_w = em.planck_um(grid, 300.0)

    for name, (metal, desc, brdf) in METALS.items():
        srf = normal_reflectance(rakic_epsilon(metal, grid))
        lo, hi = RAKIC_VALID_UM[metal]
        ext = ("Rakic 1998 fitted the LD model to data over %.3g-%.3g um; beyond that the model (Drude term) is "
               "evaluated as is up to 28 um" % (lo, hi)) if hi < 28 else None
        a_s = 1 - em.band_mean(grid, srf, solar_w)
        eps = 1 - em.band_mean(grid, srf, ir_w)
        doc = em.material_doc(name, desc + f" Derived alpha_s (E-490, 0.28-28 um) = {a_s:.3f}, "
                                           f"epsilon (300 K, 0.28-28 um) = {eps:.3f}.",
                              [RAKIC_SCRIPTS.format(m=metal),
                               "SRF(lambda) = |(N-1)/(N+1)|^2, N = sqrt(eps_LD(lambda)) (normal incidence, air)"],
                              brdf, grid, srf, extension=ext)
        print(f"{name:24s} alpha_s={a_s:.3f} eps={eps:.3f} R(0.55)={np.interp(0.55, grid, srf):.4f}")
        em.write_material(doc, args.output_dir)

    for name, (a_s, eps, ir_from, ir_to, shape_fn, desc, src, shape_note, brdf) in COATINGS.items():
        shape = shape_fn(grid) if shape_fn else None
        srf, rs, rir = two_level(grid, solar_w, ir_w, a_s, eps, ir_from, ir_to, shape)
        chk_a = 1 - em.band_mean(grid, srf, solar_w)
        chk_e = 1 - em.band_mean(grid, srf, ir_w)
        doc = em.material_doc(name, desc,
                              [src, FIT_NOTE + f"; solar level {rs:.4f}, IR level {rir:.4f}, IR step "
                               f"{ir_from}-{ir_to} um; {shape_note}",
                               "solar weighting: ASTM E-490-00a (Debian python3-pyspectral pyspectral/data/e490_00a.dat)"],
                              brdf, grid, srf)
        print(f"{name:24s} alpha_s={chk_a:.3f} eps={chk_e:.3f} Rs={rs:.3f} Rir={rir:.3f}")
        em.write_material(doc, args.output_dir)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Builds the spec's Appendix A land-cover materials (IGBP types 1-18 and the
building blocks Dirt, Fine/Medium/Coarse Snow, Ice) from the base spectra in
data/materials/base/, exactly by the Appendix A combinations:

 * every base spectrum is resampled to the common grid (cell means) inside
   its measured range and has no value outside it;
 * at each wavelength the combination uses the components that have a value
   there, with their fractions re-normalised to sum to 1 ("Where one or more
   datasets lacked values, the remaining dataset contributions are utilized
   with re-normalized fractional contributions");
 * every row's fractions are normalised by their sum (rows 16 and 18 of the
   table sum to 0.9 and 0.75; see README.md);
 * where no component has a value (beyond the libraries' 14-15 um), the last
   provided value is propagated out to 28 um (Appendix A).

A type is written only when every component it names exists (a base file
with that Appendix A name, or a type/block that was itself built), with one
documented exception (MAY_LACK): a component of one library may be absent
when the same row keeps a real spectrum of the same material from the other
library (e.g. USGS:Blue Spruce absent, JHU:Conifer present); the row is then
re-normalised over what it has, as Appendix A does for missing values, and
the file and land_cover_status.txt say so. Types that cannot be built are
listed with the missing components in land_cover_status.txt, which is
always written.

The same run writes the materials derived from these data (spec 4.3.4-4.3.5,
4.1.4.1): the camouflage paints, whose SRF is that of the background they
are meant to match (mixed forest = IGBP 5, soil = the Dirt block, water =
IGBP 17), and the single-spectrum materials of base/ that carry an
`eoir_material:` header instead of `appendix_a_name:` (mars_surface,
lunar_regolith), extended as their header states.

    build_land_cover.py --base-dir data/materials/base --output-dir build/data/materials
"""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import eoir_materials as em  # noqa: E402

# Appendix A table, verbatim (component names as printed).
BLOCKS = {
    "dirt": ("Dirt", [(0.4, "USGS:Rangeland"), (0.3, "JHU:Brown Loamy Fine Sand"),
                      (0.3, "JHU:Light Yellowish Brown Loamy Sand")]),
    "fine_snow": ("Fine Snow", [(0.5, "JHU:Fine Snow"), (0.5, "USGS:Snow 1a")]),
    "medium_snow": ("Medium Snow", [(1.0, "JHU:Medium Snow")]),
    "coarse_snow": ("Coarse Snow", [(0.5, "JHU:Coarse Snow"), (0.5, "USGS:Snow 3")]),
    "ice": ("Ice", [(1.0, "JHU:Ice")]),
}
IGBP = {
    1: ("evergreen_needleleaf_forest", "Evergreen Needle Leaf Forest",
        [(0.4, "JHU:Conifer"), (0.3, "USGS:Blue Spruce"), (0.3, "USGS:Douglas Fir")]),
    2: ("evergreen_broadleaf_forest", "Evergreen Broadleaf Forest", [(1.0, "IGBP:1")]),
    3: ("deciduous_needleleaf_forest", "Deciduous Needle Leaf Forest",
        [(0.4, "JHU:Deciduous"), (0.3, "USGS:Oak"), (0.3, "USGS:Maple")]),
    4: ("deciduous_broadleaf_forest", "Deciduous Broadleaf Forest", [(1.0, "IGBP:3")]),
    5: ("mixed_forest", "Mixed Forest", [(0.5, "IGBP:1"), (0.5, "IGBP:3")]),
    6: ("closed_shrubland", "Closed Shrubland", [(0.1, "IGBP:16"), (0.2, "Dirt"), (0.7, "IGBP:5")]),
    7: ("open_shrubland", "Open Shrubland", [(0.35, "IGBP:16"), (0.25, "Dirt"), (0.4, "IGBP:5")]),
    8: ("woody_savannas", "Woody Savannas", [(0.41, "IGBP:10"), (0.14, "USGS:Rangeland"), (0.45, "IGBP:3")]),
    9: ("savannas", "Savannas", [(0.6, "IGBP:10"), (0.2, "USGS:Rangeland"), (0.2, "IGBP:3")]),
    10: ("grasslands", "Grasslands", [(0.4, "JHU:Green Grass"), (0.3, "USGS:Lawn Grass"), (0.3, "USGS:Dry Grass")]),
    11: ("permanent_wetlands", "Permanent Wetlands", [(0.25, "IGBP:10"), (0.25, "IGBP:17"), (0.5, "USGS:Wet Lands")]),
    12: ("croplands", "Croplands", [(1.0, "IGBP:10")]),
    13: ("urban", "Urban", [(0.1, "Dirt"), (0.1, "IGBP:3"), (0.3, "USGS:Concrete"), (0.3, "USGS:Asphalt"),
                            (0.2, "USGS:Brick")]),
    14: ("cropland_mosaic", "Cropland/Mosaic", [(0.5, "IGBP:12"), (0.5, "IGBP:5")]),
    15: ("snow_and_ice", "Snow and Ice", [(0.25, "Fine Snow"), (0.25, "Medium Snow"), (0.25, "Coarse Snow"),
                                          (0.25, "Ice")]),
    16: ("barren", "Barren", [(0.3, "USGS:Rangeland"), (0.3, "USGS:Hematite Quartz"), (0.3, "JHU:Quartz")]),
    17: ("water_bodies", "Water Bodies", [(0.8, "USGS:Sea Water"), (0.2, "JHU:Sea Water")]),
    18: ("tundra", "Tundra", [(0.25, "IGBP:11"), (0.25, "USGS:Lichen"), (0.125, "IGBP:1"), (0.125, "IGBP:15")]),
}

# BRDF of eq. 1 per built type: natural surfaces are near Lambertian; vegetation
# canopies have a backscatter (hot-spot) lobe; snow/ice a weak forward lobe;
# water a strong, sharp sun-glint lobe.
VEGETATION = {"k0": 0.9, "k1": 0.7, "alpha": 1.0, "beta": 3.0,
              "reason": "canopy: near Lambertian with a backscatter (hot-spot) lobe"}
SOIL = {"k0": 0.9, "k1": 0.6, "alpha": 1.0, "beta": 2.0,
        "reason": "soil/rock/urban: near Lambertian, mild backscatter from shadowing"}
SNOW = {"k0": 0.85, "k1": 0.2, "alpha": 2.0, "beta": 2.0,
        "reason": "snow/ice: near Lambertian with a weak forward-scattering lobe"}
WATER = {"k0": 0.3, "k1": 0.05, "alpha": 30.0, "beta": 2.0,
         "reason": "water: dominated by a sharp specular sun-glint lobe"}
BRDF = {1: VEGETATION, 2: VEGETATION, 3: VEGETATION, 4: VEGETATION, 5: VEGETATION, 6: VEGETATION,
        7: SOIL, 8: VEGETATION, 9: VEGETATION, 10: VEGETATION, 11: VEGETATION, 12: VEGETATION,
        13: SOIL, 14: VEGETATION, 15: SNOW, 16: SOIL, 17: WATER, 18: VEGETATION,
        "dirt": SOIL, "fine_snow": SNOW, "medium_snow": SNOW, "coarse_snow": SNOW, "ice": SNOW}

BLOCK_BY_LABEL = {label: key for key, (label, _) in BLOCKS.items()}

# Components that may be absent, and the component of the same row and the
# same material (from the other library) that must then be present. Only
# same-material pairs are listed: a row never loses its only spectrum of a
# material (wetlands never become grass and water, barren never pure quartz).
MAY_LACK = {
    "USGS:Blue Spruce": ("JHU:Conifer", "conifer"),
    "USGS:Douglas Fir": ("JHU:Conifer", "conifer"),
    "USGS:Oak": ("JHU:Deciduous", "deciduous broadleaf"),
    "USGS:Maple": ("JHU:Deciduous", "deciduous broadleaf"),
    "USGS:Lawn Grass": ("JHU:Green Grass", "green grass"),
    "JHU:Sea Water": ("USGS:Sea Water", "sea water"),
    "USGS:Sea Water": ("JHU:Sea Water", "sea water"),
    "JHU:Fine Snow": ("USGS:Snow 1a", "fine snow"),
    "USGS:Snow 1a": ("JHU:Fine Snow", "fine snow"),
    "JHU:Coarse Snow": ("USGS:Snow 3", "coarse snow"),
    "USGS:Snow 3": ("JHU:Coarse Snow", "coarse snow"),
}

# Camouflage paints (spec 4.3.4-4.3.5): the SRF of the background each is
# meant to match; a matte paint BRDF.
PAINT = {"k0": 0.95, "k1": 0.5, "alpha": 2.0, "beta": 2.0,
         "reason": "matte camouflage paint: near Lambertian (README: paints k0 0.9-0.95, alpha = beta = 2)"}
CAMOUFLAGE = {
    "mixed_forest_camouflage": (5, "Mixed Forest (IGBP 5)"),
    "soil_camouflage": ("dirt", "the Appendix A Dirt block"),
    "water_camouflage": (17, "Water Bodies (IGBP 17)"),
}


def file_name(key):
    if isinstance(key, int):
        return f"igbp_{key:02d}_{IGBP[key][0]}"
    return key


def component_key(name):
    """'IGBP:5' -> 5, 'Dirt' -> 'dirt', 'JHU:Conifer' -> ('base', 'JHU:Conifer')."""
    if name.startswith("IGBP:"):
        return int(name.split(":")[1])
    if name in BLOCK_BY_LABEL:
        return BLOCK_BY_LABEL[name]
    return ("base", name)


def recipe(key):
    return BLOCKS[key][1] if isinstance(key, str) else IGBP[key][2]


def build_order():
    """Topological order of blocks and IGBP types (rows reference other rows)."""
    order, state = [], {}

    def visit(k):
        if state.get(k) == 2:
            return
        if state.get(k) == 1:
            raise SystemExit(f"cycle in Appendix A table at {k}")
        state[k] = 1
        for _, comp in recipe(k):
            ck = component_key(comp)
            if not isinstance(ck, tuple):
                visit(ck)
        state[k] = 2
        order.append(k)

    for k in list(BLOCKS) + list(IGBP):
        visit(k)
    return order


def combine(parts, grid):
    """parts: list of (fraction, values-with-NaN). Re-normalised where values lack."""
    num = np.zeros(grid.shape)
    den = np.zeros(grid.shape)
    for f, v in parts:
        ok = ~np.isnan(v)
        num[ok] += f * v[ok]
        den[ok] += f
    out = np.full(grid.shape, np.nan)
    has = den > 0
    out[has] = num[has] / den[has]
    return out


def base_source(meta, w, path):
    src = f"{meta.get('library', '?')}; file {meta.get('library_file', '?')}"
    if meta.get("copied_from"):
        src += f"; copied from {meta['copied_from']}"
    if meta.get("substitute"):
        src += f"; substitute: {meta['substitute']}"
    return src + f"; data/materials/base/{os.path.basename(path)}; measured {w[0]:g}-{w[-1]:g} um"


def load_base(base_dir, grid):
    spectra, sources = {}, {}
    for path in sorted(glob.glob(os.path.join(base_dir, "*.txt"))):
        meta, w, r = em.read_base(path)
        name = meta.get("appendix_a_name")
        if not name and meta.get("eoir_material"):
            continue  # a single-spectrum material, see build_single()
        if not name:
            raise SystemExit(f"{path}: no 'appendix_a_name:' or 'eoir_material:' header line")
        if name in spectra:
            raise SystemExit(f"{path}: second base spectrum for {name}")
        spectra[name] = em.resample(w, r, grid)
        sources[name] = f"{name}: " + base_source(meta, w, path)
    return spectra, sources


def build_single(path, grid):
    """A base file with an 'eoir_material:' header is one material. Header keys:
    scale_at_um / scale_to (optional): multiply so that the resampled SRF at
    that wavelength equals the value; thermal_reflectance / thermal_from_um:
    Appendix A's 'forced to some low value' -- beyond the last measured
    wavelength the SRF goes linearly to thermal_reflectance at thermal_from_um
    and stays there to 28 um; brdf_k0, brdf_k1, brdf_alpha, brdf_beta (or
    brdf_model: lunar_lommel_seeliger), brdf_reason; description. Before the first measured wavelength the first
    value is propagated."""
    meta, w, r = em.read_base(path)
    values = em.resample(w, r, grid)
    notes = []
    if meta.get("scale_at_um"):
        at, to = float(meta["scale_at_um"]), float(meta["scale_to"])
        k = to / float(np.interp(at, grid[~np.isnan(values)], values[~np.isnan(values)]))
        values = values * k
        notes.append(f"scaled by {k:.4f} so that SRF({at:g} um) = {to:g} ({meta.get('scale_reason', '')})")
    ok = ~np.isnan(values)
    last = np.flatnonzero(ok)[-1]
    low, lam = float(meta["thermal_reflectance"]), float(meta["thermal_from_um"])
    for i in range(last + 1, grid.size):
        t = min(1.0, (grid[i] - grid[last]) / (lam - grid[last])) if lam > grid[last] else 1.0
        values[i] = values[last] + t * (low - values[last])
    values = em.extend(values)  # only the leading gap is left
    ext = (f"first value propagated back to 0.28 um; from the last measured value at {grid[last]:g} um "
           f"linearly to {low:g} at {lam:g} um and constant to 28 um (Appendix A: 'forced to some low value'; "
           f"{meta.get('thermal_reason', '')})")
    if meta.get("brdf_model"):  # a named law without parameters (the engine's lunar surface)
        brdf = {"model": meta["brdf_model"], "reason": meta["brdf_reason"]}
    else:
        brdf = {"k0": float(meta["brdf_k0"]), "k1": float(meta["brdf_k1"]), "alpha": float(meta["brdf_alpha"]),
                "beta": float(meta["brdf_beta"]), "reason": meta["brdf_reason"]}
    srcs = [base_source(meta, w, path)] + [s for s in (meta.get("source_2"), meta.get("source_3")) if s]
    desc = meta.get("description", "") + ("" if not notes else " " + "; ".join(notes) + ".")
    return em.material_doc(meta["eoir_material"], desc, srcs, brdf, grid, values, extension=ext)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--base-dir", default=os.path.join(here, "base"))
    p.add_argument("--output-dir", required=True)
    args = p.parse_args()

    grid = em.common_grid()
    base, base_sources = load_base(args.base_dir, grid)
    built = {}        # key -> (values with NaN before extension, sources)
    status = []
    for key in build_order():
        rows = recipe(key)
        total = sum(f for f, _ in rows)
        missing, parts, srcs, lacking = [], [], [], []
        for f, comp in rows:
            ck = component_key(comp)
            if isinstance(ck, tuple):
                if comp not in base:
                    partner = MAY_LACK.get(comp)
                    if partner and partner[0] in base and any(c == partner[0] for _, c in rows):
                        lacking.append(f"{comp} (not found; the row keeps {partner[0]}, {partner[1]})")
                    else:
                        missing.append(comp)
                    continue
                parts.append((f / total, base[comp]))
                srcs.append(base_sources[comp])
            else:
                if ck not in built:
                    missing.append(comp)
                    continue
                parts.append((f / total, built[ck][0]))
                srcs.extend(s for s in built[ck][1] if s not in srcs)
        label = BLOCKS[key][0] if isinstance(key, str) else f"IGBP {key} {IGBP[key][1]}"
        formula = " + ".join(f"{f:g}*{c}" for f, c in rows)
        if missing:
            status.append(f"NOT BUILT  {file_name(key)}  ({label} = {formula}); missing: {', '.join(missing)}")
            continue
        values = combine(parts, grid)
        built[key] = (values, srcs)
        extended = em.extend(values)
        norm = "" if abs(total - 1) < 1e-9 else f" The printed fractions sum to {total:g}; they were divided by {total:g}."
        lack = ""
        if lacking:
            lack = (" Components lacking, the others re-normalised at every wavelength (Appendix A): "
                    + "; ".join(lacking) + ".")
        desc = (f"Appendix A land cover: {label} = {formula}.{norm}{lack} Built by data/materials/build_land_cover.py.")
        doc = em.material_doc(
            file_name(key), desc, ["spec Appendix A (STK EOIR Model Description and Validation)"] + srcs,
            BRDF[key], grid, extended,
            extension="components re-normalised where some lack values; where none has a value the nearest "
                      "provided value is propagated (to 0.28 um and out to 28 um)",
            composition=[{"component": c, "fraction": round(f / total, 6)} for f, c in rows])
        em.write_material(doc, args.output_dir)
        status.append(f"built      {file_name(key)}  ({label} = {formula})"
                      + (f"; renormalised without: {'; '.join(lacking)}" if lacking else ""))

    for name, (key, label) in CAMOUFLAGE.items():
        if key not in built:
            status.append(f"NOT BUILT  {name}  (SRF of {label}); missing: {file_name(key)}")
            continue
        doc = em.material_doc(
            name, f"Camouflage paint meant to match {label} (spec 4.3.4-4.3.5): its SRF is that of "
                  f"{file_name(key)} as built here (no measured camouflage-paint spectrum was found). "
                  "Built by data/materials/build_land_cover.py.",
            ["spec 4.3.4-4.3.5 (camouflage materials), Appendix A"] + built[key][1], PAINT, grid,
            em.extend(built[key][0]), extension=f"as {file_name(key)}")
        em.write_material(doc, args.output_dir)
        status.append(f"built      {name}  (SRF of {label})")

    for path in sorted(glob.glob(os.path.join(args.base_dir, "*.txt"))):
        meta, _, _ = em.read_base(path)
        if meta.get("eoir_material") and not meta.get("appendix_a_name"):
            doc = build_single(path, grid)
            em.write_material(doc, args.output_dir)
            status.append(f"built      {doc['name']}  (single spectrum, base/{os.path.basename(path)})")

    os.makedirs(args.output_dir, exist_ok=True)
    with open(os.path.join(args.output_dir, "land_cover_status.txt"), "w", encoding="utf-8") as f:
        f.write("# Appendix A land cover built by data/materials/build_land_cover.py\n")
        f.write("# base spectra available: " + ", ".join(sorted(base)) + "\n")
        f.write("\n".join(status) + "\n")
    nb = sum(1 for s in status if s.startswith("built"))
    print(f"build_land_cover: {nb} of {len(status)} materials built "
          f"({len(base)} base spectra); see land_cover_status.txt")
    return 0


if __name__ == "__main__":
    sys.exit(main())

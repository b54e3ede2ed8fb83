"""Shared helpers for the material data: the common wavelength grid, reading
base spectra, resampling, writing eoir-material JSON files.

Common grid "eoir-grid-1" (see README.md):
  0.28-2.50 um in 0.01 um steps, 2.55-15.00 um in 0.05 um steps,
  15.1-28.0 um in 0.1 um steps (603 points).
Only numpy and the standard library are used.
"""
import json
import math
import os

import numpy as np

GRID_ID = "eoir-grid-1"
_trapz = getattr(np, "trapezoid", None) or np.trapz  # numpy 2 renamed trapz


def common_grid():
    a = [round(0.28 + 0.01 * i, 4) for i in range(223)]          # 0.28 .. 2.50
    b = [round(2.50 + 0.05 * i, 4) for i in range(1, 251)]       # 2.55 .. 15.00
    c = [round(15.0 + 0.1 * i, 4) for i in range(1, 131)]        # 15.1 .. 28.0
    g = np.array(a + b + c)
    assert g[0] == 0.28 and g[-1] == 28.0 and np.all(np.diff(g) > 0)
    return g


def cell_edges(grid):
    """Edges of the cell around every grid point (midpoints between points)."""
    mid = 0.5 * (grid[1:] + grid[:-1])
    return np.concatenate([[grid[0] - (mid[0] - grid[0])], mid, [grid[-1] + (grid[-1] - mid[-1])]])


def read_base(path):
    """A base spectrum file: '#' header with 'key: value' lines, then two
    columns wavelength, reflectance. Returns (meta, wavelength_um, reflectance
    as a fraction), sorted by wavelength."""
    meta, rows = {}, []
    with open(path, encoding="utf-8") as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                body = s[1:].strip()
                if ":" in body:
                    k, v = body.split(":", 1)
                    meta.setdefault(k.strip(), v.strip())
                continue
            x, y = s.split()[:2]
            rows.append((float(x), float(y)))
    a = np.array(sorted(rows))
    w, r = a[:, 0], a[:, 1]
    if meta.get("x_units", "um") == "nm":
        w = w / 1000.0
    if meta.get("y_units", "fraction") == "percent":
        r = r / 100.0
    if np.any(np.diff(w) <= 0):
        raise ValueError(f"{path}: duplicate wavelengths")
    return meta, w, r


def resample(w, r, grid):
    """Mean of the (linearly interpolated) source spectrum over each grid
    cell; NaN where the cell centre lies outside the measured range. Source
    values outside [0, 1] (instrument noise) are clipped."""
    edges = cell_edges(grid)
    out = np.full(grid.shape, np.nan)
    for i, x in enumerate(grid):
        if x < w[0] or x > w[-1]:
            continue
        lo, hi = max(edges[i], w[0]), min(edges[i + 1], w[-1])
        xs = np.linspace(lo, hi, 21)
        out[i] = float(np.mean(np.interp(xs, w, r)))
    return np.clip(out, 0.0, 1.0, where=~np.isnan(out), out=out)


def extend(values):
    """Appendix A: 'the last provided value is ... propagated out to 28.0 um'.
    Leading and trailing gaps take the nearest provided value; interior gaps
    (none expected) are linearly interpolated."""
    v = np.array(values, dtype=float)
    ok = ~np.isnan(v)
    if not ok.any():
        raise ValueError("no values to extend")
    idx = np.arange(v.size)
    return np.interp(idx, idx[ok], v[ok])


def material_doc(name, description, sources, brdf, grid, reflectance, extension=None, composition=None):
    doc = {
        "format": "eoir-material",
        "version": 1,
        "name": name,
        "description": description,
        "sources": list(sources),
        "brdf": dict(brdf),
        "grid": GRID_ID,
    }
    if extension:
        doc["extension"] = extension
    if composition:
        doc["composition"] = composition
    doc["wavelength_um"] = [float(f"{x:.4f}") for x in grid]
    doc["reflectance"] = [float(f"{min(max(y, 0.0), 1.0):.5f}") for y in reflectance]
    return doc


def write_material(doc, directory):
    os.makedirs(directory, exist_ok=True)
    path = os.path.join(directory, doc["name"] + ".json")
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8", newline="\n") as f:
        # one key per line, arrays on one line each: small diffs, easy to read
        f.write("{\n")
        items = list(doc.items())
        for i, (k, v) in enumerate(items):
            f.write(f"  {json.dumps(k)}: {json.dumps(v, ensure_ascii=False)}")
            f.write(",\n" if i + 1 < len(items) else "\n")
        f.write("}\n")
    os.replace(tmp, path)
    return path


def planck_um(wl_um, temperature_k):
    """Blackbody spectral radiance, arbitrary units (shape only)."""
    c2 = 14387.77  # um K
    x = c2 / (wl_um * temperature_k)
    return 1.0 / (wl_um ** 5 * np.expm1(x))


def band_mean(grid, values, weight):
    return float(_trapz(values * weight, grid) / _trapz(weight, grid))

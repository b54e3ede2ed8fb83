"""Checks of the material and solar data (pytest).

    /usr/bin/python3 -m pytest -q data/materials/test_materials.py

The data folder checked is $EOIR_DATA_DIR, default <repo>/build/data (run
`cmake --build build --target eoir_data` first). Needs python3-numpy,
python3-jsonschema, python3-pytest.
"""
import glob
import json
import os
import subprocess
import sys

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import eoir_materials as em  # noqa: E402
import build_land_cover as blc  # noqa: E402

DATA = os.environ.get("EOIR_DATA_DIR", os.path.join(REPO, "build", "data"))
MAT = os.path.join(DATA, "materials")
SCHEMA = os.path.join(REPO, "schemas", "material.schema.json")
GRID = em.common_grid()

import jsonschema  # noqa: E402  (python3-jsonschema, installed by .ci/setup)


def material_files():
    return sorted(glob.glob(os.path.join(MAT, "*.json")))


def load(name):
    path = os.path.join(MAT, name + ".json")
    assert os.path.exists(path), f"{name}.json missing from the data folder: build the eoir_data target (.ci/setup)"
    with open(path) as f:
        d = json.load(f)
    return np.array(d["wavelength_um"]), np.array(d["reflectance"]), d


def at(name, lo, hi):
    w, r, _ = load(name)
    sel = (w >= lo) & (w <= hi)
    return r[sel]


def test_data_folder_built():
    assert os.path.isdir(MAT), f"{MAT} missing: build the eoir_data target first"
    assert len(material_files()) >= 10


@pytest.mark.parametrize("path", material_files(), ids=os.path.basename)
def test_schema_and_grid(path):
    schema = json.load(open(SCHEMA))
    with open(path) as f:
        doc = json.load(f)
    jsonschema.Draft202012Validator(schema).validate(doc)
    w = np.array(doc["wavelength_um"])
    r = np.array(doc["reflectance"])
    assert doc["name"] + ".json" == os.path.basename(path)
    assert w.size == r.size
    assert np.all(np.diff(w) > 0), "wavelengths must increase strictly"
    assert w[0] <= 0.28 and w[-1] >= 28.0
    assert np.allclose(w, GRID, atol=1e-9), "not on the common grid eoir-grid-1"
    assert doc.get("grid") == em.GRID_ID
    assert np.all((r >= 0) & (r <= 1)) and np.all(np.isfinite(r))


def test_authored_files_match_generator(tmp_path):
    """The committed authored/*.json are what author_materials.py writes."""
    e490 = "/usr/lib/python3/dist-packages/pyspectral/data/e490_00a.dat"
    assert os.path.exists(e490), f"{e490} missing: python3-pyspectral is installed by .ci/setup"
    subprocess.run([sys.executable, os.path.join(HERE, "author_materials.py"), "--e490", e490,
                    "--output-dir", str(tmp_path)], check=True, capture_output=True)
    for path in glob.glob(os.path.join(HERE, "authored", "*.json")):
        assert json.load(open(path)) == json.load(open(tmp_path / os.path.basename(path))), path


# ---- Appendix A combination logic, checked on a complete synthetic base set ----

def _write_base(directory, name, w, r):
    fname = name.replace(":", "_").replace(" ", "_").lower() + ".txt"
    with open(os.path.join(directory, fname), "w") as f:
        f.write(f"# appendix_a_name: {name}\n# library: synthetic test fixture\n# x_units: um\n# y_units: fraction\n")
        for x, y in zip(w, r):
            f.write(f"{x} {y}\n")


@pytest.fixture(scope="module")
def synthetic(tmp_path_factory):
    base = tmp_path_factory.mktemp("base")
    out = tmp_path_factory.mktemp("out")
    names = sorted({c for _, rows in blc.BLOCKS.values() for _, c in rows if ":" in c} |
                   {c for _, _, rows in blc.IGBP.values() for _, c in rows if ":" in c and not c.startswith("IGBP:")})
    assert len(names) == 27
    values = {}
    for i, n in enumerate(names):
        # distinct smooth spectra; USGS ones stop at 2.5 um (as splib07 Beckman/ASD), JHU at 14 um
        stop = 2.5 if n.startswith("USGS:") else 14.0
        w = np.linspace(0.3, stop, 400)
        r = 0.05 + 0.02 * i + 0.01 * np.sin(w * (i + 1))
        _write_base(base, n, w, r)
        values[n] = em.resample(w, r, GRID)
    subprocess.run([sys.executable, os.path.join(HERE, "build_land_cover.py"), "--base-dir", str(base),
                    "--output-dir", str(out)], check=True, capture_output=True)
    return out, values


def _read(out, name):
    return np.array(json.load(open(os.path.join(out, name + ".json")))["reflectance"])


def _renorm(pairs):
    """Independent re-implementation: per wavelength, mean of available
    components weighted by re-normalised fractions."""
    w = np.array([p[0] for p in pairs], dtype=float)
    v = np.vstack([p[1] for p in pairs])
    ok = ~np.isnan(v)
    num = np.nansum(v * w[:, None], axis=0)
    den = (ok * w[:, None]).sum(axis=0)
    res = np.where(den > 0, num / np.where(den > 0, den, 1), np.nan)
    idx = np.arange(res.size)
    good = ~np.isnan(res)
    return np.interp(idx, idx[good], res[good])


def test_all_23_built_from_complete_set(synthetic):
    out, _ = synthetic
    for k in list(blc.BLOCKS) + list(blc.IGBP):
        assert os.path.exists(os.path.join(out, blc.file_name(k) + ".json")), k


def test_igbp10_grasslands_renormalised_where_usgs_lacks(synthetic):
    out, v = synthetic
    expect = _renorm([(0.4, v["JHU:Green Grass"]), (0.3, v["USGS:Lawn Grass"]), (0.3, v["USGS:Dry Grass"])])
    got = _read(out, "igbp_10_grasslands")
    assert np.allclose(got, expect, atol=1e-5)
    # beyond 2.5 um only the JHU spectrum is left: the result is that spectrum
    sel = (GRID > 2.6) & (GRID < 14)
    assert np.allclose(got[sel], v["JHU:Green Grass"][sel], atol=1e-5)


def test_igbp18_tundra_chain_and_row_sum(synthetic):
    out, v = synthetic
    raw = {}

    def c(pairs):
        w = np.array([p[0] for p in pairs], dtype=float)
        vv = np.vstack([p[1] for p in pairs])
        ok = ~np.isnan(vv)
        den = (ok * w[:, None]).sum(axis=0)
        return np.where(den > 0, np.nansum(vv * w[:, None], axis=0) / np.where(den > 0, den, 1), np.nan)

    raw[1] = c([(0.4, v["JHU:Conifer"]), (0.3, v["USGS:Blue Spruce"]), (0.3, v["USGS:Douglas Fir"])])
    raw[10] = c([(0.4, v["JHU:Green Grass"]), (0.3, v["USGS:Lawn Grass"]), (0.3, v["USGS:Dry Grass"])])
    raw[17] = c([(0.8, v["USGS:Sea Water"]), (0.2, v["JHU:Sea Water"])])
    raw[11] = c([(0.25, raw[10]), (0.25, raw[17]), (0.5, v["USGS:Wet Lands"])])
    fine = c([(0.5, v["JHU:Fine Snow"]), (0.5, v["USGS:Snow 1a"])])
    coarse = c([(0.5, v["JHU:Coarse Snow"]), (0.5, v["USGS:Snow 3"])])
    raw[15] = c([(0.25, fine), (0.25, v["JHU:Medium Snow"]), (0.25, coarse), (0.25, v["JHU:Ice"])])
    # printed fractions 0.25/0.25/0.125/0.125 sum to 0.75: renormalised
    expect = _renorm([(0.25 / 0.75, raw[11]), (0.25 / 0.75, v["USGS:Lichen"]),
                      (0.125 / 0.75, raw[1]), (0.125 / 0.75, raw[15])])
    assert np.allclose(_read(out, "igbp_18_tundra"), expect, atol=1e-5)


def test_missing_component_is_reported_not_invented(tmp_path):
    """A row that lacks its only spectrum of a material is not built (wetlands
    are never made of grass and water alone); a USGS component without its
    JHU counterpart does not stand for the row."""
    base, out = tmp_path / "b", tmp_path / "o"
    base.mkdir()
    _write_base(base, "USGS:Blue Spruce", [0.3, 2.5], [0.1, 0.05])
    _write_base(base, "JHU:Green Grass", [0.3, 14.0], [0.1, 0.01])
    _write_base(base, "USGS:Sea Water", [0.3, 2.5], [0.05, 0.01])
    subprocess.run([sys.executable, os.path.join(HERE, "build_land_cover.py"), "--base-dir", str(base),
                    "--output-dir", str(out)], check=True, capture_output=True)
    assert not (out / "igbp_01_evergreen_needleleaf_forest.json").exists()
    assert not (out / "igbp_11_permanent_wetlands.json").exists()
    status = (out / "land_cover_status.txt").read_text()
    assert "missing: JHU:Conifer, USGS:Douglas Fir" in status
    wet = [line for line in status.splitlines() if "igbp_11_permanent_wetlands" in line][0]
    assert wet.startswith("NOT BUILT") and "USGS:Wet Lands" in wet.split("missing:")[1]


def test_same_material_renormalisation(tmp_path):
    """JHU:Conifer alone builds IGBP 1 (Blue Spruce and Douglas Fir lacking,
    Appendix A re-normalisation), and the file says so."""
    base, out = tmp_path / "b", tmp_path / "o"
    base.mkdir()
    w = np.linspace(0.3, 14.0, 300)
    r = 0.05 + 0.3 * np.exp(-((w - 1.0) / 0.4) ** 2)
    _write_base(base, "JHU:Conifer", w, r)
    subprocess.run([sys.executable, os.path.join(HERE, "build_land_cover.py"), "--base-dir", str(base),
                    "--output-dir", str(out)], check=True, capture_output=True)
    got = _read(out, "igbp_01_evergreen_needleleaf_forest")
    expect = _renorm([(0.4, em.resample(w, r, GRID))])
    assert np.allclose(got, expect, atol=1e-5)
    doc = json.load(open(out / "igbp_01_evergreen_needleleaf_forest.json"))
    assert "USGS:Blue Spruce (not found" in doc["description"]
    assert "renormalised without: USGS:Blue Spruce" in (out / "land_cover_status.txt").read_text()


def test_camouflage_is_its_background(synthetic):
    out, _ = synthetic
    for name, key in (("mixed_forest_camouflage", "igbp_05_mixed_forest"), ("water_camouflage", "igbp_17_water_bodies"),
                      ("soil_camouflage", "dirt")):
        assert np.allclose(_read(out, name), _read(out, key), atol=1e-9), name
        assert json.load(open(os.path.join(out, name + ".json")))["brdf"]["k0"] >= 0.9


# ---- physical sanity values ----

def test_aluminium_visible():
    # Rakic (1995) tabulated n,k of evaporated Al at 0.5636 um: n=1.0728, k=6.7839 -> R = 0.9148;
    # the CRC/Palik tables give R ~ 0.915-0.92 at 0.55 um.
    r = at("aluminum", 0.55, 0.55)[0]
    assert 0.905 <= r <= 0.925


def test_gold_blue_low_ir_high():
    # gold: interband absorption below ~0.5 um (R ~ 0.35-0.45 at 0.45 um), Drude metal in the IR (R > 0.97)
    assert at("gold", 0.44, 0.46).max() < 0.5
    assert at("gold", 2.0, 28.0).min() > 0.95


def test_silver_visible_high():
    # measured films reach ~0.97 at 0.5 um; the Rakic 1998 LD fit gives 0.941 there and 0.969 at 0.7 um
    assert at("silver", 0.5, 0.7).min() > 0.93
    assert at("silver", 0.7, 0.7)[0] > 0.96


@pytest.mark.parametrize("name,alpha_s,eps", [
    ("black_thermal_control", 0.95, 0.87), ("white_thermal_control", 0.17, 0.92),
    ("gold_mli", 0.38, 0.67), ("aluminum_mli", 0.12, 0.04), ("silver_mli", 0.08, 0.78),
    ("solar_panel", 0.80, 0.82)])
def test_coating_alpha_epsilon(name, alpha_s, eps):
    # published alpha_s / epsilon (Gilmore 2002 tables, see README) reproduced within 0.005
    w, r, _ = load(name)
    sol = os.path.join(DATA, "solar", "e490.txt")
    e = np.loadtxt(sol)
    solar = np.interp(w, e[:, 0], e[:, 1])
    assert abs((1 - em.band_mean(w, r, solar)) - alpha_s) < 0.005
    assert abs((1 - em.band_mean(w, r, em.planck_um(w, 300.0))) - eps) < 0.005


def _base(fname):
    _, w, r = em.read_base(os.path.join(HERE, "base", fname))
    return em.resample(w, r, GRID)


def _base_at(fname, lo, hi):
    v = _base(fname)
    return v[(GRID >= lo) & (GRID <= hi)]


def test_fresh_snow_base_spectra():
    # Fresh dry snow: visible reflectance 0.95-0.99 (> 0.8), ice absorption bands bring it to a few per cent
    # near 1.5 and 2.0 um (< 0.1), the more so the larger the grains (Warren 1982, Rev. Geophys. 20, 67, fig. 7;
    # Wiscombe & Warren 1980). JHU fine (24 um), medium (82 um) and coarse (178 um) granular snow.
    grains = ("jhu_fine_snow.txt", "jhu_medium_snow.txt", "jhu_coarse_snow.txt")
    for f in grains:
        assert _base_at(f, 0.4, 0.7).mean() > 0.9, f
        assert _base_at(f, 1.49, 1.51).mean() < 0.1, f
        assert _base_at(f, 1.99, 2.01).mean() < 0.1, f
    nir = [_base_at(f, 0.8, 1.3).mean() for f in grains]
    assert nir[0] > nir[1] > nir[2], "NIR reflectance must fall with grain size (Warren 1982)"


def test_ice_darker_than_snow():
    # Solid clear ice reflects only at its surface: Fresnel R = ((n-1)/(n+1))^2 = 0.018 for n = 1.31
    # (Warren & Brandt 2008, J. Geophys. Res. 113, D14220); far darker than any snow in the NIR.
    assert abs(_base_at("jhu_ice.txt", 0.4, 0.7).mean() - 0.018) < 0.006
    ice = at("ice", 0.8, 1.3).mean()
    for n in ("fine_snow", "medium_snow", "coarse_snow"):
        assert at(n, 0.8, 1.3).mean() > 10 * ice, n


def test_snow_blocks_in_the_absorption_bands():
    # every snow block (JHU and, where Appendix A names it, USGS melting snow) < 0.1 near 1.5 and 2.0 um
    for n in ("fine_snow", "medium_snow", "coarse_snow", "igbp_15_snow_and_ice"):
        assert at(n, 1.49, 1.51).mean() < 0.1, n
        assert at(n, 1.99, 2.01).mean() < 0.1, n
    assert at("medium_snow", 0.4, 0.7).mean() > 0.8


def test_igbp15_snow_and_ice_from_the_base_spectra():
    """Recomputed from the committed base files: Fine Snow = 0.5 JHU fine + 0.5 USGS Snow 1a, Medium Snow = JHU
    medium, Coarse Snow = 0.5 JHU coarse + 0.5 USGS Snow 3 (re-normalised over what exists), Ice = JHU ice,
    IGBP 15 = a quarter of each block, extended by the last value. A quarter is clear ice (~0.02) and part
    of the snow is melting laboratory snow (~0.55 in the visible), so IGBP 15 is darker in the visible (~0.6-0.8)
    than fresh snow (> 0.9): that is the Appendix A definition, not a defect of the data."""
    def have(f):
        return os.path.exists(os.path.join(HERE, "base", f))

    def raw(pairs):
        w = np.array([p[0] for p in pairs], dtype=float)
        v = np.vstack([p[1] for p in pairs])
        ok = ~np.isnan(v)
        den = (ok * w[:, None]).sum(axis=0)
        return np.where(den > 0, np.nansum(v * w[:, None], axis=0) / np.where(den > 0, den, 1), np.nan)

    fine = raw([(0.5, _base("jhu_fine_snow.txt"))] + ([(0.5, _base("usgs_snow_1a.txt"))] if have("usgs_snow_1a.txt") else []))
    coarse = raw([(0.5, _base("jhu_coarse_snow.txt"))] + ([(0.5, _base("usgs_snow_3.txt"))] if have("usgs_snow_3.txt") else []))
    expect = _renorm([(0.25, fine), (0.25, _base("jhu_medium_snow.txt")), (0.25, coarse), (0.25, _base("jhu_ice.txt"))])
    w, r, d = load("igbp_15_snow_and_ice")
    assert np.allclose(r, expect, atol=1e-5)
    assert 0.6 < at("igbp_15_snow_and_ice", 0.4, 0.7).mean() < 0.8
    assert at("igbp_15_snow_and_ice", 8.0, 14.0).max() < 0.06  # emissivity > 0.94 in the thermal infrared


def test_sea_water_visible_dark():
    # water bodies: visible reflectance < 0.1 (no glint)
    assert at("igbp_17_water_bodies", 0.4, 0.7).mean() < 0.1


def test_lunar_regolith_albedo():
    # Moon mean visual geometric albedo 0.12 (NSSDC Moon fact sheet; Lane & Irvine 1973 give
    # normal albedos ~0.1-0.15 over 0.55-0.75 um); red-sloped regolith (Pieters 1999, 62231)
    assert 0.09 <= at("lunar_regolith", 0.54, 0.56).mean() <= 0.15
    assert 0.10 <= at("lunar_regolith", 0.55, 0.75).mean() <= 0.15
    assert at("lunar_regolith", 0.74, 0.76).mean() > at("lunar_regolith", 0.44, 0.46).mean()
    # thermal infrared: emissivity ~0.95 (Vasavada et al. 2012)
    assert abs(at("lunar_regolith", 8.0, 14.0).mean() - 0.05) < 0.01


def test_mars_surface_bright_region():
    # Mars bright regions: R ~0.25-0.35 near 0.7 um, ~0.05-0.1 at 0.45 um, a steep Fe3+ red slope
    # (Mustard & Bell 1994, GRL 21, 353; the analogue JSC Mars-1, Allen et al. 1998)
    r45, r70 = at("mars_surface", 0.44, 0.46).mean(), at("mars_surface", 0.69, 0.71).mean()
    assert 0.2 <= r70 <= 0.35
    assert 0.02 <= r45 <= 0.12
    assert r70 / r45 > 2.5


def test_grasslands_red_edge_and_renormalised_ir():
    # grass: chlorophyll trough at 0.67 um, NIR plateau; beyond 3 um only the JHU grass remains
    w, r, d = load("igbp_10_grasslands")
    assert np.interp(0.67, w, r) < 0.2 < np.interp(0.85, w, r)
    assert "USGS:Lawn Grass (not found" in d["description"]
    assert at("igbp_10_grasslands", 8.0, 14.0).max() < 0.1


def test_base_files_name_their_source():
    for path in glob.glob(os.path.join(HERE, "base", "*.txt")):
        meta, w, r = em.read_base(path)
        assert meta.get("library") and meta.get("library_file") and meta.get("copied_from"), path
        assert " commit " in meta["copied_from"] and meta.get("coverage"), path


def test_igbp05_mixed_forest_from_the_real_base_spectra():
    """Recomputed here from the committed base files: IGBP 1 = JHU conifer (USGS
    conifers lacking), IGBP 3 = JHU deciduous (USGS oak, maple lacking),
    IGBP 5 = 0.5 IGBP 1 + 0.5 IGBP 3, extended by the last value."""
    spec = {}
    for f in ("jhu_conifer.txt", "jhu_deciduous.txt"):
        _, w, r = em.read_base(os.path.join(HERE, "base", f))
        spec[f] = em.resample(w, r, GRID)
    expect = _renorm([(0.5, spec["jhu_conifer.txt"]), (0.5, spec["jhu_deciduous.txt"])])
    w, r, _ = load("igbp_05_mixed_forest")
    assert np.allclose(r, expect, atol=1e-5)


def test_water_bodies_from_usgs_and_jhu_sea_water():
    # IGBP 17 = 0.8 USGS sea water (0.2-3 um) + 0.2 JHU sea water (2.08-14 um), re-normalised where one lacks
    expect = _renorm([(0.8, _base("usgs_sea_water.txt")), (0.2, _base("jhu_sea_water.txt"))])
    assert np.allclose(load("igbp_17_water_bodies")[1], expect, atol=1e-5)
    # liquid water in the thermal infrared: reflectance ~1-4 % (emissivity 0.96-0.99; Salisbury & D'Aria 1992,
    # Remote Sens. Environ. 42, 83), lowest near 11 um
    tir = at("igbp_17_water_bodies", 8.0, 14.0)
    assert 0.005 < tir.min() and tir.max() < 0.04
    assert at("igbp_17_water_bodies", 10.5, 11.5).mean() < at("igbp_17_water_bodies", 13.5, 14.0).mean()


def test_base_spectra_read_back():
    for path in glob.glob(os.path.join(HERE, "base", "*.txt")):
        meta, w, r = em.read_base(path)
        assert (meta.get("appendix_a_name") or meta.get("eoir_material")) and meta.get("copied_from"), path
        assert np.all(np.diff(w) > 0) and 0 <= r.min() and r.max() <= 1


def test_conifer_red_edge():
    # JHU conifer: chlorophyll red trough (~4 % at 0.67 um) and NIR plateau (~50 % at 0.8-0.9 um)
    _, w, r = em.read_base(os.path.join(HERE, "base", "jhu_conifer.txt"))
    assert np.interp(0.67, w, r) < 0.06 and np.interp(0.85, w, r) > 0.45


def test_solar_e490_total():
    sol = os.path.join(DATA, "solar", "e490.txt")
    e = np.loadtxt(sol)
    assert np.all(np.diff(e[:, 0]) > 0)
    total = em._trapz(e[:, 1], e[:, 0]) * 1e4  # W/m^2
    assert abs(total / 1366.1 - 1) < 0.005


def test_object_schema_lists_every_material():
    """schemas/object_properties.schema.json enumerates exactly the data folder's materials (and gray_body)."""
    schema = json.load(open(os.path.join(REPO, "schemas", "object_properties.schema.json")))
    listed = set(schema["properties"]["material"]["enum"])
    built = {os.path.basename(f)[:-5] for f in glob.glob(os.path.join(DATA, "materials", "*.json"))}
    assert listed == built | {"gray_body"}, (sorted(listed - built), sorted(built - listed))

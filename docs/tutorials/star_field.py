"""Tutorial "A surveillance star field, checked with SExtractor and astrometry.net".

Renders one frame of the bundled star-field demo (a GEO camera watching a
satellite among the Tycho-2 stars), then checks it with two tools that know
nothing of the engine: SExtractor (Debian source-extractor) finds the stars
in the noisy image and each detection is matched to the frame's truth, and
astrometry.net (solve-field, with the Tycho-2 index files) solves the plate,
whose WCS is compared with the one the engine wrote. Writes
OUT/star_field.png and OUT/star_field.txt (OUT defaults to
docs/tutorials/results):

    /usr/bin/python3 docs/tutorials/star_field.py [--out OUT]

The eoir CLI is $EOIR_CLI, else build/bin/eoir.
"""
import argparse
import json
import os
import shutil
import subprocess
import tempfile
import warnings

import numpy as np
from astropy.io import fits
from astropy.wcs import WCS, FITSFixedWarning

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
EOIR = os.environ.get("EOIR_CLI") or os.path.join(ROOT, "build", "bin", "eoir")


def render(work):
    """One frame of scenarios/demo/star_field.json with 0.1 mrad of jitter (one
    pixel RMS), which samples the stars as an astronomical camera does."""
    scenario = json.load(open(os.path.join(ROOT, "scenarios", "demo", "star_field.json")))
    scenario.pop("$schema")
    for sensor in scenario["sensors"]:
        sensor["parameters"]["jitter_mrad"] = 0.1
    path = os.path.join(work, "star_field.json")
    json.dump(scenario, open(path, "w"), indent=1)
    subprocess.run([EOIR, "run", path, "--out", work, "--stop", scenario["start"], "--quiet"], check=True)
    frame = json.load(open(os.path.join(work, "summary.json")))["frames"][0]
    return {k: os.path.join(work, v) for k, v in frame["files"].items()}


def sextractor(image, work):
    """Sources above 5 sigma in the noisy electrons: FITS pixel x, y (1-based) and flux."""
    params = os.path.join(work, "columns.param")
    open(params, "w").write("X_IMAGE\nY_IMAGE\nFLUX_AUTO\nFLAGS\n")
    catalogue = os.path.join(work, "sources.txt")
    subprocess.run(["source-extractor", image, "-c", "/usr/share/source-extractor/default.sex", "-CATALOG_NAME", catalogue, "-CATALOG_TYPE", "ASCII",
                    "-PARAMETERS_NAME", params, "-FILTER", "N", "-DETECT_THRESH", "5", "-ANALYSIS_THRESH", "5",
                    "-DETECT_MINAREA", "3", "-VERBOSE_TYPE", "QUIET", "-CHECKIMAGE_TYPE", "NONE"],
                   check=True, cwd=work)
    return np.atleast_2d(np.loadtxt(catalogue))


def solve_field(image, header, work):
    """astrometry.net's plate solution of the noise-free image: its WCS."""
    pixel_arcsec = 3600.0 * np.sqrt(abs(np.linalg.det(WCS(header).pixel_scale_matrix)))
    subprocess.run(["solve-field", image, "--dir", work, "--no-plots", "--overwrite", "--new-fits", "none",
                    "--scale-units", "arcsecperpix", "--scale-low", f"{0.95 * pixel_arcsec:.4f}",
                    "--scale-high", f"{1.05 * pixel_arcsec:.4f}", "--ra", f"{header['CRVAL1']:.6f}",
                    "--dec", f"{header['CRVAL2']:.6f}", "--radius", "5", "--cpulimit", "60",
                    "--crpix-center", "--tweak-order", "1", "--uniformize", "0"],
                   check=True, capture_output=True)
    return WCS(fits.getheader(os.path.join(work, os.path.splitext(os.path.basename(image))[0] + ".wcs"))), \
        pixel_arcsec


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(HERE, "results"))
    out = parser.parse_args().out
    os.makedirs(out, exist_ok=True)
    warnings.simplefilter("ignore", FITSFixedWarning)
    with tempfile.TemporaryDirectory() as work:
        files = render(work)
        truth = json.load(open(files["truth"]))
        stars = [t for t in truth if t["kind"] == "star"]
        electrons = fits.getdata(files["electrons"])
        header = fits.getheader(files["mean_electrons"])

        # 1. SExtractor: each detection against the nearest star or object of the truth.
        sources = sextractor(files["electrons"], work)
        xy_truth = np.array([[t["x_fits"], t["y_fits"]] for t in truth])
        matches = []
        for x, y, flux, flags in sources:
            d = np.hypot(xy_truth[:, 0] - x, xy_truth[:, 1] - y)
            if d.min() < 1.5:
                matches.append((int(d.argmin()), d.min()))
        found = {i for i, _ in matches}
        offsets = np.array([d for _, d in matches])
        v_found = [truth[i]["v_mag"] for i in found if truth[i]["kind"] == "star"]
        v_missed = sorted(t["v_mag"] for i, t in enumerate(truth) if t["kind"] == "star" and i not in found)

        # 2. astrometry.net: the plate solution's centre and scale against the frame's own WCS.
        theirs, pixel_arcsec = solve_field(files["mean_electrons"], header, work)
        ours = WCS(header)
        centre = [[(header["NAXIS1"] + 1) / 2.0, (header["NAXIS2"] + 1) / 2.0]]
        a, b = ours.all_pix2world(centre, 1)[0], theirs.all_pix2world(centre, 1)[0]
        sep_arcsec = 3600.0 * np.degrees(np.arccos(min(1.0, np.sin(np.radians(a[1])) * np.sin(np.radians(b[1])) +
                                                      np.cos(np.radians(a[1])) * np.cos(np.radians(b[1])) *
                                                      np.cos(np.radians(a[0] - b[0])))))

    lines = [
        f"truth: {len(stars)} stars and {len(truth) - len(stars)} object(s) in the field",
        f"SExtractor: {len(sources)} sources above 5 sigma, {len(matches)} within 1.5 pixel of a truth entry "
        f"(median offset {np.median(offsets):.3f} pixel)",
        f"  the faintest star found: V = {max(v_found):.2f}; the brightest missed: "
        f"V = {v_missed[0]:.2f}" if v_missed else "  every star found",
        f"astrometry.net: the plate solution's centre lies {sep_arcsec:.3f} arcsec "
        f"({sep_arcsec / pixel_arcsec:.4f} pixel) from the frame's own WCS",
    ]
    open(os.path.join(out, "star_field.txt"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    lo, hi = np.percentile(electrons, [5, 99.7])
    fig, ax = plt.subplots(figsize=(6, 6), dpi=100)
    ax.imshow(np.clip((electrons - lo) / (hi - lo), 0, 1), cmap="gray", origin="lower")
    ax.scatter([t["x_fits"] - 1 for t in stars], [t["y_fits"] - 1 for t in stars], s=80, facecolors="none",
               edgecolors="tab:blue", linewidths=0.7, label="truth: stars")
    ax.scatter(sources[:, 0] - 1, sources[:, 1] - 1, s=20, marker="+", color="tab:orange", linewidths=0.7,
               label="SExtractor")
    target = [t for t in truth if t["kind"] == "object"]
    ax.scatter([t["x_fits"] - 1 for t in target], [t["y_fits"] - 1 for t in target], s=160, marker="s",
               facecolors="none", edgecolors="tab:red", label="truth: the target")
    ax.legend(loc="upper right", fontsize=7)
    ax.set_axis_off()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "star_field.png"))

    # What the page claims: most stars found where the truth puts them, and the plate within a tenth of a pixel.
    assert len(matches) >= 0.8 * len(sources) and np.median(offsets) < 0.5, lines
    assert sep_arcsec / pixel_arcsec < 0.1, lines


if __name__ == "__main__":
    if shutil.which("source-extractor") is None or shutil.which("solve-field") is None:
        raise SystemExit("needs Debian's source-extractor, astrometry.net and astrometry-data-tycho2-10-19 "
                         "(.ci/setup installs them)")
    main()

#!/usr/bin/env python3
"""A satellite from a 3-D model inspected at close range (issue 22 item 5),
made with the eoir Python package (the library in build/lib, or EOIR_LIBRARY).

The predefined GEO communications satellite (data/satellites/
geo_communications.json, spec 4.3.3: a box bus, radiators, solar-array
wings, reflectors, feeds, a tower) is written as a Wavefront OBJ model by
this script (each primitive triangulated, cylinders and cones with 64
sides; one material group per part, mapped back to the part's material
and temperature with mesh_materials), then seen 40 m away by a 512 x 512,
36 deg visible camera (0.45-0.75 um, smooth mode) in sunlight twice: as the
predefined primitives and as the mesh. mesh_inspection.png shows both and
their difference; mesh_inspection.csv gives the image sums. The mesh's
facets are the only difference: the flat boxes and plates agree to
rounding, the round reflectors and feeds differ at their rims.

    /usr/bin/python3 scenarios/demo/mesh_inspection.py                    # scenarios/demo/results
    /usr/bin/python3 scenarios/demo/mesh_inspection.py --quick --out /tmp/mesh   # 128 x 128 (the test's)
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from demo_support import import_eoir  # noqa: E402

eoir = import_eoir()

SIDES = 64


def rotate(q, v):
    """v turned by the unit quaternion q = (w, x, y, z)."""
    w, x, y, z = q
    u = np.array([x, y, z])
    v = np.asarray(v, dtype=float)
    return v + 2.0 * np.cross(u, np.cross(u, v) + w * v)


def primitive(shape, dims):
    """Vertices and counter-clockwise (outward) triangles of a shape in its
    own frame, as engine/universe/shapes.hpp defines it."""
    if shape == "box":
        hx, hy, hz = (d / 2 for d in dims)
        v = [(sx * hx, sy * hy, sz * hz) for sz in (-1, 1) for sy in (-1, 1) for sx in (-1, 1)]
        f = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4),
             (2, 6, 3), (3, 6, 7), (0, 4, 2), (2, 4, 6), (1, 3, 5), (3, 7, 5)]
        return v, f
    if shape == "plate":  # one open sheet in z = 0
        hx, hy = dims[0] / 2, dims[1] / 2
        return [(-hx, -hy, 0), (hx, -hy, 0), (hx, hy, 0), (-hx, hy, 0)], [(0, 1, 2), (0, 2, 3)]
    if shape in ("cylinder", "cone"):
        r0, length = dims
        r1 = r0 if shape == "cylinder" else 0.0
        h = length / 2
        v, f = [(0, 0, -h)], []
        for k in range(SIDES):
            a = 2 * math.pi * k / SIDES
            v.append((r0 * math.cos(a), r0 * math.sin(a), -h))
        if r1 > 0:
            v.append((0, 0, h))
            for k in range(SIDES):
                a = 2 * math.pi * k / SIDES
                v.append((r1 * math.cos(a), r1 * math.sin(a), h))
        else:
            v.append((0, 0, h))
        top = SIDES + 1
        for k in range(SIDES):
            b0, b1 = 1 + k, 1 + (k + 1) % SIDES
            f.append((0, b1, b0))  # bottom cap, seen from -z
            if r1 > 0:
                t0, t1 = top + 1 + k, top + 1 + (k + 1) % SIDES
                f += [(b0, b1, t1), (b0, t1, t0), (top, t0, t1)]
            else:
                f.append((b0, b1, top))
        return v, f
    raise ValueError(f"no triangulation for shape {shape}")


def write_model(parts, path: Path):
    """The composite's parts as one OBJ; returns mesh_materials for it."""
    lines, materials, base = ["# geo_communications (spec 4.3.3) triangulated by mesh_inspection.py"], {}, 1
    for i, p in enumerate(parts):
        v, f = primitive(p["shape"], p["dimensions_m"])
        q = p.get("orientation_wxyz", [1, 0, 0, 0])
        off = np.array(p.get("offset_m", [0, 0, 0]))
        name = f"part{i}_{p['material']}"
        materials[name] = {"material": p["material"], "temperature_K": p["temperature_K"],
                           "reflectance": p["reflectance"]}
        lines += [f"v {x:.9f} {y:.9f} {z:.9f}" for x, y, z in (rotate(q, pt) + off for pt in v)]
        lines.append(f"usemtl {name}")
        lines += [f"f {a + base} {b + base} {c + base}" for a, b, c in f]
        base += len(v)
    path.write_text("\n".join(lines) + "\n")
    return materials


def render(composite: str, pixels: int) -> np.ndarray:
    e = eoir.Engine()
    e.set_time("2010-03-30T02:25:00Z")  # the Sun near +x J2000
    e.add_object("central_body", "Earth")
    target = np.array([0.0, 42164.2e3, 0.0])
    e.add_object("satellite", "Comsat")
    e.set("Comsat", "shape", "composite")
    e.set("Comsat", "composite", composite)
    e.set_state("Comsat", target, attitude=(0.9238795, 0.0, 0.0, 0.3826834))
    e.add_object("satellite", "Inspector")
    e.set("Inspector", "shape", "none")
    e.set_state("Inspector", target + np.array([30.0, -17.0, 20.0]))
    e.add_sensor("Camera", "Inspector")
    for k, v in {"horizontal_pixels": pixels, "vertical_pixels": pixels, "horizontal_fov_deg": 36.0,
                 "vertical_fov_deg": 36.0, "band_low_um": 0.45, "band_high_um": 0.75, "scene_mode": "smooth",
                 "noise_enabled": False}.items():
        e.set("Camera", k, v)
    e.point_at("Camera", "Comsat")
    e.render("Camera")
    image = e.image("Camera", "scene_radiance")
    e.close()
    return image


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", type=Path, default=HERE / "results")
    ap.add_argument("--quick", action="store_true", help="128 x 128 (the test suite's check)")
    ap.add_argument("--check-ratio", type=float, default=None,
                    help="exit 1 unless the mesh's image sum is the primitives' within this fraction")
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    pixels = 128 if args.quick else 512
    parts = json.loads((REPO / "data" / "satellites" / "geo_communications.json").read_text())["parts"]
    model = args.out / "geo_communications.obj"
    materials = write_model(parts, model)
    as_mesh = json.dumps([{"shape": "mesh", "mesh_file": str(model), "dimensions_m": [1.0],
                           "mesh_materials": materials}])
    images = {"primitives": render("geo_communications", pixels), "mesh": render(as_mesh, pixels)}
    sums = {k: float(v.sum()) for k, v in images.items()}
    triangles = sum(1 for line in model.read_text().splitlines() if line.startswith("f "))
    ratio = sums["mesh"] / sums["primitives"]
    with open(args.out / "mesh_inspection.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["model", "triangles", "radiance_sum_W_cm2_sr", "ratio_to_primitives"])
        w.writerow(["primitives", 0, f"{sums['primitives']:.9e}", "1"])
        w.writerow(["mesh", triangles, f"{sums['mesh']:.9e}", f"{ratio:.6f}"])
    stretch = lambda a: np.sqrt(np.clip(a / max(np.percentile(a, 99.9), 1e-30), 0, 1))  # noqa: E731
    fig, axes = plt.subplots(1, 3, figsize=(15, 5.4))
    for ax, (name, image) in zip(axes, images.items()):
        ax.imshow(stretch(image), cmap="gray")
        ax.set_title(f"{name}: sum {sums[name]:.4g} W/(cm² sr)" + (f", {triangles} triangles" if name == "mesh" else ""))
        ax.axis("off")
    diff = images["mesh"] - images["primitives"]
    lim = max(np.percentile(abs(diff), 99.9), 1e-30)
    axes[2].imshow(diff, cmap="RdBu_r", vmin=-lim, vmax=lim)
    axes[2].set_title(f"mesh - primitives (sums differ by {100 * (ratio - 1):+.2f} %)")
    axes[2].axis("off")
    fig.suptitle("GEO communications satellite 40 m away, 0.45-0.75 um, 36 deg field: primitives and a 3-D model")
    fig.tight_layout()
    fig.savefig(args.out / "mesh_inspection.png", dpi=90)
    print(f"primitives {sums['primitives']:.6e}, mesh {sums['mesh']:.6e} ({triangles} triangles): ratio {ratio:.6f}")
    if args.check_ratio is not None and not (sums["primitives"] > 0 and abs(ratio - 1.0) <= args.check_ratio):
        print(f"FAILED: ratio {ratio:.6f} not within {args.check_ratio} of 1")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

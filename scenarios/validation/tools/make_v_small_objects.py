"""Generates ../v_small_objects.json (issue 23 item 1; spec 4.1.6.1, ERRATA eq. 11
and the energy check of 6.2.5.1) from ../v_phase2.json (make_v_geo.py):
Satellite1 and Satellite2 fixed in J2000 as there, Satellite2 the predefined
composite geo_communications; Sensor1 images it (64 x 64 pixels of 2.5 mrad,
4 x 4 samples: resolved, small extended or a point source by range),
Sensor2 (8 x 8 pixels of 2.5 deg) sees it as a point target at every range.
The test (tests/validation/small_objects_6_2_5_1_test.cpp) sets the target's
shape, the band and the places.
"""
import json
import math
import pathlib

HERE = pathlib.Path(__file__).resolve().parent.parent

doc = json.loads((HERE / "v_phase2.json").read_text())
doc["name"] = "V_SmallObjects"
doc["description"] = (
    "Issue 23 item 1 (spec 4.1.6.1, ERRATA eq. 11; the energy check of 6.2.5.1): Satellite2, a predefined "
    "composite satellite or a 1 m sphere (the test sets its shape), seen from Satellite1 at ranges of 1 to "
    "40,000 km; Sensor1 (64 x 64 pixels of 2.5 mrad) images it extended, small extended or as a point source by "
    "range, Sensor2 (8 x 8 pixels of 2.5 deg) always sees it as a point target, whose irradiance is the "
    "reference. The test places both satellites and sets the band.")
for o in doc["objects"]:
    if o["name"] == "Satellite2":
        o["properties"] = {"shape": "composite", "composite": "geo_communications"}
common = {"band_low_um": 0.4, "band_high_um": 0.7, "spectral_intervals": 30, "focal_length_cm": 10.0,
          "f_number": 4.0, "diffraction_wavelength_um": 0.55, "noise_enabled": False}
fov_deg = round(math.degrees(64 * 2.5e-3), 7)
doc["sensors"][0]["parameters"] = dict(common, horizontal_pixels=64, vertical_pixels=64,
                                       horizontal_fov_deg=fov_deg, vertical_fov_deg=fov_deg)
doc["sensors"][1]["parameters"] = dict(common, horizontal_pixels=8, vertical_pixels=8, horizontal_fov_deg=20.0,
                                       vertical_fov_deg=20.0)
(HERE / "v_small_objects.json").write_text(json.dumps(doc, indent=2) + "\n")
print("wrote v_small_objects.json")

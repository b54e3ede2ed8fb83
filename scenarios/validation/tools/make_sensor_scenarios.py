"""Generates the spec 7.x sensor-validation scenarios (../valid_sens_*.json).

Geometry is kept simple and exact: the sensor's platform sits still at
P = (7000 km, 0, 0) in J2000 (a two-point ephemeris) and the sensor keeps the
identity attitude, so it looks along J2000 +z with body +x (image right) along
J2000 +x and body +y (image up) along J2000 +y. Targets are placed at
P + range * (sin a, sin b, cos) offsets. The 7.5.5 scenario uses two-body
orbits as the spec describes (a = 7300 and 7310 km).
"""
import json
import math
import pathlib

# The Earth of the sensor experiments: a uniform black body (300 K unless a
# scenario says otherwise), neither reflecting sunlight nor following the
# climatology: the spec 7 experiments test the sensor model against a
# background of known radiance.
EARTH_300K = {"name": "Earth", "properties": {"temperature_K": 300.0, "reflectance": 0.0, "thermal_model": "uniform"}}

HERE = pathlib.Path(__file__).resolve().parent.parent
EPOCH = "2010-08-25T18:00:00Z"
STOP = "2010-08-25T18:05:00Z"
P = (7000e3, 0.0, 0.0)
IDENTITY = [1.0, 0.0, 0.0, 0.0]


def still(position):
    """A two-point J2000 ephemeris that keeps an object at `position`."""
    pts = [{"time": t, "position_m": list(position), "velocity_m_s": [0.0, 0.0, 0.0]} for t in (EPOCH, STOP)]
    return {"type": "ephemeris", "frame": "j2000", "points": pts}


def ahead(range_m, x_deg=0.0, y_deg=0.0):
    """P plus range along the direction with tan(alpha), tan(beta) offsets in degrees."""
    tx, ty = math.tan(math.radians(x_deg)), math.tan(math.radians(y_deg))
    n = math.sqrt(1 + tx * tx + ty * ty)
    return (P[0] + range_m * tx / n, P[1] + range_m * ty / n, P[2] + range_m / n)


def scenario(name, description, objects, sensor_parent, parameters, pointing=None, stop=EPOCH):
    sensor = {"name": "Sensor1", "parent": sensor_parent, "parameters": parameters}
    sensor["pointing"] = pointing or {"type": "fixed_inertial", "quaternion": IDENTITY}
    return {"$schema": "../../schemas/scenario.schema.json", "format": "eoir-scenario", "version": 1,
            "name": name, "description": description, "start": EPOCH, "stop": stop, "step_s": 60,
            "objects": objects, "sensors": [sensor]}


def platform(kind, name):
    return {"name": name, "kind": kind, "motion": still(P), "attitude": {"type": "fixed_inertial", "quaternion": IDENTITY},
            "properties": {"shape": "none"}}


def body(kind, name, position, radius_m, temperature_K):
    return {"name": name, "kind": kind, "motion": still(position),
            "properties": {"shape": "sphere", "dimensions_m": [radius_m], "material": "gray_body",
                           "reflectance": 0.0, "temperature_K": temperature_K}}


def write(name, doc):
    (HERE / name).write_text(json.dumps(doc, indent=2) + "\n")
    print("wrote", name)


lwir = {"band_low_um": 8.0, "band_high_um": 12.0, "spectral_intervals": 50}

# 7.1: the Earth exactly fills the field from GEO (both axes).
write("valid_sens_fov_extent.json", {
    "$schema": "../../schemas/scenario.schema.json", "format": "eoir-scenario", "version": 1,
    "name": "Valid_Sens_FOVextent",
    "description": "Spec 7.1: a nadir-pointing sensor on a geostationary satellite, 0.4-0.7 um; horizontal FOV "
                   "17.401 deg = 2 asin(6378.1/42164.2), vertical 17.342 deg = 2 asin(6356.8/42164.2): the Earth "
                   "fills the field exactly.",
    "start": EPOCH, "stop": EPOCH, "step_s": 60, "central_bodies": [EARTH_300K],
    "objects": [{"name": "Satellite1", "kind": "satellite",
                 "motion": {"type": "kepler", "central_body": "Earth", "semi_major_axis_km": 42164.2,
                            "eccentricity": 0.0, "inclination_deg": 0.0, "raan_deg": 0.0,
                            "arg_perigee_deg": 0.0, "true_anomaly_deg": 0.0, "epoch": EPOCH},
                 "attitude": {"type": "nadir"}, "properties": {"shape": "none"}}],
    "sensors": [{"name": "Sensor1", "parent": "Satellite1", "pointing": {"type": "nadir"},
                 "parameters": {"horizontal_pixels": 128, "vertical_pixels": 128, "horizontal_fov_deg": 17.401,
                                "vertical_fov_deg": 17.342, "band_low_um": 0.4, "band_high_um": 0.7,
                                "spectral_intervals": 10, "focal_length_cm": 10.0, "f_number": 2.0,
                                "diffraction_wavelength_um": 0.55, "noise_enabled": False}}]})

# 7.2.1: five identical point sources, one on the axis and four exactly on
# the edges of a 10 x 10 deg field, 100 km away, each at a pixel corner.
targets = [("Aircraft2", 0, 0), ("Aircraft3", 5, 0), ("Aircraft4", -5, 0), ("Aircraft5", 0, 5), ("Aircraft6", 0, -5)]
objs = [platform("aircraft", "Aircraft1")]
for name, a, b in targets:
    # 5 deg from the line of sight along one axis: tan offsets = tan(5 deg).
    objs.append(body("aircraft", name, ahead(100e3, a, b), 0.5, 300.0))
write("valid_sens_ideal_fov_point_src.json", scenario(
    "Valid_Sens_IdealFOV_PointSrc",
    "Spec 7.2.1: five identical 0.5 m spheres at 300 K, 100 km away: one on the line of sight, four 5.0 deg from "
    "it along the horizontal and vertical axes, exactly on the edges of the 10 x 10 deg field (128 x 128 pixels, "
    "each source on a pixel corner).",
    objs, "Aircraft1",
    dict(lwir, horizontal_pixels=128, vertical_pixels=128, horizontal_fov_deg=10.0, vertical_fov_deg=10.0,
         focal_length_cm=20.0, f_number=2.0, diffraction_wavelength_um=10.0, noise_enabled=False)))

# 7.2.2, 7.3, 7.4: a uniform blackbody sphere that overfills the field.
write("valid_sens_uniform_ext_area_src.json", scenario(
    "Valid_Sens_UniformExtAreaSrc",
    "Spec 7.2.2, 7.3, 7.4: a sensor views a gray-body sphere (Satellite2, radius 100 km, 1000 km away, "
    "reflectance 0) that overfills its 1 x 1 deg field in the 8-12 um band; dark NER 1e-9 W/(cm^2 sr).",
    [platform("satellite", "Satellite1"), body("satellite", "Satellite2", ahead(1000e3), 100e3, 300.0)],
    "Satellite1",
    dict(lwir, horizontal_pixels=128, vertical_pixels=128, horizontal_fov_deg=1.0, vertical_fov_deg=1.0,
         focal_length_cm=50.0, f_number=2.0, diffraction_wavelength_um=10.0, integration_time_ms=1.0,
         sensitivity_quantity="radiance", sensitivity_pairs=[1.0, 1e-9],
         saturation_quantity="radiance", saturation_pairs=[1.0, 4e-3], saturation_enabled=False)))

# 7.5.1-7.5.4: a point source at the centre of pixel (127, 127) of a 255 x 255
# sensor whose Airy disk covers several pixels (IFOV 0.04 mrad at f = 16 cm).
pitch_cm = 0.04e-3 * 16.0
fov = math.degrees(2 * math.atan(255 * pitch_cm / (2 * 16.0)))
write("valid_sens_psf.json", scenario(
    "Valid_Sens_PSF",
    "Spec 7.5.1-7.5.4: a 0.05 m sphere (Aircraft2, 300 K) 100 km away on the line of sight of a 255 x 255 pixel "
    "sensor, 10-14 um, f = 16 cm, F/2, lambda_diff 12 um: the Airy disk (58.6 um) covers about 9 pixels of "
    "6.4 um (IFOV 0.04 mrad). The source is at the centre of pixel (127, 127).",
    [platform("aircraft", "Aircraft1"), body("aircraft", "Aircraft2", ahead(100e3), 0.05, 300.0)], "Aircraft1",
    {"horizontal_pixels": 255, "vertical_pixels": 255, "horizontal_fov_deg": fov, "vertical_fov_deg": fov,
     "band_low_um": 10.0, "band_high_um": 14.0, "spectral_intervals": 20, "focal_length_cm": 16.0,
     "f_number": 2.0, "diffraction_wavelength_um": 12.0, "noise_enabled": False}))

# 7.5.5 and 7.7.2: Satellite1 (a = 7300 km) views Satellite2 (a = 7310 km, a
# 1 cm sphere at 250 K), 10 km away at the start, against space; pixel pitch
# equal to the Airy diameter 2.44 lambda F# (10 um, F/4 -> 97.6 um).
airy_cm = 2.44 * 10e-4 * 4.0
fov = math.degrees(2 * math.atan(127 * airy_cm / (2 * 100.0)))
orbit = {"type": "kepler", "central_body": "Earth", "eccentricity": 0.0, "inclination_deg": 45.0, "raan_deg": 30.0,
         "arg_perigee_deg": 0.0, "true_anomaly_deg": 0.0, "epoch": "2010-08-03T16:00:00Z"}
write("valid_sens_point_src_target.json", {
    "$schema": "../../schemas/scenario.schema.json", "format": "eoir-scenario", "version": 1,
    "name": "Valid_Sens_PointSrcTarget",
    "description": "Spec 7.5.5 and 7.7.2: a sensor on Satellite1 (a = 7300 km) points at Satellite2 (a = 7310 km, "
                   "same plane and phase: 10 km above it at the start), a 1 cm gray-body sphere at 250 K against "
                   "space; 8-12 um, 127 x 127 pixels whose pitch equals the Airy diameter (97.6 um at 10 um, F/4).",
    "start": "2010-08-03T16:00:00Z", "stop": "2010-08-03T16:20:00Z", "step_s": 60, "central_bodies": [EARTH_300K],
    "objects": [
        {"name": "Satellite1", "kind": "satellite", "motion": dict(orbit, semi_major_axis_km=7300.0),
         "attitude": {"type": "nadir"}, "properties": {"shape": "none"}},
        {"name": "Satellite2", "kind": "satellite", "motion": dict(orbit, semi_major_axis_km=7310.0),
         "properties": {"shape": "sphere", "dimensions_m": [0.01], "material": "gray_body", "reflectance": 0.0,
                        "temperature_K": 250.0}}],
    "sensors": [{"name": "Sensor1", "parent": "Satellite1", "pointing": {"type": "target", "target": "Satellite2"},
                 "parameters": dict(lwir, horizontal_pixels=127, vertical_pixels=127, horizontal_fov_deg=fov,
                                    vertical_fov_deg=fov, focal_length_cm=100.0, f_number=4.0,
                                    diffraction_wavelength_um=10.0, integration_time_ms=10.0,
                                    sensitivity_quantity="irradiance", sensitivity_pairs=[10.0, 1e-18],
                                    saturation_enabled=False, noise_enabled=False)}]})

# 7.7.1: a sensor 100 km up (Aircraft3) looks straight down at a 1 m sphere
# at 350 K (Aircraft2, 1.6 km up) against a 300 K background (Aircraft1)
# that fills the field. The background is the top of a sphere of radius
# 1000 km whose top is at 0 km, flat to 0.1 m across the field. The sensor
# is the Table 3 geometry in the 8-12 um band: pitch 100.2207 um, f = 147 cm,
# F/3.5, lambda_diff 10 um (ensquared energy 0.86396), NEI 1e-18 W/cm^2 at
# 10 ms, saturation off (the background alone exceeds an SEI of 1e-15).
def geodetic(name, alt_m, props):
    return {"name": name, "kind": "aircraft",
            "motion": {"type": "fixed_geodetic", "lat_deg": 0.0, "lon_deg": 0.0, "alt_m": alt_m},
            "properties": props}

write("valid_sens_pt_src_tgt_uniform_bkg.json", {
    "$schema": "../../schemas/scenario.schema.json", "format": "eoir-scenario", "version": 1,
    "name": "Valid_Sens_PtSrcTgtUniformBkg",
    "description": "Spec 7.7.1: a sensor on Aircraft3 (100 km up) views a 1 m gray-body sphere (Aircraft2, 1.6 km "
                   "up, 350 K) against a uniform 300 K background (Aircraft1) that fills the field; 8-12 um, 50 "
                   "intervals, NEI 1e-18 W/cm^2, peak irradiance responsivity 3.779e20 e-/(W/cm^2).",
    "start": "2010-08-25T18:00:00Z", "stop": "2010-08-25T18:05:00Z", "step_s": 60,
    "objects": [
        geodetic("Aircraft1", -1000e3, {"shape": "sphere", "dimensions_m": [1000e3], "material": "gray_body",
                                        "reflectance": 0.0, "temperature_K": 300.0}),
        geodetic("Aircraft2", 1.6e3, {"shape": "sphere", "dimensions_m": [1.0], "material": "gray_body",
                                      "reflectance": 0.0, "temperature_K": 350.0}),
        geodetic("Aircraft3", 100e3, {"shape": "none"}),
    ],
    "sensors": [{"name": "Sensor1", "parent": "Aircraft3", "pointing": {"type": "target", "target": "Aircraft2"},
                 "parameters": dict(lwir, horizontal_pixels=128, vertical_pixels=128, horizontal_fov_deg=0.5,
                                    vertical_fov_deg=0.5, focal_length_cm=147.0, f_number=3.5,
                                    diffraction_wavelength_um=10.0, integration_time_ms=10.0,
                                    sensitivity_quantity="irradiance", sensitivity_pairs=[10.0, 1e-18],
                                    saturation_enabled=False)}]})

# 7.8: a nadir-pointing 24 x 24 deg sensor on a geostationary Satellite1
# watches a LEO Satellite2 (a 2 m sphere at 300 K) for 24 hours; against the
# 288 K Earth the contrast is nearly nil, against space the SNR is ~5-9.
write("valid_sens_snr_access.json", {
    "$schema": "../../schemas/scenario.schema.json", "format": "eoir-scenario", "version": 1,
    "name": "Valid_Sens_SNR_Access",
    "description": "Spec 7.8 (ERRATA: the sensor is on Satellite1, the target is Satellite2): a nadir-pointing "
                   "24 x 24 deg sensor, 8-12 um, on a geostationary satellite; the target is a LEO satellite at "
                   "300 K seen against the 288 K Earth (SNR ~0) or space (SNR ~5.3-7).",
    "start": "2010-12-08T22:00:00Z", "stop": "2010-12-09T22:00:00Z", "step_s": 60,
    "central_bodies": [{"name": "Earth", "properties": dict(EARTH_300K["properties"], temperature_K=288.0)}],
    "objects": [
        {"name": "Satellite1", "kind": "satellite",
         "motion": {"type": "kepler", "central_body": "Earth", "semi_major_axis_km": 42164.17, "eccentricity": 0.0,
                    "inclination_deg": 0.0, "raan_deg": 0.0, "arg_perigee_deg": 0.0, "true_anomaly_deg": 0.0,
                    "epoch": "2010-12-08T22:00:00Z"},
         "attitude": {"type": "nadir"}, "properties": {"shape": "none"}},
        {"name": "Satellite2", "kind": "satellite",
         "motion": {"type": "kepler", "central_body": "Earth", "semi_major_axis_km": 7000.0, "eccentricity": 0.001,
                    "inclination_deg": 60.0, "raan_deg": 20.0, "arg_perigee_deg": 0.0, "true_anomaly_deg": 0.0,
                    "epoch": "2010-12-08T22:00:00Z"},
         "properties": {"shape": "sphere", "dimensions_m": [2.0], "material": "gray_body", "reflectance": 0.0,
                        "temperature_K": 300.0}}],
    "sensors": [{"name": "Sensor1", "parent": "Satellite1", "pointing": {"type": "nadir"},
                 "parameters": dict(lwir, spectral_intervals=10, horizontal_pixels=256, vertical_pixels=256,
                                    horizontal_fov_deg=24.0, vertical_fov_deg=24.0, focal_length_cm=10.0,
                                    f_number=2.0, diffraction_wavelength_um=10.0, integration_time_ms=10.0,
                                    sensitivity_quantity="irradiance", sensitivity_pairs=[10.0, 4.6e-18],
                                    saturation_enabled=False)}]})

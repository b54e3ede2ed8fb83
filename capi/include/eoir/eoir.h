/*
 * eoir.h — the stable C ABI of the EOIR engine (version 1).
 *
 * Rules (see README "C ABI"):
 *  - Only <stddef.h>/<stdint.h> types cross this boundary; the header compiles
 *    as C99 with -Wall -Wextra -pedantic -Werror.
 *  - Every call returns eoir_status (0 = EOIR_OK, negative = error) and leaves
 *    a thread-local message readable with eoir_last_error(); the message names
 *    the offending field, e.g. "position[1]: not finite (nan)".
 *  - Checks that involve several fields (band edges in order) are made when
 *    the sensor is evaluated (data providers, images), so that parameters can
 *    be changed one at a time in any order.
 *  - Structs passed in begin with uint32_t struct_size; fields are only ever
 *    appended; the library reads at most struct_size bytes.
 *  - Buffers are caller-allocated. Strings returned as const char* are static
 *    (names, units) unless documented otherwise.
 *  - Units: positions in metres, velocities in m/s, angles in degrees unless a
 *    name says otherwise, radiometry in the spec's W, cm, sr, um.
 *  - Threads: calls on one engine from several threads are serialized (each
 *    call holds the engine's lock for its duration), never interleaved, so
 *    they cannot corrupt it; calls on different engines run fully in
 *    parallel. Pointers an engine returns (object names) stay valid only
 *    until the next call that changes the engine. eoir_engine_destroy must
 *    not race with other calls on the same engine.
 */
#ifndef EOIR_EOIR_H
#define EOIR_EOIR_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#  if defined(EOIR_BUILDING_LIBRARY)
#    define EOIR_API __declspec(dllexport)
#  else
#    define EOIR_API __declspec(dllimport)
#  endif
#else
#  define EOIR_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ version */
/* EOIR_VERSION_MAJOR, EOIR_VERSION_MINOR, EOIR_VERSION_PATCH and
 * EOIR_VERSION_STRING: the engine's one version (the CMake project's), which
 * is also this ABI's: MAJOR is the soname (libeoir.so.MAJOR), MINOR counts
 * additions to the ABI (the "1.5" of the comments below), PATCH fixes.
 * eoir_version.h is generated beside this header (build tree and install). */
#include "eoir_version.h"

/* Returns EOIR_VERSION_MAJOR*10000 + MINOR*100 + PATCH of the loaded library. */
EOIR_API uint32_t eoir_version(void);
/* The version as "1.0.0" (static string). */
EOIR_API const char* eoir_version_string(void);

/* ------------------------------------------------------------------- status */
/* Explicit values in gapped blocks; never renumbered. */
typedef int32_t eoir_status;
#define EOIR_OK 0
/* -100 block: the call's arguments */
#define EOIR_ERR_NULL_ARGUMENT     -100 /* a required pointer is NULL */
#define EOIR_ERR_STRUCT_SIZE       -101 /* struct_size too small or zero */
#define EOIR_ERR_OUT_OF_RANGE      -102 /* NaN, infinite, negative, reversed... */
#define EOIR_ERR_UNKNOWN_NAME      -103 /* unknown object, property, group, element, shape, material */
#define EOIR_ERR_TYPE_MISMATCH     -104 /* property read or written with the wrong type */
#define EOIR_ERR_BUFFER_TOO_SMALL  -105 /* *count_out tells the size needed */
/* -200 block: the modeled universe */
#define EOIR_ERR_LIMIT_EXCEEDED    -200 /* an object limit reached (spec 3.1; eoir_engine_set_limits) */
#define EOIR_ERR_ALREADY_EXISTS    -201 /* an object of that name exists */
#define EOIR_ERR_NOT_ALLOWED       -202 /* e.g. removing the Sun, target equal to parent */
#define EOIR_ERR_NO_STATE          -203 /* the object has no state at the engine time */
/* -300 block: files */
#define EOIR_ERR_IO                -300 /* cannot open, write or rename */
#define EOIR_ERR_CORRUPT_FILE      -301 /* not JSON, truncated, wrong field type, unknown field */
#define EOIR_ERR_FILE_VERSION      -302 /* written by a newer format version */
/* -400 block: plugin negotiation */
#define EOIR_ERR_ABI_MISMATCH      -400 /* host asked for an ABI major this library lacks */
/* -500 block: the host's requests (1.3) */
#define EOIR_ERR_CANCELLED         -500 /* the host's progress callback asked to stop; nothing changed */
/* -900 block */
#define EOIR_ERR_INTERNAL          -900 /* a bug: please report with eoir_last_error() */

/* Message of the last failing call on this thread ("" after a success). */
EOIR_API const char* eoir_last_error(void);
/* Static symbolic name of a status, e.g. "EOIR_ERR_OUT_OF_RANGE". */
EOIR_API const char* eoir_status_name(eoir_status status);

/* ------------------------------------------------------------------- limits */
/* Spec 3.1: the default profile of every new engine. From 1.7 an engine's
 * object limits are set at run time (eoir_engine_set_limits) up to the
 * EOIR_CEILING_* values; the others are fixed. */
#define EOIR_MAX_SATELLITES        16
#define EOIR_MAX_VEHICLES           6 /* aircraft plus ground vehicles */
#define EOIR_MAX_SITES             16 /* sites (1.5; not in spec 3.1), not vehicles */
#define EOIR_MAX_MISSILES           6
#define EOIR_MAX_MISSILE_STAGES    18
#define EOIR_MAX_SENSORS            6 /* scene-generator/sensor-model pairs */
#define EOIR_MAX_REFERENCE_PAIRS    8 /* sensitivity or saturation (spec 5.9, 5.10) */
#define EOIR_MAX_NAME_LENGTH       63
#define EOIR_CEILING_SATELLITES 100000 /* 1.7: the highest value of each run-time limit */
#define EOIR_CEILING_VEHICLES    10000
#define EOIR_CEILING_SITES       10000
#define EOIR_CEILING_MISSILES    10000
#define EOIR_CEILING_SENSORS       256

/* ------------------------------------------------------------------- engine */
typedef struct eoir_engine_s* eoir_engine;

typedef struct eoir_engine_desc {
  uint32_t struct_size; /* sizeof(eoir_engine_desc) */
  uint32_t threads;     /* worker threads, 0 = all cores, at most 1024 */
  uint64_t seed;        /* seed of the noise generator (saved in the state) */
  /* appended in 1.3; read only when struct_size covers it */
  const char* data_dir; /* the data folder (solar spectrum, materials, Earth maps, stars); NULL: $EOIR_DATA_DIR,
                           else share/eoir/data beside the library, else the build tree's */
} eoir_engine_desc;

/* desc may be NULL for defaults (all cores, seed 1). The new engine holds the
 * Sun only, at J2000.0 TT. */
EOIR_API eoir_status eoir_engine_create(const eoir_engine_desc* desc, eoir_engine* engine_out);
/* Accepts NULL. */
EOIR_API void eoir_engine_destroy(eoir_engine engine);

/* The engine's object limits (1.7). A new engine has the default profile
 * (EOIR_MAX_SATELLITES, ...); eoir_object_add and eoir_sensor_add refuse an
 * object past its limit with EOIR_ERR_LIMIT_EXCEEDED naming the limit
 * ("max_satellites"). Saved with the state. */
typedef struct eoir_limits {
  uint32_t struct_size;    /* sizeof(eoir_limits) */
  uint32_t max_satellites; /* each in [1, EOIR_CEILING_*] */
  uint32_t max_vehicles;   /* aircraft plus ground vehicles */
  uint32_t max_sites;
  uint32_t max_missiles;
  uint32_t max_sensors;    /* scene-generator/sensor-model pairs */
} eoir_limits;

/* Sets every limit at once: a value of 0 or above its ceiling is
 * EOIR_ERR_OUT_OF_RANGE, one below the objects of its kind the engine holds
 * EOIR_ERR_NOT_ALLOWED, each naming the field ("max_satellites"); nothing
 * changes then. */
EOIR_API eoir_status eoir_engine_set_limits(eoir_engine engine, const eoir_limits* limits);
/* Writes the limits (struct_size set by the caller). */
EOIR_API eoir_status eoir_engine_get_limits(eoir_engine engine, eoir_limits* limits_out);

/* --------------------------------------------------------------------- time */
/* Two-part Julian date (jd1 + jd2, as ERFA) in an explicit time scale. The
 * engine keeps time internally as TT days since J2000.0 and a fraction of a
 * day (spec 3.2). Every call taking a time accepts 1000-01-01 to 3000-01-01
 * TT (JD 2086302.5 to 2816787.5, where ERFA's planetary ephemerides are
 * valid), each part within +/-1e7 days; other dates are EOIR_ERR_OUT_OF_RANGE
 * naming the field. UTC before 1960 is taken as TAI (no leap seconds). */
typedef enum eoir_time_scale {
  EOIR_TIME_UTC = 0,
  EOIR_TIME_TAI = 1,
  EOIR_TIME_TT = 2,
  EOIR_TIME_TDB = 3
} eoir_time_scale;

typedef struct eoir_time {
  int32_t scale; /* eoir_time_scale */
  double jd1;
  double jd2;
} eoir_time;

EOIR_API eoir_status eoir_engine_set_time(eoir_engine engine, const eoir_time* time);
EOIR_API eoir_status eoir_engine_get_time(eoir_engine engine, int32_t scale, eoir_time* time_out);
/* ISO-8601 UTC ("2010-08-25T18:00:00Z", fractional seconds allowed) to a UTC
 * two-part Julian date, and back (writes at most capacity bytes with '\0'). */
EOIR_API eoir_status eoir_time_from_iso(const char* iso_utc, eoir_time* time_out);
EOIR_API eoir_status eoir_time_to_iso(const eoir_time* time, char* buffer, size_t capacity);

/* ------------------------------------------------------ the modeled universe */
typedef enum eoir_object_kind {
  EOIR_KIND_CENTRAL_BODY = 1,   /* Sun, Mercury..Neptune, Moon (names fixed) */
  EOIR_KIND_STAR_FIELD = 2,     /* name "Stars" */
  EOIR_KIND_SATELLITE = 3,
  EOIR_KIND_AIRCRAFT = 4,
  EOIR_KIND_GROUND_VEHICLE = 5,
  EOIR_KIND_MISSILE = 6,
  EOIR_KIND_SENSOR = 7,         /* use eoir_sensor_add */
  EOIR_KIND_SITE = 8            /* 1.5: fixed on the Earth (properties latitude_deg, longitude_deg,
                                   height_m on WGS84); carries sensors, images nothing, takes no
                                   state; body axes east, north, up */
} eoir_object_kind;

/* Adds an object. Central bodies must be named Sun, Mercury, Venus, Earth,
 * Mars, Jupiter, Saturn, Uranus, Neptune or Moon; the star field "Stars".
 * Names are 1..63 bytes. Fails with EOIR_ERR_LIMIT_EXCEEDED past the limits
 * (sites count against EOIR_MAX_SITES only). */
EOIR_API eoir_status eoir_object_add(eoir_engine engine, int32_t kind, const char* name);
/* Adds a scene-generator/sensor-model pair attached to a parent object (any
 * object but the star field). The sensor starts with the defaults of
 * `eoir sensor-defaults`. */
EOIR_API eoir_status eoir_sensor_add(eoir_engine engine, const char* name, const char* parent);
/* Removes an object (never the Sun); removing a parent removes its sensors. */
EOIR_API eoir_status eoir_object_remove(eoir_engine engine, const char* name);
EOIR_API eoir_status eoir_object_count(eoir_engine engine, size_t* count_out);
/* Name and kind of the index-th object (0-based, in insertion order). */
EOIR_API eoir_status eoir_object_at(eoir_engine engine, size_t index, const char** name_out, int32_t* kind_out);

/* -------------------------------------------------------------------- state */
typedef enum eoir_frame {
  EOIR_FRAME_J2000 = 0,       /* Earth-centred inertial (GCRS ~ J2000), metres */
  EOIR_FRAME_EARTH_FIXED = 1, /* Earth-centred Earth-fixed (ITRS, WGS84), metres */
  EOIR_FRAME_GEODETIC = 2,    /* position = {lat deg, lon deg, height m} on WGS84;
                                 velocity and attitude as in EARTH_FIXED */
  EOIR_FRAME_GEODETIC_NED = 3 /* position as in GEODETIC; velocity (m/s),
                                 attitude and angular velocity in the local
                                 north-east-down axes at that place (attitude =
                                 body -> NED; aircraft body x forward, y right,
                                 z down: heading, pitch, roll are its ZYX Euler
                                 angles). Kept and extrapolated as an
                                 Earth-fixed state (a straight line in the
                                 Earth-fixed frame, attitude fixed there).
                                 Height 0 is the ellipsoid's surface (no
                                 terrain). */
} eoir_frame;

typedef struct eoir_state {
  uint32_t struct_size;
  int32_t frame;        /* eoir_frame */
  double position[3];   /* metres (or lat, lon, height for GEODETIC) */
  double velocity[3];   /* m/s */
  double attitude[4];   /* unit quaternion {w, x, y, z}: body to frame */
  /* appended in 1.3; read and written only when struct_size covers it */
  double angular_velocity[3]; /* rad/s about the frame's axes (at most 1000) */
} eoir_state;

/* State of an object at a time (NULL time = the engine time). Between pushes
 * the engine moves the object along its velocity (constant-velocity
 * extrapolation) and turns its attitude at the angular velocity (point
 * sources streak across the focal plane during the integration time as both
 * move). Central bodies move on their own (ERFA ephemerides) and sites stay
 * at their geodetic position: both refuse states (EOIR_ERR_NOT_ALLOWED).
 * Sensors take their parent's position; a sensor's attitude set here
 * overrides the parent's. */
EOIR_API eoir_status eoir_object_set_state(eoir_engine engine, const char* name,
                                           const eoir_time* time, const eoir_state* state);
/* State at the engine time in the requested frame (struct_size and frame set
 * by the caller). */
EOIR_API eoir_status eoir_object_get_state(eoir_engine engine, const char* name, eoir_state* state_inout);

/* Pointing (1.5): each sets the sensor's own attitude at the engine time as
 * eoir_object_set_state would (its position stays its parent's).
 *
 * By topocentric azimuth (deg from north through east, within +-360) and
 * elevation (deg above the geodetic horizon, [-90, 90]) at the sensor's
 * WGS84 position: body +z along that direction, body +y toward the zenith
 * side (up in the picture). The attitude is held in the Earth-fixed frame,
 * so the view stays on that azimuth and elevation as the Earth turns (the
 * stars streak). EOIR_ERR_OUT_OF_RANGE names azimuth_deg or elevation_deg. */
EOIR_API eoir_status eoir_sensor_point_azel(eoir_engine engine, const char* sensor, double azimuth_deg,
                                            double elevation_deg);
/* At an object: body +z toward its geometric position, body +y toward the
 * sensor's zenith within 100 km of the ellipsoid (else toward the J2000
 * north pole), in J2000 with the angular velocity that keeps the target on
 * the boresight (both objects' motion): the target stays still during the
 * integration and the rest of the scene streaks. Call it again after the
 * time changes to keep tracking. EOIR_ERR_NOT_ALLOWED for the star field,
 * the sensor's parent or a target at the sensor's place. */
EOIR_API eoir_status eoir_sensor_point_at(eoir_engine engine, const char* sensor, const char* target);

/* --------------------------------------------------------------- properties */
/* Objects and sensors carry named, typed properties. The names, types, units
 * and ranges are listed by eoir_property_info and in README "Properties":
 * e.g. shape ("sphere", "box", ...), dimensions_m, material, temperature_K,
 * reflectance for objects; horizontal_pixels, horizontal_fov_deg,
 * band_low_um, f_number, focal_length_cm, ... for sensors (spec 5). */
typedef enum eoir_value_type {
  EOIR_TYPE_NUMBER = 1,  /* double */
  EOIR_TYPE_INTEGER = 2, /* int64_t */
  EOIR_TYPE_BOOL = 3,    /* int32_t 0/1 */
  EOIR_TYPE_STRING = 4,
  EOIR_TYPE_ARRAY = 5,   /* array of doubles */
  EOIR_TYPE_CURVE = 6    /* data providers only: x and y arrays */
} eoir_value_type;

/* Integers are accepted where numbers are expected, and whole numbers where
 * integers are; any other type mismatch is EOIR_ERR_TYPE_MISMATCH. A value
 * outside the property's range (eoir_property_info), NaN or infinite, a bool
 * other than 0 or 1 is EOIR_ERR_OUT_OF_RANGE naming the property; an array
 * of more than 2^20 values is EOIR_ERR_LIMIT_EXCEEDED. */
EOIR_API eoir_status eoir_set_number(eoir_engine engine, const char* object, const char* property, double value);
EOIR_API eoir_status eoir_set_integer(eoir_engine engine, const char* object, const char* property, int64_t value);
EOIR_API eoir_status eoir_set_bool(eoir_engine engine, const char* object, const char* property, int32_t value);
EOIR_API eoir_status eoir_set_string(eoir_engine engine, const char* object, const char* property, const char* value);
EOIR_API eoir_status eoir_set_array(eoir_engine engine, const char* object, const char* property,
                                    const double* values, size_t count);

EOIR_API eoir_status eoir_get_number(eoir_engine engine, const char* object, const char* property, double* value_out);
EOIR_API eoir_status eoir_get_integer(eoir_engine engine, const char* object, const char* property, int64_t* value_out);
EOIR_API eoir_status eoir_get_bool(eoir_engine engine, const char* object, const char* property, int32_t* value_out);
/* Copies at most capacity bytes including '\0'; EOIR_ERR_BUFFER_TOO_SMALL
 * if it does not fit. */
EOIR_API eoir_status eoir_get_string(eoir_engine engine, const char* object, const char* property,
                                     char* buffer, size_t capacity);
/* *count_out receives the length; values may be NULL to ask for it. */
EOIR_API eoir_status eoir_get_array(eoir_engine engine, const char* object, const char* property,
                                    double* values, size_t capacity, size_t* count_out);

#define EOIR_PROPERTY_FIDELITY 1 /* a knob trading speed for accuracy (README "Fidelity") */

typedef struct eoir_property_info {
  uint32_t struct_size;
  const char* name;        /* static */
  int32_t type;            /* eoir_value_type */
  const char* unit;        /* static, "" if none */
  const char* description; /* static */
  /* appended in 1.3; each written only when struct_size covers it */
  uint32_t flags;          /* EOIR_PROPERTY_* bits */
  uint32_t range_open;     /* bit 0: minimum excluded, bit 1: maximum excluded */
  double minimum;          /* numbers, integers and array elements: -HUGE_VAL if unbounded */
  double maximum;          /* +HUGE_VAL if unbounded; both infinite for strings and bools */
  const char* choices;     /* static: strings with a closed set, "a,b,c"; "" otherwise */
} eoir_property_info;

/* The index-th property of an object (0-based); EOIR_ERR_OUT_OF_RANGE past
 * the end. */
EOIR_API eoir_status eoir_property_info_at(eoir_engine engine, const char* object, size_t index,
                                           eoir_property_info* info_out);

/* ----------------------------------------------------------- data providers */
/* The report-generator interface. Groups and elements are named as in the
 * STK EOIR reports, e.g. group "EOIR Sensor Optics", element
 * "Ensquared Energy". target may be NULL for groups without a target. */
typedef struct eoir_element_info {
  uint32_t struct_size;
  const char* name;   /* static */
  int32_t type;       /* EOIR_TYPE_NUMBER, EOIR_TYPE_INTEGER, EOIR_TYPE_BOOL or EOIR_TYPE_CURVE */
  const char* unit;   /* static; for curves the unit of y */
  const char* x_unit; /* static; curves only ("cycles/mrad"), else "" */
} eoir_element_info;

EOIR_API eoir_status eoir_provider_group_at(size_t index, const char** group_out);
EOIR_API eoir_status eoir_provider_element_at(const char* group, size_t index, eoir_element_info* info_out);

/* A scalar element (number, integer or bool, returned as double) at the
 * engine time. */
EOIR_API eoir_status eoir_provider_get(eoir_engine engine, const char* group, const char* element,
                                       const char* sensor, const char* target, double* value_out);
/* A curve element: x (spatial frequency, cycles/mrad) and y arrays, caller
 * allocated; x or y may be NULL to ask for *count_out. */
EOIR_API eoir_status eoir_provider_get_curve(eoir_engine engine, const char* group, const char* element,
                                             const char* sensor, const char* target,
                                             double* x, double* y, size_t capacity, size_t* count_out);
/* A scalar element at each of `count` times (1.3): values_out[i] at times[i]
 * (at most 2^22 times, else EOIR_ERR_LIMIT_EXCEEDED naming count).
 * The engine time is left at the last time. Reports progress to the host and
 * stops with EOIR_ERR_CANCELLED when asked. */
EOIR_API eoir_status eoir_provider_series(eoir_engine engine, const char* group, const char* element,
                                          const char* sensor, const char* target, const eoir_time* times,
                                          size_t count, double* values_out);

/* ------------------------------------------------------ materials, spectra */
/* Materials (spec 4.1.4.1): the data folder's (see `eoir properties`), gray_body,
 * and the user's. Adds or replaces the material a file defines (format
 * schemas/material.schema.json: SRF on 0.28-28 um, emissivity 1 - SRF, BRDF
 * parameters of eq. 1); EOIR_ERR_CORRUPT_FILE names the field and file. Objects
 * then take its name in their `material` property. Saved with the state. */
EOIR_API eoir_status eoir_material_load(eoir_engine engine, const char* path);
/* Adds or replaces a tabulated spectral radiance (spec 4.1.4: the table whose
 * entry 0 is the Sun): count >= 2 points, wavelengths strictly increasing,
 * radiances >= 0 in W/(cm^2 sr um). Objects take its name in their `spectrum`
 * property (self-radiance instead of eps B(T)). Saved with the state. */
EOIR_API eoir_status eoir_spectrum_add(eoir_engine engine, const char* name, const double* wavelength_um,
                                       const double* radiance_W_cm2_sr_um, size_t count);

/* ------------------------------------------------------------ save, restore */
/* The whole engine state (objects, properties, sensors, time, noise seeds) as
 * a versioned JSON .scd file (schemas/scd.schema.json). Written to a
 * temporary file beside path and renamed; on any error the file on disk and
 * the engine are left as they were. */
EOIR_API eoir_status eoir_state_save(eoir_engine engine, const char* path);
EOIR_API eoir_status eoir_state_load(eoir_engine engine, const char* path);
/* One sensor's parameters on their own (spec 3.4; schemas/sensor.schema.json).
 * Loading replaces the parameters of an existing sensor. */
EOIR_API eoir_status eoir_sensor_save(eoir_engine engine, const char* sensor, const char* path);
EOIR_API eoir_status eoir_sensor_load(eoir_engine engine, const char* sensor, const char* path);

/* ------------------------------------------------------------------- images */
/* One frame of a scene-generator/sensor-model pair (spec 4.1, 5.11), rendered
 * at the engine time. Images are stored row-major, row 0 at the top, as seen
 * by an observer at the sensor looking along body +z with body +y up: column
 * grows toward body -x (body +x is on the left of the picture), row toward
 * body -y. The focal-plane inversion of eqs. 15-16 is undone; with north up,
 * east is on the left, as on any picture of the sky. */
typedef enum eoir_image_kind {
  EOIR_IMAGE_SCENE_RADIANCE = 1,  /* effective radiance per scene sample (eq. 48), W/(cm^2 sr); 4x4 per pixel */
  EOIR_IMAGE_SCENE_DISPLAY = 2,   /* display bytes of the scene view (spec 4.1.2), one per sample */
  EOIR_IMAGE_SENSOR_ELECTRONS = 3, /* total response with noise and saturation (eq. 55), electrons */
  EOIR_IMAGE_SENSOR_MEAN = 4,     /* noise-free response r_L + r_E (eqs. 49-50), electrons */
  EOIR_IMAGE_SENSOR_DISPLAY = 5,  /* display bytes of the sensor view, one per pixel */
  EOIR_IMAGE_SENSOR_ADU = 6       /* 1.7: the detector stage's ADU per pixel (sensor property detector_model;
                                     README "Detector model"); eoir_image_get_adu, or eoir_image_get as doubles */
} eoir_image_kind;

/* Renders the frame of `sensor` at the engine time (ray casting, shading,
 * band integration, OTF convolution, point sources, noise from the engine's
 * seeded generator). The frame is kept until the next render of that sensor.
 * Settings: sensor properties noise_enabled, detector_model (1.7), display_agc, display_gain_step, display_stretch,
 * motion_substeps (the scene as the mean of that many scenes over the integration: resolved objects that move smear),
 * the fidelity knobs (scene_mode, band_integration, samples_per_pixel, ...;
 * README "Fidelity") and objects' patch_size_m. The host's progress callback
 * is called between stages; a non-zero return cancels the render
 * (EOIR_ERR_CANCELLED, the previous frame stays). */
EOIR_API eoir_status eoir_render(eoir_engine engine, const char* sensor);

/* The fidelity settings the last frame of `sensor` was rendered with (1.4),
 * as a JSON object: {"error_budget": b, "estimated_error": e,
 * "spectral_intervals": N, "<knob>": value, ...} with every fidelity knob
 * (README "Fidelity"). With the sensor property error_budget at 0 these are
 * the sensor's own settings and estimated_error is 0; with a budget > 0 they
 * are those the engine chose for that frame, and estimated_error is its
 * error model's estimate of the relative RMS error of the pixel means (README
 * "Adaptive fidelity"). *length_out receives the text's length without the
 * '\0'; buffer may be NULL to ask for it, else EOIR_ERR_BUFFER_TOO_SMALL if
 * capacity < length + 1; EOIR_ERR_NO_STATE if no frame was rendered. */
EOIR_API eoir_status eoir_frame_fidelity_get(eoir_engine engine, const char* sensor, char* buffer, size_t capacity,
                                             size_t* length_out);

typedef struct eoir_image_info {
  uint32_t struct_size;
  uint32_t width;        /* samples or pixels */
  uint32_t height;
  int32_t kind;          /* eoir_image_kind */
  const char* unit;      /* static: "W/(cm^2 sr)", "electrons", "" (display) */
  double time_jd_utc[2]; /* the frame's time, UTC two-part Julian date */
  double boresight_ra_deg;   /* sensor +z in J2000 */
  double boresight_dec_deg;
  double up_ra_deg;          /* sensor +y in J2000 */
  double up_dec_deg;
  /* appended in 1.6; written only when struct_size covers them */
  double start_jd_utc[2];    /* the integration's start and end (time_jd_utc is its middle), UTC */
  double end_jd_utc[2];
  double astrometric_ra_deg; /* the image's astrometric TAN WCS (ICRS as a plate solution against a star */
  double astrometric_dec_deg; /* catalogue gives it: the field's aberration and light deflection absorbed;
                                 refraction not): RA/Dec of the image centre (the boresight) */
  double astrometric_cd_deg[4]; /* at the centre, degrees per column and row of this image: {dxi/dcolumn,
                                   dxi/drow, deta/dcolumn, deta/drow}, xi toward east and eta toward north in
                                   the tangent plane; rows grow downward as images are stored */
  double observer_position_m[3];    /* the sensor at the frame time (the middle), J2000 (GCRS) axes */
  double observer_velocity_m_s[3];
  double observer_earth_fixed_m[3]; /* the same position in Earth-fixed axes (ITRS, WGS84) */
  double saturation_electrons;      /* sensor images: the saturation level (spec 5.11.5); 0 if it is off */
  double read_noise_electrons;      /* sensor images: the dark noise sigma (spec 5.11.4); 0 if noise is off */
  /* appended in 1.7; with detector_model on, saturation_electrons is the full well and
     read_noise_electrons the read noise (0 if noise is off); all four are 0 with it off */
  double gain_e_per_adu;            /* detector: conversion gain, electrons per ADU */
  double bias_adu;                  /* detector: bias added before the ADC, ADU */
  double saturation_adu;            /* detector: the ADU of a full well, at most adc_max_adu */
  double adc_max_adu;               /* detector: 2^adc_bits - 1 */
} eoir_image_info;

EOIR_API eoir_status eoir_image_info_get(eoir_engine engine, const char* sensor, int32_t kind,
                                         eoir_image_info* info_out);
/* Copies the image (width*height values) into a caller buffer; EOIR_ERR_NO_STATE
 * if no frame was rendered. Display kinds use eoir_image_get_bytes. */
EOIR_API eoir_status eoir_image_get(eoir_engine engine, const char* sensor, int32_t kind, double* values,
                                    size_t capacity);
/* The display images (spec 4.1.2) as bytes; made on the first request for a frame
 * (a render that nobody reads the displays of does not pay for them). */
EOIR_API eoir_status eoir_image_get_bytes(eoir_engine engine, const char* sensor, int32_t kind, uint8_t* bytes,
                                          size_t capacity);
/* 1.7: the detector stage's ADU image (width*height values, EOIR_IMAGE_SENSOR_ADU) into a caller buffer;
 * EOIR_ERR_NO_STATE if no frame was rendered or the frame was rendered with detector_model off. */
EOIR_API eoir_status eoir_image_get_adu(eoir_engine engine, const char* sensor, uint32_t* adu, size_t capacity);

/* "For Each Pixel Pick" (spec 6.2.1): what a scene sample (space 0) or a
 * sensor pixel (space 1, its centre sample) sees in the last frame. */
typedef struct eoir_pick {
  uint32_t struct_size;
  int32_t hit;               /* 0 sky, 1 object surface */
  char object[64];           /* object name, "" for the sky */
  int32_t patch;             /* patch dA index on that object, -1 for the sky */
  double range_m;            /* to the surface; the sky sphere's radius for the sky */
  int32_t has_geodetic;      /* central bodies: latitude/longitude valid */
  double latitude_deg;
  double longitude_deg;
  double right_ascension_deg; /* sky: J2000 RA/Dec of the sample direction */
  double declination_deg;
  double effective_radiance;  /* W/(cm^2 sr), eq. 48 */
  double temperature_K;
} eoir_pick;

/* wavelengths_um and spectral_radiance (W/(cm^2 sr um)) receive the spectral
 * radiance vector on the sensor's spectral grid (spec 5.3); they may be NULL
 * (then capacity is ignored); *count_out receives the grid size. */
EOIR_API eoir_status eoir_pick_get(eoir_engine engine, const char* sensor, int32_t space, uint32_t x, uint32_t y,
                                   eoir_pick* pick_out, double* wavelengths_um, double* spectral_radiance,
                                   size_t capacity, size_t* count_out);

/* Eq. 9's terms of the same sample, one per call (1.6; spec 4.1.5.3, the
 * components of 6.2.5.4), per interval of the sensor's spectral grid into
 * values (capacity values; *count_out the grid size; values may be NULL to
 * ask the size). Radiances in W/(cm^2 sr um). In vacuum T_out is 1 and the
 * path's terms are 0. Unknown term: EOIR_ERR_OUT_OF_RANGE naming "term". */
typedef enum eoir_pick_term {
  EOIR_PICK_TERM_SURFACE = 0,       /* leaving the surface: eq. 9's bracket (reflected light, DownWelling,
                                       emission); for the sky, the background light */
  EOIR_PICK_TERM_DOWNWELLING = 1,   /* of which DownWelling / pi x SRF */
  EOIR_PICK_TERM_TRANSMITTANCE = 2, /* T_out of the path to the sensor (dimensionless) */
  EOIR_PICK_TERM_PATH_THERMAL = 3,  /* L_path: the path's thermal emission */
  EOIR_PICK_TERM_PATH_SCATTER = 4,  /* L_scatter: sunlight its air scatters into the line of sight */
  EOIR_PICK_TERM_AT_SENSOR = 5      /* surface x T_out + L_path + L_scatter (eoir_pick_get's spectral radiance) */
} eoir_pick_term;
EOIR_API eoir_status eoir_pick_term_get(eoir_engine engine, const char* sensor, int32_t space, uint32_t x,
                                        uint32_t y, int32_t term, double* values, size_t capacity,
                                        size_t* count_out);

/* ------------------------------------------------------ targets and truth */
/* Sensor-to-target metrics (spec 5.13, Table 2) are data providers of group
 * "EOIR Sensor-to-Target Metrics" read with eoir_provider_get and a target.
 * The SNR is 0 while the target is outside the field of view or hidden
 * behind another object. */

/* The SNR access constraint (spec 7.8): the SNR of `target` seen by `sensor`
 * at `time` (NULL: the engine time; otherwise the engine time is set to it
 * first, and objects move from their last pushed states). Hosts call it
 * from their access computation as a constraint plugin. */
EOIR_API eoir_status eoir_snr_constraint(eoir_engine engine, const char* sensor, const char* target,
                                         const eoir_time* time, double* snr_out);

/* The spectral irradiance at the aperture of `target` seen by `sensor` as a
 * point (spec 4.1.6.1: its detailed or simple model, eq. 7 or the sum over
 * its tessellations) at the engine time, on the sensor's spectral grid:
 * wavelengths_um and irradiance (W/(cm^2 um)) may be NULL to ask for
 * *count_out. (1.3) */
EOIR_API eoir_status eoir_target_spectrum_get(eoir_engine engine, const char* sensor, const char* target,
                                              double* wavelengths_um, double* irradiance_W_cm2_um, size_t capacity,
                                              size_t* count_out);

/* Per-frame truth: each object in the field of the last frame of `sensor`
 * (central bodies only where imaged as point sources) and, with a star
 * field, each catalogue star imaged (1.3). Pixel positions are where the
 * image has them: from inside the Earth's atmosphere, stars and point
 * sources beyond the atmosphere appear raised toward the zenith by the
 * refraction (1.5); the directions (RA/Dec, azimuth/elevation) stay
 * unrefracted. Three directions (1.6): apparent (right_ascension_deg,
 * declination_deg: where the image has it, J2000 = GCRS axes; stars, the
 * Moon and planets at their apparent places, other objects at their
 * geometric direction), astrometric (ICRS as eoir_image_info's astrometric
 * WCS gives it at the object's pixel, refraction aside) and geometric (the
 * true direction at the frame time). */
#define EOIR_TRUTH_OBJECT 0
#define EOIR_TRUTH_STAR 1

typedef struct eoir_truth {
  uint32_t struct_size;
  char object[64];           /* object name, or the star's catalogue id */
  double pixel_x;            /* sub-pixel position, 0 = centre of pixel 0 (columns as images) */
  double pixel_y;            /* 0 = centre of the top row */
  double range_m;            /* 0 for stars */
  int32_t point_source;      /* 1: Omega_T < Omega_EIFOV (spec 5.13.1) */
  int32_t visible;           /* not hidden behind another object */
  double effective_irradiance;  /* W/cm^2, point sources (eq. 61) */
  double effective_radiance;    /* W/(cm^2 sr), extended targets (eq. 74) */
  double snr;                   /* eq. 65 or 76 */
  /* appended in 1.3; written only when struct_size covers them */
  int32_t kind;                 /* EOIR_TRUTH_OBJECT or EOIR_TRUTH_STAR */
  int32_t reserved;
  double right_ascension_deg;   /* direction from the sensor, apparent, J2000 axes */
  double declination_deg;
  double v_mag, b_v_mag;        /* stars: Johnson V and B-V; 0 for objects */
  double start_pixel_x, start_pixel_y;  /* position at the start and the end of the integration */
  double end_pixel_x, end_pixel_y;      /* (a point source's streak; the frame-time position otherwise) */
  /* appended in 1.5; written only when struct_size covers them */
  int32_t topocentric;          /* 1 if the sensor is within 100 km of the WGS84 ellipsoid: the next two hold */
  int32_t reserved_1_5;
  double azimuth_deg;           /* the direction of right_ascension_deg, declination_deg on the sensor's local */
  double elevation_deg;         /* horizon: from north through east in [0, 360), above the geodetic horizon
                                   (unrefracted); both 0 if topocentric is 0 */
  double air_mass;              /* air along the line of sight to the object, or toward space for a star, in
                                   sea-level vertical columns (spec 6.2.5.4: 1 straight up from sea level);
                                   0 while the Earth's atmosphere is off */
  /* appended in 1.6; written only when struct_size covers them */
  double astrometric_ra_deg;    /* the astrometric direction (ICRS) at the middle of the integration */
  double astrometric_dec_deg;
  double start_astrometric_ra_deg, start_astrometric_dec_deg;  /* ... at its start and its end */
  double end_astrometric_ra_deg, end_astrometric_dec_deg;
  double geometric_ra_deg;      /* the geometric direction at the frame time (no light time, no aberration, */
  double geometric_dec_deg;     /* no deflection; stars: the catalogue place with proper motion and parallax) */
} eoir_truth;

EOIR_API eoir_status eoir_truth_count(eoir_engine engine, const char* sensor, size_t* count_out);
EOIR_API eoir_status eoir_truth_get(eoir_engine engine, const char* sensor, size_t index, eoir_truth* truth_out);

/* ------------------------------------------------------------------- plugin */
/* The host's services, passed to the plugin entry point. Any pointer may be
 * NULL. Engines created after the entry call report to them: progress during
 * renders and series of data providers (a non-zero return cancels with
 * EOIR_ERR_CANCELLED), and log messages (a debug line per render). They are
 * called on the thread that made the engine call. */
typedef struct eoir_host_api {
  uint32_t struct_size;
  void* user;
  /* level: 0 debug, 1 info, 2 warning, 3 error */
  void (*log)(void* user, int32_t level, const char* message);
  /* fraction in [0, 1]; return non-zero to ask the engine to cancel */
  int32_t (*progress)(void* user, double fraction, const char* what);
} eoir_host_api;

/* Append-only function table of ABI major 1. New entries only at the end;
 * check struct_size before using one. */
typedef struct eoir_api_v1 {
  uint32_t struct_size;
  uint32_t abi_major;
  uint32_t abi_minor;
  uint32_t (*version)(void);
  const char* (*last_error)(void);
  const char* (*status_name)(eoir_status);
  eoir_status (*engine_create)(const eoir_engine_desc*, eoir_engine*);
  void (*engine_destroy)(eoir_engine);
  eoir_status (*engine_set_time)(eoir_engine, const eoir_time*);
  eoir_status (*engine_get_time)(eoir_engine, int32_t, eoir_time*);
  eoir_status (*time_from_iso)(const char*, eoir_time*);
  eoir_status (*time_to_iso)(const eoir_time*, char*, size_t);
  eoir_status (*object_add)(eoir_engine, int32_t, const char*);
  eoir_status (*sensor_add)(eoir_engine, const char*, const char*);
  eoir_status (*object_remove)(eoir_engine, const char*);
  eoir_status (*object_count)(eoir_engine, size_t*);
  eoir_status (*object_at)(eoir_engine, size_t, const char**, int32_t*);
  eoir_status (*object_set_state)(eoir_engine, const char*, const eoir_time*, const eoir_state*);
  eoir_status (*object_get_state)(eoir_engine, const char*, eoir_state*);
  eoir_status (*set_number)(eoir_engine, const char*, const char*, double);
  eoir_status (*set_integer)(eoir_engine, const char*, const char*, int64_t);
  eoir_status (*set_bool)(eoir_engine, const char*, const char*, int32_t);
  eoir_status (*set_string)(eoir_engine, const char*, const char*, const char*);
  eoir_status (*set_array)(eoir_engine, const char*, const char*, const double*, size_t);
  eoir_status (*get_number)(eoir_engine, const char*, const char*, double*);
  eoir_status (*get_integer)(eoir_engine, const char*, const char*, int64_t*);
  eoir_status (*get_bool)(eoir_engine, const char*, const char*, int32_t*);
  eoir_status (*get_string)(eoir_engine, const char*, const char*, char*, size_t);
  eoir_status (*get_array)(eoir_engine, const char*, const char*, double*, size_t, size_t*);
  eoir_status (*property_info_at)(eoir_engine, const char*, size_t, eoir_property_info*);
  eoir_status (*provider_group_at)(size_t, const char**);
  eoir_status (*provider_element_at)(const char*, size_t, eoir_element_info*);
  eoir_status (*provider_get)(eoir_engine, const char*, const char*, const char*, const char*, double*);
  eoir_status (*provider_get_curve)(eoir_engine, const char*, const char*, const char*, const char*,
                                    double*, double*, size_t, size_t*);
  eoir_status (*state_save)(eoir_engine, const char*);
  eoir_status (*state_load)(eoir_engine, const char*);
  eoir_status (*sensor_save)(eoir_engine, const char*, const char*);
  eoir_status (*sensor_load)(eoir_engine, const char*, const char*);
  /* appended in 1.1 (images) */
  eoir_status (*render)(eoir_engine, const char*);
  eoir_status (*image_info_get)(eoir_engine, const char*, int32_t, eoir_image_info*);
  eoir_status (*image_get)(eoir_engine, const char*, int32_t, double*, size_t);
  eoir_status (*image_get_bytes)(eoir_engine, const char*, int32_t, uint8_t*, size_t);
  eoir_status (*pick_get)(eoir_engine, const char*, int32_t, uint32_t, uint32_t, eoir_pick*, double*, double*,
                          size_t, size_t*);
  /* appended in 1.2 (targets) */
  eoir_status (*snr_constraint)(eoir_engine, const char*, const char*, const eoir_time*, double*);
  eoir_status (*truth_count)(eoir_engine, const char*, size_t*);
  eoir_status (*truth_get)(eoir_engine, const char*, size_t, eoir_truth*);
  /* appended in 1.3 */
  eoir_status (*provider_series)(eoir_engine, const char*, const char*, const char*, const char*, const eoir_time*,
                                 size_t, double*);
  eoir_status (*material_load)(eoir_engine, const char*);
  eoir_status (*spectrum_add)(eoir_engine, const char*, const double*, const double*, size_t);
  eoir_status (*target_spectrum_get)(eoir_engine, const char*, const char*, double*, double*, size_t, size_t*);
  /* appended in 1.4 (adaptive fidelity) */
  eoir_status (*frame_fidelity_get)(eoir_engine, const char*, char*, size_t, size_t*);
  /* appended in 1.5 (pointing) */
  eoir_status (*sensor_point_azel)(eoir_engine, const char*, double, double);
  eoir_status (*sensor_point_at)(eoir_engine, const char*, const char*);
  /* appended in 1.6 (eq. 9's terms) */
  eoir_status (*pick_term_get)(eoir_engine, const char*, int32_t, uint32_t, uint32_t, int32_t, double*, size_t,
                               size_t*);
  /* appended in 1.7 (the detector stage) */
  eoir_status (*image_get_adu)(eoir_engine, const char*, uint32_t*, size_t);
  /* appended in 1.7 (object limits) */
  eoir_status (*engine_set_limits)(eoir_engine, const eoir_limits*);
  eoir_status (*engine_get_limits)(eoir_engine, eoir_limits*);
} eoir_api_v1;

/* The plugin's one entry point (resolved by name with dlsym). Returns, in
 * *api_out, the table for abi_major (cast to eoir_api_v1* for major 1), or
 * EOIR_ERR_ABI_MISMATCH with a message naming both majors. The host table is
 * copied and kept for the process until the next call; host may be NULL,
 * which clears earlier callbacks. */
typedef eoir_status (*eoir_plugin_entry_fn)(uint32_t abi_major, const eoir_host_api* host, const void** api_out);
EOIR_API eoir_status eoir_plugin_entry(uint32_t abi_major, const eoir_host_api* host, const void** api_out);
#define EOIR_PLUGIN_ENTRY_SYMBOL "eoir_plugin_entry"

#ifdef __cplusplus
}
#endif
#endif /* EOIR_EOIR_H */

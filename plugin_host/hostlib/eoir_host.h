/*
 * eoir_host.h — the eoir CLI's host-side models as a small C library
 * (libeoir_host.so), for hosts that want scenarios without re-implementing
 * them: the Python package loads it with ctypes (eoir.Scenario), so a
 * scenario moves and points its objects exactly as `eoir run` does.
 *
 * A session loads the engine library (eoir_plugin_loader: the argument,
 * EOIR_LIBRARY, ...), creates an engine, registers a scenario file's bodies,
 * objects, sensors and properties, and on each set_time pushes every state
 * (fixed geodetic, Kepler, SGP4 from two-line elements, ephemeris; nadir,
 * fixed or target pointing). The engine handle is the library's: call the
 * eoir_* functions of that same library on it (a host that loaded the same
 * file shares it), never eoir_engine_destroy (the session owns it).
 *
 * Every call returns an eoir_status (eoir.h) and leaves a thread-local
 * message (eoir_host_last_error): a bad scenario file is
 * EOIR_ERR_CORRUPT_FILE naming the file and JSON path, engine errors keep
 * their status. JSON outputs go to caller buffers: *needed receives the
 * size with the '\0'; EOIR_ERR_BUFFER_TOO_SMALL if capacity is less.
 * C99; only eoir_host_* symbols are exported.
 */
#ifndef EOIR_HOST_H
#define EOIR_HOST_H

#include <stddef.h>
#include <stdint.h>

#include "eoir/eoir.h"

#ifdef __cplusplus
extern "C" {
#endif

#define EOIR_HOST_VERSION 2 /* 2: eoir_host_session_open_with */

typedef struct eoir_host_session_s* eoir_host_session;

EOIR_API uint32_t eoir_host_version(void);
EOIR_API const char* eoir_host_last_error(void);

/* library may be NULL (then EOIR_LIBRARY, the library beside the program,
 * the build's). seed and threads as eoir_engine_desc. Files the scenario
 * names must lie in its folder (README "Bounds"): one outside is
 * EOIR_ERR_CORRUPT_FILE naming the field. */
EOIR_API eoir_status eoir_host_session_open(const char* library, const char* scenario_file, uint64_t seed,
                                            uint32_t threads, eoir_host_session* session_out);
/* Option bits of eoir_host_session_open_with (version 2). */
#define EOIR_HOST_ALLOW_PATHS_OUTSIDE 1u /* the scenario may name files outside its folder */
/* eoir_host_session_open with options (EOIR_HOST_* bits; others are
 * EOIR_ERR_OUT_OF_RANGE naming options). */
EOIR_API eoir_status eoir_host_session_open_with(const char* library, const char* scenario_file, uint64_t seed,
                                                 uint32_t threads, uint32_t options,
                                                 eoir_host_session* session_out);
EOIR_API void eoir_host_session_close(eoir_host_session session);
/* The session's eoir_engine, and the path of the engine library it loaded. */
EOIR_API eoir_engine eoir_host_session_engine(eoir_host_session session);
EOIR_API const char* eoir_host_session_library(eoir_host_session session);

/* {"name", "description", "file", "start", "stop", "step_s", "objects":
 * [{"name", "kind", "motion"}], "sensors": [{"name", "parent"}]} */
EOIR_API eoir_status eoir_host_session_describe(eoir_host_session session, char* buffer, size_t capacity,
                                                size_t* needed);
/* The times of `eoir run`: start (NULL: the scenario's) to stop (NULL: the
 * scenario's), every step_s (<= 0: the scenario's), stop included; a JSON
 * array of ISO-8601 UTC strings. At most 1,000,000 steps. */
EOIR_API eoir_status eoir_host_session_times(eoir_host_session session, const char* start, const char* stop,
                                             double step_s, char* buffer, size_t capacity, size_t* needed);
/* Sets the engine time (ISO-8601 UTC) and pushes every object's state. */
EOIR_API eoir_status eoir_host_session_set_time(eoir_host_session session, const char* iso_utc);
/* The header cards `eoir run` writes into the FITS file of the last frame
 * rendered for `sensor` (image_kind EOIR_IMAGE_SCENE_RADIANCE,
 * _SENSOR_ELECTRONS, _SENSOR_MEAN, or _SENSOR_ADU of a frame rendered with
 * detector_model on): a JSON array of [key, value, comment]
 * (value a string, number, integer or bool; COMMENT/HISTORY cards have
 * key "COMMENT"/"HISTORY" and the text as value). */
EOIR_API eoir_status eoir_host_session_fits_header(eoir_host_session session, const char* sensor,
                                                   int32_t image_kind, int64_t frame_index, char* buffer,
                                                   size_t capacity, size_t* needed);
/* The per-frame truth `eoir run` writes for the last frame of `sensor`
 * (schemas/truth.schema.json: FITS pixels, ICRS RA/Dec, SNR...). */
EOIR_API eoir_status eoir_host_session_truth(eoir_host_session session, const char* sensor, char* buffer,
                                             size_t capacity, size_t* needed);

/* SGP4 from two-line elements at a UTC time: TEME (km, km/s, as SGP4 gives
 * it) and J2000 (m, m/s, as scenarios push it). Any output may be NULL. */
EOIR_API eoir_status eoir_host_tle_state(const char* line1, const char* line2, const char* iso_utc,
                                         double teme_position_km[3], double teme_velocity_km_s[3],
                                         double j2000_position_m[3], double j2000_velocity_m_s[3]);

#ifdef __cplusplus
}
#endif
#endif /* EOIR_HOST_H */

// `eoir run`: renders every sensor of a scenario over time through the C ABI
// (eoir_render, eoir_image_info_get, eoir_image_get, eoir_image_get_bytes)
// and writes FITS and PNG files plus summary.json
// (schemas/run_summary.schema.json) into an output directory.
#pragma once
#include <string>
#include <vector>

#include "engine.hpp"
#include "fits_writer.hpp"
#include "scenario.hpp"

namespace eoir::cli {

// The marker file of a run in progress (or interrupted) in the output folder.
constexpr const char* kIncompleteMarker = "INCOMPLETE";

struct RunOptions {
  std::string scenario_file;
  std::string out_dir;
  std::vector<double> times;         // seconds since J2000 (UTC-based, see iso_time.hpp)
  std::vector<std::string> sensors;  // empty: every sensor of the scenario
  bool quiet = false;
  bool cube = false;                 // also <sensor>_electrons_cube.fits (every frame, one 3-D image)
  std::string stretch;               // if not empty: every sensor's display_stretch (--stretch)
  std::string save_state;            // if not empty: eoir_state_save after the last frame
};

// Per frame (time step i, sensor s), in DIR:
//   <s>_<i:04d>_radiance.fits        scene radiance, 4x4 samples per pixel, W/(cm2 sr)
//   <s>_<i:04d>_electrons.fits       sensor response with noise, electrons
//   <s>_<i:04d>_mean_electrons.fits  noise-free sensor response, electrons
//   <s>_<i:04d>_scene.png            scene display bytes
//   <s>_<i:04d>_sensor.png           sensor display bytes
//   <s>_<i:04d>_truth.json           per-frame truth: the objects in the field
//                                    (eoir_truth_get; schemas/truth.schema.json)
// then summary.json. File names keep [A-Za-z0-9._-] of the sensor name and
// replace other characters with '_'. A frame with nothing in the field (no
// truth entry and a uniform scene radiance) or with more than half of its
// pixels saturated gets a line on stderr and an entry in its "warnings".
// Complete or not (issue 25 item 12): DIR/INCOMPLETE is written before the
// first frame (and an earlier summary.json removed); summary.json, written
// last, has "complete": true, and INCOMPLETE is removed after it. A failed
// run leaves INCOMPLETE with a line "failed: WHY"; a killed one leaves it
// as written. A run is complete iff summary.json exists.
// Throws EngineError, ScenarioError or std::runtime_error naming the problem.
// Returns the number of frames written.
std::size_t run_frames(Engine& engine, const Scenario& scenario, const RunOptions& options);

// The header cards `eoir run` writes into a FITS file of the last frame
// rendered for `sensor` (image_kind: EOIR_IMAGE_SCENE_RADIANCE,
// _SENSOR_ELECTRONS or _SENSOR_MEAN): the integration's times (DATE-OBS its
// start), the observer's place, BUNIT and detector cards, sensor, pointing
// and the astrometric TAN WCS. `index` is the FRAME card. Throws EngineError
// (also for an engine library older than C ABI 1.6).
eoir::imageio::FitsHeader frame_fits_header(Engine& engine, const Scenario& scenario, const SensorSpec& sensor,
                                            std::size_t index, int32_t image_kind);

// The per-frame truth `eoir run` writes (schemas/truth.schema.json) for the
// last frame rendered for `sensor`, as JSON text.
std::string frame_truth_json(Engine& engine, const Scenario& scenario, const std::string& sensor);

// The file-name form of a sensor name.
std::string file_stem(const std::string& sensor_name);

}  // namespace eoir::cli

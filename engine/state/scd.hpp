// The engine's whole state as a versioned JSON .scd file (spec 3.4,
// schemas/scd.schema.json), and one sensor's parameters on their own.
#pragma once
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "engine.hpp"

namespace eoir::state {

// Version 2 adds the user's materials and spectra (version 1 files still
// load), and its optional engine.limits the engine's object limits (written
// only when they differ from the default profile).
constexpr int scd_format_version = 2;
constexpr int sensor_format_version = 1;

nlohmann::json engine_to_json(const Engine& engine);
// Builds a complete new engine from `doc`; throws eoir::Error(corrupt_file or
// file_version) naming the JSON path of the problem. The threads and host
// callbacks of `options` are the restoring host's choice; the seed is the
// file's.
std::unique_ptr<Engine> engine_from_json(const nlohmann::json& doc, const EngineOptions& options);

nlohmann::json sensor_to_json(const universe::Object& sensor);
// Returns the parameters the file describes (validated, consistent).
sensor::SensorParameters sensor_from_json(const nlohmann::json& doc);

// Parse text as JSON (universe/json_document.hpp); a syntax error,
// truncation, duplicate key, deep nesting or overflow is corrupt_file naming
// the file and the JSON path.
nlohmann::json parse_document(const std::string& text, const std::string& path);

void save_engine(const Engine& engine, const std::string& path);
std::unique_ptr<Engine> load_engine(const std::string& path, const EngineOptions& options);
void save_sensor(const universe::Object& sensor, const std::string& path);
sensor::SensorParameters load_sensor(const std::string& path);

}  // namespace eoir::state

// eoir — the command-line host of the EOIR engine. It loads libeoir as a
// plugin (through eoir_plugin_loader, never by linking it), builds a scenario
// through the C ABI, drives time and states, and reports data providers.
//
// Exit status: 0 success, 1 bad command line, 2 bad scenario or an engine
// error (the message names the JSON path or the engine's complaint).
#include <chrono>
#include <cstddef>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "access.hpp"
#include "atomic_write.hpp"
#include "engine.hpp"
#include "iso_time.hpp"
#include "report.hpp"
#include "run.hpp"
#include "scenario.hpp"
#include "session.hpp"

#ifndef EOIR_CLI_VERSION
#define EOIR_CLI_VERSION "0.0.0"
#endif
#ifndef EOIR_SCENARIO_DIR_DEFAULT
#define EOIR_SCENARIO_DIR_DEFAULT "scenarios"
#endif

namespace {

using namespace eoir::cli;

constexpr const char* kTargetGroup = "EOIR Sensor-to-Target Metrics";

const char* const kUsage =
    "usage: eoir [--library PATH] [COMMAND ...]\n"
    "\n"
    "Headless EO/IR sensor engine, command-line host.\n"
    "\n"
    "commands:\n"
    "  (none)                 run the bundled demo scenario (scenarios/demo/default.json)\n"
    "                         and print its static sensor metrics\n"
    "  report SCENARIO --provider GROUP --sensor NAME [--target NAME]\n"
    "         [--start ISO] [--stop ISO] [--step SECONDS]\n"
    "         [--format json|csv] [--out FILE] [--quiet]\n"
    "                         evaluate every element of a data-provider group over time\n"
    "                         (default: the scenario start only; with --stop, every --step\n"
    "                         seconds, stop included; --step defaults to the scenario's step_s)\n"
    "  run SCENARIO --out DIR [--start ISO] [--stop ISO] [--step SECONDS]\n"
    "         [--sensor NAME ...] [--quiet]\n"
    "                         render every sensor (or those named) at each time step and\n"
    "                         write per frame <sensor>_<NNNN>_radiance.fits,\n"
    "                         _electrons.fits, _mean_electrons.fits, _scene.png, _sensor.png,\n"
    "                         _truth.json (the objects in the field: pixel, range, SNR)\n"
    "                         and a summary.json into DIR (created if missing); the times\n"
    "                         default to the scenario's start, stop and step_s\n"
    "  access SCENARIO --sensor NAME --target NAME --min-snr X\n"
    "         [--start ISO] [--stop ISO] [--step SECONDS] [--format json|csv] [--out FILE] [--quiet]\n"
    "                         intervals where the SNR of the target seen by the sensor is >= X\n"
    "                         (spec 7.8 SNR access constraint): the SNR is sampled every --step\n"
    "                         seconds (default: the scenario's start, stop and step_s) and each\n"
    "                         crossing is refined by bisection to 1 ms; times with milliseconds\n"
    "  validate SCENARIO      check a scenario file and load it into an engine\n"
    "  groups                 list the data-provider groups and their elements\n"
    "  --help, -h             this help\n"
    "  --version              program and engine versions\n"
    "\n"
    "options:\n"
    "  --library PATH         engine library to load (else $EOIR_LIBRARY, else the build's)\n"
    "\n"
    "environment: EOIR_LIBRARY (engine library), EOIR_SCENARIO_DIR (bundled scenarios)\n"
    "exit status: 0 ok, 1 bad command line, 2 bad scenario or engine error\n";

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string scenario_dir() {
  const char* env = std::getenv("EOIR_SCENARIO_DIR");
  return (env != nullptr && env[0] != '\0') ? env : EOIR_SCENARIO_DIR_DEFAULT;
}

double parse_seconds(const std::string& s, const char* option) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end == nullptr || *end != '\0' || !std::isfinite(v))
    throw UsageError(std::string(option) + ": '" + s + "' is not a number of seconds");
  return v;
}

double parse_time_option(const std::string& s, const char* option) {
  try {
    return parse_iso(s);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string(option) + ": " + e.what());
  }
}

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "'" : ", '") + s + "'";
  return out.empty() ? "(none)" : out;
}

// Names of the engine's objects of a kind (0 = any).
std::vector<std::string> engine_objects(const Engine& engine, int32_t kind) {
  std::vector<std::string> names;
  std::size_t n = 0;
  engine.check(engine.api().object_count(engine.handle(), &n), "object_count");
  for (std::size_t i = 0; i < n; ++i) {
    const char* name = nullptr;
    int32_t k = 0;
    engine.check(engine.api().object_at(engine.handle(), i, &name, &k), "object_at");
    if (kind == 0 || k == kind) names.emplace_back(name ? name : "");
  }
  return names;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  for (const auto& x : v)
    if (x == s) return true;
  return false;
}

// Writes through a temporary file renamed into place, or to stdout.
void emit(const std::optional<std::string>& out_file, const std::string& text) {
  if (!out_file) {
    std::cout << text;
    std::cout.flush();
    return;
  }
  try {
    eoir::imageio::write_file_atomically(*out_file, text.data(), text.size());
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("--out: ") + e.what());
  }
}

// Command-line options of one command: "--name value" options (repeatable
// ones collect every value), flags, and one positional SCENARIO.
struct Options {
  std::optional<std::string> scenario;
  std::map<std::string, std::vector<std::string>> values;
  std::map<std::string, bool> flags;
  std::optional<std::string> get(const std::string& name) const {
    auto it = values.find(name);
    if (it == values.end() || it->second.empty()) return std::nullopt;
    return it->second.back();
  }
};

// `numbers_as_values`: a token like "-5" is a value, not an option (access's
// --min-snr -5 is then refused by its own check).
Options parse_options(const std::vector<std::string>& args, const std::string& command,
                      const std::vector<std::string>& valued, const std::vector<std::string>& flags,
                      bool numbers_as_values = false) {
  Options o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (contains(valued, a)) {
      if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
      o.values[a].push_back(args[++i]);
    } else if (a == "--quiet" || a == "-q") {
      if (!contains(flags, "--quiet")) throw UsageError(command + ": unknown option " + a);
      o.flags["--quiet"] = true;
    } else if (contains(flags, a)) {
      o.flags[a] = true;
    } else if (a.size() > 1 && a[0] == '-' && !(numbers_as_values && a[1] >= '0' && a[1] <= '9')) {
      throw UsageError(command + ": unknown option " + a);
    } else if (!o.scenario) {
      o.scenario = a;
    } else {
      throw UsageError(command + ": unexpected argument '" + a + "'");
    }
  }
  return o;
}

// --start, --stop and --step, checked (the scenario supplies the defaults).
struct TimeRange {
  std::optional<double> start_s, stop_s, step_s;
};

TimeRange parse_time_range(const Options& o) {
  TimeRange r;
  if (const auto step = o.get("--step")) {
    r.step_s = parse_seconds(*step, "--step");
    if (!(*r.step_s > 0)) throw UsageError("--step: must be positive, not " + *step);
  }
  if (const auto start = o.get("--start")) r.start_s = parse_time_option(*start, "--start");
  if (const auto stop = o.get("--stop")) r.stop_s = parse_time_option(*stop, "--stop");
  if (r.start_s && r.stop_s && *r.stop_s < *r.start_s)
    throw UsageError("--stop " + *o.get("--stop") + " is before --start " + *o.get("--start"));
  return r;
}

// The scenario's stop unless --stop is given (or --start lies past it).
double default_stop(const TimeRange& r, const Scenario& sc) {
  const double t0 = r.start_s.value_or(sc.start_s);
  return r.stop_s.value_or(r.start_s && *r.start_s > sc.stop_s ? t0 : sc.stop_s);
}

// t0, t0 + dt, ... up to t1, with t1 itself always last.
std::vector<double> step_times(double t0, double t1, double dt, const std::string& command, std::size_t most) {
  if (t1 < t0) throw UsageError("--stop " + format_iso(t1) + " is before the start " + format_iso(t0));
  std::vector<double> times;
  for (long long k = 0;; ++k) {
    const double t = t0 + static_cast<double>(k) * dt;
    if (t > t1 + 1e-6) break;
    times.push_back(t);
    if (times.size() > most)
      throw UsageError(command + ": more than " + std::to_string(most) + " time steps; use a larger --step");
  }
  if (times.back() < t1 - 1e-6) times.push_back(t1);
  return times;
}

int cmd_report(const std::vector<std::string>& args, const char* library) {
  const Options o = parse_options(
      args, "report", {"--provider", "--sensor", "--target", "--start", "--stop", "--step", "--format", "--out"},
      {"--quiet"});
  const auto scenario_file = o.scenario, provider = o.get("--provider"), sensor = o.get("--sensor"),
             target = o.get("--target"), out_file = o.get("--out");
  const std::string format = o.get("--format").value_or("json");
  const bool quiet = o.flags.count("--quiet") > 0;
  if (!scenario_file) throw UsageError("report: missing SCENARIO");
  if (!provider) throw UsageError("report: missing --provider GROUP");
  if (!sensor) throw UsageError("report: missing --sensor NAME");
  if (format != "json" && format != "csv") throw UsageError("--format: '" + format + "' is not json or csv");
  const TimeRange range = parse_time_range(o);

  const Scenario sc = load_scenario(*scenario_file);
  const double t0 = range.start_s.value_or(sc.start_s);
  const double t1 = range.stop_s.value_or(t0);  // a report defaults to one row
  const std::vector<double> times = step_times(t0, t1, range.step_s.value_or(sc.step_s), "report", 10000000);

  Engine engine(library);
  Session session(engine, sc);
  const std::vector<std::string> groups = provider_groups(engine.api());
  if (!contains(groups, *provider))
    throw UsageError("--provider: unknown data-provider group '" + *provider + "'; known groups: " + join(groups));
  const std::vector<std::string> sensors = engine_objects(engine, EOIR_KIND_SENSOR);
  if (!contains(sensors, *sensor))
    throw UsageError("--sensor: unknown sensor '" + *sensor + "' in " + *scenario_file + "; sensors: " + join(sensors));
  if (target && !contains(engine_objects(engine, 0), *target))
    throw UsageError("--target: unknown object '" + *target + "' in " + *scenario_file);
  if (*provider == kTargetGroup && !target)
    throw UsageError("--provider '" + *provider + "' needs --target NAME");
  const std::vector<ElementInfo> elements = provider_elements(engine.api(), *provider);

  std::vector<ReportRow> rows;
  rows.reserve(times.size());
  const auto began = std::chrono::steady_clock::now();
  bool progress_shown = false;
  // On a terminal a line rewritten in place every 1 %; otherwise a line every 10 %.
  const bool tty = isatty(fileno(stderr)) != 0;
  const std::size_t every = std::max<std::size_t>(1, times.size() / (tty ? 100 : 10));
  for (std::size_t i = 0; i < times.size(); ++i) {
    session.set_time(times[i]);
    rows.push_back(evaluate_row(engine, *provider, elements, *sensor, target, times[i]));
    if (!quiet) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
      if ((times.size() > 100 || elapsed > 2.0) && ((i + 1) % every == 0 || i + 1 == times.size())) {
        std::fprintf(stderr, "%seoir report: %zu/%zu rows (%.0f %%)%s", tty ? "\r" : "", i + 1, times.size(),
                     100.0 * static_cast<double>(i + 1) / static_cast<double>(times.size()), tty ? "" : "\n");
        progress_shown = tty;
      }
    }
  }
  if (progress_shown) std::fprintf(stderr, "\n");

  std::ostringstream text;
  if (format == "json") {
    write_json(text, *provider, *sensor, target, rows);
  } else if (write_csv(text, elements, rows)) {
    std::fprintf(stderr, "eoir report: curve elements are not written to CSV (use --format json)\n");
  }
  emit(out_file, text.str());
  return 0;
}

int cmd_run(const std::vector<std::string>& args, const char* library) {
  const Options o = parse_options(args, "run", {"--out", "--start", "--stop", "--step", "--sensor"}, {"--quiet"});
  const auto scenario_file = o.scenario, out_dir = o.get("--out");
  RunOptions opt;
  if (o.values.count("--sensor")) opt.sensors = o.values.at("--sensor");
  opt.quiet = o.flags.count("--quiet") > 0;
  if (!scenario_file) throw UsageError("run: missing SCENARIO");
  if (!out_dir) throw UsageError("run: missing --out DIR");
  if (out_dir->empty()) throw UsageError("--out: empty directory name");
  const TimeRange range = parse_time_range(o);

  const Scenario sc = load_scenario(*scenario_file);
  const double t0 = range.start_s.value_or(sc.start_s);
  opt.times = step_times(t0, default_stop(range, sc), range.step_s.value_or(sc.step_s), "run", 9999);
  opt.scenario_file = *scenario_file;
  opt.out_dir = *out_dir;

  Engine engine(library);
  run_frames(engine, sc, opt);
  return 0;
}

// ISO time with milliseconds always written ("...:05.000Z").
std::string format_iso_ms(double t_s) {
  std::string s = format_iso(t_s);
  if (s.find('.') == std::string::npos && !s.empty() && s.back() == 'Z') s.insert(s.size() - 1, ".000");
  return s;
}

// True if the function table has the entry at byte offset `offset`.
bool api_has(const eoir_api_v1& api, std::size_t offset_end) { return api.struct_size >= offset_end; }

int cmd_access(const std::vector<std::string>& args, const char* library) {
  const Options o = parse_options(
      args, "access", {"--sensor", "--target", "--min-snr", "--start", "--stop", "--step", "--format", "--out"},
      {"--quiet"}, true);
  const auto scenario_file = o.scenario, sensor = o.get("--sensor"), target = o.get("--target"),
             min_snr_text = o.get("--min-snr"), out_file = o.get("--out");
  const std::string format = o.get("--format").value_or("json");
  const bool quiet = o.flags.count("--quiet") > 0;
  if (!scenario_file) throw UsageError("access: missing SCENARIO");
  if (!sensor) throw UsageError("access: missing --sensor NAME");
  if (!target) throw UsageError("access: missing --target NAME");
  if (!min_snr_text) throw UsageError("access: missing --min-snr X");
  if (format != "json" && format != "csv") throw UsageError("--format: '" + format + "' is not json or csv");
  double min_snr = 0;
  {
    char* end = nullptr;
    const std::string& m = *min_snr_text;
    min_snr = std::strtod(m.c_str(), &end);
    if (m.empty() || end == nullptr || *end != '\0' || !std::isfinite(min_snr))
      throw UsageError("--min-snr: '" + m + "' is not a finite number");
  }
  const TimeRange range = parse_time_range(o);

  const Scenario sc = load_scenario(*scenario_file);
  // Times in whole milliseconds on the host time line (iso_time.hpp).
  const auto to_ms = [](double t) { return static_cast<int64_t>(std::llround(t * 1000.0)); };
  const int64_t t0 = to_ms(range.start_s.value_or(sc.start_s));
  const int64_t t1 = to_ms(default_stop(range, sc));
  if (t1 < t0)
    throw UsageError("--stop " + format_iso(static_cast<double>(t1) / 1000.0) + " is before the start " +
                     format_iso(static_cast<double>(t0) / 1000.0));
  const double dt = range.step_s.value_or(sc.step_s);
  const int64_t dt_ms = to_ms(dt);
  if (dt_ms < 1) throw UsageError("--step: " + std::to_string(dt) + " s is below the 1 ms resolution of times");
  std::vector<int64_t> samples;
  for (int64_t t = t0; t <= t1; t += dt_ms) {
    samples.push_back(t);
    if (samples.size() > 10000000) throw UsageError("access: more than 10^7 steps; use a larger --step");
  }
  if (samples.back() < t1) samples.push_back(t1);

  Engine engine(library);
  Session session(engine, sc);
  const eoir_api_v1& api = engine.api();
  if (!api_has(api, offsetof(eoir_api_v1, snr_constraint) + sizeof api.snr_constraint) || api.snr_constraint == nullptr)
    throw std::runtime_error(std::string("the engine library ") + engine.library_path() +
                             " has no SNR constraint (C ABI 1.2 needed)");
  const std::vector<std::string> sensors = engine_objects(engine, EOIR_KIND_SENSOR);
  if (!contains(sensors, *sensor))
    throw UsageError("--sensor: unknown sensor '" + *sensor + "' in " + *scenario_file + "; sensors: " + join(sensors));
  const std::vector<std::string> objects = engine_objects(engine, 0);
  if (!contains(objects, *target))
    throw UsageError("--target: unknown object '" + *target + "' in " + *scenario_file + "; objects: " + join(objects));

  const auto snr_at = [&](int64_t ms) {
    const double t = static_cast<double>(ms) / 1000.0;
    session.set_time(t);
    const std::string iso = format_iso(t);
    eoir_time time{};
    engine.check(api.time_from_iso(iso.c_str(), &time), "time " + iso);
    double snr = 0;
    const eoir_status s = api.snr_constraint(engine.handle(), sensor->c_str(), target->c_str(), &time, &snr);
    if (s == EOIR_ERR_NOT_ALLOWED) {
      const SensorSpec* spec = sc.find_sensor(*sensor);
      const bool parent = spec != nullptr && spec->parent == *target;
      throw UsageError("--target: the engine refuses target '" + *target + "' for sensor '" + *sensor + "'" +
                       (parent ? " (it is the sensor's parent)" : "") + ": " + api.last_error() + " (" +
                       api.status_name(s) + ")");
    }
    engine.check(s, "SNR of " + *target + " seen by " + *sensor + " at " + iso);
    return snr;
  };

  const auto began = std::chrono::steady_clock::now();
  const bool tty = isatty(fileno(stderr)) != 0;
  bool progress_open = false;
  const auto progress = [&](const char* phase, std::size_t done, std::size_t total) {
    if (quiet || total == 0) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    if (samples.size() <= 100 && elapsed <= 2.0) return;
    const std::size_t every = std::max<std::size_t>(1, total / (tty ? 100 : 10));
    if (done % every != 0 && done != total) return;
    std::fprintf(stderr, "%seoir access: %s %zu/%zu (%zu %%)%s", tty ? "\r\033[K" : "",
                 std::strcmp(phase, "sample") == 0 ? "sampled steps" : "refined boundaries", done, total,
                 done * 100 / total, tty ? "" : "\n");
    if (tty && done == total) std::fprintf(stderr, "\n");
    progress_open = tty && done != total;
  };
  const AccessResult result =
      find_access(samples, [&](int64_t ms) { const double v = snr_at(ms); return v >= min_snr; }, progress);
  if (progress_open) std::fprintf(stderr, "\n");
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();

  const double tolerance_s = 0.001;
  std::ostringstream text;
  if (format == "json") {
    nlohmann::ordered_json doc;
    doc["sensor"] = *sensor;
    doc["target"] = *target;
    doc["min_snr"] = min_snr;
    doc["start"] = format_iso_ms(static_cast<double>(t0) / 1000.0);
    doc["stop"] = format_iso_ms(static_cast<double>(t1) / 1000.0);
    doc["step_s"] = static_cast<double>(dt_ms) / 1000.0;
    doc["tolerance_s"] = tolerance_s;
    doc["intervals"] = nlohmann::ordered_json::array();
    for (const AccessInterval& iv : result.intervals) {
      nlohmann::ordered_json j;
      j["start"] = format_iso_ms(static_cast<double>(iv.start_ms) / 1000.0);
      j["stop"] = format_iso_ms(static_cast<double>(iv.stop_ms) / 1000.0);
      j["duration_s"] = static_cast<double>(iv.stop_ms - iv.start_ms) / 1000.0;
      doc["intervals"].push_back(std::move(j));
    }
    doc["evaluations"] = result.evaluations;
    text << doc.dump(2) << "\n";
  } else {
    text << "start,stop,duration_s\n";
    for (const AccessInterval& iv : result.intervals) {
      char d[64];
      std::snprintf(d, sizeof d, "%.3f", static_cast<double>(iv.stop_ms - iv.start_ms) / 1000.0);
      text << format_iso_ms(static_cast<double>(iv.start_ms) / 1000.0) << ","
           << format_iso_ms(static_cast<double>(iv.stop_ms) / 1000.0) << "," << d << "\n";
    }
  }
  emit(out_file, text.str());
  if (!quiet)
    std::fprintf(stderr, "eoir access: %zu interval%s with SNR >= %g, %zu SNR evaluations, %.2f s\n",
                 result.intervals.size(), result.intervals.size() == 1 ? "" : "s", min_snr, result.evaluations, wall);
  return 0;
}

int cmd_validate(const std::vector<std::string>& args, const char* library) {
  if (args.size() != 1) throw UsageError("validate: expected exactly one SCENARIO");
  const Scenario sc = load_scenario(args[0]);
  Engine engine(library);
  Session session(engine, sc);
  std::size_t steps = 0;
  for (long long k = 0;; ++k) {
    const double t = sc.start_s + static_cast<double>(k) * sc.step_s;
    if (t > sc.stop_s + 1e-6) break;
    session.set_time(t);
    if (++steps > 1000000) break;
  }
  session.set_time(sc.stop_s);
  std::printf("%s: valid (scenario '%s': %zu objects, %zu sensors, %zu time steps)\n", args[0].c_str(),
              sc.name.c_str(), sc.objects.size(), sc.sensors.size(), steps);
  return 0;
}

int cmd_default(const char* library) {
  const std::string file = scenario_dir() + "/demo/default.json";
  const Scenario sc = load_scenario(file);
  Engine engine(library);
  Session session(engine, sc);
  session.set_time(sc.start_s);
  std::cout << "EOIR " << EOIR_CLI_VERSION << " (engine " << engine.api().version() / 10000 << "."
            << engine.api().version() / 100 % 100 << "." << engine.api().version() % 100 << ", "
            << engine.library_path() << ")\n"
            << "scenario: " << sc.name << " (" << file << ")\n";
  if (!sc.description.empty()) std::cout << sc.description << "\n";
  std::cout << "time: " << format_iso(sc.start_s) << "\n";
  for (const SensorSpec& s : sc.sensors) {
    std::cout << "\nsensor " << s.name << " on " << s.parent << "\n";
    for (const std::string& group : provider_groups(engine.api())) {
      if (group == kTargetGroup) continue;  // needs a target
      const std::vector<ElementInfo> elements = provider_elements(engine.api(), group);
      try {
        const ReportRow row = evaluate_row(engine, group, elements, s.name, std::nullopt, sc.start_s);
        std::cout << "\n";
        write_table(std::cout, group, row);
      } catch (const EngineError& e) {
        std::cerr << "eoir: skipped " << group << ": " << e.what() << "\n";
      }
    }
  }
  std::cout << "\nRun `eoir --help` for the commands.\n";
  return 0;
}

int cmd_groups(const char* library) {
  Engine engine(library);
  for (const std::string& g : provider_groups(engine.api())) {
    std::cout << g << "\n";
    for (const ElementInfo& e : provider_elements(engine.api(), g))
      std::cout << "  " << e.name << (e.unit.empty() ? "" : " [" + e.unit + "]")
                << (e.type == EOIR_TYPE_CURVE ? " (curve vs " + e.x_unit + ")" : "") << "\n";
  }
  return 0;
}

int cmd_version(const char* library) {
  std::cout << "eoir " << EOIR_CLI_VERSION << " (C ABI " << EOIR_VERSION_MAJOR << "." << EOIR_VERSION_MINOR << ")\n";
  try {
    Engine engine(library);
    const uint32_t v = engine.api().version();
    std::cout << "engine " << v / 10000 << "." << v / 100 % 100 << "." << v % 100 << " (" << engine.library_path()
              << ")\n";
  } catch (const std::exception& e) {
    std::cout << "engine: not loaded (" << e.what() << ")\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string library_storage;
  const char* library = nullptr;
  try {
    if (args.size() >= 2 && args[0] == "--library") {
      library_storage = args[1];
      library = library_storage.c_str();
      args.erase(args.begin(), args.begin() + 2);
    }
    if (args.empty()) return cmd_default(library);
    const std::string cmd = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
      std::cout << kUsage;
      return 0;
    }
    if (cmd == "--version") return cmd_version(library);
    if (cmd == "report") return cmd_report(rest, library);
    if (cmd == "run") return cmd_run(rest, library);
    if (cmd == "access") return cmd_access(rest, library);
    if (cmd == "validate") return cmd_validate(rest, library);
    if (cmd == "groups") return cmd_groups(library);
    throw UsageError("unknown command '" + cmd + "'");
  } catch (const UsageError& e) {
    std::cerr << "eoir: " << e.what() << "\n(run `eoir --help` for usage)\n";
    return 1;
  } catch (const ScenarioError& e) {
    std::cerr << "eoir: " << e.what() << "\n";
    return 2;
  } catch (const EngineError& e) {
    std::cerr << "eoir: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "eoir: " << e.what() << "\n";
    return 2;
  }
}

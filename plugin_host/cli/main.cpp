// eoir — the command-line host of the EOIR engine. It loads libeoir as a
// plugin (through eoir_plugin_loader, never by linking it), builds a scenario
// through the C ABI, drives time and states, and reports data providers.
//
// Exit status: 0 success, 1 bad command line, 2 bad scenario or an engine
// error (the message names the JSON path or the engine's complaint).
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include <cerrno>

#include "access.hpp"
#include "atomic_write.hpp"
#include "engine.hpp"
#include "iso_time.hpp"
#include "pick.hpp"
#include "report.hpp"
#include "run.hpp"
#include "scenario.hpp"
#include "session.hpp"
#include "suggest.hpp"
#include "time_steps.hpp"

#ifndef EOIR_CLI_VERSION
#define EOIR_CLI_VERSION "0.0.0"
#endif
#ifndef EOIR_SONAME
#define EOIR_SONAME "libeoir.so"
#endif
#ifndef EOIR_SCENARIO_DIR_DEFAULT
#define EOIR_SCENARIO_DIR_DEFAULT "scenarios"
#endif

namespace {

using namespace eoir::cli;

constexpr const char* kTargetGroup = "EOIR Sensor-to-Target Metrics";

const char* const kUsage =
    "usage: eoir [--library PATH] [--seed N] [--threads N] [COMMAND ...]\n"
    "\n"
    "Headless EO/IR sensor engine, command-line host.\n"
    "\n"
    "commands:\n"
    "  (none)                 run the bundled demo scenario (scenarios/demo/default.json)\n"
    "                         and print its static sensor metrics\n"
    "  report SCENARIO --provider GROUP --sensor NAME [--target NAME] ...\n"
    "                         evaluate every element of a data-provider group over time\n"
    "  run SCENARIO --out DIR [--sensor NAME ...] [--cube] ...\n"
    "                         render every sensor at each time step: FITS, PNG, truth, regions\n"
    "  access SCENARIO --sensor NAME --target NAME --min-snr X ...\n"
    "                         intervals where the target's SNR is >= X (spec 7.8)\n"
    "  pick SCENARIO --sensor NAME --x N --y N ...\n"
    "                         eq. 9 term by term per spectral interval at one sample or pixel\n"
    "  validate SCENARIO      check a scenario file as `run` would, without rendering\n"
    "  properties KIND        every property of a kind: type, unit, default, description\n"
    "  save-state SCENARIO --out FILE [--time ISO]\n"
    "                         the engine state of a scenario at a time, as a .scd file\n"
    "  load-state FILE        restore a .scd file; print its time, objects and sensor metrics\n"
    "  groups                 list the data-provider groups and their elements\n"
    "  help [COMMAND]         this help, or a command's\n"
    "  --version              the versions: program, C ABI, soname, data, Python package,\n"
    "                         and the engine library loaded\n"
    "\n"
    "`eoir COMMAND --help` describes a command. Options take their value as\n"
    "`--name value` or `--name=value`.\n"
    "\n"
    "options of every command that creates an engine:\n"
    "  --library PATH         engine library to load (else $EOIR_LIBRARY, else the one\n"
    "                         beside this program, else the build's)\n"
    "  --seed N               seed of the engine's noise generator (default 1)\n"
    "  --threads N            worker threads, 0 = all cores (default 0)\n"
    "\n"
    "environment: EOIR_LIBRARY (engine library), EOIR_SCENARIO_DIR (bundled scenarios)\n"
    "exit status: 0 ok, 1 bad command line, 2 bad scenario or engine error\n";

const char* const kEngineOptions =
    "  --library PATH    engine library; --seed N   noise seed (default 1);\n"
    "  --threads N       worker threads, 0 = all cores (default 0); --help   this help\n";

const char* const kTimeOptions =
    "  --start ISO       first time (default: the scenario's start)\n"
    "  --stop ISO        last time, always included (default: the scenario's stop)\n"
    "  --step SECONDS    time step (default: the scenario's step_s)\n";

struct CommandSpec {
  std::string name;
  std::string usage;                // first lines of `eoir NAME --help`
  std::vector<std::string> valued;  // options with a value
  std::vector<std::string> flags;
  bool numbers_as_values = false;   // "-5" is a value, not an option
  bool engine = true;               // takes --library, --seed, --threads
};

const std::vector<CommandSpec>& commands() {
  static const std::vector<CommandSpec> specs = {
      {"report",
       "usage: eoir report SCENARIO --provider GROUP --sensor NAME [--target NAME]\n"
       "                   [--start ISO] [--stop ISO] [--step SECONDS]\n"
       "                   [--format json|csv] [--out FILE] [--quiet]\n"
       "\n"
       "Evaluates every element of a data-provider group (`eoir groups`) at each time\n"
       "step of the scenario (start to stop, every step_s, stop included).\n"
       "\n"
       "  --provider GROUP  data-provider group, e.g. \"EOIR Sensor Optics\"\n"
       "  --sensor NAME     sensor of the scenario\n"
       "  --target NAME     target object (needed by \"EOIR Sensor-to-Target Metrics\")\n",
       {"--provider", "--sensor", "--target", "--start", "--stop", "--step", "--format", "--out"},
       {"--quiet", "--allow-paths-outside"}},
      {"run",
       "usage: eoir run SCENARIO --out DIR [--start ISO] [--stop ISO] [--step SECONDS]\n"
       "                [--sensor NAME ...] [--cube] [--stretch NAME] [--save-state FILE] [--quiet]\n"
       "\n"
       "Renders every sensor (or those named) at each time step and writes into DIR\n"
       "(created if missing), per frame <sensor>_<NNNN>_:\n"
       "  radiance.fits, electrons.fits, mean_electrons.fits  images with an astrometric\n"
       "                    TAN WCS (ICRS, as a plate solution gives it), DATE-OBS (start\n"
       "                    of the integration), DATE-AVG, DATE-END, BUNIT, OBSGEO; FITS row\n"
       "                    1 is the bottom row, as ds9 shows the PNG\n"
       "  scene.png, sensor.png   display images (saturated pixels white)\n"
       "  truth.json        objects in the field: FITS pixel (1-based), astrometric RA/Dec\n"
       "                    (and apparent, geometric), range, SNR\n"
       "  truth.reg         the same as a ds9 region file (fk5 circles with labels)\n"
       "and summary.json.\n"
       "\n"
       "  --sensor NAME     render only this sensor (repeatable)\n"
       "  --cube            also write <sensor>_electrons_cube.fits: every frame of the run\n"
       "                    as one 3-D FITS data cube (NAXIS3 = time step, per-plane times\n"
       "                    in a TIMES table extension), streamed plane by plane as the\n"
       "                    frames are rendered (memory does not grow with the run)\n"
       "  --stretch NAME    display stretch of the PNGs for every sensor: linear, log,\n"
       "                    asinh or zscale (default: each sensor's display_stretch)\n"
       "  --save-state FILE save the engine state after the last frame (.scd)\n"
       "A frame with nothing in the field (no object or star, a uniform scene) or with\n"
       "more than half of its pixels saturated is warned about on stderr and in\n"
       "summary.json (the frame's \"warnings\").\n",
       {"--out", "--start", "--stop", "--step", "--sensor", "--save-state", "--stretch"},
       {"--quiet", "--cube", "--allow-paths-outside"}},
      {"access",
       "usage: eoir access SCENARIO --sensor NAME --target NAME --min-snr X\n"
       "                   [--start ISO] [--stop ISO] [--step SECONDS]\n"
       "                   [--format json|csv] [--out FILE] [--quiet]\n"
       "\n"
       "Intervals where the SNR of the target seen by the sensor is >= X (spec 7.8 SNR\n"
       "access constraint): the SNR is sampled every step and each crossing is refined\n"
       "by bisection to 1 ms.\n",
       {"--sensor", "--target", "--min-snr", "--start", "--stop", "--step", "--format", "--out"},
       {"--quiet", "--allow-paths-outside"},
       true},
      {"pick",
       "usage: eoir pick SCENARIO --sensor NAME --x N --y N [--space sample|pixel]\n"
       "                 [--time ISO] [--format csv|json] [--out FILE]\n"
       "\n"
       "Renders the sensor at --time (default: the scenario's start) and prints what one\n"
       "scene sample or sensor pixel (its centre sample) sees, eq. 9 term by term per\n"
       "spectral interval (spec 4.1.5.3; the components of 6.2.5.4): wavelength_um,\n"
       "surface (what leaves the surface: reflected light, DownWelling, emission; the\n"
       "background light for the sky), downwelling (of which DownWelling), transmittance\n"
       "(T_out), path_thermal (L_path), path_scatter (L_scatter) and at_sensor\n"
       "(surface x transmittance + path_thermal + path_scatter), radiances in\n"
       "W/(cm^2 sr um); with the object hit, latitude/longitude and effective radiance.\n"
       "\n"
       "  --sensor NAME     sensor of the scenario\n"
       "  --x N, --y N      column and row from the top (0-based)\n"
       "  --space S         sample (scene samples, the default) or pixel\n"
       "  --time ISO        time of the frame (default: the scenario's start)\n",
       {"--sensor", "--x", "--y", "--space", "--time", "--format", "--out"},
       {"--allow-paths-outside"}},
      {"validate",
       "usage: eoir validate SCENARIO\n"
       "\n"
       "Checks a scenario as `run` would without rendering: the file (schema rules,\n"
       "names, orbits above the central body's surface), every property through the\n"
       "engine, every sensor's parameters together (band edges in order...), and every\n"
       "object's motion at each time step from start to stop.\n",
       {},
       {"--allow-paths-outside"}},
      {"properties",
       "usage: eoir properties KIND [--format table|json]\n"
       "\n"
       "Every property of a kind of object, with its type, unit, default, range and\n"
       "meaning. KIND: sensor, satellite, aircraft, ground_vehicle, missile, site,\n"
       "star_field, central_body (the Earth's defaults) or a central body's name\n"
       "(Sun, Moon...). Defaults are read from a fresh engine; ranges are the\n"
       "engine's (eoir_property_info): a value outside one is refused when set.\n",
       {"--format"},
       {}},
      {"save-state",
       "usage: eoir save-state SCENARIO --out FILE [--time ISO]\n"
       "\n"
       "Loads a scenario into an engine, moves it to --time (default: the scenario's\n"
       "start) and saves the whole engine state as a .scd file (schemas/scd.schema.json),\n"
       "written to a temporary file and renamed.\n",
       {"--out", "--time"},
       {"--allow-paths-outside"}},
      {"load-state",
       "usage: eoir load-state FILE [--sensor NAME]\n"
       "\n"
       "Restores a .scd file into an engine (eoir_state_load) and prints its time, its\n"
       "objects and the static metrics of every sensor (or of --sensor).\n",
       {"--sensor"},
       {}},
      {"groups", "usage: eoir groups\n\nLists the data-provider groups and their elements with units.\n", {}, {}},
      {"help", "usage: eoir help [COMMAND]\n", {}, {}, false, false},
  };
  return specs;
}

std::vector<std::string> command_names() {
  std::vector<std::string> names;
  for (const auto& c : commands()) names.push_back(c.name);
  return names;
}

const CommandSpec* find_command(const std::string& name) {
  for (const auto& c : commands())
    if (c.name == name) return &c;
  return nullptr;
}

std::string command_help(const CommandSpec& c) {
  std::string h = c.usage;
  if (c.name == "report" || c.name == "run" || c.name == "access") h += kTimeOptions;
  if (c.name == "report" || c.name == "access")
    h += "  --format json|csv (default json); --out FILE (written atomically; default stdout)\n";
  if (c.name == "pick") h += "  --format csv|json (default csv); --out FILE (written atomically; default stdout)\n";
  if (c.name == "report" || c.name == "run" || c.name == "access") h += "  --quiet           no progress on stderr\n";
  if (std::find(c.flags.begin(), c.flags.end(), "--allow-paths-outside") != c.flags.end())
    h += "  --allow-paths-outside  let the scenario name files outside its folder (README \"Bounds\")\n";
  if (c.engine) h += "\ncommon options:\n" + std::string(kEngineOptions);
  return h;
}

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// $EOIR_SCENARIO_DIR, else the installed tree's share/eoir/scenarios beside
// the program, else the source tree's.
std::string scenario_dir() {
  const char* env = std::getenv("EOIR_SCENARIO_DIR");
  if (env != nullptr && env[0] != '\0') return env;
#ifdef EOIR_RELATIVE_SCENARIO_DIR
  char exe[4096];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n > 0) {
    exe[n] = '\0';
    std::string dir(exe);
    dir = dir.substr(0, dir.find_last_of('/')) + "/" + EOIR_RELATIVE_SCENARIO_DIR;
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(dir, ec);
    if (!ec) dir = canonical.string();
    if (access((dir + "/demo/default.json").c_str(), R_OK) == 0) return dir;
  }
#endif
  return EOIR_SCENARIO_DIR_DEFAULT;
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

// Command-line options of one command: "--name value" or "--name=value"
// options (repeatable ones collect every value), flags, and one positional
// argument (SCENARIO, FILE or KIND).
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

// The scenario's file policy from the command line (scenario.hpp).
ScenarioOptions scenario_options(const Options& o) {
  ScenarioOptions so;
  so.allow_paths_outside = o.flags.count("--allow-paths-outside") > 0;
  return so;
}

// `eoir COMMAND --help`
struct HelpRequested {
  const CommandSpec* command;
};

const std::vector<std::string> kEngineValued = {"--library", "--seed", "--threads"};

Options parse_options(const std::vector<std::string>& args, const CommandSpec& spec) {
  std::vector<std::string> valued = spec.valued;
  if (spec.engine) valued.insert(valued.end(), kEngineValued.begin(), kEngineValued.end());
  std::vector<std::string> known = valued;
  known.insert(known.end(), spec.flags.begin(), spec.flags.end());
  known.push_back("--help");
  const std::string& command = spec.name;
  Options o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string a = args[i];
    std::optional<std::string> inline_value;
    if (a.rfind("--", 0) == 0 && a.find('=') != std::string::npos) {
      inline_value = a.substr(a.find('=') + 1);
      a = a.substr(0, a.find('='));
    }
    if (a == "--help" || a == "-h") throw HelpRequested{&spec};
    if (contains(valued, a)) {
      if (inline_value) {
        o.values[a].push_back(*inline_value);
      } else {
        if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
        o.values[a].push_back(args[++i]);
      }
    } else if (contains(spec.flags, a == "-q" ? std::string("--quiet") : a)) {
      if (inline_value) throw UsageError(command + ": " + a + " takes no value");
      o.flags[a == "-q" ? std::string("--quiet") : a] = true;
    } else if (a.size() > 1 && a[0] == '-' && !(spec.numbers_as_values && (a[1] >= '0' && a[1] <= '9'))) {
      throw UsageError(command + ": unknown option " + a + did_you_mean(a, known));
    } else if (!o.scenario) {
      o.scenario = args[i];
    } else {
      throw UsageError(command + ": unexpected argument '" + args[i] + "'");
    }
  }
  return o;
}

// Options given before the command (eoir --seed 3 run ...).
struct Global {
  std::optional<std::string> library, seed, threads;
};

uint64_t parse_seed(const std::string& s) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), &end, 10);
  if (s.empty() || s[0] == '-' || s[0] == '+' || end == nullptr || *end != '\0' || errno == ERANGE)
    throw UsageError("--seed: '" + s + "' is not an integer in [0, 2^64)");
  return v;
}

uint32_t parse_threads(const std::string& s) {
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (s.empty() || end == nullptr || *end != '\0' || errno == ERANGE || v < 0 || v > 1024)
    throw UsageError("--threads: '" + s + "' is not an integer in [0, 1024] (0 = all cores)");
  return static_cast<uint32_t>(v);
}

// The engine a command creates: its own options win over the global ones.
struct EngineChoice {
  std::string library;
  EngineConfig config;
};

EngineChoice engine_choice(const Options& o, const Global& g) {
  EngineChoice c;
  const auto pick = [&](const char* name, const std::optional<std::string>& global) {
    const auto v = o.get(name);
    return v ? v : global;
  };
  if (const auto lib = pick("--library", g.library)) c.library = *lib;
  if (const auto seed = pick("--seed", g.seed)) c.config.seed = parse_seed(*seed);
  if (const auto threads = pick("--threads", g.threads)) c.config.threads = parse_threads(*threads);
  return c;
}

// Creates the engine of a command (EngineChoice must outlive it).
EngineConfig config_of(const EngineChoice& c) {
  EngineConfig config = c.config;
  config.library = c.library.empty() ? nullptr : c.library.c_str();
  return config;
}

// --start, --stop and --step, checked (the scenario supplies the defaults).
struct TimeRange {
  std::optional<double> start_s, stop_s, step_s;
};

TimeRange parse_time_range(const Options& o) {
  TimeRange r;
  if (const auto step = o.get("--step")) {
    r.step_s = parse_seconds(*step, "--step");
    try {
      check_step(*r.step_s, "--step");
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
  }
  if (const auto start = o.get("--start")) r.start_s = parse_time_option(*start, "--start");
  if (const auto stop = o.get("--stop")) r.stop_s = parse_time_option(*stop, "--stop");
  if (r.start_s && r.stop_s && *r.stop_s < *r.start_s)
    throw UsageError("--stop " + *o.get("--stop") + " is before --start " + *o.get("--start"));
  return r;
}

// The scenario's stop unless --stop is given (or --start lies past it).
double default_stop(const TimeRange& r, const Scenario& sc) { return default_stop(r.start_s, r.stop_s, sc); }

// t0, t0 + dt, ... up to t1, with t1 itself always last (time_steps.hpp).
std::vector<double> step_times(double t0, double t1, double dt, const std::string& command, std::size_t most) {
  try {
    return eoir::cli::step_times(t0, t1, dt, most);
  } catch (const std::invalid_argument& e) {
    const std::string why = e.what();
    throw UsageError(why.rfind("more than", 0) == 0 ? command + ": " + why : why);
  }
}

int cmd_report(const std::vector<std::string>& args, const Global& g) {
  const Options o = parse_options(args, *find_command("report"));
  const EngineChoice choice = engine_choice(o, g);
  const auto scenario_file = o.scenario, provider = o.get("--provider"), sensor = o.get("--sensor"),
             target = o.get("--target"), out_file = o.get("--out");
  const std::string format = o.get("--format").value_or("json");
  const bool quiet = o.flags.count("--quiet") > 0;
  if (!scenario_file) throw UsageError("report: missing SCENARIO");
  if (!provider) throw UsageError("report: missing --provider GROUP");
  if (!sensor) throw UsageError("report: missing --sensor NAME");
  if (format != "json" && format != "csv") throw UsageError("--format: '" + format + "' is not json or csv");
  const TimeRange range = parse_time_range(o);

  const Scenario sc = load_scenario(*scenario_file, scenario_options(o));
  const double t0 = range.start_s.value_or(sc.start_s);
  const std::vector<double> times =
      step_times(t0, default_stop(range, sc), range.step_s.value_or(sc.step_s), "report", kMaxReportSteps);

  Engine engine(config_of(choice));
  Session session(engine, sc);
  const std::vector<std::string> groups = provider_groups(engine.api());
  if (!contains(groups, *provider))
    throw UsageError("--provider: unknown data-provider group '" + *provider + "'" + did_you_mean(*provider, groups) +
                     "; known groups: " + join(groups));
  const std::vector<std::string> sensors = engine_objects(engine, EOIR_KIND_SENSOR);
  if (!contains(sensors, *sensor))
    throw UsageError("--sensor: unknown sensor '" + *sensor + "' in " + *scenario_file + did_you_mean(*sensor, sensors) +
                     "; sensors: " + join(sensors));
  if (target && !contains(engine_objects(engine, 0), *target))
    throw UsageError("--target: unknown object '" + *target + "' in " + *scenario_file +
                     did_you_mean(*target, engine_objects(engine, 0)));
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

int cmd_run(const std::vector<std::string>& args, const Global& g) {
  const Options o = parse_options(args, *find_command("run"));
  const EngineChoice choice = engine_choice(o, g);
  const auto scenario_file = o.scenario, out_dir = o.get("--out");
  RunOptions opt;
  if (o.values.count("--sensor")) opt.sensors = o.values.at("--sensor");
  opt.quiet = o.flags.count("--quiet") > 0;
  opt.cube = o.flags.count("--cube") > 0;
  if (const auto stretch = o.get("--stretch")) opt.stretch = *stretch;
  if (const auto save = o.get("--save-state")) {
    if (save->empty()) throw UsageError("--save-state: empty file name");
    opt.save_state = *save;
  }
  if (!scenario_file) throw UsageError("run: missing SCENARIO");
  if (!out_dir) throw UsageError("run: missing --out DIR");
  if (out_dir->empty()) throw UsageError("--out: empty directory name");
  const TimeRange range = parse_time_range(o);

  const Scenario sc = load_scenario(*scenario_file, scenario_options(o));
  const double t0 = range.start_s.value_or(sc.start_s);
  opt.times = step_times(t0, default_stop(range, sc), range.step_s.value_or(sc.step_s), "run", 9999);
  opt.scenario_file = *scenario_file;
  opt.out_dir = *out_dir;

  Engine engine(config_of(choice));
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

int cmd_access(const std::vector<std::string>& args, const Global& g) {
  const Options o = parse_options(args, *find_command("access"));
  const EngineChoice choice = engine_choice(o, g);
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

  const Scenario sc = load_scenario(*scenario_file, scenario_options(o));
  // Times in whole milliseconds on the host time line (iso_time.hpp).
  const auto to_ms = [](double t) { return static_cast<int64_t>(std::llround(t * 1000.0)); };
  const int64_t t0 = to_ms(range.start_s.value_or(sc.start_s));
  const int64_t t1 = to_ms(default_stop(range, sc));
  if (t1 < t0)
    throw UsageError("--stop " + format_iso(static_cast<double>(t1) / 1000.0) + " is before the start " +
                     format_iso(static_cast<double>(t0) / 1000.0));
  const double dt = range.step_s.value_or(sc.step_s);
  const int64_t dt_ms = to_ms(dt);
  if (dt_ms < 1) throw UsageError("--step: " + nlohmann::json(dt).dump() + " s is below the 1 ms resolution of times");
  std::vector<int64_t> samples;
  for (int64_t t = t0; t <= t1; t += dt_ms) {
    samples.push_back(t);
    if (samples.size() > 10000000) throw UsageError("access: more than 10^7 steps; use a larger --step");
  }
  if (samples.back() < t1) samples.push_back(t1);

  Engine engine(config_of(choice));
  Session session(engine, sc);
  const eoir_api_v1& api = engine.api();
  if (!api_has(api, offsetof(eoir_api_v1, snr_constraint) + sizeof api.snr_constraint) || api.snr_constraint == nullptr)
    throw std::runtime_error(std::string("the engine library ") + engine.library_path() +
                             " has no SNR constraint (C ABI 1.2 needed)");
  const std::vector<std::string> sensors = engine_objects(engine, EOIR_KIND_SENSOR);
  if (!contains(sensors, *sensor))
    throw UsageError("--sensor: unknown sensor '" + *sensor + "' in " + *scenario_file + did_you_mean(*sensor, sensors) +
                     "; sensors: " + join(sensors));
  const std::vector<std::string> objects = engine_objects(engine, 0);
  if (!contains(objects, *target))
    throw UsageError("--target: unknown object '" + *target + "' in " + *scenario_file + did_you_mean(*target, objects) +
                     "; objects: " + join(objects));

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

// A non-negative integer index (--x, --y).
uint32_t parse_index(const std::string& s, const char* option) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(s.c_str(), &end, 10);
  if (s.empty() || s[0] < '0' || s[0] > '9' || end == nullptr || *end != '\0' || errno == ERANGE || v > 0xFFFFFFFFull)
    throw UsageError(std::string(option) + ": '" + s + "' is not a non-negative integer");
  return static_cast<uint32_t>(v);
}

int cmd_pick(const std::vector<std::string>& args, const Global& g) {
  const Options o = parse_options(args, *find_command("pick"));
  const EngineChoice choice = engine_choice(o, g);
  const auto sensor = o.get("--sensor"), x = o.get("--x"), y = o.get("--y"), out_file = o.get("--out");
  const std::string format = o.get("--format").value_or("csv"), space = o.get("--space").value_or("sample");
  if (!o.scenario) throw UsageError("pick: missing SCENARIO");
  if (!sensor) throw UsageError("pick: missing --sensor NAME");
  if (!x) throw UsageError("pick: missing --x N");
  if (!y) throw UsageError("pick: missing --y N");
  if (format != "csv" && format != "json") throw UsageError("--format: '" + format + "' is not csv or json");
  if (space != "sample" && space != "pixel") throw UsageError("--space: '" + space + "' is not sample or pixel");
  PickOptions opt;
  opt.scenario_file = *o.scenario;
  opt.sensor = *sensor;
  opt.pixel = space == "pixel";
  opt.x = parse_index(*x, "--x");
  opt.y = parse_index(*y, "--y");
  std::optional<double> at;
  if (const auto t = o.get("--time")) at = parse_time_option(*t, "--time");
  const Scenario sc = load_scenario(*o.scenario, scenario_options(o));
  opt.time_s = at.value_or(sc.start_s);
  Engine engine(config_of(choice));
  try {
    const PickTerms p = pick_terms(engine, sc, opt);
    emit(out_file, format == "json" ? pick_json(sc, opt, p) : pick_csv(sc, opt, p));
  } catch (const PickArgumentError& e) {
    throw UsageError(e.what());
  }
  return 0;
}

// Evaluates every group without a target for each sensor at the engine's
// time: the checks that involve several parameters (band edges in order...)
// happen here, as they do when `run` renders.
void check_sensors(Engine& engine, const Scenario& sc, double t) {
  for (const SensorSpec& s : sc.sensors)
    for (const std::string& group : provider_groups(engine.api())) {
      if (group == kTargetGroup) continue;
      const std::vector<ElementInfo> elements = provider_elements(engine.api(), group);
      try {
        (void)evaluate_row(engine, group, elements, s.name, std::nullopt, t);
      } catch (const EngineError& e) {
        throw EngineError(s.path + ".parameters: " + e.what(), e.status());
      }
    }
}

int cmd_validate(const std::vector<std::string>& args, const Global& g) {
  const Options o = parse_options(args, *find_command("validate"));
  const EngineChoice choice = engine_choice(o, g);
  if (!o.scenario) throw UsageError("validate: missing SCENARIO");
  const Scenario sc = load_scenario(*o.scenario, scenario_options(o));
  // The scenario's own times, refused as report refuses them.
  const std::vector<double> times = step_times(sc.start_s, sc.stop_s, sc.step_s, "validate", kMaxReportSteps);
  Engine engine(config_of(choice));
  Session session(engine, sc);
  for (std::size_t k = 0; k < times.size(); ++k) {
    session.set_time(times[k]);
    if (k == 0) check_sensors(engine, sc, times[k]);
  }
  std::printf("%s: valid (scenario '%s': %zu objects, %zu sensors, %zu time steps)\n", o.scenario->c_str(),
              sc.name.c_str(), sc.objects.size(), sc.sensors.size(), times.size());
  return 0;
}

// Static metrics of each sensor (or of `only`) at the engine's time.
void print_sensor_metrics(const Engine& engine, const std::vector<std::pair<std::string, std::string>>& sensors,
                          double t) {
  for (const auto& [name, parent] : sensors) {
    std::cout << "\nsensor " << name << " on " << parent << "\n";
    for (const std::string& group : provider_groups(engine.api())) {
      if (group == kTargetGroup) continue;  // needs a target
      const std::vector<ElementInfo> elements = provider_elements(engine.api(), group);
      try {
        const ReportRow row = evaluate_row(engine, group, elements, name, std::nullopt, t);
        std::cout << "\n";
        write_table(std::cout, group, row);
      } catch (const EngineError& e) {
        std::cerr << "eoir: skipped " << group << ": " << e.what() << "\n";
      }
    }
  }
}

std::string engine_version_text(const Engine& engine) {
  const uint32_t v = engine.api().version();
  return std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." + std::to_string(v % 100);
}

int cmd_default(const Global& g) {
  const EngineChoice choice = engine_choice(Options{}, g);
  const std::string file = scenario_dir() + "/demo/default.json";
  const Scenario sc = load_scenario(file);
  Engine engine(config_of(choice));
  Session session(engine, sc);
  session.set_time(sc.start_s);
  std::cout << "EOIR " << EOIR_CLI_VERSION << " (engine " << engine_version_text(engine) << ", "
            << engine.library_path() << ")\n"
            << "scenario: " << sc.name << " (" << file << ")\n";
  if (!sc.description.empty()) std::cout << sc.description << "\n";
  std::cout << "time: " << format_iso(sc.start_s) << "\n";
  std::vector<std::pair<std::string, std::string>> sensors;
  for (const SensorSpec& s : sc.sensors) sensors.emplace_back(s.name, s.parent);
  print_sensor_metrics(engine, sensors, sc.start_s);
  std::cout << "\nRun `eoir --help` for the commands.\n";
  return 0;
}

int cmd_groups(const std::vector<std::string>& args, const Global& g) {
  const Options o = parse_options(args, *find_command("groups"));
  if (o.scenario) throw UsageError("groups: unexpected argument '" + *o.scenario + "'");
  const EngineChoice choice = engine_choice(o, g);
  Engine engine(config_of(choice));
  for (const std::string& gr : provider_groups(engine.api())) {
    std::cout << gr << "\n";
    for (const ElementInfo& e : provider_elements(engine.api(), gr))
      std::cout << "  " << e.name << (e.unit.empty() ? "" : " [" + e.unit + "]")
                << (e.type == EOIR_TYPE_CURVE ? " (curve vs " + e.x_unit + ")" : "") << "\n";
  }
  return 0;
}

// ---- properties KIND
const char* type_text(int32_t t) {
  switch (t) {
    case EOIR_TYPE_NUMBER: return "number";
    case EOIR_TYPE_INTEGER: return "integer";
    case EOIR_TYPE_BOOL: return "bool";
    case EOIR_TYPE_STRING: return "string";
    case EOIR_TYPE_ARRAY: return "array";
    default: return "?";
  }
}

// "[0, 1]", "(0, 180)", ">= 1", "sphere|box|..."; "" if unconstrained.
std::string range_text(const PropertyInfo& p) {
  if (!p.choices.empty()) {
    std::string t;
    for (const auto& c : p.choices) t += (t.empty() ? "" : "|") + c;
    return t;
  }
  const auto num = [](double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", x);
    return std::string(b);
  };
  const bool lo = std::isfinite(p.minimum), hi = std::isfinite(p.maximum);
  if (lo && hi)
    return std::string(p.minimum_open ? "(" : "[") + num(p.minimum) + ", " + num(p.maximum) +
           (p.maximum_open ? ")" : "]");
  if (lo) return std::string(p.minimum_open ? "> " : ">= ") + num(p.minimum);
  if (hi) return std::string(p.maximum_open ? "< " : "<= ") + num(p.maximum);
  return "";
}

int cmd_properties(const std::vector<std::string>& args, const Global& g) {
  const Options o = parse_options(args, *find_command("properties"));
  const EngineChoice choice = engine_choice(o, g);
  const std::string format = o.get("--format").value_or("table");
  if (format != "table" && format != "json") throw UsageError("--format: '" + format + "' is not table or json");
  if (!o.scenario) throw UsageError("properties: missing KIND (sensor, satellite, aircraft, ground_vehicle, "
                                    "missile, site, star_field, central_body or a central body's name)");
  const std::string kind = *o.scenario;
  static const std::vector<std::pair<std::string, int32_t>> kinds = {
      {"satellite", EOIR_KIND_SATELLITE}, {"aircraft", EOIR_KIND_AIRCRAFT},
      {"ground_vehicle", EOIR_KIND_GROUND_VEHICLE}, {"missile", EOIR_KIND_MISSILE}, {"site", EOIR_KIND_SITE}};
  static const std::vector<std::string> bodies = {"Sun", "Mercury", "Venus", "Earth", "Mars", "Jupiter",
                                                  "Saturn", "Uranus", "Neptune", "Moon"};
  Engine engine(config_of(choice));
  const eoir_api_v1& api = engine.api();
  const eoir_engine e = engine.handle();
  std::string object;
  if (kind == "sensor") {
    engine.check(api.object_add(e, EOIR_KIND_SATELLITE, "Host"), "satellite");
    engine.check(api.sensor_add(e, "Sensor", "Host"), "sensor");
    object = "Sensor";
  } else if (kind == "star_field") {
    engine.check(api.object_add(e, EOIR_KIND_STAR_FIELD, "Stars"), "star field");
    object = "Stars";
  } else if (kind == "central_body" || contains(bodies, kind)) {
    object = kind == "central_body" ? "Earth" : kind;
    if (object != "Sun") engine.check(api.object_add(e, EOIR_KIND_CENTRAL_BODY, object.c_str()), object);
  } else {
    int32_t code = 0;
    for (const auto& [name, c] : kinds)
      if (name == kind) code = c;
    if (code == 0) {
      std::vector<std::string> known = {"sensor", "star_field", "central_body"};
      for (const auto& k : kinds) known.push_back(k.first);
      known.insert(known.end(), bodies.begin(), bodies.end());
      throw UsageError("properties: unknown kind '" + kind + "'" + did_you_mean(kind, known) + "; kinds: " +
                       join(known));
    }
    engine.check(api.object_add(e, code, "Object"), kind);
    object = "Object";
  }
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  bool ranges_listed = true;
  for (const PropertyInfo& info : engine.properties(object)) {
    nlohmann::ordered_json p;
    p["name"] = info.name;
    p["type"] = type_text(info.type);
    p["unit"] = info.unit;
    p["default"] = engine.value(object, info.name, info.type);
    ranges_listed = ranges_listed && info.has_range;
    p["range"] = info.has_range ? nlohmann::ordered_json(range_text(info)) : nlohmann::ordered_json(nullptr);
    p["fidelity"] = info.fidelity;
    p["description"] = info.description;
    list.push_back(std::move(p));
  }
  if (format == "json") {
    nlohmann::ordered_json doc;
    doc["kind"] = kind;
    doc["properties"] = list;
    std::cout << doc.dump(2) << "\n";
    return 0;
  }
  std::cout << "properties of a " << kind << (kind == "central_body" ? " (the Earth's defaults)" : "")
            << (ranges_listed ? " (F: a fidelity knob trading speed for accuracy)"
                              : " (range: checked by the engine when set; not listed by C ABI 1.2)")
            << "\n\n";
  std::size_t wn = 4, wt = 4, wu = 4, wd = 7, wr = 5;
  const auto default_text = [](const nlohmann::ordered_json& v) {
    std::string t = v.is_string() ? v.get<std::string>() : v.dump();
    if (t.size() > 40) t = t.substr(0, 37) + "...";
    return t.empty() ? std::string("\"\"") : t;
  };
  for (const auto& p : list) {
    wn = std::max(wn, p["name"].get<std::string>().size());
    wt = std::max(wt, p["type"].get<std::string>().size());
    wu = std::max(wu, p["unit"].get<std::string>().size());
    wd = std::max(wd, default_text(p["default"]).size());
    if (p["range"].is_string()) wr = std::max(wr, p["range"].get<std::string>().size());
  }
  const auto range_cell = [](const nlohmann::ordered_json& p) {
    return p["range"].is_string() && !p["range"].get<std::string>().empty() ? p["range"].get<std::string>()
                                                                             : std::string("-");
  };
  const auto pad = [](std::string s, std::size_t w) { return s + std::string(w > s.size() ? w - s.size() : 0, ' '); };
  std::cout << pad("name", wn) << "  " << pad("type", wt) << "  " << pad("unit", wu) << "  " << pad("default", wd)
            << "  " << pad("range", wr) << "  F  description\n";
  for (const auto& p : list)
    std::cout << pad(p["name"].get<std::string>(), wn) << "  " << pad(p["type"].get<std::string>(), wt) << "  "
              << pad(p["unit"].get<std::string>().empty() ? "-" : p["unit"].get<std::string>(), wu) << "  "
              << pad(default_text(p["default"]), wd) << "  " << pad(range_cell(p), wr) << "  "
              << (p["fidelity"].get<bool>() ? "F" : " ") << "  " << p["description"].get<std::string>() << "\n";
  return 0;
}

// ---- save-state / load-state
int cmd_save_state(const std::vector<std::string>& args, const Global& g) {
  const Options o = parse_options(args, *find_command("save-state"));
  const EngineChoice choice = engine_choice(o, g);
  if (!o.scenario) throw UsageError("save-state: missing SCENARIO");
  const auto out = o.get("--out");
  if (!out || out->empty()) throw UsageError("save-state: missing --out FILE");
  std::optional<double> at;
  if (const auto t = o.get("--time")) at = parse_time_option(*t, "--time");
  const Scenario sc = load_scenario(*o.scenario, scenario_options(o));
  Engine engine(config_of(choice));
  Session session(engine, sc);
  const double t = at.value_or(sc.start_s);
  session.set_time(t);
  engine.check(engine.api().state_save(engine.handle(), out->c_str()), "--out " + *out);
  std::printf("eoir save-state: wrote %s (scenario '%s' at %s)\n", out->c_str(), sc.name.c_str(),
              format_iso(t).c_str());
  return 0;
}

int cmd_load_state(const std::vector<std::string>& args, const Global& g) {
  const Options o = parse_options(args, *find_command("load-state"));
  const EngineChoice choice = engine_choice(o, g);
  if (!o.scenario) throw UsageError("load-state: missing FILE");
  Engine engine(config_of(choice));
  const eoir_api_v1& api = engine.api();
  engine.check(api.state_load(engine.handle(), o.scenario->c_str()), *o.scenario);
  eoir_time t{};
  engine.check(api.engine_get_time(engine.handle(), EOIR_TIME_UTC, &t), "time");
  char iso[64];
  engine.check(api.time_to_iso(&t, iso, sizeof iso), "time");
  std::cout << "state: " << *o.scenario << "\ntime: " << iso << "\nobjects:\n";
  std::size_t n = 0;
  engine.check(api.object_count(engine.handle(), &n), "object_count");
  std::vector<std::pair<std::string, std::string>> sensors;
  std::vector<std::string> sensor_names;
  static const char* const kind_names[] = {"?", "central body", "star field", "satellite", "aircraft",
                                           "ground vehicle", "missile", "sensor", "site"};
  for (std::size_t i = 0; i < n; ++i) {
    const char* name = nullptr;
    int32_t k = 0;
    engine.check(api.object_at(engine.handle(), i, &name, &k), "object_at");
    std::cout << "  " << (name ? name : "") << " (" << kind_names[(k >= 1 && k <= EOIR_KIND_SITE) ? k : 0] << ")\n";
    if (k == EOIR_KIND_SENSOR) {
      sensor_names.emplace_back(name ? name : "");
      sensors.emplace_back(sensor_names.back(), "its parent");
    }
  }
  if (const auto only = o.get("--sensor")) {
    if (!contains(sensor_names, *only))
      throw UsageError("--sensor: unknown sensor '" + *only + "' in " + *o.scenario + did_you_mean(*only, sensor_names) +
                       "; sensors: " + join(sensor_names));
    sensors = {{*only, "its parent"}};
  }
  print_sensor_metrics(engine, sensors, 0);
  return 0;
}

// Every version of the build, all from project(eoir VERSION ...) in
// CMakeLists.txt; the engine's line is the library actually loaded.
int cmd_version(const Global& g) {
  std::cout << "eoir " << EOIR_CLI_VERSION << "\n"
            << "C ABI " << EOIR_VERSION_MAJOR << "." << EOIR_VERSION_MINOR << " (this program's eoir.h "
            << EOIR_VERSION_STRING << ")\n"
            << "soname " << EOIR_SONAME << "\n"
            << "data " << EOIR_CLI_VERSION << " (built with the engine; no version of its own)\n"
            << "python package eoir " << EOIR_CLI_VERSION << " (bindings/python)\n";
  try {
    const EngineChoice choice = engine_choice(Options{}, g);
    Engine engine(config_of(choice));
    std::cout << "engine " << engine_version_text(engine) << " (" << engine.library_path() << ")\n";
  } catch (const std::exception& e) {
    std::cout << "engine: not loaded (" << e.what() << ")\n";
  }
  return 0;
}

int cmd_help(const std::vector<std::string>& args) {
  if (args.empty()) {
    std::cout << kUsage;
    return 0;
  }
  const CommandSpec* c = find_command(args[0]);
  if (c == nullptr)
    throw UsageError("help: unknown command '" + args[0] + "'" + did_you_mean(args[0], command_names()));
  std::cout << command_help(*c);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  Global g;
  try {
    // Global options before the command: --library, --seed, --threads.
    while (!args.empty()) {
      std::string a = args[0];
      std::optional<std::string> value;
      if (a.rfind("--", 0) == 0 && a.find('=') != std::string::npos) {
        value = a.substr(a.find('=') + 1);
        a = a.substr(0, a.find('='));
      }
      if (!contains(kEngineValued, a)) break;
      std::size_t used = 1;
      if (!value) {
        if (args.size() < 2) throw UsageError(a + " needs a value");
        value = args[1];
        used = 2;
      }
      (a == "--library" ? g.library : a == "--seed" ? g.seed : g.threads) = *value;
      args.erase(args.begin(), args.begin() + static_cast<std::ptrdiff_t>(used));
    }
    if (g.seed) (void)parse_seed(*g.seed);
    if (g.threads) (void)parse_threads(*g.threads);
    if (args.empty()) return cmd_default(g);
    const std::string cmd = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (cmd == "--help" || cmd == "-h") return cmd_help({});
    if (cmd == "help") return cmd_help(rest);
    if (cmd == "--version") return cmd_version(g);
    if (cmd == "report") return cmd_report(rest, g);
    if (cmd == "run") return cmd_run(rest, g);
    if (cmd == "access") return cmd_access(rest, g);
    if (cmd == "pick") return cmd_pick(rest, g);
    if (cmd == "validate") return cmd_validate(rest, g);
    if (cmd == "groups") return cmd_groups(rest, g);
    if (cmd == "properties") return cmd_properties(rest, g);
    if (cmd == "save-state") return cmd_save_state(rest, g);
    if (cmd == "load-state") return cmd_load_state(rest, g);
    std::vector<std::string> known = command_names();
    known.push_back("--help");
    known.push_back("--version");
    throw UsageError(std::string(cmd.rfind("-", 0) == 0 ? "unknown option '" : "unknown command '") + cmd + "'" +
                     did_you_mean(cmd, known));
  } catch (const HelpRequested& h) {
    std::cout << command_help(*h.command);
    return 0;
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

#include "engine.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/constants.hpp"
#include "core/data_dir.hpp"
#include "core/error.hpp"
#include "core/frames.hpp"
#include "metrics/atmospheric_path.hpp"
#include "scene/apparent_grid.hpp"
#include "scene/astrometric_frame.hpp"
#include "scene/motion_substeps.hpp"
#include "scene/pick.hpp"
#include "universe/composite.hpp"
#include "sensor/display.hpp"
#include "universe/object_motion.hpp"
#include "universe/object_properties.hpp"
#include "universe/star_catalog.hpp"

namespace eoir {
namespace {
using clock_type = std::chrono::steady_clock;
double seconds_between(clock_type::time_point a, clock_type::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}
}  // namespace

Engine::Engine(const EngineOptions& options) : options_(options), noise_rng_(options.seed) {}

void Engine::changed() {
  ++revision_;
  target_cache_.clear();
}

void Engine::progress(double fraction, const char* what) const {
  if (options_.progress && !options_.progress(fraction, what))
    throw Error(Status::cancelled, std::string(what) + ": cancelled by the host");
}

void Engine::set_time(const EngineTime& t) {
  time_ = t;
  target_cache_.clear();
}

void Engine::set_limits(const universe::ObjectLimits& limits) { universe_.set_limits(limits); }

void Engine::add_object(universe::ObjectKind kind, const std::string& name) {
  universe_.add(kind, name);
  changed();
}

void Engine::add_sensor(const std::string& name, const std::string& parent) {
  universe_.add(universe::ObjectKind::sensor, name, parent);
  models_.erase(name);
  adaptive_.erase(name);
  frames_.erase(name);
  spare_buffers_.erase(name);
  changed();
}

void Engine::remove_object(const std::string& name) {
  const std::string gone = universe_.get(name).name;
  std::vector<std::string> sensors;
  for (const auto& o : universe_.objects())
    if (o.name == gone || (o.kind == universe::ObjectKind::sensor && o.parent == gone)) sensors.push_back(o.name);
  universe_.remove(gone);
  for (const auto& s : sensors) {
    models_.erase(s);
    worlds_.erase(s);
    adaptive_.erase(s);
    frames_.erase(s);
    spare_buffers_.erase(s);
  }
  changed();
}

void Engine::push_state(const std::string& name, const EngineTime& epoch, int frame, const double position[3],
                        const double velocity[3], const double attitude_wxyz[4], const double angular_velocity_rad_s[3]) {
  universe::push_state(universe_.get(name), epoch, frame, position, velocity, attitude_wxyz, angular_velocity_rad_s);
  changed();
}

void Engine::restore_state(const std::string& name, const universe::PushedState& s) {
  universe::Object& o = universe_.get(name);
  const double r[3] = {s.position_m.x(), s.position_m.y(), s.position_m.z()};
  const double v[3] = {s.velocity_m_s.x(), s.velocity_m_s.y(), s.velocity_m_s.z()};
  const double q[4] = {s.attitude.w(), s.attitude.x(), s.attitude.y(), s.attitude.z()};
  const double w[3] = {s.angular_velocity_rad_s.x(), s.angular_velocity_rad_s.y(), s.angular_velocity_rad_s.z()};
  universe::push_state(o, s.epoch, s.frame == universe::StateFrame::j2000 ? 0 : 1, r, v, q, w);  // validates
  o.state.attitude = s.attitude;  // bit for bit (push_state normalises)
  changed();
}

void Engine::set_property(const std::string& object, const std::string& property, const Value& value) {
  universe::Object& o = universe_.get(object, "object");
  // Names the universe cannot check alone: materials and spectra.
  if (property == "material" && std::holds_alternative<std::string>(value))
    library().materials.get(std::get<std::string>(value), "material");
  if (property == "spectrum" && std::holds_alternative<std::string>(value)) {
    const std::string& name = std::get<std::string>(value);
    if (!name.empty() && !library().spectra.find(name))
      throw Error(Status::unknown_name, "spectrum: no spectrum named '" + name + "' in the spectrum table");
  }
  if (property == "catalog_file" && std::holds_alternative<std::string>(value) &&
      !std::get<std::string>(value).empty())
    library().star_catalog(std::get<std::string>(value), o.stars.catalog_epoch_year);  // read and checked now
  Value stored = value;
  if (property == "composite" && std::holds_alternative<std::string>(value)) {
    // A predefined satellite's name (spec 4.3.3) stands for its parts.
    const std::string& given = std::get<std::string>(value);
    if (universe::PredefinedComposites::is_name(given)) stored = Value(library().satellites.parts(given, "composite"));
    const auto parts = universe::parse_composite(std::get<std::string>(stored), "composite");
    for (std::size_t i = 0; i < parts.size(); ++i)
      if (parts[i].material)
        library().materials.get(*parts[i].material, "composite[" + std::to_string(i) + "].material");
  }
  universe::set_property(o, property, stored);
  changed();
}

const universe::Library& Engine::library() {
  if (!library_) {
    auto lib = std::make_shared<universe::Library>(universe::Library::load(resolve_data_dir(options_.data_dir)));
    for (const auto& m : user_materials_) lib->materials.add(m);
    for (const auto& sp : user_spectra_) lib->spectra.add(sp);
    library_ = lib;
  }
  return *library_;
}

void Engine::add_material(const universe::Material& material) {
  universe::validate(material.brdf, material.name + ".brdf");
  auto lib = std::make_shared<universe::Library>(library());
  lib->materials.add(material);
  library_ = lib;
  user_materials_.erase(std::remove_if(user_materials_.begin(), user_materials_.end(),
                                       [&](const universe::Material& m) { return m.name == material.name; }),
                        user_materials_.end());
  user_materials_.push_back(material);
  changed();
}

void Engine::add_spectrum(const universe::NamedSpectrum& spectrum) {
  auto lib = std::make_shared<universe::Library>(library());
  lib->spectra.add(spectrum);
  library_ = lib;
  user_spectra_.erase(std::remove_if(user_spectra_.begin(), user_spectra_.end(),
                                     [&](const universe::NamedSpectrum& x) { return x.name == spectrum.name; }),
                      user_spectra_.end());
  user_spectra_.push_back(spectrum);
  changed();
}

void Engine::set_sensor_parameters(const std::string& sensor, const universe::SensorParameters& parameters) {
  universe_.sensor(sensor);  // must exist and be a sensor
  universe::validate(parameters);
  universe::Object& o = universe_.get(sensor);
  o.sensor = parameters;
  ++o.revision;
  changed();
}

std::shared_ptr<const sensor::SensorModel> Engine::sensor_model(const std::string& name) {
  const universe::Object& s = universe_.sensor(name);
  auto it = models_.find(name);
  if (it != models_.end() && it->second.revision == s.revision) return it->second.model;
  auto model = sensor::resolve_sensor(s.sensor);
  models_[name] = CachedModel{s.revision, model};
  return model;
}

std::shared_ptr<const scene::World> Engine::world(const std::string& sensor) {
  const auto model = sensor_model(sensor);
  auto it = worlds_.find(sensor);
  if (it != worlds_.end() && it->second.revision == revision_ && it->second.time == time_) return it->second.world;
  auto w = scene::build_world(universe_, library(), time_, universe_.sensor(sensor),
                              scene::ViewDefinition{model->grid, model->spectral, model->fidelity(),
                                                    model->parameters.integration_time_ms * 1e-3},
                              world_cache_.get());
  ++world_builds_;
  worlds_[sensor] = CachedWorld{revision_, time_, w};
  return w;
}

metrics::ElementValue Engine::provider(const std::string& group, const std::string& element,
                                       const std::string& sensor, const std::string& target) {
  const metrics::GroupSpec& g = metrics::provider_group(group);
  if (g.needs_target) {
    if (target.empty())
      throw Error(Status::null_argument, "target: group '" + group + "' needs a target object");
    if (metrics::is_atmospheric_path_element(element)) {
      const auto w = world(sensor);
      return metrics::atmospheric_path_element(
          metrics::atmospheric_path(*w, metrics::find_target(*w, universe_, target)), element);
    }
    return metrics::target_element(target_metrics(sensor, target), element);
  }
  const sensor::StaticMetrics& m = static_metrics(sensor);
  if (!target.empty()) universe_.get(target, "target");  // a named target must exist even if unused
  return metrics::static_element(m, group, element);
}

std::vector<double> Engine::provider_series(const std::string& group, const std::string& element,
                                            const std::string& sensor, const std::string& target,
                                            const std::vector<EngineTime>& times) {
  std::vector<double> values;
  values.reserve(times.size());
  const std::size_t every = std::max<std::size_t>(1, times.size() / 100);
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (i % every == 0) progress(static_cast<double>(i) / static_cast<double>(times.size()), "report");
    set_time(times[i]);
    const metrics::ElementValue v = provider(group, element, sensor, target);
    if (v.type == metrics::ElementType::curve)
      throw Error(Status::type_mismatch, "element: '" + element + "' is a curve, not a scalar");
    values.push_back(v.number);
  }
  progress(1.0, "report");
  return values;
}

const metrics::TargetMetrics& Engine::target_metrics(const std::string& sensor, const std::string& target) {
  const auto key = std::make_pair(sensor, target);
  auto it = target_cache_.find(key);
  if (it != target_cache_.end()) return it->second;
  const auto model = sensor_model(sensor);
  const auto w = world(sensor);
  const scene::WorldObject& t = metrics::find_target(*w, universe_, target);
  return target_cache_.emplace(key, metrics::target_metrics(*w, *model, t)).first->second;
}

const Frame& Engine::render(const std::string& name) {
  const auto t0 = clock_type::now();
  progress(0.0, "render");
  auto frame = std::make_shared<Frame>();
  frame->sensor_model = sensor_model(name);
  frame->world = world(name);
  const universe::SensorParameters& own = frame->sensor_model->parameters;
  if (own.fidelity.error_budget > 0) {
    CachedAdaptive& cached = adaptive_[name];
    if (cached.chosen_for != frame->world) {
      cached.choice = scene::choose_fidelity(*frame->world, universe_, own.spectral_intervals, options_.threads);
      cached.chosen_for = frame->world;
    }
    adaptive_frame(name, cached.choice, *frame);
  } else
    frame->fidelity = scene::fixed_fidelity(own.fidelity, own.spectral_intervals);
  const sensor::SensorModel& model = *frame->sensor_model;
  const scene::World& w = *frame->world;
  const auto t1 = clock_type::now();
  progress(0.05, "render");
  FrameBuffers& spare = spare_buffers_[name];
  // Motion sub-steps (scene/motion_substeps.hpp): the worlds of the sub-steps.
  frame->substep_worlds = scene::substep_worlds(w, universe_, library(), universe_.sensor(name),
                                                model.parameters.motion_substeps, world_cache_.get());
  const auto& substeps = frame->substep_worlds;
  const double substep_worlds_s = seconds_between(t1, clock_type::now());  // counted with the ray casting
  frame->scene_in_strips =
      static_cast<double>(sensor::whole_frame_bytes(model)) > model.fidelity().scene_memory_max_mib * 1048576.0;
  if (frame->scene_in_strips) {
    // The scene made strip by strip as the convolution asks for its rows.
    frame->scene = scene::generate_point_sources(w);
    scene::SceneRows rows;
    double cast_s = 0;
    const double grid_rows = static_cast<double>(w.grid().height());
    const sensor::SceneRowSource source = [&](std::int64_t first, std::int64_t last) -> const double* {
      const auto start = clock_type::now();
      rows = scene::generate_moving_scene_rows(w, substeps, first, last, options_.threads, std::move(rows));
      cast_s += seconds_between(start, clock_type::now());
      frame->scene.rays += rows.rays;
      progress(0.05 + 0.5 * static_cast<double>(last) / grid_rows, "render");
      return rows.radiance_W_cm2_sr.data();
    };
    frame->sensor = sensor::render_sensor_image(model, frame->scene.image, noise_rng_, options_.threads,
                                                std::move(spare.sensor), &source);
    frame->scene.ray_casting_s = cast_s;
    frame->sensor.convolution_s -= cast_s;
  } else {
    frame->scene = scene::generate_moving_scene(w, substeps, options_.threads, std::move(spare.scene));
    progress(0.6, "render");
    frame->sensor =
        sensor::render_sensor_image(model, frame->scene.image, noise_rng_, options_.threads, std::move(spare.sensor));
  }
  frame->scene.ray_casting_s += substep_worlds_s;
  progress(0.9, "render");
  const auto t2 = clock_type::now();
  const universe::SensorParameters& p = model.parameters;
  sensor::DisplayOptions display;
  display.agc = p.display_agc;
  display.gain_step = p.display_gain_step;
  display.stretch = p.display_stretch;
  frame->scene_display_options = display;
  display.full_scale = std::isfinite(model.metrics.saturation_electrons) ? model.metrics.saturation_electrons : 1e6;
  display.saturation = model.metrics.saturation_electrons;  // +inf with saturation off
  if (p.detector.enabled) display.full_scale = display.saturation = p.detector.full_well_e;  // sensor/detector.hpp
  frame->sensor_display_options = display;
  frame->display_threads = options_.threads;
  frame->scene_display_storage = std::move(spare.scene_display);
  frame->sensor_display_storage = std::move(spare.sensor_display);
  const auto t3 = clock_type::now();
  // Per-frame truth: the target metrics of every object and star in the
  // field, evaluated on the same world, with their directions (frame.hpp).
  const geometry::SampleGrid& grid = w.grid();
  const frames::Horizon horizon = frames::horizon_at(w.time, w.observer.position_m);
  const scene::AstrometricFrame astrometric(w);
  frame->astrometric_wcs = astrometric.wcs();
  frame->observer_earth_fixed_m = frames::j2000_to_earth_fixed(w.time) * w.observer.position_m;
  // The directions of a truth row (frame.hpp): apparent at the frame time,
  // astrometric at the middle, start and end of the integration, geometric.
  struct Directions {
    Eigen::Vector3d apparent, astrometric, start, end, geometric;
  };
  const auto add_truth = [&](TruthEntry e, const Directions& d, double streak_c, double streak_r) {
    e.topocentric = horizon.near_earth;
    if (e.topocentric) frames::azimuth_elevation_deg(horizon.j2000_to_enu * d.apparent, e.azimuth_deg, e.elevation_deg);
    scene::ra_dec_deg(d.apparent, e.ra_deg, e.dec_deg);
    scene::ra_dec_deg(d.astrometric, e.astrometric_ra_deg, e.astrometric_dec_deg);
    scene::ra_dec_deg(d.start, e.start_astrometric_ra_deg, e.start_astrometric_dec_deg);
    scene::ra_dec_deg(d.end, e.end_astrometric_ra_deg, e.end_astrometric_dec_deg);
    scene::ra_dec_deg(d.geometric, e.geometric_ra_deg, e.geometric_dec_deg);
    const double dx = 0.5 * streak_c / static_cast<double>(grid.per_pixel);
    const double dy = 0.5 * streak_r / static_cast<double>(grid.per_pixel);
    e.start_x = e.metrics.pixel_x - dx;
    e.start_y = e.metrics.pixel_y - dy;
    e.end_x = e.metrics.pixel_x + dx;
    e.end_y = e.metrics.pixel_y + dy;
    frame->truth.push_back(std::move(e));
  };
  const scene::ApparentGrid apparent(w);  // point sources' streaks as the image has them
  const double half_integration_s = 0.5 * w.view.integration_time_s;
  for (const auto& o : w.objects) {
    if (o->imaging == scene::Imaging::outside) continue;
    if (o->central_body && o->imaging != scene::Imaging::point_source) continue;
    TruthEntry e;
    e.object = o->name;
    e.metrics = metrics::target_metrics(w, model, *o);
    if (!e.metrics.in_field) continue;
    e.air_mass = w.atmosphere.air_mass(w.atmosphere.path_to(o->placed.position_m));
    scene::GridPlace place;
    apparent.object(*o, place);
    // The apparent direction moves over the integration as the object's
    // position (seen one light time earlier) relative to the observer's;
    // the astrometric ones are the frame's map of the apparent ones.
    const universe::Object& u = universe_.get(o->name);
    const auto toward = [&](const EngineTime& t, const Eigen::Vector3d& observer) {
      return (universe::kinematics_at(universe_, u, t.plus_seconds(-o->light_time_s)).position_m - observer)
          .normalized();
    };
    const Eigen::Vector3d middle = toward(w.time, w.observer.position_m);
    Directions d;
    d.apparent = o->placed.position_m.normalized();
    d.astrometric = astrometric.astrometric(d.apparent);
    d.start = astrometric.astrometric(d.apparent + toward(w.time.plus_seconds(-half_integration_s),
                                                          w.observer.position_start_m) - middle);
    d.end = astrometric.astrometric(d.apparent + toward(w.time.plus_seconds(half_integration_s),
                                                        w.observer.position_end_m) - middle);
    d.geometric = universe::kinematics_at(universe_, u, w.time).position_m - w.observer.position_m;
    add_truth(std::move(e), d, place.streak_columns, place.streak_rows);
  }
  // A star's places do not move over an integration (its streak is the
  // sensor's turning). Its astrometric place, which the frame's map gives
  // from the apparent one (to 1e-15 rad), is the chain without deflection
  // and aberration: made so directly; it is also the geometric place.
  universe::ApparentPlaceOptions astrometric_place;
  astrometric_place.light_deflection = astrometric_place.aberration = false;
  const universe::ApparentPlaceContext star_context =
      w.sky.catalogue ? universe::apparent_place_context_geocentric(w.time, w.observer.position_m,
                                                                    w.observer.velocity_m_s,
                                                                    w.sky.catalogue->epoch_julian_year())
                      : astrometric.context();
  for (const scene::WorldStar& s : w.sky.stars) {
    TruthEntry e;
    e.kind = TruthEntry::Kind::star;
    e.object = s.id;
    e.metrics = metrics::star_metrics(w, model, s);
    e.v_mag = s.v_mag;
    e.b_v_mag = s.b_v_mag;
    e.air_mass = w.atmosphere.air_mass_toward(s.direction_j2000);
    const Eigen::Vector3d place =
        universe::apparent_direction(w.sky.catalogue->stars()[s.catalogue_index], star_context, astrometric_place);
    const Directions d{s.direction_j2000, place, place, place, place};
    add_truth(std::move(e), d, s.streak_columns, s.streak_rows);
  }
  if (!w.sky.warning.empty() && w.sky.warning != last_sky_warning_ && options_.log)
    options_.log(2, w.sky.star_field + ": " + w.sky.warning);
  last_sky_warning_ = w.sky.warning;
  const auto t4 = clock_type::now();
  FrameTimings& tm = frame->timings;
  tm.setup_s = seconds_between(t0, t1);
  tm.shading_s = frame->scene.point_sources_s;
  tm.ray_casting_s = frame->scene.ray_casting_s;
  tm.rays = frame->scene.rays;
  tm.convolution_s = frame->sensor.convolution_s;
  tm.point_sources_s = frame->sensor.point_sources_s;
  tm.noise_s = frame->sensor.noise_s;
  tm.display_s = seconds_between(t2, t3);
  tm.truth_s = seconds_between(t3, t4);
  progress(1.0, "render");
  if (options_.log) {
    std::ostringstream s;
    s << "render " << name << ": " << tm.rays << " rays, " << frame->scene.image.point_sources.size()
      << " point sources, " << 1e3 * seconds_between(t0, t4) << " ms";
    options_.log(0, s.str());
  }
  std::shared_ptr<const Frame>& slot = frames_[name];
  if (slot.use_count() == 1) {
    Frame& old = *std::const_pointer_cast<Frame>(slot);
    spare.scene = std::move(old.scene);
    spare.sensor = std::move(old.sensor);
    spare.scene_display = std::move(old.scene_display_storage);
    spare.sensor_display = std::move(old.sensor_display_storage);
  }
  slot = frame;
  return *frame;
}

void Engine::adaptive_frame(const std::string& name, const scene::FidelityChoice& choice, Frame& frame) {
  scene::FidelityChoice settings = choice;  // the key: the knobs, not the estimate
  settings.spectral_error = settings.sampling_error = settings.patch_error = settings.point_source_error =
      settings.atmosphere_error = 0;
  const std::string key = settings.json();
  const universe::Object& s = universe_.sensor(name);
  CachedAdaptive& cached = adaptive_[name];
  if (!cached.model || cached.model_revision != s.revision || cached.settings != key) {
    universe::SensorParameters p = s.sensor;
    p.fidelity = choice.fidelity;
    p.spectral_intervals = choice.spectral_intervals;
    cached.model = sensor::resolve_sensor(p);
    cached.model_revision = s.revision;
    cached.world.reset();
  }
  if (!cached.world || cached.world_revision != revision_ || !(cached.time == time_) || cached.settings != key) {
    const sensor::SensorModel& m = *cached.model;
    cached.world = scene::build_world(universe_, library(), time_, s,
                                      scene::ViewDefinition{m.grid, m.spectral, m.fidelity(),
                                                            m.parameters.integration_time_ms * 1e-3},
                                      world_cache_.get());
    cached.world_revision = revision_;
    cached.time = time_;
    ++world_builds_;
  }
  cached.settings = key;
  frame.sensor_model = cached.model;
  frame.world = cached.world;
  frame.fidelity = choice;
}

const Frame& Engine::frame(const std::string& name) const {
  universe_.sensor(name);
  auto it = frames_.find(name);
  if (it == frames_.end())
    throw Error(Status::no_state, "sensor: no frame rendered for '" + name + "' yet; call eoir_render first");
  return *it->second;
}

scene::Pick Engine::pick(const std::string& sensor, int space, std::int64_t x, std::int64_t y) const {
  const Frame& f = frame(sensor);
  if (space != 0 && space != 1) throw Error(Status::out_of_range, "space: 0 (sample) or 1 (pixel)");
  const geometry::SampleGrid& g = f.grid();
  const std::int64_t k = g.per_pixel;
  const std::int64_t limit_x = space == 0 ? g.field_width() : g.pixels_x;
  const std::int64_t limit_y = space == 0 ? g.field_height() : g.pixels_y;
  if (x < 0 || x >= limit_x) throw Error(Status::out_of_range, "x: " + std::to_string(x) + " >= " + std::to_string(limit_x));
  if (y < 0 || y >= limit_y) throw Error(Status::out_of_range, "y: " + std::to_string(y) + " >= " + std::to_string(limit_y));
  // A pixel is picked at its centre sample (index k / 2 of its k).
  const std::int64_t c = (space == 0 ? x : x * k + k / 2) + g.guard_samples();
  const std::int64_t r = (space == 0 ? y : y * k + k / 2) + g.guard_samples();
  if (f.scene_in_strips) {  // the sample's row made again
    const scene::SceneRows row =
        scene::generate_moving_scene_rows(*f.world, f.substep_worlds, r, r + 1, options_.threads);
    return scene::pick_sample(*f.world, row.radiance_W_cm2_sr[static_cast<std::size_t>(c)],
                              row.hits[static_cast<std::size_t>(c)], c, r);
  }
  const auto i = static_cast<std::size_t>(r * g.width() + c);
  return scene::pick_sample(*f.world, f.scene.image.radiance_W_cm2_sr[i], f.scene.hits[i], c, r);
}

void Engine::scene_field_radiance(const std::string& sensor, double* values) const {
  const Frame& f = frame(sensor);
  const geometry::SampleGrid& g = f.grid();
  const std::int64_t w = g.width(), guard = g.guard_samples(), fw = g.field_width(), fh = g.field_height();
  // Rows [first, last) of the grid from radiance, which holds rows from buffer_first on.
  const auto copy_rows = [&](const std::vector<double>& radiance, std::int64_t buffer_first, std::int64_t first,
                             std::int64_t last) {
    for (std::int64_t r = first; r < last; ++r)
      std::copy_n(radiance.begin() + (r - buffer_first) * w + guard, fw, values + (r - guard) * fw);
  };
  if (!f.scene_in_strips) {
    copy_rows(f.scene.image.radiance_W_cm2_sr, 0, guard, guard + fh);
    return;
  }
  constexpr std::int64_t kRowsPerStrip = 256;
  scene::SceneRows rows;
  for (std::int64_t first = guard; first < guard + fh; first += kRowsPerStrip) {
    const std::int64_t last = std::min(guard + fh, first + kRowsPerStrip);
    rows = scene::generate_moving_scene_rows(*f.world, f.substep_worlds, first, last, options_.threads,
                                             std::move(rows));
    copy_rows(rows.radiance_W_cm2_sr, first, first, last);
  }
}

}  // namespace eoir

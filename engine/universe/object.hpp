// One object of the modeled universe (spec 3.1): central body, star field,
// satellite, aircraft, ground vehicle, missile, sensor (an SSG-SMP), or site
// (a place fixed on the Earth that carries sensors and images nothing).
#pragma once
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/frames.hpp"
#include "core/time.hpp"
#include "universe/atmosphere_settings.hpp"
#include "universe/cloud_settings.hpp"
#include "universe/central_bodies.hpp"
#include "universe/missile.hpp"
#include "universe/sensor_parameters.hpp"
#include "universe/shapes.hpp"

namespace eoir::universe {

enum class ObjectKind : int {
  central_body = 1,
  star_field = 2,
  satellite = 3,
  aircraft = 4,
  ground_vehicle = 5,
  missile = 6,
  sensor = 7,
  site = 8,
};
const char* kind_name(ObjectKind kind);  // "satellite", ...

// Frame in which a pushed state is kept and extrapolated.
enum class StateFrame : int { j2000 = 0, earth_fixed = 1 };

// The last state a host pushed, in its own frame; the engine moves the object
// along its velocity (and keeps its attitude fixed in that frame) until the
// next push.
struct PushedState {
  bool valid = false;
  EngineTime epoch;
  StateFrame frame = StateFrame::j2000;
  frames::Vec3 position_m = frames::Vec3::Zero();
  frames::Vec3 velocity_m_s = frames::Vec3::Zero();
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();  // body -> frame
  // About which the attitude turns between pushes, in the frame's axes (rad/s).
  frames::Vec3 angular_velocity_rad_s = frames::Vec3::Zero();
};

// How an object's surface temperature varies (spec 4.3.1.3): uniform
// (temperature_K everywhere); subsolar (eq. 12: T_ss cos^(1/4) of the angle
// from the subsolar point on the day side, the night side cooling toward
// night_temperature_K); eclipse (satellites: temperature_K in sunlight,
// eclipse_temperature_K in the Earth's shadow, radiative equilibrium in the
// penumbra).
// climatology (the Earth: the diurnal cycle between the monthly mean daily
// minimum and maximum of its latitude, land or water by the land mask).
enum class ThermalModel : int { uniform = 0, subsolar = 1, eclipse = 2, climatology = 3 };
const std::vector<std::string>& thermal_model_names();

// How a distant area source smaller than a sample is imaged (spec 4.1.6.1):
// detailed (the sum over its visible tessellations, each with its SRF and
// BRDF) or simple (a Lambertian sphere of equal volume with the phase law);
// automatic is detailed for satellites and missiles, simple otherwise.
enum class PointSourceModel : int { automatic = 0, detailed = 1, simple = 2 };
const std::vector<std::string>& point_source_model_names();

// Physical properties of a body-like object (satellites, vehicles, missiles;
// central bodies have fixed shapes).
struct BodyProperties {
  ShapeKind shape = ShapeKind::sphere;
  std::vector<double> dimensions_m{1.0};
  std::string material = "gray_body";
  double temperature_K = 300.0;
  double reflectance = 0.0;  // gray-body SRF; emissivity = 1 - SRF (spec 4.1.4.1)
  std::int64_t stages = 1;   // missiles only (spec 4.3.6)
  double patch_size_m = 0.0; // tessellation (spec 4.1.5.2): patch edge; 0 = automatic (the sensor's fidelity)
  std::string composite = "[]";  // parts of shape "composite" as set (universe/composite.hpp)
  std::shared_ptr<const std::vector<ShapePart>> composite_parts =
      std::make_shared<const std::vector<ShapePart>>();  // parsed once, when set
  std::string mesh_file;  // shape "mesh": the model file (dimensions_m = [scale])
  std::shared_ptr<const MeshModel> mesh;  // read once, when set
  std::string mesh_materials = "{}";      // the file's materials mapped (universe/composite.hpp)
  MeshMaterials mesh_materials_parsed;
  ThermalModel thermal_model = ThermalModel::uniform;
  double subsolar_temperature_K = 390.0;  // the Moon's (Lawson and Jakosky)
  double night_temperature_K = 95.0;
  double eclipse_temperature_K = 200.0;   // thermal model eclipse: in full shadow
  PointSourceModel point_source_model = PointSourceModel::automatic;
  std::string spectrum;  // a tabulated self-radiance (universe/spectrum_table.hpp) instead of eps B(T); "" none
  bool rings = false;    // Saturn (central body): its disc's brightness with the rings' (on by default)
  // Missiles (universe/missile.hpp): stages as set, parsed once; "[]" = none
  // (the missile is its shape). The launch as set ("" = not launched).
  std::string missile_stages = "[]";
  std::shared_ptr<const std::vector<MissileStage>> missile_stage_list =
      std::make_shared<const std::vector<MissileStage>>();
  std::string launch_time_utc;
  std::optional<EngineTime> launch_time;
};

// The shape parts of a body in its body frame: the composite's parts, one part
// for a simple shape, none for shape none.
std::vector<ShapePart> shape_parts(const BodyProperties& body);

// The sky (spec 4.1.4, 4.1.6.1, 4.3.2): catalogue stars and the background
// light. Without a star field object the sky is black and no surface
// receives background light.
struct StarFieldProperties {
  double limiting_magnitude = 9.0;
  std::string catalog_file;              // "" = the data folder's Hipparcos/Tycho; else a CSV (star_catalog.hpp)
  double catalog_epoch_year = 2000.0;    // TDB Julian year of the CSV's positions
  bool background_light = true;          // E_bkg of eq. 4 on surfaces, E_bkg / pi as sky radiance
  double zodiacal_light_scale = 1.0;     // 1 = Leinert Table 19 (90 deg elongation in the ecliptic)
};

// A site: fixed on the Earth at a WGS84 geodetic position. Its body axes are
// its local horizon (x east, y north, z up along the geodetic normal), so a
// sensor on it that is not pointed looks at the zenith with north up.
struct SiteProperties {
  double latitude_deg = 0.0;
  double longitude_deg = 0.0;
  double height_m = 0.0;  // above the ellipsoid
};

struct Object {
  std::string name;
  ObjectKind kind = ObjectKind::satellite;
  CentralBody central_body = CentralBody::sun;  // central bodies only
  std::string parent;  // sensors only
  BodyProperties body;
  AtmosphereSettings atmosphere;  // central bodies: only the Earth's may be on
  CloudSettings clouds;           // central bodies: only the Earth's may be on
  StarFieldProperties stars;
  SensorParameters sensor;
  SiteProperties site;
  PushedState state;  // never valid for sites (their position is site)
  std::uint64_t revision = 0;  // bumped on every property change (sensor-model caches)
};

}  // namespace eoir::universe

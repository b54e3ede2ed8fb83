// The Earth's atmosphere as its central body's properties (spec 4.3.1.1):
// the model (none keeps every path in vacuum), the profile of temperature,
// pressure and absorbers (US76 or one of the six AFGL 1986 models), the
// scaling of the water-vapour and ozone columns, and the aerosol model with
// the meteorological visibility that sets its 0.55 um extinction near the
// ground. Read by engine/atmosphere/, which builds the state they describe.
#pragma once
#include <string>
#include <vector>

namespace eoir::universe {

enum class AtmosphereModel : int { none = 0, simple = 1 };
enum class AtmosphereProfileName : int {
  us_standard_1976 = 0,
  tropical = 1,
  midlatitude_summer = 2,
  midlatitude_winter = 3,
  subarctic_summer = 4,
  subarctic_winter = 5,
};
enum class AerosolModel : int { rural = 0, urban = 1, maritime = 2, none = 3 };

const std::vector<std::string>& atmosphere_model_names();
const std::vector<std::string>& atmosphere_profile_names();
const std::vector<std::string>& aerosol_model_names();

struct AtmosphereSettings {
  AtmosphereModel model = AtmosphereModel::none;
  AtmosphereProfileName profile = AtmosphereProfileName::us_standard_1976;
  AerosolModel aerosol = AerosolModel::rural;
  double visibility_km = 23.0;       // meteorological range (Koschmieder: 3.912 / extinction at 0.55 um)
  bool downwelling = true;           // the sky's light on surfaces (eq. 9; ERRATA row on 4.1.5.3)
  bool airglow = true;               // the night airglow's layer (atmosphere/airglow.hpp)
  double water_vapor_scale = 1.0;    // multiplies the profile's H2O column
  double ozone_scale = 1.0;          // multiplies the profile's O3 column
  bool operator==(const AtmosphereSettings& o) const {
    return model == o.model && profile == o.profile && aerosol == o.aerosol && visibility_km == o.visibility_km &&
           downwelling == o.downwelling && airglow == o.airglow && water_vapor_scale == o.water_vapor_scale && ozone_scale == o.ozone_scale;
  }
};

}  // namespace eoir::universe

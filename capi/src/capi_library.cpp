// The user's materials and tabulated spectra (spec 4.1.4, 4.1.4.1).
#include "capi_internal.hpp"

using namespace eoir;
using eoir::capi::need;
using eoir::capi::str;
using eoir::capi::with_engine;

extern "C" {

EOIR_API eoir_status eoir_material_load(eoir_engine engine, const char* path) {
  return with_engine(engine, [&](Engine& e) { e.add_material(universe::load_material(str(path, "path"))); });
}

EOIR_API eoir_status eoir_spectrum_add(eoir_engine engine, const char* name, const double* wavelength_um,
                                       const double* radiance_W_cm2_sr_um, size_t count) {
  return with_engine(engine, [&](Engine& e) {
    const std::string n = str(name, "name");
    need(wavelength_um, "wavelength_um");
    need(radiance_W_cm2_sr_um, "radiance_W_cm2_sr_um");
    constexpr size_t max_points = 1u << 20;
    if (count > max_points)
      throw Error(Status::limit_exceeded, "count: at most " + std::to_string(max_points) + " points, got " +
                                              std::to_string(count));
    e.add_spectrum(universe::NamedSpectrum{
        n, "user", TabulatedFunction(std::vector<double>(wavelength_um, wavelength_um + count),
                                     std::vector<double>(radiance_W_cm2_sr_um, radiance_W_cm2_sr_um + count), n)});
  });
}
}

#include "universe/composite.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/value.hpp"
#include "universe/json_document.hpp"
#include "universe/object_bounds.hpp"

namespace eoir::universe {
namespace {
using nlohmann::json;

[[noreturn]] void bad(const std::string& where, const std::string& what) {
  throw Error(Status::out_of_range, where + ": " + what);
}

std::vector<double> numbers(const json& j, const std::string& where, std::size_t count) {
  if (!j.is_array()) bad(where, "expected an array of " + std::to_string(count) + " numbers");
  std::vector<double> v;
  for (std::size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_number()) bad(where + "[" + std::to_string(i) + "]", "expected a number");
    v.push_back(j[i].get<double>());
    require_finite(v.back(), where + "[" + std::to_string(i) + "]");
  }
  if (count && v.size() != count) bad(where, "expected " + std::to_string(count) + " numbers, got " + std::to_string(v.size()));
  return v;
}

void flatten(const json& parts, const std::string& where, const Eigen::Vector3d& offset,
             const Eigen::Quaterniond& orientation, std::optional<double> temperature, std::optional<double> reflectance,
             std::optional<std::string> material, int depth, std::vector<ShapePart>& out) {
  if (depth > max_composite_depth)
    throw Error(Status::limit_exceeded, where + ": composites nest at most " + std::to_string(max_composite_depth) + " deep");
  if (!parts.is_array()) bad(where, "expected an array of parts");
  if (parts.empty() && depth > 1) bad(where, "a nested composite needs at least one part");
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    const json& p = parts[i];
    if (!p.is_object()) bad(at, "expected an object");
    for (auto it = p.begin(); it != p.end(); ++it) {
      static const char* known[] = {"shape", "dimensions_m", "offset_m", "orientation_wxyz", "temperature_K",
                                    "reflectance", "material", "parts"};
      bool ok = false;
      for (const char* k : known) ok = ok || it.key() == k;
      if (!ok) throw Error(Status::unknown_name, at + "." + it.key() + ": unknown field of a composite part");
    }
    Eigen::Vector3d local_offset = Eigen::Vector3d::Zero();
    if (p.contains("offset_m")) {
      const auto o = numbers(p["offset_m"], at + ".offset_m", 3);
      for (std::size_t k = 0; k < 3; ++k)
        check_range(o[k], Range{-object_bounds::max_length_m, object_bounds::max_length_m},
                    at + ".offset_m[" + std::to_string(k) + "]", "m");
      local_offset = Eigen::Vector3d(o[0], o[1], o[2]);
    }
    Eigen::Quaterniond local = Eigen::Quaterniond::Identity();
    if (p.contains("orientation_wxyz")) {
      const auto q = numbers(p["orientation_wxyz"], at + ".orientation_wxyz", 4);
      const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      if (std::fabs(n - 1.0) > 1e-6) bad(at + ".orientation_wxyz", "quaternion must have unit norm, |q| = " + std::to_string(n));
      local = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
    }
    std::optional<double> t = temperature, r = reflectance;
    std::optional<std::string> mat = material;
    if (p.contains("material")) {
      if (!p["material"].is_string() || p["material"].get<std::string>().empty())
        bad(at + ".material", "expected a material name");
      mat = p["material"].get<std::string>();
    }
    if (p.contains("temperature_K")) {
      if (!p["temperature_K"].is_number()) bad(at + ".temperature_K", "expected a number");
      t = p["temperature_K"].get<double>();
      check_range(*t, Range{0, object_bounds::max_temperature_K}, at + ".temperature_K", "K");
    }
    if (p.contains("reflectance")) {
      if (!p["reflectance"].is_number()) bad(at + ".reflectance", "expected a number");
      r = p["reflectance"].get<double>();
      check_range(*r, Range{0, 1}, at + ".reflectance");
    }
    // Compose: the part's frame inside its parent, inside the object.
    const Eigen::Vector3d body_offset = offset + orientation * local_offset;
    const Eigen::Quaterniond body_orientation = orientation * local;
    if (p.contains("parts")) {
      if (p.contains("shape") || p.contains("dimensions_m")) bad(at, "a nested composite has parts, not a shape");
      flatten(p["parts"], at + ".parts", body_offset, body_orientation, t, r, mat, depth + 1, out);
      continue;
    }
    if (!p.contains("shape") || !p["shape"].is_string()) bad(at + ".shape", "missing (or give nested parts)");
    const ShapeKind kind = parse_shape(p["shape"].get<std::string>(), at + ".shape");
    if (kind == ShapeKind::composite) bad(at + ".shape", "nest composites with \"parts\"");
    const std::vector<double> dims = p.contains("dimensions_m") ? numbers(p["dimensions_m"], at + ".dimensions_m", 0)
                                                                  : std::vector<double>{};
    check_dimensions(kind, dims, at + ".dimensions_m");
    if (out.size() >= max_composite_parts)
      throw Error(Status::limit_exceeded, at + ": at most " + std::to_string(max_composite_parts) + " parts per object");
    out.push_back(ShapePart{kind, dims, body_offset, body_orientation, t, r, mat, std::nullopt});
  }
}
}  // namespace

std::vector<ShapePart> parse_composite(const std::string& text, const std::string& field) {
  const json doc = parse_json_document(text, field, Status::out_of_range);
  std::vector<ShapePart> out;
  flatten(doc, field, Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity(), std::nullopt, std::nullopt, std::nullopt, 1,
          out);
  return out;
}

}  // namespace eoir::universe

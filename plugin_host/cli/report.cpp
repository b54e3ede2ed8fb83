#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "iso_time.hpp"

namespace eoir::cli {

std::vector<std::string> provider_groups(const eoir_api_v1& api) {
  std::vector<std::string> groups;
  for (std::size_t i = 0; i < 1024; ++i) {
    const char* g = nullptr;
    if (api.provider_group_at(i, &g) != EOIR_OK || g == nullptr) break;
    groups.emplace_back(g);
  }
  return groups;
}

std::vector<ElementInfo> provider_elements(const eoir_api_v1& api, const std::string& group) {
  std::vector<ElementInfo> elements;
  for (std::size_t i = 0; i < 4096; ++i) {
    eoir_element_info info{};
    info.struct_size = sizeof info;
    if (api.provider_element_at(group.c_str(), i, &info) != EOIR_OK) break;
    ElementInfo e;
    e.name = info.name ? info.name : "";
    e.type = info.type;
    e.unit = info.unit ? info.unit : "";
    e.x_unit = info.x_unit ? info.x_unit : "";
    elements.push_back(std::move(e));
  }
  return elements;
}

ReportRow evaluate_row(const Engine& engine, const std::string& group, const std::vector<ElementInfo>& elements,
                       const std::string& sensor, const std::optional<std::string>& target, double t_s) {
  const eoir_api_v1& api = engine.api();
  const char* tgt = target ? target->c_str() : nullptr;
  ReportRow row;
  row.t_s = t_s;
  for (const ElementInfo& info : elements) {
    ElementValue v;
    v.info = &info;
    const std::string where = group + " / " + info.name + " at " + format_iso(t_s);
    if (info.type == EOIR_TYPE_CURVE) {
      std::size_t count = 0;
      eoir_status s = api.provider_get_curve(engine.handle(), group.c_str(), info.name.c_str(), sensor.c_str(), tgt,
                                             nullptr, nullptr, 0, &count);
      if (s != EOIR_OK && s != EOIR_ERR_BUFFER_TOO_SMALL) engine.check(s, where);
      v.x.resize(count);
      v.y.resize(count);
      s = api.provider_get_curve(engine.handle(), group.c_str(), info.name.c_str(), sensor.c_str(), tgt, v.x.data(),
                                 v.y.data(), count, &count);
      engine.check(s, where);
      v.x.resize(count);
      v.y.resize(count);
    } else {
      engine.check(api.provider_get(engine.handle(), group.c_str(), info.name.c_str(), sensor.c_str(), tgt, &v.value),
                   where);
    }
    row.values.push_back(std::move(v));
  }
  return row;
}

namespace {
nlohmann::ordered_json number(double x) {
  if (!std::isfinite(x)) return nullptr;  // JSON has no NaN or infinity
  return x;
}
}  // namespace

void write_json(std::ostream& out, const std::string& provider, const std::string& sensor,
                const std::optional<std::string>& target, const std::vector<ReportRow>& rows) {
  nlohmann::ordered_json doc;
  doc["provider"] = provider;
  doc["sensor"] = sensor;
  doc["target"] = target ? nlohmann::ordered_json(*target) : nlohmann::ordered_json(nullptr);
  doc["rows"] = nlohmann::ordered_json::array();
  for (const ReportRow& row : rows) {
    nlohmann::ordered_json r;
    r["time"] = format_iso(row.t_s);
    nlohmann::ordered_json values = nlohmann::ordered_json::object();
    for (const ElementValue& v : row.values) {
      nlohmann::ordered_json e;
      switch (v.info->type) {
        case EOIR_TYPE_BOOL:
          e["value"] = v.value != 0.0;
          break;
        case EOIR_TYPE_INTEGER:
          if (std::isfinite(v.value))
            e["value"] = static_cast<long long>(std::llround(v.value));
          else
            e["value"] = nullptr;
          break;
        case EOIR_TYPE_CURVE: {
          nlohmann::ordered_json y = nlohmann::ordered_json::array(), x = nlohmann::ordered_json::array();
          for (double d : v.y) y.push_back(number(d));
          for (double d : v.x) x.push_back(number(d));
          e["value"] = std::move(y);
          e["unit"] = v.info->unit;
          e["x"] = std::move(x);
          e["x_unit"] = v.info->x_unit;
          break;
        }
        default:
          e["value"] = number(v.value);
      }
      e["unit"] = v.info->unit;
      values[v.info->name] = std::move(e);
    }
    r["values"] = std::move(values);
    doc["rows"].push_back(std::move(r));
  }
  out << doc.dump(2) << "\n";
}

namespace {
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

std::string format_value(double x, int32_t type, const char* fmt) {
  if (type == EOIR_TYPE_BOOL) return x != 0.0 ? "true" : "false";
  char buf[64];
  if (type == EOIR_TYPE_INTEGER && std::isfinite(x))
    std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(std::llround(x)));
  else
    std::snprintf(buf, sizeof buf, fmt, x);
  return buf;
}
}  // namespace

bool write_csv(std::ostream& out, const std::vector<ElementInfo>& elements, const std::vector<ReportRow>& rows) {
  bool omitted = false;
  out << "time";
  for (const ElementInfo& e : elements) {
    if (e.type == EOIR_TYPE_CURVE) {
      omitted = true;
      continue;
    }
    out << "," << csv_field(e.unit.empty() ? e.name : e.name + " [" + e.unit + "]");
  }
  out << "\n";
  for (const ReportRow& row : rows) {
    out << format_iso(row.t_s);
    for (const ElementValue& v : row.values)
      if (v.info->type != EOIR_TYPE_CURVE) out << "," << format_value(v.value, v.info->type, "%.17g");
    out << "\n";
  }
  return omitted;
}

void write_table(std::ostream& out, const std::string& group, const ReportRow& row) {
  std::size_t width = 0;
  for (const ElementValue& v : row.values) width = std::max(width, v.info->name.size());
  out << group << "\n";
  for (const ElementValue& v : row.values) {
    std::string value;
    if (v.info->type == EOIR_TYPE_CURVE)
      value = "curve, " + std::to_string(v.y.size()) + " points vs " + v.info->x_unit;
    else
      value = format_value(v.value, v.info->type, "%.6g");
    char line[512];
    std::snprintf(line, sizeof line, "  %-*s  %14s  %s", static_cast<int>(width), v.info->name.c_str(), value.c_str(),
                  v.info->unit.c_str());
    out << line << "\n";
  }
}

}  // namespace eoir::cli

#include "scenario_host.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace eoir::test {

double Image::mean(int x0, int y0, int w, int h) const {
  double s = 0;
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x) s += at(x, y);
  return s / (static_cast<double>(w) * h);
}

double Image::stddev(int x0, int y0, int w, int h) const {
  const double m = mean(x0, y0, w, h);
  double s = 0;
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x) s += (at(x, y) - m) * (at(x, y) - m);
  return std::sqrt(s / (static_cast<double>(w) * h - 1));
}

double Image::sum() const {
  double s = 0;
  for (double v : values) s += v;
  return s;
}

double reference_band_radiance_8_12(double T) {
  if (T <= 0) return 0;
  const double c1 = 2 * 6.62607015e-34 * 299792458.0 * 299792458.0 * 1e20;  // W um^4 / (cm^2 sr)
  const double c2 = 6.62607015e-34 * 299792458.0 / 1.380649e-23 * 1e6;     // um K
  auto B = [&](double l) { return c1 / std::pow(l, 5) / std::expm1(c2 / (l * T)); };
  const int n = 4000;
  const double a = 8, b = 12, h = (b - a) / n;
  double s = B(a) + B(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * B(a + i * h);
  return s * h / 3;
}

std::string validation_scenario(const std::string& name) {
  return std::string(EOIR_SOURCE_DIR) + "/scenarios/validation/" + name;
}

ScenarioHost::ScenarioHost(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
  const std::string file = validation_scenario(name);
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot open " + file);
  nlohmann::json doc = nlohmann::json::parse(in);
  if (edit) edit(doc);
  engine_ = std::make_unique<cli::Engine>(EOIR_LIBRARY_PATH);
  scenario_ = std::make_unique<cli::Scenario>(cli::parse_scenario(doc, file));
  session_ = std::make_unique<cli::Session>(*engine_, *scenario_);
  at(0.0);
}

void ScenarioHost::at(double seconds) { session_->set_time(scenario_->start_s + seconds); }

void ScenarioHost::set_number(const std::string& o, const std::string& p, double v) {
  engine_->check(api().set_number(handle(), o.c_str(), p.c_str(), v), o + "." + p);
}
void ScenarioHost::set_bool(const std::string& o, const std::string& p, bool v) {
  engine_->check(api().set_bool(handle(), o.c_str(), p.c_str(), v ? 1 : 0), o + "." + p);
}
void ScenarioHost::set_string(const std::string& o, const std::string& p, const std::string& v) {
  engine_->check(api().set_string(handle(), o.c_str(), p.c_str(), v.c_str()), o + "." + p);
}

void ScenarioHost::render(const std::string& sensor) {
  engine_->check(api().render(handle(), sensor.c_str()), "render " + sensor);
}

Image ScenarioHost::image(int kind, const std::string& sensor) {
  eoir_image_info info{};
  info.struct_size = sizeof info;
  engine_->check(api().image_info_get(handle(), sensor.c_str(), kind, &info), "image info");
  Image img;
  img.width = static_cast<int>(info.width);
  img.height = static_cast<int>(info.height);
  img.values.resize(static_cast<size_t>(img.width) * img.height);
  engine_->check(api().image_get(handle(), sensor.c_str(), kind, img.values.data(), img.values.size()), "image");
  return img;
}

Pick ScenarioHost::pick(int x, int y, int space, const std::string& sensor) {
  eoir_pick p{};
  p.struct_size = sizeof p;
  size_t count = 0;
  engine_->check(api().pick_get(handle(), sensor.c_str(), space, static_cast<uint32_t>(x), static_cast<uint32_t>(y),
                                &p, nullptr, nullptr, 0, &count),
                 "pick");
  return Pick{p.hit != 0, p.object, p.range_m, p.effective_radiance, p.latitude_deg, p.longitude_deg};
}

double ScenarioHost::metric(const std::string& group, const std::string& element, const std::string& sensor) {
  double v = 0;
  engine_->check(api().provider_get(handle(), group.c_str(), element.c_str(), sensor.c_str(), nullptr, &v),
                 group + "/" + element);
  return v;
}

double ScenarioHost::target_metric(const std::string& element, const std::string& target, const std::string& sensor) {
  double v = 0;
  engine_->check(api().provider_get(handle(), "EOIR Sensor-to-Target Metrics", element.c_str(), sensor.c_str(),
                                    target.c_str(), &v),
                 "target metric " + element);
  return v;
}

eoir_status ScenarioHost::try_target_metric(const std::string& element, const std::string& target,
                                            const std::string& sensor, std::string& message) {
  double v = 0;
  const eoir_status st = api().provider_get(handle(), "EOIR Sensor-to-Target Metrics", element.c_str(),
                                            sensor.c_str(), target.empty() ? nullptr : target.c_str(), &v);
  message = api().last_error();
  return st;
}

}  // namespace eoir::test

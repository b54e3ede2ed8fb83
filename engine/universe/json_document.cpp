#include "universe/json_document.hpp"

#include <set>
#include <vector>

namespace eoir::universe {
namespace {
using nlohmann::json;

class Guard : public nlohmann::json_sax<json> {
 public:
  std::string error;
  bool null() override { return next(); }
  bool boolean(bool) override { return next(); }
  bool number_integer(number_integer_t) override { return next(); }
  bool number_unsigned(number_unsigned_t) override { return next(); }
  bool number_float(number_float_t, const string_t&) override { return next(); }
  bool string(string_t&) override { return next(); }
  bool binary(binary_t&) override { return next(); }
  bool start_object(std::size_t) override { return open(true); }
  bool start_array(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override {
    levels_.back().key = k;
    if (levels_.back().keys.insert(k).second) return true;
    error = where() + ": duplicate key '" + k + "'";
    return false;
  }
  bool parse_error(std::size_t at, const std::string& token, const nlohmann::json::exception& e) override {
    next();  // the value that failed
    error = where() + ": " +
            (e.id == 406 ? "number out of range (" + token + ")"
                         : "not valid JSON (truncated or corrupt) at byte " + std::to_string(at) + " (last read '" +
                               token.substr(0, 40) + "'; NaN and Infinity are not JSON numbers): " + e.what());
    return false;
  }

 private:
  struct Level {
    bool object;
    std::set<std::string> keys;
    std::string key;
    std::size_t count = 0;
  };
  bool next() {
    if (!levels_.empty() && !levels_.back().object) ++levels_.back().count;
    return true;
  }
  bool open(bool object) {
    next();
    if (levels_.size() >= max_json_depth) {
      error = where() + ": nested deeper than " + std::to_string(max_json_depth) + " arrays/objects";
      return false;
    }
    levels_.push_back(Level{object, {}, {}, 0});
    return true;
  }
  bool close() {
    levels_.pop_back();
    return true;
  }
  std::string where() const {
    std::string p;
    for (const Level& l : levels_) {
      if (!l.object) p += "[" + std::to_string(l.count ? l.count - 1 : 0) + "]";
      else if (!l.key.empty()) p += (p.empty() ? "" : ".") + l.key;
    }
    return p.empty() ? "(document)" : p;
  }
  std::vector<Level> levels_;
};
}  // namespace

json parse_json_document(const std::string& text, const std::string& origin, Status status) {
  Guard guard;
  if (!json::sax_parse(text, &guard, json::input_format_t::json, true) || !guard.error.empty())
    throw Error(status, origin + ": " + (guard.error.empty() ? "not valid JSON" : guard.error));
  try {
    return json::parse(text);
  } catch (const json::exception& e) {  // not expected after the pass above
    throw Error(status, origin + ": not valid JSON: " + e.what());
  }
}

}  // namespace eoir::universe

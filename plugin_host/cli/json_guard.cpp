#include "json_guard.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <set>
#include <vector>

namespace eoir::cli {
namespace {

using nlohmann::json;

// One streaming pass that builds nothing: it tracks where it is (for
// messages), the depth and the keys of each open object.
class Checker : public nlohmann::json_sax<json> {
 public:
  std::string error;  // "PATH: why" once a check failed

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(true); }
  bool start_array(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& k) override {
    Level& l = stack_.back();
    if (!l.keys.insert(k).second) {
      l.key = k;
      error = path() + ": duplicate key '" + k + "' (each key may appear once per object)";
      return false;
    }
    l.key = k;
    return true;
  }

  bool parse_error(std::size_t position, const std::string& token, const nlohmann::json::exception& ex) override {
    // Number overflow (406) names the value's path; syntax errors the byte.
    if (ex.id == 406) {
      element_pending_ = true;
      error = path() + ": number out of range (" + token + ")";
    } else {
      error = "not valid JSON at byte " + std::to_string(position) + ": " + ex.what();
      const std::string where = path();
      if (!where.empty() && where != "(document)") error += " (in " + where + ")";
    }
    return false;
  }

 private:
  struct Level {
    bool object = false;
    std::set<std::string> keys;
    std::string key;
    std::size_t count = 0;  // arrays: elements started so far
  };

  // A value starts at the current position: in an array it takes the next index.
  void begin_element() {
    if (!stack_.empty() && !stack_.back().object) ++stack_.back().count;
  }
  bool value() {
    begin_element();
    return true;
  }
  bool open(bool object) {
    begin_element();
    if (static_cast<int>(stack_.size()) >= kMaxJsonDepth) {
      error = path() + ": nested deeper than " + std::to_string(kMaxJsonDepth) + " arrays/objects";
      return false;
    }
    stack_.push_back(Level{object, {}, {}, 0});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }

  // The path of the element being read, e.g. "objects[1].motion.points[3]".
  std::string path() const {
    std::string p;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const Level& l = stack_[i];
      if (l.object) {
        if (l.key.empty() && i + 1 == stack_.size()) break;
        p += (p.empty() ? "" : ".") + l.key;
      } else {
        // the element being read: count-1 once started, count while pending
        const std::size_t index = l.count == 0 ? 0 : l.count - ((i + 1 == stack_.size() && element_pending_) ? 0 : 1);
        p += "[" + std::to_string(index) + "]";
      }
    }
    if (p.size() > 120) p = p.substr(0, 60) + "..." + p.substr(p.size() - 40);  // deep documents
    return p.empty() ? "(document)" : p;
  }

  std::vector<Level> stack_;
  bool element_pending_ = false;
};

}  // namespace

json parse_json_checked(const std::string& text) {
  Checker checker;
  const bool ok = json::sax_parse(text, &checker, json::input_format_t::json, true);
  if (!ok || !checker.error.empty())
    throw JsonInputError(checker.error.empty() ? std::string("not valid JSON") : checker.error);
  try {
    return json::parse(text);
  } catch (const json::exception& e) {  // not expected after the pass above
    throw JsonInputError(std::string("not valid JSON: ") + e.what());
  }
}

std::string read_file_capped(const std::string& path, std::size_t max_bytes) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw JsonInputError("cannot open the file: " + std::string(std::strerror(errno)));
  struct stat st {};
  if (::fstat(fd, &st) == 0) {
    if (S_ISDIR(st.st_mode)) {
      ::close(fd);
      throw JsonInputError("cannot open the file: Is a directory");
    }
    if (S_ISREG(st.st_mode) && static_cast<unsigned long long>(st.st_size) > max_bytes) {
      ::close(fd);
      throw JsonInputError("the file is larger than the limit of " + std::to_string(max_bytes >> 20) + " MiB");
    }
  }
  std::string out;
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      throw JsonInputError("cannot read the file: " + std::string(std::strerror(err)));
    }
    if (n == 0) break;
    if (out.size() + static_cast<std::size_t>(n) > max_bytes) {
      ::close(fd);
      throw JsonInputError("the file is larger than the limit of " + std::to_string(max_bytes >> 20) + " MiB");
    }
    out.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return out;
}

}  // namespace eoir::cli

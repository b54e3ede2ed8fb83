// The modeled universe of interest (spec 3.1): the registry of objects, with
// its object limits (universe/object_limits.hpp; the spec's by default).
// Copyable, so that a restore can build a new universe and swap it in only
// when it is complete.
#pragma once
#include <array>
#include <string>
#include <unordered_map>
#include <vector>

#include "universe/object.hpp"
#include "universe/object_limits.hpp"

namespace eoir::universe {

class Universe {
 public:
  Universe();  // holds the Sun, which can never be removed (spec 3.1)

  // Throws eoir::Error: unknown_name (central-body or star-field names),
  // already_exists, limit_exceeded, out_of_range (empty or long name).
  Object& add(ObjectKind kind, const std::string& name, const std::string& parent = "");
  // Removes an object and the sensors attached to it; never the Sun.
  void remove(const std::string& name);

  Object* find(const std::string& name);
  const Object* find(const std::string& name) const;
  // Throws eoir::Error(unknown_name) "field: no object named 'X'".
  Object& get(const std::string& name, const char* field = "object");
  const Object& get(const std::string& name, const char* field = "object") const;
  // Like get, and also throws unless the object is a sensor.
  const Object& sensor(const std::string& name, const char* field = "sensor") const;

  const std::vector<Object>& objects() const { return objects_; }

  const ObjectLimits& limits() const { return limits_; }
  // Throws out_of_range (check_limits) or not_allowed naming the field when
  // a limit is below the objects of its kind the universe holds.
  void set_limits(const ObjectLimits& limits);

 private:
  std::size_t count(ObjectKind kind) const { return counts_[static_cast<std::size_t>(kind)]; }
  void reindex();
  std::vector<Object> objects_;
  std::unordered_map<std::string, std::size_t> index_;  // name -> position in objects_
  std::array<std::size_t, 9> counts_{};                 // per ObjectKind
  ObjectLimits limits_;
};

}  // namespace eoir::universe

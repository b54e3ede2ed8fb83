// The modeled universe of interest (spec 3.1): the registry of objects, with
// the compile-time limits of core/limits.hpp. Copyable, so that a restore can
// build a new universe and swap it in only when it is complete.
#pragma once
#include <string>
#include <vector>

#include "universe/object.hpp"

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

 private:
  std::size_t count(ObjectKind kind) const;
  std::vector<Object> objects_;
};

}  // namespace eoir::universe

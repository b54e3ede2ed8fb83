// The named properties of each kind of object, as the C ABI and the .scd file
// see them (README "Properties").
#pragma once
#include <vector>

#include "core/value.hpp"
#include "universe/object.hpp"

namespace eoir::universe {

const std::vector<PropertySpec<Object>>& properties_of(ObjectKind kind);
// Throws eoir::Error(unknown_name) "object 'X' has no property 'p'".
const PropertySpec<Object>& find_property(const Object& object, const std::string& property);
// Sets with type check (integers are accepted where numbers are expected and
// whole numbers where integers are) and validation; bumps the revision.
void set_property(Object& object, const std::string& property, const Value& value);
Value get_property(const Object& object, const std::string& property);

}  // namespace eoir::universe

// The static data-provider catalogue (spec 5.12 Table 1; report styles of 7.6).
#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"
#include "metrics/static_providers.hpp"

using namespace eoir::metrics;

TEST(StaticProviders, GroupsAndNames) {
  const auto& groups = static_provider_groups();
  ASSERT_EQ(groups.size(), 4u);
  EXPECT_STREQ(groups[0].name, "EOIR Sensor Spatial Performance");
  EXPECT_STREQ(groups[1].name, "EOIR Sensor Spectral Performance");
  EXPECT_STREQ(groups[2].name, "EOIR Radiometric Performance");
  EXPECT_STREQ(groups[3].name, "EOIR Sensor Optics");
  EXPECT_EQ(groups[0].elements.size(), 14u);
  EXPECT_EQ(groups[1].elements.size(), 3u);
  EXPECT_EQ(groups[2].elements.size(), 7u);
  EXPECT_EQ(groups[3].elements.size(), 13u);
  for (const auto& g : groups) {
    EXPECT_FALSE(g.needs_target);
    std::set<std::string> names;
    for (const auto& e : g.elements) {
      EXPECT_TRUE(names.insert(e.name).second) << e.name;
      if (e.type == ElementType::curve) {
        EXPECT_STREQ(e.x_unit, "cycles/mrad");
      }
    }
  }
}

TEST(StaticProviders, ValuesAndErrors) {
  const eoir::sensor::StaticMetrics m = eoir::sensor::compute_static_metrics({});
  for (const auto& g : static_provider_groups())
    for (const auto& e : g.elements) {
      const ElementValue v = static_element(m, g.name, e.name);
      EXPECT_EQ(v.type, e.type) << e.name;
      if (v.type == ElementType::curve) {
        ASSERT_NE(v.curve, nullptr);
        EXPECT_EQ(v.curve->value.size(), 101u);
      }
    }
  const ElementValue pixels = static_element(m, "EOIR Sensor Spatial Performance", "Number of Horizontal Pixels");
  EXPECT_EQ(pixels.type, ElementType::integer);
  EXPECT_EQ(pixels.number, 128.0);
  EXPECT_EQ(static_element(m, "EOIR Sensor Optics", "Ensquared Energy").number, m.ensquared_energy);
  EXPECT_EQ(static_element(m, "EOIR Sensor Optics", "Optics OTF").curve, &m.optics_otf);
  try {
    static_element(m, "EOIR Sensor Optics", "Focal Length");
    FAIL();
  } catch (const eoir::Error& e) {
    EXPECT_EQ(e.status(), eoir::Status::unknown_name);
    EXPECT_STREQ(e.what(), "element: unknown element 'Focal Length' of group 'EOIR Sensor Optics'");
  }
  try {
    static_element(m, "EOIR Sensor Nonsense", "F-number");
    FAIL();
  } catch (const eoir::Error& e) {
    EXPECT_EQ(e.status(), eoir::Status::unknown_name);
    EXPECT_NE(std::string(e.what()).find("EOIR Sensor Nonsense"), std::string::npos);
  }
}

// Display images (spec 4.1.2): automatic gain control maps the least value to
// 0 and the greatest to 255 (linear between, rounded); without it the gain
// maps full_scale * 30^-step to 255 and clips; a constant image is mid-grey.
// The result is the same for any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sensor/display.hpp"

namespace s = eoir::sensor;

TEST(Display, AgcMapsTheRangeTo0Through255) {
  std::vector<double> v(100000);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = 3.0 + std::sin(0.001 * static_cast<double>(i)) * 2.0;
  v[77777] = 10.0;  // the greatest
  v[12] = -4.0;     // the least
  const auto one = s::compress_for_display(v, true, 0, 1.0, 1);
  const auto two = s::compress_for_display(v, true, 0, 1.0, 2);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one[77777], 255);
  EXPECT_EQ(one[12], 0);
  for (std::size_t i = 0; i < v.size(); i += 1009)
    EXPECT_EQ(one[i], static_cast<std::uint8_t>(std::lround((v[i] + 4.0) * 255.0 / 14.0))) << i;
}

TEST(Display, FixedGainStepsOfThirtyAndClipping) {
  const std::vector<double> v{0.0, 0.5e-6, 1e-6, 2e-6, 1e-6 / 30.0};
  const auto step0 = s::compress_for_display(v, false, 0, 1e-6, 2);
  EXPECT_EQ(step0, (std::vector<std::uint8_t>{0, 128, 255, 255, 9}));
  const auto step1 = s::compress_for_display(v, false, 1, 1e-6, 2);
  EXPECT_EQ(step1[4], 255);  // full scale / 30 maps to 255 one step up
}

TEST(Display, ConstantImageIsMidGrey) {
  const std::vector<double> v(5000, 2.5);
  for (auto b : s::compress_for_display(v, true, 0, 1.0, 2)) ASSERT_EQ(b, 128);
  const std::vector<double> zero(5000, 0.0);
  for (auto b : s::compress_for_display(zero, true, 0, 1.0, 2)) ASSERT_EQ(b, 0);
}

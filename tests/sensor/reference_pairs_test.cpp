// Spec 5.9-5.10: reference-pair interpolation and extrapolation (eqs. 43-46).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "sensor/reference_pairs.hpp"

using namespace eoir::sensor;

TEST(ReferencePairs, OnePairEq44And46) {
  const std::vector<ReferencePair> one{{10.0, 4.0e-18}};
  EXPECT_DOUBLE_EQ(operating_sensitivity(one, 10.0), 4.0e-18);
  EXPECT_NEAR(operating_sensitivity(one, 40.0), 2.0e-18, 1e-30);      // 1/sqrt(t)
  EXPECT_NEAR(operating_sensitivity(one, 2.5), 8.0e-18, 1e-30);
  EXPECT_NEAR(operating_saturation(one, 40.0), 1.0e-18, 1e-30);       // 1/t
  EXPECT_NEAR(operating_saturation(one, 5.0), 8.0e-18, 1e-30);
}

TEST(ReferencePairs, SeveralPairsOutOfOrderEq43And45) {
  // Deliberately unsorted: the model sorts by time (spec 5.9).
  const std::vector<ReferencePair> pairs{{20.0, 3.0}, {5.0, 1.0}, {10.0, 2.0}};
  // Linear between neighbours.
  EXPECT_DOUBLE_EQ(operating_sensitivity(pairs, 7.5), 1.5);
  EXPECT_DOUBLE_EQ(operating_sensitivity(pairs, 15.0), 2.5);
  EXPECT_DOUBLE_EQ(operating_saturation(pairs, 12.5), 2.25);
  // At an interior pair exactly.
  EXPECT_DOUBLE_EQ(operating_sensitivity(pairs, 10.0), 2.0);
  // Below t_1: NEI_1 sqrt(t_1/t), SEI_1 t_1/t.
  EXPECT_DOUBLE_EQ(operating_sensitivity(pairs, 1.25), 1.0 * std::sqrt(5.0 / 1.25));
  EXPECT_DOUBLE_EQ(operating_saturation(pairs, 1.25), 1.0 * 5.0 / 1.25);
  // Above t_n.
  EXPECT_DOUBLE_EQ(operating_sensitivity(pairs, 80.0), 3.0 * std::sqrt(20.0 / 80.0));
  EXPECT_DOUBLE_EQ(operating_saturation(pairs, 80.0), 3.0 * 20.0 / 80.0);
}

TEST(ReferencePairs, IrradianceRadianceConversionKeepsElectrons) {
  // ne = NEI R_E = NER R_L (spec 5.11.4): Table 3's NEI 1e-18 -> NER 2.083e-10.
  const double r_l = 2.542e11, r_e = 5.295e19;
  const double ner = radiance_from_irradiance(1.0e-18, r_l, r_e);
  EXPECT_NEAR(ner, 2.083e-10, 0.001e-10);
  EXPECT_DOUBLE_EQ(ner * r_l, 1.0e-18 * r_e);
  EXPECT_NEAR(irradiance_from_radiance(ner, r_l, r_e), 1.0e-18, 1e-30);
}

TEST(ReferencePairs, Validation) {
  auto status_of = [](const std::vector<ReferencePair>& pairs, std::string* message) {
    try {
      validate_reference_pairs(pairs, "sensitivity_pairs");
    } catch (const eoir::Error& e) {
      *message = e.what();
      return e.status();
    }
    return eoir::Status::ok;
  };
  std::string message;
  EXPECT_EQ(status_of({}, &message), eoir::Status::out_of_range);
  EXPECT_NE(message.find("sensitivity_pairs"), std::string::npos);
  // Past EOIR_MAX_REFERENCE_PAIRS: the limit status the C ABI gives (one check
  // serves both since the sensor's validation has one home).
  EXPECT_EQ(status_of(std::vector<ReferencePair>(9, ReferencePair{1.0, 1.0}), &message), eoir::Status::limit_exceeded);
  EXPECT_NE(message.find("at most 8"), std::string::npos) << message;
  std::vector<ReferencePair> eight;
  for (int i = 1; i <= 8; ++i) eight.push_back({double(i), 1.0});
  EXPECT_EQ(status_of(eight, &message), eoir::Status::ok);
  EXPECT_EQ(status_of({{0.0, 1.0}}, &message), eoir::Status::out_of_range);
  EXPECT_NE(message.find("sensitivity_pairs[0].integration_time_ms"), std::string::npos) << message;
  EXPECT_EQ(status_of({{1.0, NAN}}, &message), eoir::Status::out_of_range);
  EXPECT_NE(message.find("sensitivity_pairs[0].value"), std::string::npos) << message;
  EXPECT_EQ(status_of({{1.0, 1.0}, {1.0, 2.0}}, &message), eoir::Status::out_of_range);
  EXPECT_NE(message.find("sensitivity_pairs[1].integration_time_ms"), std::string::npos) << message;
}

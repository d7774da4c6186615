// verify's scattering rows (docs/scattering.md §6) on scattering_tiny: pss_msm4's and pss_msm6's
// bounds at scatter.beta 0 and 1 agree with pss_lp's on the same row-prefiltered moments, and a
// six-moment closed form with one sign flipped fails.
#include <gtest/gtest.h>

#include <cstdio>

#include "moments/hamburger.h"
#include "report/scatter_verify_report.h"
#include "techniques/scatter/prefiltered_scatter.h"
#include "util/error.h"
#include "verify/scatter_verification.h"

namespace mb {
namespace {

constexpr int kResolution = 128;

const ScatterVerifyFrames& tiny() {
  static const auto frames =
      scatter_verify_frames(load_dataset("scattering_tiny"), kResolution, 80, 2015, 2);
  return *frames;
}

// pss_msm6 with hamburger6_sign_flipped (moments/hamburger.h) in place of hamburger6: one sign of
// the forward substitution flipped.
class FlippedPssMsm6 : public PrefilteredScatter {
 public:
  explicit FlippedPssMsm6(const ScatterParams& params)
      : PrefilteredScatter("pss_msm6", params), beta_(params.beta) {}

 protected:
  void prefilter(const RectifiedMap& map) override {
    sums_ = std::make_unique<RowPrefixSums>(map, 6, [](double z, double* out) {
      out[0] = z;
      for (int j = 1; j < 6; ++j) out[j] = out[j - 1] * z;
    });
  }
  double shadowed_fraction(const RectifiedRay& ray) const override {
    double b[6];
    sums_->mean(ray, b);
    const MsmBound<double> r = hamburger6_sign_flipped(b, ray.depth);
    return r.lower + beta_ * r.at_zf;
  }

 private:
  double beta_;
  std::unique_ptr<RowPrefixSums> sums_;
};

TEST(VerifyScatter, MomentRowsMatchTheLpAtBothBetas) {
  ASSERT_EQ(tiny().frames.size(), 1u);
  for (const char* name : {"pss_msm4", "pss_msm6"})
    for (const double beta : {0.0, 1.0}) {
      const ScatterVerifyRow row = verify_scatter_row(name, beta, tiny().frames, kResolution);
      std::printf("%s beta %g against %s: %zu rays, %zu undefined, largest dF %.3g (%s)\n", name,
                  beta, row.lp_technique.c_str(), row.rays, row.undefined, row.largest,
                  row.worst.c_str());
      EXPECT_TRUE(row.passed()) << name << " " << beta << ": " << row.beyond << " beyond, "
                                << row.lp_failures << " LP failures";
      EXPECT_EQ(row.rays, 80u);
      EXPECT_GT(row.compared, 40u) << name << " " << beta;
    }
}

TEST(VerifyScatter, AFlippedSignFails) {
  const ScatterMaker flipped = [](const ScatterParams& p) -> std::unique_ptr<ScatterTechnique> {
    return std::make_unique<FlippedPssMsm6>(p);
  };
  for (const double beta : {0.0, 1.0}) {
    const ScatterVerifyRow row =
        verify_scatter_row("pss_msm6", flipped, beta, tiny().frames, kResolution);
    std::printf("pss_msm6 with a flipped sign, beta %g: %zu of %zu rays beyond, largest dF %.3g\n",
                beta, row.beyond, row.compared, row.largest);
    EXPECT_FALSE(row.passed()) << beta;
    EXPECT_GT(row.beyond, 10u) << beta;
  }
}

TEST(VerifyScatter, OnlyTheRowsWithARecipe) {
  EXPECT_EQ(scatter_verify_names(), (std::vector<std::string>{"pss_msm4", "pss_msm6"}));
  EXPECT_THROW(check_scatter_verify_technique("pss_csm"), InputError);
  EXPECT_THROW(check_scatter_verify_technique("pss_msm4_16bit"), InputError);
}

// The section's text says what passed() does: LP failures are counted and not compared, so a row
// with some passes while its compared rays lie within the tolerance (docs/scattering.md §6).
TEST(VerifyScatter, TheReportSaysLpFailuresDoNotFailARow) {
  ScatterVerifyRow row;
  row.technique = "pss_msm6", row.lp_technique = "pss_lp:power6", row.kind = "equal";
  row.rays = 10, row.lp_failures = 3, row.compared = 7, row.beyond = 0, row.tolerance = 1e-5;
  ASSERT_TRUE(row.passed());
  const std::string md = scatter_verify_section({row}, "scattering_tiny", kResolution);
  EXPECT_NE(md.find("| pass |"), std::string::npos) << md;
  EXPECT_EQ(md.find("LP failure, fails"), std::string::npos) << md;
  EXPECT_NE(md.find("counted and not compared"), std::string::npos) << md;
  row.compared = 0, row.lp_failures = 10;
  EXPECT_FALSE(row.passed());  // no ray compared: the text's other cause of exit 5
  EXPECT_NE(md.find("no ray compared at all"), std::string::npos) << md;
}

}  // namespace
}  // namespace mb

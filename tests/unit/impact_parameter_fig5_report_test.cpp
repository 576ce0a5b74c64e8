// Fig. 5's seed statistics (experiments/impact_parameter/report_fig5.cpp) on made-up sweep
// outcomes: the core pressure of an eddy pair enters only from seeds whose pair is significant
// (issue 43 §2), the eddy fraction carries its binomial error, and the caption's sigma_max ratios
// (0.568 / 0.894 and 1.56 / 0.894) are placed among the seeds' ratios.
#include "experiments/impact_parameter/spec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace granrepro;
using namespace granrepro::experiments::impact_parameter_detail;

namespace {

ImpactSpec spec(long seeds) {
    ImpactSpec s;
    s.seeds = seeds;
    s.restitutions = {0.80, 0.90, 0.95};
    s.stress_cells = 5;
    s.eddy_significance = 0.99;
    return s;
}

double scalar(const Result& r, const std::string& name) {
    const auto* x = r.find_scalar(name);
    EXPECT_NE(x, nullptr) << name;
    return x ? x->value : NAN;
}

} // namespace

TEST(ImpactParameterFig5Report, CorePressureOnlyFromSeedsWithASignificantPair) {
    const ImpactSpec s = spec(4);
    std::vector<PointResult> pts(s.n_2d());
    // r = 0.8: seeds 0 and 1 have a significant pair with low core pressure; seeds 2 and 3 do not,
    // and their strongest (not significant) pairs have high core pressure.
    const double beats[] = {1.0, 0.99, 0.5, 0.0}, core[] = {0.8, 0.9, 1.5, 1.6};
    for (std::size_t seed = 0; seed < 4; ++seed)
        for (std::size_t k = 0; k < 3; ++k) {
            PointResult& p = pts[seed * s.per_seed() + k];
            p.eddy_strength = 0.1;
            p.eddy_beats = k == 0 ? beats[seed] : 0.0;
            p.eddy_core_pressure_ratio = k == 0 ? core[seed] : 1.0;
            p.flow_fraction = 0.2;
        }
    Result res;
    fig5_eddies(res, s, pts);
    EXPECT_DOUBLE_EQ(scalar(res, "eddy_pair_fraction_r0.80"), 0.5);
    EXPECT_DOUBLE_EQ(scalar(res, "eddy_pair_fraction_err_r0.80"), std::sqrt(0.5 * 0.5 / 4));
    EXPECT_DOUBLE_EQ(scalar(res, "eddy_core_pressure_ratio_seeds_r0.80"), 2);
    EXPECT_DOUBLE_EQ(scalar(res, "eddy_core_pressure_ratio_median_r0.80"), 0.85);
    EXPECT_NEAR(scalar(res, "eddy_core_pressure_ratio_sem_r0.80"), std::sqrt(0.005) / std::sqrt(2.0), 1e-12);
    EXPECT_DOUBLE_EQ(scalar(res, "eddy_core_pressure_ratio_median_all_r0.80"), 1.2);
    // No seed with a pair at r = 0.9: no median, and a fraction of 0 with error 0.
    EXPECT_TRUE(std::isnan(scalar(res, "eddy_core_pressure_ratio_median_r0.90")));
    EXPECT_DOUBLE_EQ(scalar(res, "eddy_pair_fraction_err_r0.90"), 0.0);
}

TEST(ImpactParameterFig5Report, SigmaMaxRatiosAgainstTheCaption) {
    const ImpactSpec s = spec(10);
    std::vector<PointResult> pts(s.n_2d());
    // sigma_max(0.8) = 1; sigma_max(0.9) = 0.1, 0.2, ..., 1.0; sigma_max(0.95) = 10 x that.
    for (std::size_t seed = 0; seed < 10; ++seed) {
        const double r9 = 0.1 * double(seed + 1);
        const double sig[] = {1.0, r9, 10 * r9};
        for (std::size_t k = 0; k < 3; ++k) {
            pts[seed * s.per_seed() + k].sigma_max = sig[k];
            pts[seed * s.per_seed() + k].v_rms = 1.0 + double(k);
        }
    }
    Result res;
    fig5_orderings(res, s, pts);
    // 0.568 / 0.894 = 0.6353: seeds 0.1 ... 0.6 lie below it.
    EXPECT_DOUBLE_EQ(scalar(res, "sigma_max_ratio_090_over_080_fraction_below_paper"), 0.6);
    EXPECT_NEAR(scalar(res, "sigma_max_ratio_090_over_080_median"), 0.55, 1e-12);
    EXPECT_NEAR(scalar(res, "sigma_max_ratio_090_over_080_q10"), 0.19, 1e-12);
    EXPECT_NEAR(scalar(res, "sigma_max_ratio_090_over_080_q90"), 0.91, 1e-12);
    // 1.56 / 0.894 = 1.745: seeds 1, 2, ..., 10 -> only the first below it.
    EXPECT_DOUBLE_EQ(scalar(res, "sigma_max_ratio_095_over_080_fraction_below_paper"), 0.1);
    EXPECT_NEAR(scalar(res, "sigma_max_ratio_095_over_080_median"), 5.5, 1e-12);
}

// brake-failure's spec, its sweep's shared inputs and outcome, and what its files share.
#pragma once
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "data/fields.hpp"
#include "analysis/curve_analysis.hpp"
#include "data/result.hpp"
#include "experiments/common/columns.hpp"
#include "models/hertz_kuwabara_kono.hpp"
#include "models/linear_spring_dashpot.hpp"
#include "scenarios/impact_shot.hpp"

namespace granrepro::experiments::brake_failure_detail {

// The catalog every output handle of brake-failure registers with (data/outputs.hpp).
inline constexpr Outputs outputs{"brake-failure"};

struct BrakeFailureSpec : ImpactShotSpec {
    double offset = 0;             // flight line's distance from the wall grain's centre [m]
    double vx_i = 0;               // initial speed towards the wall [m/s]
    double vy_min = 0, vy_max = 0; // the figure's v_y^i range [m/s]
    int n_vy = 0;
    double fine_factor = 0;        // the Δt check runs at dt / fine_factor
    std::vector<double> betas;     // k' = beta k_N
    double hkk_xi_ref = 0;         // overlap at which HKK matches the linear law [m]
    GRANREPRO_FIELDS_BASE(ImpactShotSpec, offset, vx_i, vy_min, vy_max, n_vy, fine_factor, betas, hkk_xi_ref)
    // Half the chord y_c that the free grain's centre runs in contact on its straight path [m].
    double half_chord() const { return std::sqrt(reach() * reach() - offset * offset); }
};

// The figure's law, time step and v_y^i grid, that grid extended to 10 vy_max, and HKK.
struct Sweep {
    LinearSpringDashpot law;
    double dt;
    std::vector<double> vy, vy_ext;
    HertzKuwabaraKono hkk;
};

struct Curve {
    std::vector<double> dvy, dvx, dvy_shear;
    std::vector<int> complete;
    GRANREPRO_FIELDS(dvy, dvx, dvy_shear, complete)
};

// Curves: Fig. 3, dt / fine_factor, HKK, elastic limit (gamma_N = 0) and paper parameters both on
// the extended grid, then per reading of Eq. (2) one curve on the figure's grid and one on the
// extended grid (the study of which F_N enters Coulomb's law, panel (b)), then k' = beta k_N per beta.
enum : std::size_t { kFig3, kFine, kHkk, kElasticExt, kPaperExt, kFirstReading,
                     kFirstBeta = kFirstReading + 2 * kFrictionNormals.size() };
// The curves' points per spec: kFirstBeta + one per beta.
inline std::size_t curve_count(const BrakeFailureSpec& s) { return kFirstBeta + s.betas.size(); }

// A head-on collision of the free grain with the wall grain or with a free twin: the measured
// t_col and e_N of Eq. (4) and the largest overlap (text below Eq. 4). NaN: the contact never ended.
struct HeadOn {
    double t_col = NAN, e_N = NAN, xi_max = NAN;
    GRANREPRO_FIELDS(t_col, e_N, xi_max)
};
// The head-on collisions, points curve_count(s) + kind after the curves: free-wall at the run's dt,
// the same at dt/20 (overlaps are read at step ends), free-wall with gamma_N = 0 at its t_col/1000,
// and two free grains at their own t_col / steps_per_contact.
enum HeadOnKind : std::size_t { kHeadOn, kHeadOnFine, kHeadOnElastic, kHeadOnTwin, kHeadOns };

// One sweep point's outcome: a curve (index below curve_count) or a head-on collision (the rest);
// the index decides which part is filled.
struct Point {
    Curve curve;
    HeadOn head_on;
    GRANREPRO_FIELDS(curve, head_on)
};


// Reports (report.cpp).
void report_head_on(Result& r, const ImpactShotSpec& s, const Sweep& w, const std::array<HeadOn, kHeadOns>& h);
Peak report_fig3(Result& r, const Sweep& w, const std::vector<Curve>& curves);
void report_high_velocity(Result& r, const BrakeFailureSpec& s, const Sweep& w, const std::vector<Curve>& curves);
void report_collapse(Result& r, const BrakeFailureSpec& s, const Sweep& w, const std::vector<Curve>& curves, const Peak& pk);
void report_readings(Result& r, const BrakeFailureSpec& s, const Sweep& w, const std::vector<Curve>& curves);

} // namespace granrepro::experiments::brake_failure_detail

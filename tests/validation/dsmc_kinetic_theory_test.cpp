// DSMC (Luding 1998 Sec. 2.4) against kinetic theory of the 2D hard-disk gas.
//
// Collision rate. For 2D Maxwellians with temperature T (= m <v_x^2>, so K = N T), the relative
// velocity of a pair is Maxwellian with reduced mass m/2, i.e. each component has variance 2T/m,
// and its modulus is Rayleigh distributed with mean
//     <|v_ij|> = sqrt(2T/m) sqrt(pi/2) = sqrt(pi T/m).
// Eqs. (15)-(16) give N_c(N_c-1)/2 sigma <|v_ij|> tau / V collisions per cell and step, sigma = 2d,
// i.e. (uniform positions, <N_c(N_c-1)> = <N_c>^2 (N-1)/N) the dilute Boltzmann rate per particle
//     omega_B = 2 (collisions)/(N t) = n' sigma <|v_ij|> = 2 n' d sqrt(pi T/m),  n' = (N-1)/A.
// With V = V_c - V_0 the rate is enhanced by V_c/(V_c - V_0) (exactly 1/(1 - rho/0.82) in the
// mean mode); Enskog's rate is omega_E = 2 n d g(d) sqrt(pi T/m) with Henderson's
// g(d) = (1 - 7 rho/16)/(1 - rho)^2, so omega_mean/omega_E = (1-rho)^2/((1-7rho/16)(1-rho/0.82)),
// 0.909 at rho = 0.25: the correction is close to, but not, Enskog.
//
// Homogeneous cooling. A smooth collision with normal relative speed g_n loses
// (1-r^2)/2 (m/2) g_n^2 (RoughDiskCollision, beta0 = -1). With b/d uniform (Eq. 17), g_n^2 =
// |g|^2 (1 - (b/d)^2) averages to 2/3 |g|^2, and collisions are weighted by |g|, so
// <|g|^3>/<|g|> = 3 (2T/m) = 6 T/m for the Rayleigh law above: <loss> = (1-r^2) T per collision.
// With N omega/2 collisions per unit time and K = N T,
//     dT/dt = -(1-r^2) omega T / 2,   omega = omega_0 sqrt(T/T_0)
//  => T/T_0 = K/K_0 = 1/(1 + t/t_0)^2,   t_0 = 4 / ((1-r^2) omega_0)            (Eq. 18)
// (not 2/((1-r^2) omega_0)). With omega_0 = omega_E this is Eq. (19) with sqrt(2 pi) in place
// of the printed sqrt(pi) (vbar = sqrt(2K_0/(N m))): the paper's own number, t_0^-1 = 23.24 1/s
// for d = 1 mm, vbar = 0.2047 m/s, rho = 0.25, r = 0.8, follows from sqrt(2 pi) (23.27 1/s);
// the printed formula would give 32.9 1/s.
#include "engines/dsmc/dsmc_engine.hpp"

#include <gsl/gsl_statistics_double.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace granrepro;

namespace {

constexpr double kD = 1e-3; // [m]
constexpr double kM = 1e-6; // [kg]

double box_for(std::size_t n, double rho) { return kD * std::sqrt(static_cast<double>(n) * std::numbers::pi / (4.0 * rho)); }

// equal_speeds: every particle has speed 1 m/s in a random direction (far from Maxwellian);
// otherwise Gaussian components. Zero total momentum either way for the Maxwellian.
DsmcEngine gas(std::size_t n, double rho, DsmcConfig cfg, bool equal_speeds = false, std::uint64_t seed = 1) {
    const double l = box_for(n, rho);
    cfg.lx = cfg.ly = l;
    cfg.seed = seed;
    RngStream rng(seed, 1000);
    std::vector<Vec2> pos(n), vel(n);
    for (auto& p : pos) p = {rng.uniform(0.0, l), rng.uniform(0.0, l)};
    Vec2 mean;
    for (auto& v : vel) {
        if (equal_speeds) {
            const double a = rng.uniform(0.0, 2.0 * std::numbers::pi);
            v = {std::cos(a), std::sin(a)};
        } else {
            v = {rng.normal(), rng.normal()};
            mean += v;
        }
    }
    if (!equal_speeds)
        for (auto& v : vel) v -= mean / static_cast<double>(n);
    return DsmcEngine(cfg, pos, vel, std::vector<double>(n, 0.5 * kD), std::vector<double>(n, kM));
}

double temperature_over_m(const DsmcEngine& e) { return e.kinetic_energy() / (static_cast<double>(e.size()) * kM); }

// Dilute Boltzmann rate per particle, 2 n' d sqrt(pi T/m) [1/s].
double boltzmann_rate(const DsmcEngine& e) {
    const double area = e.config().lx * e.config().ly;
    return 2.0 * (static_cast<double>(e.size()) - 1.0) / area * kD * std::sqrt(std::numbers::pi * temperature_over_m(e));
}

double henderson_g(double rho) { return (1.0 - 7.0 * rho / 16.0) / ((1.0 - rho) * (1.0 - rho)); }

struct Rate {
    double omega = 0.0;     // measured collisions per particle and time [1/s]
    double predicted = 0.0; // what Eqs. (15)-(16) promise for the cells actually seen [1/s]
    double collisions = 0.0;
};

// Elastic run of `per_particle` collisions per particle.
Rate measure_rate(DsmcEngine& e, double per_particle) {
    const double n = static_cast<double>(e.size());
    const auto target = static_cast<std::uint64_t>(per_particle * n / 2.0);
    const double t0 = e.time(), x0 = e.exposure();
    const std::uint64_t c0 = e.total_collisions();
    while (e.total_collisions() - c0 < target) e.step();
    Rate r;
    r.collisions = static_cast<double>(e.total_collisions() - c0);
    const double t = e.time() - t0;
    r.omega = 2.0 * r.collisions / (n * t);
    r.predicted = 2.0 * (e.exposure() - x0) * e.cross_section() * std::sqrt(std::numbers::pi * temperature_over_m(e)) / (n * t);
    return r;
}

} // namespace

TEST(DsmcKineticTheory, PlainRateIsTheDiluteBoltzmannRate) {
    for (double rho : {0.05, 0.25}) {
        auto e = gas(40000, rho, {});
        const double omega_b = boltzmann_rate(e);
        const Rate r = measure_rate(e, 30.0);
        // Collision counts are Poisson-like: relative error 1/sqrt(C).
        const double tol = 5.0 / std::sqrt(r.collisions);
        std::printf("rho = %.2f: omega/omega_B = %.5f (tolerance %.4f), cells %zux%zu of %.2f d\n", rho,
                    r.omega / omega_b, tol, e.cells_x(), e.cells_y(), e.cell_width() / kD);
        EXPECT_NEAR(r.omega / omega_b, 1.0, tol);
        EXPECT_NEAR(r.omega / r.predicted, 1.0, tol);
    }
}

TEST(DsmcKineticTheory, FreeVolumeRateAgainstEnskog) {
    const double rho = 0.25;
    const double chi_fv = 1.0 / (1.0 - rho / 0.82), g = henderson_g(rho);
    // Mean mode: exactly the factor 1/(1 - rho/0.82).
    {
        DsmcConfig cfg;
        cfg.free_volume = DsmcFreeVolume::mean;
        auto e = gas(40000, rho, cfg);
        const double omega_b = boltzmann_rate(e);
        const Rate r = measure_rate(e, 30.0);
        const double tol = 5.0 / std::sqrt(r.collisions);
        const double omega_e = omega_b * g;
        std::printf("mean mode: omega/omega_B = %.4f (1/(1-rho/0.82) = %.4f), omega/omega_E = %.4f (analytic %.4f)\n",
                    r.omega / omega_b, chi_fv, r.omega / omega_e, chi_fv / g);
        EXPECT_NEAR(r.omega / omega_b / chi_fv, 1.0, tol);
        EXPECT_NEAR(r.omega / omega_e, chi_fv / g, 2.0 * tol);
        RecordProperty("mean_mode_omega_over_enskog", std::to_string(r.omega / omega_e));
    }
    // Cell mode (the paper's wording, V_0 from the particles in the cell): with 2d cells and
    // ~1.3 particles per cell at rho = 0.25 the cell-to-cell fluctuations of V_c - V_0 dominate;
    // with larger cells it approaches the mean mode. Measured, not asserted against Enskog; the
    // implementation is checked against Eq. (15) for the cells it saw.
    for (double cells : {2.0, 5.0, 10.0}) {
        DsmcConfig cfg;
        cfg.free_volume = DsmcFreeVolume::cell;
        cfg.min_cell_diameters = cells;
        auto e = gas(40000, rho, cfg);
        const double omega_b = boltzmann_rate(e);
        const Rate r = measure_rate(e, 20.0);
        const double tol = 5.0 / std::sqrt(r.collisions);
        std::printf("cell mode, cells of %.2f d: omega/omega_B = %.4f, omega/omega_E = %.4f, measured/Eq.(15) = %.5f\n",
                    e.cell_width() / kD, r.omega / omega_b, r.omega / (omega_b * g), r.omega / r.predicted);
        EXPECT_NEAR(r.omega / r.predicted, 1.0, tol);
        EXPECT_GT(r.omega / omega_b, chi_fv * (1.0 - tol)); // Jensen: <1/(V_c - V_0)> >= 1/<V_c - V_0>
        RecordProperty("cell_mode_" + std::to_string(static_cast<int>(cells)) + "d_omega_over_enskog",
                       std::to_string(r.omega / (omega_b * g)));
    }
}

TEST(DsmcKineticTheory, EqualSpeedsRelaxToMaxwellian) {
    const std::size_t n = 20000;
    auto e = gas(n, 0.1, {}, true);
    const double k0 = e.kinetic_energy();
    auto kurtosis = [&] {
        std::vector<double> c;
        c.reserve(2 * n);
        for (const auto& v : e.velocities()) { c.push_back(v.x); c.push_back(v.y); }
        return gsl_stats_kurtosis(c.data(), 1, c.size()) + 3.0; // GSL returns the excess
    };
    const double kurt0 = kurtosis();
    EXPECT_NEAR(kurt0, 1.5, 0.05); // <cos^4>/<cos^2>^2 = 3/2
    measure_rate(e, 3.0);
    const double kurt3 = kurtosis();
    measure_rate(e, 7.0);
    const double kurt10 = kurtosis();
    // With the paper's cells (~0.8 particles per cell here) a pair often collides again with its
    // last partner, which only reshuffles energy within the pair: relaxation per collision is
    // slower than with large cells (3.0 after 10 collisions per particle with 30 d cells, 2.88
    // with these), so the Maxwellian is checked after 20.
    measure_rate(e, 10.0);
    const double kurt20 = kurtosis();
    const double sd = std::sqrt(24.0 / static_cast<double>(2 * n)); // standard error of the kurtosis
    const double drift = e.kinetic_energy() / k0 - 1.0;
    std::printf("kurtosis of v_x: start %.3f, after 3 collisions/particle %.3f, after 10 %.3f, after 20 %.3f "
                "(3 +- %.3f); energy drift %.2e\n", kurt0, kurt3, kurt10, kurt20, sd, drift);
    EXPECT_LT(kurt3, 3.0 - 5.0 * sd); // it does relax, not start Maxwellian
    EXPECT_GT(kurt10, kurt3);
    EXPECT_NEAR(kurt20, 3.0, 5.0 * sd);
    // Elastic collisions conserve energy exactly up to round-off, so the statistical error is 0.
    EXPECT_LT(std::fabs(drift), 1e-12);
}

namespace {

struct Cooling {
    double worst = 0.0;       // max |K/K_Haff - 1| over the sampled times
    double at_t0 = 0.0;       // K/K_Haff at t = t0
    double collisions = 0.0;  // per particle up to 2 t0, over omega0 t0 ln 3
};

// r = 0.8, rho = 0.25 from a Maxwellian; t0 = 4/((1-r^2) omega0) with omega0 the rate the
// collision rule implies (Boltzmann times the mean free-volume factor when that is on).
Cooling cool(DsmcFreeVolume mode, double cell_diameters, const char* label) {
    const double r = 0.8;
    DsmcConfig cfg;
    cfg.r = r;
    cfg.free_volume = mode;
    cfg.min_cell_diameters = cell_diameters;
    auto e = gas(40000, 0.25, cfg);
    const double chi = mode == DsmcFreeVolume::off ? 1.0 : e.mean_free_volume_factor();
    const double omega0 = boltzmann_rate(e) * chi;
    const double t0 = 4.0 / ((1.0 - r * r) * omega0);
    const double k0 = e.kinetic_energy();
    Cooling c;
    for (double s : {0.25, 0.5, 1.0, 1.5, 2.0}) {
        e.run_until(s * t0);
        const double ratio = e.kinetic_energy() / k0 * (1.0 + s) * (1.0 + s);
        std::printf("%s, cells %.1f d: t/t0 = %.2f  K/K0 / Eq.(18) = %.4f\n", label, e.cell_width() / kD, s, ratio);
        c.worst = std::max(c.worst, std::fabs(ratio - 1.0));
        if (s == 1.0) c.at_t0 = ratio;
    }
    const double per_particle = 2.0 * static_cast<double>(e.total_collisions()) / static_cast<double>(e.size());
    // int_0^{2 t0} omega dt = omega0 t0 ln 3 collisions per particle.
    c.collisions = per_particle / (omega0 * t0 * std::log(3.0));
    return c;
}

} // namespace

// Haff's law needs molecular chaos between successive collisions. Cells of ~30 d hold ~300
// particles at rho = 0.25, so a pair that has just collided is rarely drawn again.
TEST(DsmcKineticTheory, InelasticCoolingFollowsHaffEq18) {
    for (auto mode : {DsmcFreeVolume::off, DsmcFreeVolume::mean}) {
        const Cooling c = cool(mode, 30.0, mode == DsmcFreeVolume::off ? "plain" : "mean free volume");
        EXPECT_LT(c.worst, 0.03);
        EXPECT_NEAR(c.collisions, 1.0, 0.02);
        RecordProperty(mode == DsmcFreeVolume::off ? "haff_plain_30d_at_t0" : "haff_meanfv_30d_at_t0", std::to_string(c.at_t0));
    }
}

// With the paper's cells (2 d at rho = 0.25: 1.3 particles per cell) a pair that has collided
// stays in one cell for several steps and is drawn again with probability ~ sigma/L_c ~ 1; its
// normal relative velocity was already reduced by r, so it dissipates less than a fresh pair and
// the gas cools slower than Eq. (18). Measured, and asserted to vanish as the cells grow.
TEST(DsmcKineticTheory, SmallCellsCoolSlowerThroughRepeatedPartners) {
    const Cooling c2 = cool(DsmcFreeVolume::off, 2.0, "plain");
    const Cooling c10 = cool(DsmcFreeVolume::off, 10.0, "plain");
    std::printf("K/K_Haff at t0: cells 2 d %.4f, 10 d %.4f\n", c2.at_t0, c10.at_t0);
    RecordProperty("haff_plain_2d_at_t0", std::to_string(c2.at_t0));
    RecordProperty("haff_plain_10d_at_t0", std::to_string(c10.at_t0));
    EXPECT_GT(c2.at_t0, c10.at_t0);
    EXPECT_GT(c10.at_t0, 1.0);
    EXPECT_LT(c10.at_t0 - 1.0, 0.5 * (c2.at_t0 - 1.0));
}

// The displacement correction pushes a pair that collided apart by d: point particles acquire a
// correlation hole at short distance, so fewer pairs share a small cell and the plain rate drops
// below omega_B (measured 0.84 omega_B with 2 d cells at rho = 0.25, 0.99 with 10 d cells).
TEST(DsmcKineticTheory, DisplacementLowersTheRateInSmallCells) {
    double ratio[2] = {0.0, 0.0};
    int k = 0;
    for (double cells : {2.0, 10.0}) {
        DsmcConfig cfg;
        cfg.displacement = true;
        cfg.min_cell_diameters = cells;
        auto e = gas(40000, 0.25, cfg);
        e.run_steps(300); // let the correlation hole form
        const Rate r = measure_rate(e, 20.0);
        ratio[k++] = r.omega / boltzmann_rate(e);
        EXPECT_NEAR(r.omega / r.predicted, 1.0, 5.0 / std::sqrt(r.collisions));
    }
    std::printf("with displacement: omega/omega_B = %.4f (2 d cells), %.4f (10 d cells)\n", ratio[0], ratio[1]);
    RecordProperty("displacement_2d_omega_over_boltzmann", std::to_string(ratio[0]));
    EXPECT_LT(ratio[0], 0.92);
    EXPECT_GT(ratio[1], 0.97);
}

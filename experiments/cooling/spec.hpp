// cooling (Figs. 2, 3, 6 and 7): the spec, one run's trace, the seeds' initial states, and the
// functions the compute and report files share.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "data/fields.hpp"
#include "core/rng_stream.hpp"
#include "core/vec2.hpp"
#include "data/result.hpp"
#include "engines/dsmc/dsmc_config.hpp"
#include "experiments/common/columns.hpp"
#include "harness/experiment.hpp"
#include "observables/impact_parameter_histogram.hpp"
#include "observables/velocity_correlation.hpp"
#include "scenarios/ed_gas.hpp"
#include "theory/kinetic_theory.hpp"

namespace granrepro { // text choices of cooling.toml (read_spec finds them by argument-dependent lookup)
inline void parse_choice(const std::string& s, DsmcFreeVolume& v) {
    v = s == "cell" ? DsmcFreeVolume::cell : s == "mean" ? DsmcFreeVolume::mean : DsmcFreeVolume::off;
}
inline void parse_choice(const std::string& s, DsmcPartner& v) { v = s == "nearest" ? DsmcPartner::nearest : DsmcPartner::uniform; }
} // namespace granrepro

// Not granrepro::experiments::cooling: that name is the experiment's function (registry.cpp).
namespace granrepro::experiments::cooling_detail {

// The catalog every output handle of cooling registers with (data/outputs.hpp).
inline constexpr Outputs outputs{"cooling"};

enum class InitialVelocities { uniform, maxwellian };
inline void parse_choice(const std::string& s, InitialVelocities& v) {
    v = s == "maxwellian" ? InitialVelocities::maxwellian : InitialVelocities::uniform;
}

struct CoolingSpec {
    long n_side = 0; // N = n_side^2
    double rho = 0, r = 0, d = 0, mass = 0, vbar = 0; // area fraction, restitution, [m], [kg], [m/s]
    InitialVelocities initial_velocities = InitialVelocities::uniform;
    long seeds = 0;
    double mu = 0, t_c = 0, dsmc_t_c = 0; // ED friction; TC thresholds [s]
    double equilibration = 0;             // collisions per particle at r = 1 before t = 0
    double t_end = 0;                     // [s]
    std::vector<double> snapshot_times, bd_windows; // [s]
    double sk_k_max = 0;
    std::vector<double> a2_window; // [t0]
    long a2_samples = 0, samples_per_decade = 0;
    double departure_level = 0;
    bool run_ed = true, run_dsmc = true;
    double dsmc_cell_diameters = 0, dsmc_mft_fraction = 0, dsmc_step_factor = 0;
    double dsmc_rcp_fraction = 0; // V_0's packing fraction in the free-volume factor (Sec. 2.4: 0.82)
    DsmcFreeVolume dsmc_free_volume = DsmcFreeVolume::off; DsmcPartner dsmc_partner = DsmcPartner::uniform;
    long dsmc_free_volume_block = 0;
    bool dsmc_no_repeat = false, dsmc_displacement = false;
    bool velocity_correlation = false; // pair velocity correlations at the snapshots (a study's observable)
    GRANREPRO_FIELDS(n_side, rho, r, d, mass, vbar, initial_velocities, seeds, mu, t_c, dsmc_t_c, equilibration,
                     t_end, snapshot_times, bd_windows, sk_k_max, a2_window, a2_samples, samples_per_decade,
                     departure_level, run_ed, run_dsmc, dsmc_cell_diameters, dsmc_mft_fraction, dsmc_step_factor,
                     dsmc_free_volume, dsmc_partner, dsmc_free_volume_block, dsmc_no_repeat, dsmc_displacement,
                     dsmc_rcp_fraction, velocity_correlation)

    // Enskog collision rate per particle at t = 0 with Henderson's g(d) [1/s], and Haff's t0 [s].
    double omega_enskog() const { return theory::enskog_collision_rate_vbar(rho, d, vbar, theory::henderson_contact_value(rho)); }
    double t0() const { return theory::haff_t0(r, omega_enskog()); }
    double box() const { return d * std::sqrt(double(n_side * n_side) * M_PI / 4 / rho); } // [m]
    // The snapshot times the run reaches [s].
    std::vector<double> snapshots() const {
        std::vector<double> s;
        for (double t : snapshot_times)
            if (t <= t_end) s.push_back(t);
        return s;
    }
};

// g(r/d) with its counting error, and S(k), at one snapshot time; with velocity_correlation the
// pair velocity correlations C_n, C_t (observables/velocity_correlation.hpp) and their errors.
struct Snapshot {
    std::vector<double> g, g_err, S;
    std::vector<double> vc_n, vc_n_err, vc_t, vc_t_err, vc_a, vc_a_err;
    GRANREPRO_FIELDS(g, g_err, S, vc_n, vc_n_err, vc_t, vc_t_err, vc_a, vc_a_err)
};

// The counts per b/d bin of one P(b/d) time window.
struct WindowCounts {
    std::vector<std::uint64_t> bins;
    GRANREPRO_FIELDS(bins)
};

// What one method (ED or DSMC) produced from one initial state. fields() lists what a run carries
// between samples (and its checkpoints hold) and what its sweep point returns: the wall time is
// set at the end (a mid-run checkpoint keeps its own clock), P(b/d) is made from the counts when
// the point is read back.
struct Trace {
    std::vector<double> t, kx, ky, krot, cn, elastic_cn, a2, a2_err;
    std::vector<Snapshot> snaps;
    std::vector<double> g_r, S_k;
    std::vector<WindowCounts> pbd_counts; // the impact-parameter histogram's state
    std::vector<ImpactParameterHistogram::Window> pbd;
    std::vector<double> pbd_centres;
    double wall_seconds = 0; // this run's, resumed parts included
    // DSMC: the engine's cells per box side (the lattice whose imprint on S(k) Fig. 7's report
    // measures), set where the engine exists so that the report builds none; ED: 0.
    long dsmc_cells_per_side = 0;
    template <class V>
    void fields(V&& v) {
        v("t", t), v("kx", kx), v("ky", ky), v("krot", krot), v("cn", cn), v("elastic_cn", elastic_cn);
        v("a2", a2), v("a2_err", a2_err), v("snapshots", snaps), v("g_r", g_r), v("S_k", S_k);
        v("impact_parameter", pbd_counts), v("wall_seconds", wall_seconds);
        v("dsmc_cells_per_side", dsmc_cells_per_side);
    }
};

// A seed's state at t = 0; its collision_rate is that of the second half of the equilibration.
struct Setup : EquilibratedGas {
    std::vector<double> rad, mass;
    double L = 0; // box side [m]
};

// compute.cpp: seed index k's initial state (deterministic) and one method's run from it.
Setup prepare(const CoolingSpec& c, std::uint64_t seed, long seed_index);
Trace run_method(const RunContext& ctx, const CoolingSpec& c, const Setup& s, long k, bool is_ed);

// The seeds' initial states, each equilibrated when first needed (by a sweep point or by the
// report) and then kept: a process equilibrates only the seeds it uses, so an MPI rank serving
// points does not redo every seed's equilibration (issue 28). prepare() is deterministic.
class Setups {
public:
    Setups(const CoolingSpec& c, std::uint64_t seed) : c_(&c), seed_(seed), n_(c.seeds), slots_(new Slot[std::size_t(c.seeds)]) {}
    long size() const { return n_; }
    const Setup& operator[](long k) const {
        Slot& slot = slots_[std::size_t(k)];
        std::call_once(slot.once, [&] { slot.value = prepare(*c_, seed_, k); });
        return slot.value;
    }

private:
    struct Slot {
        std::once_flag once;
        Setup value;
    };
    const CoolingSpec* c_;
    std::uint64_t seed_;
    long n_;
    std::unique_ptr<Slot[]> slots_;
};

// compute.cpp, also used by validate and the report.
DsmcConfig dsmc_config(const CoolingSpec& c, double L);
std::array<double, 2> sonine_a2(const std::vector<Vec2>& vel);
std::uint64_t setup_stream(long k);
std::vector<Vec2> initial_velocities(const CoolingSpec& c, const std::vector<double>& mass, RngStream& rng);
VelocityCorrelation velocity_correlation(double L, double d);
Trace with_pbd(Trace tr, const CoolingSpec& c);

// report.cpp: the whole report, and what the figures' parts share.
Result report_all(const CoolingSpec& c, std::uint64_t seed, const Setups& setups, const std::vector<Trace>& eds,
                  const std::vector<Trace>& dss);
Result report_dsmc_only(const CoolingSpec& c, const std::vector<Trace>& dss);
double mean_over(const std::vector<double>& v, const std::vector<double>& x, double lo, double hi);
double max_over(const std::vector<double>& v, const std::vector<double>& x, double lo, double hi);
double min_over(const std::vector<double>& v, const std::vector<double>& x, double lo, double hi);
void add_mean_sd(Result& res, const ScalarOut& mean, const ScalarOut& sd, const std::vector<double>& v);

// report_fig2.cpp: K(t) against Eq. (18), a2, DSMC against ED.
std::vector<double> k_ratio(const Trace& tr);
double max_dev(const Trace& tr, double t0, double t_max);
void add_energy_table(Result& res, const Trace& tr, double t0, const char* name);
void add_ed_cooling(Result& res, const CoolingSpec& c, const std::vector<Trace>& eds);
void add_dsmc_kinetics(Result& res, const std::vector<Trace>& dss, const CoolingSpec& c);
void add_ed_dsmc_energy(Result& res, const std::vector<Trace>& eds, const std::vector<Trace>& dss, double t0, double level);
void add_loss_per_collision(Result& res, const CoolingSpec& c, const std::vector<Trace>& eds, const std::vector<Trace>& dss);

// report_fig3.cpp: P(b/d).
double grazing_ratio(const ImpactParameterHistogram::Window& w, const std::vector<double>& centres);
void add_impact_parameter(Result& res, const Trace& ed);

// report_fig6_7.cpp: g(r/d), S(k) and the velocity correlations.
double small_k_S(const Trace& tr, const Snapshot& at, double k_max);
void add_structure_tables(Result& res, const Trace& tr, const std::vector<double>& snaps, double rho, const char* name);
void add_velocity_correlation(Result& res, const CoolingSpec& c, const std::vector<Trace>& trs, const char* name);
void add_ed_g(Result& res, const std::vector<Trace>& eds, const std::vector<double>& snaps, double t0);
void add_ed_sk(Result& res, const std::vector<Trace>& eds, const std::vector<double>& snaps, double k_small, double s_eq);
void add_sk_change_intervals(Result& res, const std::vector<Trace>& eds, const std::vector<Trace>& dss, const std::vector<double>& snaps, double k_small);
void add_sk_agreement(Result& res, const std::vector<Trace>& eds, const std::vector<Trace>& dss, const std::vector<double>& snaps, double k_small);
void add_cell_imprint(Result& res, const std::vector<Trace>& eds, const std::vector<Trace>& dss);

} // namespace granrepro::experiments::cooling_detail

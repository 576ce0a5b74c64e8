// Direct Simulation Monte Carlo for smooth inelastic disks in a periodic box (Luding 1998,
// Sec. 2.4; Bird's scheme). One step of length tau:
//   1. free flight r += v tau, wrapped into [0,lx) x [0,ly);
//   2. counting sort into nx x ny cells of side >= L_c = max(lambda/2, 2 d_max) (dsmc_rules.hpp);
//   3. per cell with N_c >= 2: M_c candidate pairs, Eq. (15),
//          M_c = N_c (N_c - 1) sigma_max v_max tau / (2 V),   sigma_max = 2 d_max (2D cross-section),
//      V = V_c, or the free volume V_c - V_0 (DsmcConfig::free_volume). The fractional part of M_c is
//      drawn stochastically: floor(M_c) + 1 with probability frac(M_c), so E[M] = M_c exactly and
//      nothing depends on a carried remainder when cells are re-chosen;
//   4. each candidate (i, j): i uniform in the cell, j another particle of the cell, uniform or the
//      nearest to i (DsmcConfig::partner), never i's last partner if that one's last partner is i
//      (DsmcConfig::no_repeat_partner). Uniform i and j give the pairs uniformly. It is accepted with
//      probability sigma_ij |v_ij| / (sigma_max v_max), sigma_ij = 2 (a_i + a_j). For equal disks this
//      is Eq. (16). The paper prints "|v_ij|/v_max < Z", which would accept with probability
//      1 - |v_ij|/v_max; its own sentence ("collision probability proportional to the relative
//      velocity") and Bird's method require |v_ij|/v_max > Z, implemented here. If a candidate
//      exceeds the bound, v_max is raised to it at once (Bird's practice) and the event counted;
//   5. accepted pairs collide with an impact parameter b uniform in [-d_ij, d_ij] (molecular chaos,
//      Eq. 17), d_ij = a_i + a_j. With g = v_i - v_j, u = b/d_ij and the unit vectors e = g/|g|,
//      e_perp = perp(e), the normal from j to i at the virtual contact is
//          n = -sqrt(1 - u^2) e - u e_perp,
//      so that g.n = -|g| sqrt(1-u^2) < 0 (approaching) and (r_i - r_j) x e = d_ij n x e = b, Eq. (17).
//      Velocities change by the Collision operator, in DsmcEngine the Walton-Braun impulse
//      (RoughDiskCollision, beta0 = -1: normal part times -r, tangential part unchanged); under the
//      TC model (Eq. 7, t_c > 0) r -> 1 when either partner's previous collision is at most t_c old.
//   6. optional displacement (Sec. 2.4, second correction, after Alexander, Garcia & Alder's
//      consistent Boltzmann algorithm, the paper's Ref. [67]): "an offset of d to the particle
//      distance along the direction of the momentum transfer". Read literally: the separation
//      r_i - r_j grows by d_ij along dP_i/|dP_i| (= n for smooth disks), split so the centre of
//      mass stays put: r_i += m_j/(m_i+m_j) d_ij n, r_j -= m_i/(m_i+m_j) d_ij n. This is the jump a
//      hard-disk pair makes relative to point particles, so the streaming now carries the
//      collisional (virial) momentum flux d_ij n (x) dP of a dense gas.
// Time step: tau = L_c / (step_factor v_fast), and with mft_fraction > 0 also tau <= mft_fraction /
// omega (omega the measured collision rate per particle), both re-evaluated every
// resample_interval steps.
// All collisions of a step are stamped with the step's end time. The collision observer gets a
// CollisionRecord with ri = position of i, rj = ri - d_ij n (the virtual contact partner, so that
// (rj - ri) (x) dP is the hard-disk virial of the collisional stress), b_over_d = |u|.
#pragma once
#include "core/collision_record.hpp"
#include "core/interrupt.hpp"
#include "core/rng_stream.hpp"
#include "core/vec2.hpp"
#include "engines/dsmc/dsmc_config.hpp"
#include "engines/dsmc/dsmc_state.hpp"
#include "models/rough_disk_collision.hpp"
#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace granrepro {

// A collision operator the DSMC engine can use: a value type built from the smooth Walton-Braun
// parameters of the config (r, or r = 1 for the TC model's elastic collisions; mu = 0,
// beta0 = -1; q), with collide<false>(v1, 0, m1, a1, v2, 0, m2, a2, n).dP the momentum change of
// disk 1 as documented in RoughDiskCollision. DSMC disks carry no spin, so only the smooth form
// is called; a frictional operator's tangential part is never applied.
template <class C>
concept DsmcCollisionOperator = std::copyable<C> && std::default_initializable<C> &&
    std::constructible_from<C, RoughDiskCollision> && requires(const C& c, Vec2 v, double x) {
        { c.template collide<false>(v, x, x, x, v, x, x, x, v).dP } -> std::convertible_to<Vec2>;
    };

template <DsmcCollisionOperator Collision>
class BasicDsmcEngine {
public:
    // Starts from the given arrays (e.g. the state an ED equilibration produced): positions [m]
    // (wrapped into the box), velocities [m/s], radii [m], masses [kg], all of one length N >= 2.
    // Throws InputError on inconsistent input.
    BasicDsmcEngine(const DsmcConfig& config, std::vector<Vec2> position, std::vector<Vec2> velocity,
                    std::vector<double> radius, std::vector<double> mass);
    explicit BasicDsmcEngine(const DsmcState& state);

    // One step, of length min(tau, max_dt). Obs is any callable taking const CollisionRecord&.
    template <class Obs>
    void step(Obs& obs, double max_dt = std::numeric_limits<double>::infinity());
    void step() { NoObserver o; step(o); }

    template <class Obs>
    void run_steps(std::uint64_t n, Obs& obs) { for (std::uint64_t k = 0; k < n; ++k) step(obs); }
    void run_steps(std::uint64_t n) { NoObserver o; run_steps(n, o); }

    // Steps until time() == t_end exactly: the last step is shortened to land on t_end. A run
    // stopped with run_until(t) and resumed from save_state() is bit-identical to one that also
    // called run_until(t) on the way.
    template <class Obs>
    void run_until(double t_end, Obs& obs) {
        while (time_ < t_end) {
            if ((steps_ & 63) == 0) engine_pause_point();
            const double before = time_;
            step(obs, t_end - time_);
            if (!(time_ > before)) // a step too short for the clock's resolution would loop for ever
                throw std::runtime_error("DSMC: a time step of " + std::to_string(tau_) + " s does not advance t = " +
                                         std::to_string(time_) + " s");
        }
    }
    void run_until(double t_end) { NoObserver o; run_until(t_end, o); }

    DsmcState save_state() const;
    void restore_state(const DsmcState& s);

    // Changing the collision law between steps (e.g. r = 1 equilibration, then r = 0.8).
    void set_restitution(double r);
    void set_tc(double t_c);

    std::size_t size() const { return pos_.size(); }
    const DsmcConfig& config() const { return cfg_; }
    double time() const { return time_; }
    double tau() const { return tau_; }          // current step [s] (after the first resampling)
    double v_max() const { return v_max_; }      // current relative-speed bound [m/s]
    std::uint64_t steps() const { return steps_; }
    const std::vector<Vec2>& positions() const { return pos_; }
    const std::vector<Vec2>& velocities() const { return vel_; }
    const std::vector<double>& radii() const { return rad_; }
    const std::vector<double>& masses() const { return mass_; }
    const std::vector<std::uint64_t>& collision_counts() const { return count_; }
    std::uint64_t total_collisions() const { return collisions_; }
    std::uint64_t elastic_collisions() const { return elastic_collisions_; }
    std::uint64_t candidates() const { return candidates_; }
    std::uint64_t vmax_raises() const { return vmax_raises_; }
    const std::vector<std::uint32_t>& last_partners() const { return partner_; }
    // Sum over steps and cells of N_c (N_c - 1) tau / (2 V) [s/m^2]: times sigma <|v_ij|> it is the
    // number of collisions Eqs. (15)-(16) promise (a test of the implementation, not of physics).
    double exposure() const { return exposure_; }
    std::size_t cells_x() const { return nx_; }
    std::size_t cells_y() const { return ny_; }
    double cell_width() const { return wx_; }   // [m]
    double cell_height() const { return wy_; }  // [m]
    double mean_free_path() const { return lambda_; } // [m], the one the cells were sized with
    double cross_section() const { return sigma_max_; } // sigma = 2 d_max [m]
    // Free volume factor V_c/(V_c - V_0) of the mean mode for the box-averaged area fraction.
    double mean_free_volume_factor() const;
    double kinetic_energy() const; // translational, [J]
    Vec2 total_momentum() const;   // [kg m/s]
    std::size_t memory_bytes() const;

private:
    struct NoObserver {
        void operator()(const CollisionRecord&) const {}
    };

    void validate_and_setup();
    // The config's law: smooth disks (mu = 0, beta0 = -1) with restitution r.
    Collision smooth_law(double r) const { return Collision(RoughDiskCollision{r, 0.0, -1.0, cfg_.q}); }
    void resample();
    void move_and_sort(double dt);
    double free_volume(std::size_t cell, std::size_t begin, std::size_t count) const;
    void block_areas(); // cell mode with free_volume_block > 1: block_area_ from the sorted cells
    std::uint32_t choose_partner(std::size_t begin, std::size_t cnt, std::size_t k1);
    bool repeat(std::uint32_t i, std::uint32_t j) const { return partner_[i] == j && partner_[j] == i; }
    static double wrap(double x, double l) {
        x -= l * std::floor(x / l);
        return x >= l ? x - l : x; // tiny negative x: x + l may round to l
    }

    // A flight of one step is shorter than a cell (tau rule), so one subtraction almost always
    // suffices; the division in wrap() is the fallback, not the rule.
    static double wrap_near(double x, double l) {
        if (x >= l) x -= l;
        else if (x < 0.0) x += l;
        return (x >= 0.0 && x < l) ? x : wrap(x, l);
    }

    template <class Obs>
    void collide_cell(std::size_t cell, std::size_t begin, std::size_t count, double dt, Obs& obs);

    DsmcConfig cfg_;
    RngStream rng_;
    std::vector<Vec2> pos_, vel_;
    std::vector<double> rad_, mass_, last_;
    std::vector<std::uint64_t> count_;
    std::vector<std::uint32_t> partner_;
    double time_ = 0.0, tau_ = 0.0, v_max_ = 0.0;
    std::uint64_t steps_ = 0, collisions_ = 0, elastic_collisions_ = 0, candidates_ = 0, vmax_raises_ = 0;
    double exposure_ = 0.0;
    double resample_time_ = 0.0;
    std::uint64_t resample_collisions_ = 0;

    // Derived from config + particles (rebuilt on restore).
    std::size_t nx_ = 1, ny_ = 1;
    double wx_ = 0.0, wy_ = 0.0, inv_wx_ = 0.0, inv_wy_ = 0.0, cell_area_ = 0.0;
    double sigma_max_ = 0.0, lambda_ = 0.0, area_fraction_ = 0.0;
    Collision law_, elastic_law_;
    // Scratch (not state): cell of each particle, particles in cell order, cell start offsets.
    std::vector<std::uint32_t> cell_of_, order_, start_, scratch_fill_;
    std::vector<double> cell_r2_, block_area_, scratch_r2_; // per cell: sum of r^2, the block's disk area [m^2]
};

template <DsmcCollisionOperator Collision>
template <class Obs>
void BasicDsmcEngine<Collision>::step(Obs& obs, double max_dt) {
    if (steps_ % cfg_.resample_interval == 0) resample();
    const double dt = tau_ < max_dt ? tau_ : max_dt;
    if (!std::isfinite(dt)) throw std::logic_error("DSMC: all particles at rest and no end time: no time scale");
    move_and_sort(dt);
    time_ += dt;
    const std::size_t ncell = nx_ * ny_;
    if (cfg_.free_volume == DsmcFreeVolume::cell && cfg_.free_volume_block > 1) block_areas();
    for (std::size_t c = 0; c < ncell; ++c) {
        const std::size_t b = start_[c], cnt = start_[c + 1] - b;
        if (cnt >= 2) collide_cell(c, b, cnt, dt, obs);
    }
    ++steps_;
}

template <DsmcCollisionOperator Collision>
inline std::uint32_t BasicDsmcEngine<Collision>::choose_partner(std::size_t begin, std::size_t cnt, std::size_t k1) {
    const std::uint32_t i = order_[begin + k1];
    if (cfg_.partner == DsmcPartner::nearest) {
        // Lowest index wins a tie (order_ is stable), so the choice depends on the state only.
        std::uint32_t best = kNoPartner;
        double best_d2 = std::numeric_limits<double>::infinity();
        const Vec2 pi = pos_[i];
        for (std::size_t q = 0; q < cnt; ++q) {
            if (q == k1) continue;
            const std::uint32_t j = order_[begin + q];
            if (cfg_.no_repeat_partner && repeat(i, j)) continue;
            const double d2 = norm2(pos_[j] - pi);
            if (d2 < best_d2) {
                best_d2 = d2;
                best = j;
            }
        }
        return best;
    }
    auto k2 = rng_.index(cnt - 1);
    if (k2 >= k1) ++k2;
    std::uint32_t j = order_[begin + k2];
    if (cfg_.no_repeat_partner && repeat(i, j)) {
        if (cnt < 3) return kNoPartner;
        // Uniform among the cnt - 2 members that are neither i nor its last partner.
        auto k3 = rng_.index(cnt - 2);
        const std::size_t lo = std::min<std::size_t>(k1, k2), hi = std::max<std::size_t>(k1, k2);
        if (k3 >= lo) ++k3;
        if (k3 >= hi) ++k3;
        j = order_[begin + k3];
    }
    return j;
}

template <DsmcCollisionOperator Collision>
template <class Obs>
void BasicDsmcEngine<Collision>::collide_cell(std::size_t cell, std::size_t begin, std::size_t cnt, double dt, Obs& obs) {
    const double pairs_half = 0.5 * static_cast<double>(cnt) * static_cast<double>(cnt - 1);
    const double inv_v = 1.0 / free_volume(cell, begin, cnt);
    exposure_ += pairs_half * dt * inv_v;
    // Eq. (15) with the stochastic rounding described at the top.
    const double mc = pairs_half * sigma_max_ * v_max_ * dt * inv_v;
    double whole = std::floor(mc);
    if (rng_.uniform() < mc - whole) whole += 1.0;
    const auto m = static_cast<std::uint64_t>(whole);
    candidates_ += m;
    for (std::uint64_t k = 0; k < m; ++k) {
        const auto k1 = rng_.index(cnt);
        const std::uint32_t i = order_[begin + k1];
        const std::uint32_t j = choose_partner(begin, cnt, k1);
        if (j == kNoPartner) continue; // no admissible partner: a void candidate
        const Vec2 g = vel_[i] - vel_[j];
        const double gabs = norm(g);
        const double dij = rad_[i] + rad_[j];
        const double s = 2.0 * dij * gabs; // sigma_ij |v_ij|
        if (s > sigma_max_ * v_max_) {
            v_max_ = s / sigma_max_;
            ++vmax_raises_;
        }
        // Eq. (16), with the inequality as the text means it (see top).
        if (!(rng_.uniform() * sigma_max_ * v_max_ < s)) continue;

        const double u = rng_.uniform(-1.0, 1.0); // b/d_ij, Eq. (17)
        const Vec2 e = g / gabs;
        const Vec2 n = -std::sqrt(1.0 - u * u) * e - u * perp(e);
        const double ti = time_ - last_[i], tj = time_ - last_[j];
        const bool elastic = cfg_.t_c > 0.0 && (ti <= cfg_.t_c || tj <= cfg_.t_c);
        const Collision& law = elastic ? elastic_law_ : law_;
        const auto res = law.template collide<false>(vel_[i], 0.0, mass_[i], rad_[i], vel_[j], 0.0, mass_[j], rad_[j], n);
        vel_[i] += res.dP / mass_[i];
        vel_[j] -= res.dP / mass_[j];

        CollisionRecord rec;
        rec.t = time_;
        rec.i = static_cast<int>(i);
        rec.j = static_cast<int>(j);
        rec.ri = pos_[i];
        rec.rj = pos_[i] - dij * n;
        rec.n = n;
        rec.dP = res.dP;
        rec.b_over_d = std::fabs(u);
        rec.elastic = elastic;

        if (cfg_.displacement) {
            const double mt = mass_[i] + mass_[j];
            const Vec2 di = (mass_[j] / mt * dij) * n, dj = (mass_[i] / mt * dij) * n;
            pos_[i] = {wrap(pos_[i].x + di.x, cfg_.lx), wrap(pos_[i].y + di.y, cfg_.ly)};
            pos_[j] = {wrap(pos_[j].x - dj.x, cfg_.lx), wrap(pos_[j].y - dj.y, cfg_.ly)};
        }
        ++count_[i];
        ++count_[j];
        last_[i] = last_[j] = time_;
        partner_[i] = j;
        partner_[j] = i;
        ++collisions_;
        if (elastic) ++elastic_collisions_;
        obs(rec);
    }
}

// dsmc_engine.cpp defines the members for the operators it instantiates (add new ones there).
using DsmcEngine = BasicDsmcEngine<RoughDiskCollision>;

} // namespace granrepro

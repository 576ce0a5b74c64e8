// Parameters of a DSMC run (Luding 1998, Sec. 2.4): everything except the per-particle state.
#pragma once
#include <cstdint>

namespace granrepro {

// How the free volume V_c - V_0 of Eq. (15) is formed (Luding Sec. 2.4, first dense-gas
// correction). V_0 = (sum of the disk areas) / 0.82, the area the particles would fill in 2D
// random close packing.
enum class DsmcFreeVolume : std::uint8_t {
    off,   // plain Eq. (15): V_c
    cell,  // the paper's wording: V_0 from the particles actually in that cell at that step
    mean,  // V_0 from the mean number of particles per cell (box-averaged area fraction); a
           // smoother variant: it multiplies every rate by exactly 1/(1 - rho/0.82)
};

struct DsmcConfig {
    double lx = 1.0; // periodic box width [m]
    double ly = 1.0; // periodic box height [m]

    double r = 1.0;  // normal restitution [-], 0 <= r <= 1 (Walton-Braun with beta0 = -1: smooth)
    double q = 0.5;  // I = q m a^2 [-]; irrelevant for smooth disks, passed to the operator only
    // TC model, Luding Eq. (7): a collision is elastic when either partner collided at most t_c
    // earlier [s]. 0 = plain inelastic DSMC.
    // Caution: all collisions of one step happen at the same instant, so with any t_c > 0 a
    // particle's second collision within a step is elastic. As the gas cools tau grows and this
    // share with it (37 % of the collisions by t = 0.06 s in the cooling run with t_c = 1e-5 s).
    // DSMC cannot collapse (no positions enter its collisions), so t_c = 0 is the sound choice.
    double t_c = 0.0;

    // Time step tau = L_c / (step_factor * v_fast), v_fast the largest particle speed at the last
    // resampling: the fastest particle needs step_factor steps to cross a cell [-], > 0.
    double step_factor = 5.0;
    // v_max (Eq. 15/16) = 2 v_fast and tau are re-sampled every resample_interval steps [-], >= 1.
    std::uint32_t resample_interval = 10;
    // Cell side target L_c = max(lambda/2, min_cell_diameters * d_max) [-] (paper: 2).
    // Small cells hold ~1 particle in 2D, so a pair that has just collided is often drawn again
    // (probability ~ sigma/L_c per collision). Harmless for elastic equilibrium rates, but an
    // inelastic pair re-collides with an already reduced normal velocity: at rho = 0.25, r = 0.8
    // the paper's 2 d cells cool 15% slower than Eq. (18) at t = t0, 10 d cells 3%, 30 d cells 1.5%
    // (tests/validation/dsmc_kinetic_theory_test.cpp).
    double min_cell_diameters = 2.0;

    // Dense-gas corrections of Sec. 2.4.
    DsmcFreeVolume free_volume = DsmcFreeVolume::off;
    double rcp_fraction = 0.82; // 2D random-close-packing area fraction [-] (paper's value)
    // Guard for the cell mode: V_c - V_0 is never taken below free_volume_floor * V_c [-], so an
    // over-full cell (more particles than fit at random close packing) gets a large but finite
    // collision rate instead of a division by zero or a negative M_c.
    double free_volume_floor = 0.05;
    // Second correction: after each collision the pair's separation grows by the contact distance
    // (a_i + a_j) along the momentum transfer (centre of mass kept). See dsmc_engine.hpp.
    bool displacement = false;

    std::uint64_t seed = 1;   // run seed
    std::uint64_t stream = 0; // stream index (independent sweep points)
};

} // namespace granrepro

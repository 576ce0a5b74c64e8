// Parameters of a DSMC run (Luding 1998, Sec. 2.4): everything except the per-particle state.
#pragma once
#include "data/fields.hpp"
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

// How the second member of a candidate pair is chosen once the first, i, is drawn uniformly from
// the cell (Eq. 15 fixes only how many candidates a cell gets, not which pairs).
enum class DsmcPartner : std::uint8_t {
    uniform, // any other particle of the cell (Bird's original scheme; the paper's wording)
    nearest, // the particle of the cell nearest to i: the limit of Bird's sub-cells (Molecular
             // Gas Dynamics, 1994) known as "virtual sub-cells" (Bird, "Sophisticated DSMC",
             // DSMC07 notes, 2007). Collisions between far-apart members of a large cell are
             // avoided, so the cell no longer sets the length below which positions are mixed
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

    // Remedies for the known defects of small-cell DSMC (none is in the paper; all off by default):
    // Partner choice inside a cell (see DsmcPartner).
    DsmcPartner partner = DsmcPartner::uniform;
    // No repeated partners: a pair whose members' last collision was with each other is not a
    // candidate again (Shevyrin, Bondar & Ivanov, AIP Conf. Proc. 762, 565 (2005); Bird,
    // "Sophisticated DSMC", 2007): two disks that have just
    // collided move apart and cannot meet again before one of them has hit a third. With uniform
    // partners another partner is drawn when the cell has one, else the candidate is void.
    bool no_repeat_partner = false;
    // Time step bound by the mean free time: tau <= mft_fraction / omega, omega the collision
    // rate per particle measured over the last resampling interval (kinetic theory, Boltzmann
    // times the free-volume factor, before any was measured) [-]. 0 = off (only the cell-crossing
    // rule above).
    double mft_fraction = 0.0;

    // Dense-gas corrections of Sec. 2.4.
    DsmcFreeVolume free_volume = DsmcFreeVolume::off;
    double rcp_fraction = 0.82; // 2D random-close-packing area fraction [-] (paper's value)
    // Guard for the cell mode: V_c - V_0 is never taken below free_volume_floor * V_c [-], so an
    // over-full cell (more particles than fit at random close packing) gets a large but finite
    // collision rate instead of a division by zero or a negative M_c.
    double free_volume_floor = 0.05;
    // Cell mode only: V_0 / V_c is taken over the block of free_volume_block x free_volume_block
    // cells centred on the cell (periodic) [-], odd >= 1. 1 = the paper's wording (the cell's own
    // particles); with ~1.3 disks per 2 d cell that estimate is mostly noise, and <1/(V_c - V_0)>
    // over the noise exceeds 1/(V_c - <V_0>) several times (Jensen), so a 3 x 3 or 5 x 5 block
    // estimates the local density over 6-10 d while pairs are still drawn in the small cell.
    std::uint32_t free_volume_block = 1;
    // Second correction: after each collision the pair's separation grows by the contact distance
    // (a_i + a_j) along the momentum transfer (centre of mass kept). See dsmc_engine.hpp.
    bool displacement = false;

    std::uint64_t seed = 1;   // run seed
    std::uint64_t stream = 0; // stream index (independent sweep points)

    // The one list of fields, walked by the state files (io/h5_fields.hpp).
    GRANREPRO_FIELDS(lx, ly, r, q, t_c, step_factor, resample_interval, min_cell_diameters, partner,
                     no_repeat_partner, mft_fraction, free_volume, rcp_fraction, free_volume_floor, free_volume_block,
                     displacement, seed, stream)
};

} // namespace granrepro

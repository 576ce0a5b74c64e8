// Kinetic theory of the 2D hard-disk gas, elastic and inelastic (smooth disks, normal
// restitution r), as used to check the ED and DSMC engines and the paper's numbers. Temperature
// per particle T = m <v^2>/2 in 2D (K = N T), so T/m = vbar^2/2 with Luding's vbar = sqrt(2K/(N m)).
#pragma once
#include <cmath>
#include <numbers>

namespace granrepro::theory {

// Henderson's contact value of the 2D hard-disk pair correlation at area fraction rho
// (D. Henderson, Mol. Phys. 30, 971 (1975)): g(d) = (1 - 7 rho/16) / (1 - rho)^2. Luding's s_*
// of Eq. (19) is 1/g(d).
inline double henderson_contact_value(double rho) { return (1.0 - 7.0 * rho / 16.0) / ((1.0 - rho) * (1.0 - rho)); }

// Henderson's equation of state (same reference): beta p / n = Z = (1 + rho^2/8) / (1 - rho)^2,
// exactly the virial form Z = 1 + 2 rho g(d) with the g(d) above.
inline double henderson_compressibility(double rho) { return (1.0 + rho * rho / 8.0) / ((1.0 - rho) * (1.0 - rho)); }

// Long-wavelength limit of the equilibrium structure factor, the isothermal compressibility
// S(0) = 1 / (d(beta p)/dn) = 1 / d(rho Z)/d rho, from Henderson's Z:
//   d(rho Z)/d rho = [(1 + 3 rho^2/8)(1 - rho) + 2 (rho + rho^3/8)] / (1 - rho)^3.
// 0.3318 at rho = 0.25 (an ideal gas, and plain DSMC, has S(0) = 1).
inline double hard_disk_structure_factor_zero(double rho) {
    const double num = (1.0 + 3.0 * rho * rho / 8.0) * (1.0 - rho) + 2.0 * (rho + rho * rho * rho / 8.0);
    return (1.0 - rho) * (1.0 - rho) * (1.0 - rho) / num;
}

// Enskog collision rate per particle of 2D disks of diameter d at number density n [1/m^2]:
// omega = 2 n d g sqrt(pi T/m) [1/s] (Chapman & Cowling; 2 d is the 2D cross-section and
// sqrt(pi T/m) the mean relative speed of two Maxwellian disks), g the contact value
// (1: dilute Boltzmann gas).
inline double enskog_collision_rate(double n, double d, double t_over_m, double g) {
    return 2.0 * n * d * g * std::sqrt(std::numbers::pi * t_over_m);
}

// The same at area fraction rho and Luding's vbar (T/m = vbar^2/2, n = 4 rho/(pi d^2)):
// omega = 8 rho vbar g / (sqrt(2 pi) d).
inline double enskog_collision_rate_vbar(double rho, double d, double vbar, double g) {
    return 8.0 * rho * vbar * g / (std::sqrt(2.0 * std::numbers::pi) * d);
}

// Haff's homogeneous cooling (P. K. Haff, J. Fluid Mech. 134, 401 (1983); Luding Eq. 18): with
// dT/dt = -(1 - r^2) omega T / 2 and omega proportional to sqrt(T) (the loss per collision is
// (1 - r^2) T for Maxwellian disks with b uniform), K/K0 = 1/(1 + t/t0)^2 with
// t0 = 4 / ((1 - r^2) omega0), omega0 the collision rate at t = 0. This is Eq. (19) with
// sqrt(2 pi) where the paper prints sqrt(pi); the paper's number 23.24 1/s is the sqrt(2 pi) one.
inline double haff_t0(double r, double omega0) { return 4.0 / ((1.0 - r * r) * omega0); }
// Luding's Eq. (19) as printed: t0 = sqrt(pi) d s_* / (2 (1 - r^2) rho vbar), s_* = 1/g(d) =
// (1 - rho)^2 / (1 - 7 rho/16). It is haff_t0 with the Enskog rate at sqrt(2)-times too large
// a value; drivers show it beside the kinetic t0 (the rejected reading of Eq. 19).
inline double luding_eq19_t0_printed(double r, double rho, double d, double vbar) {
    const double s_star = (1.0 - rho) * (1.0 - rho) / (1.0 - 7.0 * rho / 16.0);
    return std::sqrt(std::numbers::pi) * d * s_star / (2.0 * (1.0 - r * r) * rho * vbar);
}
inline double haff_energy_ratio(double t, double t0) { return 1.0 / ((1.0 + t / t0) * (1.0 + t / t0)); }
// Collisions per particle (2 x pair collisions / N) up to t under Haff's law: omega0 t0 ln(1 + t/t0).
inline double haff_collisions_per_particle(double t, double t0, double omega0) { return omega0 * t0 * std::log1p(t / t0); }

// Second Sonine coefficient of the homogeneous cooling state of smooth inelastic hard spheres in
// dimension dim, first Sonine approximation: T. P. C. van Noije and M. H. Ernst, Granular Matter 1,
// 57 (1998):
//   a2 = 16 (1 - r)(1 - 2 r^2) / (9 + 24 dim + (8 dim - 41) r + 30 (1 - r) r^2).
// -0.0219 for disks at r = 0.8; zero at r = 1 and at r = 1/sqrt(2). The same for Boltzmann and
// Enskog gases (g(d) cancels).
inline double van_noije_ernst_a2(double r, int dim) {
    const double dd = static_cast<double>(dim);
    return 16.0 * (1.0 - r) * (1.0 - 2.0 * r * r) / (9.0 + 24.0 * dd + (8.0 * dd - 41.0) * r + 30.0 * (1.0 - r) * r * r);
}

// a2 from the velocity moments in 2D: a2 = <v^4> / <v^4>_Maxwell - 1, <v^4>_Maxwell = 2 <v^2>^2.
// Measured about the mean velocity (zero in a periodic box at rest).
inline double sonine_a2_2d(double mean_v2, double mean_v4) { return mean_v4 / (2.0 * mean_v2 * mean_v2) - 1.0; }
// Its standard error for N independent Maxwellian velocities: v^2 is exponential, so
// Var(v^4) = 20 <v^2>^4 and sigma(a2) = sqrt(5/N).
inline double sonine_a2_2d_maxwell_error(double n) { return std::sqrt(5.0 / n); }

// Free-volume factor of Luding Sec. 2.4's first dense-gas correction, V_c/(V_c - V_0) with
// V_0 = (disk area)/rcp for the mean area fraction rho: 1/(1 - rho/rcp) (rcp = 0.82 in 2D).
inline double free_volume_factor(double rho, double rcp) { return 1.0 / (1.0 - rho / rcp); }

} // namespace granrepro::theory

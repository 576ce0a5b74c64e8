// The sizing rules of Luding 1998 Sec. 2.4 as free functions, so that tests and experiment drivers
// can state what the engine will choose before building it.
#pragma once
#include <cstddef>

namespace granrepro {

// Mean free path of a 2D gas of disks of diameter d [m] at number density n [1/m^2]:
//     lambda = <|v|> / omega = sqrt(pi T/(2m)) / (n sigma sqrt(pi T/m) chi) = 1 / (sqrt(2) n sigma chi),
// with the 2D cross-section sigma = 2d (Eq. 15: a disk hits every centre within |b| < d) and chi
// the rate enhancement of the collision rule (1 for plain Eq. (15), 1/(1 - rho/0.82) with the
// free-volume correction, g(d) for Enskog).
double dsmc_mean_free_path(double number_density, double diameter, double chi = 1.0);

// Cells per side: the largest count whose cells are not smaller than the target side
// L_c = max(lambda/2, min_side) [m]. Flooring keeps every cell >= L_c, so the paper's lower bound
// of two diameters holds exactly; cells are lx/nx by ly/ny, square when lx/ly = nx/ny and
// otherwise of aspect ratio at most 1 + 1/min(nx, ny). At least one cell per side.
std::size_t dsmc_cells_per_side(double box_length, double mean_free_path, double min_side);

// Time step: the fastest particle, speed v_fast [m/s], needs step_factor steps to cross a cell of
// side cell_side [m]; tau = cell_side / (step_factor v_fast) [s]. +inf when v_fast = 0.
double dsmc_time_step(double cell_side, double v_fast, double step_factor);

} // namespace granrepro

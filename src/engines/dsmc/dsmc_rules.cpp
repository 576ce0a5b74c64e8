#include "engines/dsmc/dsmc_rules.hpp"

#include "core/input_error.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

namespace granrepro {

double dsmc_mean_free_path(double number_density, double diameter, double chi) {
    if (!(number_density > 0.0) || !(diameter > 0.0) || !(chi > 0.0))
        throw InputError("DSMC mean free path: need n > 0, d > 0, chi > 0");
    return 1.0 / (std::sqrt(2.0) * number_density * 2.0 * diameter * chi);
}

std::size_t dsmc_cells_per_side(double box_length, double mean_free_path, double min_side) {
    if (!(box_length > 0.0) || !(mean_free_path > 0.0) || !(min_side >= 0.0))
        throw InputError("DSMC cells: need a positive box length and mean free path");
    const double target = std::max(0.5 * mean_free_path, min_side);
    const double k = std::floor(box_length / target);
    return k < 1.0 ? 1 : static_cast<std::size_t>(k);
}

double dsmc_time_step(double cell_side, double v_fast, double step_factor) {
    if (!(cell_side > 0.0) || !(step_factor > 0.0) || !(v_fast >= 0.0))
        throw InputError("DSMC time step: need cell side > 0, step factor > 0, v_fast >= 0");
    if (v_fast == 0.0) return std::numeric_limits<double>::infinity();
    return cell_side / (step_factor * v_fast);
}

} // namespace granrepro

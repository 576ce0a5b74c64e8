// The structure factor S(k) of Luding 1998 Sec. 3.3, Fig. 7.
//
// Convention implemented (the paper's, as far as it states one):
//  * Density: the particles are mapped onto an M x M lattice by nearest-grid-point assignment
//    (each particle adds 1 to the cell holding its centre), "where M is the closest power of 2
//    that gives a lattice box size of about one diameter": M = 2^m minimising |l/M - d|.
//  * rho_n = sum_cells c(x) exp(-2 pi i n.x / M) by FFTW (real-to-complex 2D), n = (n_x, n_y)
//    integer mode indices; S_n = |rho_n|^2 / N, so S = 1 for uncorrelated points and S_0 = N.
//    With NGP and a box that is exactly M cells wide, uniform random points give <S_n> = 1 for
//    every n != 0 (mod M), not just at small n: the cell index of a uniform point is uniform.
//  * Axis: the paper plots against k = l/lambda (wavelengths per system size), i.e. the
//    dimensionless |n|. S(k) is the average of S_n over the shell k - 1/2 <= |n| < k + 1/2,
//    k = 1 .. M/2 (larger shells are cut by the Brillouin zone corners). Physical wavenumber:
//    q = 2 pi k / l [1/m].
//  * Several snapshots are averaged mode by mode before the shell average.
// Square periodic boxes only: k = l/lambda has no single meaning when Lx != Ly.
#pragma once
#include "core/vec2.hpp"

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace granrepro {

class StructureFactor {
public:
    // Smallest power of two M with |l/M - d| minimal; l box side [m], d particle diameter [m].
    static int lattice_size(double l, double d);

    // l side of the square periodic box [m], d particle diameter [m]; M overrides the lattice
    // size (power of two >= 2) when > 0. Plans the FFT once (FFTW_ESTIMATE: deterministic plans,
    // so reruns give bit-identical spectra; MEASURE would time algorithms and may pick others).
    // Throws std::invalid_argument on bad arguments.
    // Movable, not copyable (it owns the FFTW arrays and plan).
    StructureFactor(double l, double d, int M = 0);

    int M() const { return M_; }
    double box() const { return l_; }

    // Adds one snapshot (positions [m], wrapped into the box). Not thread-safe on one object;
    // distinct objects may run in parallel threads.
    void accumulate(std::span<const Vec2> positions);

    struct Shell {
        std::vector<double> k;        // shell index k = l/lambda (dimensionless), 1 .. M/2
        std::vector<double> S;        // shell average of <S_n>
        std::vector<double> error;    // standard error of S over the modes*snapshots of the shell
        std::vector<std::size_t> modes; // number of modes n in the shell
    };
    Shell radial_average() const;
    std::size_t snapshots() const { return snapshots_; }
    void reset();

    // The last snapshot, for checks: cell occupation numbers c (row-major, y outer) and the
    // half spectrum S_n = |rho_n|^2/N of size M x (M/2+1) from FFTW's r2c layout (row index i for
    // n_y, column j for n_x >= 0). mode_weight(j) says how many of the M^2 modes the entry
    // stands for: 2 for 0 < j < M/2 (n and -n), else 1; so sum weight*S_n = sum over all modes.
    const std::vector<double>& last_density() const { return density_; }
    const std::vector<double>& last_spectrum() const { return last_; }
    int mode_weight(int j) const { return (j == 0 || 2 * j == M_) ? 1 : 2; }
    // Signed mode index for FFT index i in [0, M): i for i <= M/2, i - M above.
    int signed_mode(int i) const { return i <= M_ / 2 ? i : i - M_; }

private:
    // fftw_free, and fftw_destroy_plan under the planner lock; void* keeps fftw3.h out of the header.
    struct FftwFree { void operator()(void* p) const; };
    struct PlanDestroy { void operator()(void* p) const; };

    double l_ = 0.0;
    int M_ = 0;
    int half_ = 0; // M/2 + 1
    std::unique_ptr<double, FftwFree> in_; // fftw_malloc'd M*M reals
    std::unique_ptr<void, FftwFree> out_;  // fftw_complex[M*(M/2+1)]
    std::unique_ptr<void, PlanDestroy> plan_; // fftw_plan
    std::vector<double> density_, last_, sum_, sum2_;
    std::size_t snapshots_ = 0;
};

} // namespace granrepro

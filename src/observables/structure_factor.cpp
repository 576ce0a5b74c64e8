#include "observables/structure_factor.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

namespace granrepro {

namespace {
// FFTW's planner (and plan destruction) touch global state and are not thread-safe; executing a
// plan on its own arrays is. Engines running sweep points in parallel threads share this lock.
std::mutex& fftw_planner_mutex() {
    static std::mutex m;
    return m;
}
} // namespace

int StructureFactor::lattice_size(double l, double d) {
    if (!(l > 0.0) || !(d > 0.0)) throw std::invalid_argument("StructureFactor: l, d must be > 0");
    int best = 2;
    for (int M = 2; M <= (1 << 24); M *= 2) {
        if (std::abs(l / M - d) < std::abs(l / best - d)) best = M;
        if (l / M < 0.5 * d) break; // further doublings only move away from d
    }
    return best;
}

void StructureFactor::FftwFree::operator()(void* p) const { fftw_free(p); }

void StructureFactor::PlanDestroy::operator()(void* p) const {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(static_cast<fftw_plan>(p));
}

StructureFactor::StructureFactor(double l, double d, int M) : l_(l) {
    if (!(l > 0.0) || !(d > 0.0)) throw std::invalid_argument("StructureFactor: l, d must be > 0");
    M_ = M > 0 ? M : lattice_size(l, d);
    if (M_ < 2 || (M_ & (M_ - 1)) != 0)
        throw std::invalid_argument("StructureFactor: M must be a power of two >= 2");
    half_ = M_ / 2 + 1;
    const auto nreal = static_cast<std::size_t>(M_) * static_cast<std::size_t>(M_);
    const auto ncomplex = static_cast<std::size_t>(M_) * static_cast<std::size_t>(half_);
    {
        std::lock_guard<std::mutex> lock(fftw_planner_mutex());
        in_.reset(fftw_alloc_real(nreal));
        auto* out = fftw_alloc_complex(ncomplex);
        out_.reset(out);
        if (!in_ || !out) throw std::bad_alloc();
        plan_.reset(fftw_plan_dft_r2c_2d(M_, M_, in_.get(), out, FFTW_ESTIMATE));
    }
    if (!plan_) throw std::runtime_error("StructureFactor: FFTW planning failed");
    density_.assign(nreal, 0.0);
    last_.assign(ncomplex, 0.0);
    sum_.assign(ncomplex, 0.0);
    sum2_.assign(ncomplex, 0.0);
}

void StructureFactor::accumulate(std::span<const Vec2> pos) {
    if (!plan_) throw std::logic_error("StructureFactor: moved-from object");
    if (pos.empty()) throw std::invalid_argument("StructureFactor: no particles");
    std::fill(density_.begin(), density_.end(), 0.0);
    for (const Vec2& p : pos) {
        double u = p.x / l_, v = p.y / l_;
        u -= std::floor(u);
        v -= std::floor(v);
        const int ix = std::min(M_ - 1, static_cast<int>(u * M_));
        const int iy = std::min(M_ - 1, static_cast<int>(v * M_));
        density_[static_cast<std::size_t>(iy) * M_ + ix] += 1.0;
    }
    // The planner may have scribbled on in_; copy the density in only now.
    std::copy(density_.begin(), density_.end(), in_.get());
    fftw_execute(static_cast<fftw_plan>(plan_.get()));
    const auto* out = static_cast<const fftw_complex*>(out_.get());
    const double inv_n = 1.0 / static_cast<double>(pos.size());
    for (std::size_t m = 0; m < last_.size(); ++m) {
        const double s = (out[m][0] * out[m][0] + out[m][1] * out[m][1]) * inv_n;
        last_[m] = s;
        sum_[m] += s;
        sum2_[m] += s * s;
    }
    ++snapshots_;
}

StructureFactor::Shell StructureFactor::radial_average() const {
    const int kmax = M_ / 2;
    Shell sh;
    std::vector<double> w(static_cast<std::size_t>(kmax) + 1, 0.0), s(w), s2(w);
    sh.modes.assign(static_cast<std::size_t>(kmax) + 1, 0);
    // FFTW r2c layout: index i (rows, slow) is the first dimension = y, j (fast) the second = x.
    for (int i = 0; i < M_; ++i) {
        const double ny = signed_mode(i);
        for (int j = 0; j < half_; ++j) {
            const double nx = j;
            const double kn = std::sqrt(nx * nx + ny * ny);
            const auto k = static_cast<long>(std::floor(kn + 0.5));
            if (k < 1 || k > kmax) continue;
            const auto m = static_cast<std::size_t>(i) * half_ + j;
            const double wt = mode_weight(j);
            w[k] += wt;
            s[k] += wt * sum_[m];
            s2[k] += wt * sum2_[m];
            sh.modes[k] += static_cast<std::size_t>(wt);
        }
    }
    sh.modes.erase(sh.modes.begin());
    const double ns = static_cast<double>(snapshots_);
    for (int k = 1; k <= kmax; ++k) {
        sh.k.push_back(k);
        if (w[k] == 0.0 || snapshots_ == 0) {
            sh.S.push_back(0.0);
            sh.error.push_back(0.0);
            continue;
        }
        // Samples: every (mode, snapshot); +n and -n are not independent (|rho_-n| = |rho_n|), so
        // the count of independent samples is about half the weight.
        const double nsamp = w[k] * ns;
        const double mean = s[k] / nsamp;
        const double var = std::max(0.0, s2[k] / nsamp - mean * mean);
        const double indep = std::max(1.0, 0.5 * nsamp);
        sh.S.push_back(mean);
        sh.error.push_back(std::sqrt(var / indep));
    }
    return sh;
}

void StructureFactor::reset() {
    std::fill(sum_.begin(), sum_.end(), 0.0);
    std::fill(sum2_.begin(), sum2_.end(), 0.0);
    snapshots_ = 0;
}

} // namespace granrepro

#include "scenarios/pipe_setup.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "core/rng_stream.hpp"

namespace granrepro {

LinearSpringDashpot pipe_law(double k_N, double e_N, double m_mean) {
    return LinearSpringDashpot::from_restitution(k_N, e_N, m_mean);
}

namespace {

double max_diameter(const PipeSpec& s) { return s.d_mean * (1 + s.polydispersity); }

// Triangular lattice sites between the wall crests, its spacing shrunk from the area per grain
// until n grains fit or the spacing reaches the largest diameter (then fewer than n sites).
std::vector<std::pair<double, double>> lattice_sites(const PipeSpec& s, long n) {
    const double d_max = max_diameter(s);
    const double area = (s.geo.width - 2 * s.geo.wall_radius) * s.geo.length;
    const double x_lo = s.geo.wall_radius + 0.5 * d_max + 1e-6, x_hi = s.geo.width - x_lo;
    std::vector<std::pair<double, double>> sites;
    for (double a = std::sqrt(area / double(n) / (std::sqrt(3.0) / 2)); a >= d_max; a *= 0.995) {
        sites.clear();
        const int rows = int(s.geo.length / (a * std::sqrt(3.0) / 2));
        const double row_h = s.geo.length / rows;
        for (int r = 0; r < rows; ++r)
            for (double x = x_lo + (r % 2) * 0.5 * a; x <= x_hi; x += a) sites.push_back({x, r * row_h});
        if (long(sites.size()) >= n) break;
    }
    return sites;
}

} // namespace

long pipe_grain_count(const PipeSpec& s) {
    // Area fraction relative to the channel between the wall crests, (width - d_wall) x length.
    const double area = (s.geo.width - 2 * s.geo.wall_radius) * s.geo.length;
    const double mean_d2 = s.d_mean * s.d_mean * (1 + s.polydispersity * s.polydispersity / 3);
    return std::lround(s.phi * area / (M_PI / 4 * mean_d2));
}

bool pipe_lattice_fits(const PipeSpec& s) {
    const long n = pipe_grain_count(s);
    return long(lattice_sites(s, n).size()) >= n;
}

double pipe_time_step(const PipeSpec& s, const LinearSpringDashpot& law) {
    const double d_min = s.d_mean * (1 - s.polydispersity);
    const double m_min = s.m_mean * (d_min / s.d_mean) * (d_min / s.d_mean);
    return law.collision_time(0.5 * m_min) / s.steps_per_contact;
}

PipeStart pipe_start(const PipeSpec& s) {
    RngStream rng(s.seed, s.stream);
    const long n = pipe_grain_count(s);
    std::vector<std::pair<double, double>> sites = lattice_sites(s, n);
    if (long(sites.size()) < n) throw std::runtime_error("area fraction too high for a lattice start");
    for (std::size_t i = sites.size() - 1; i > 0; --i) std::swap(sites[i], sites[rng.index(i + 1)]);
    sites.resize(std::size_t(n));
    PipeStart g;
    for (long i = 0; i < n; ++i) {
        g.vx.push_back(s.agitation * rng.normal());
        g.vy.push_back(s.agitation * rng.normal());
    }
    const double mx = std::accumulate(g.vx.begin(), g.vx.end(), 0.0) / double(n);
    const double my = std::accumulate(g.vy.begin(), g.vy.end(), 0.0) / double(n);
    for (std::size_t i = 0; i < std::size_t(n); ++i) {
        const double d = s.d_mean * (1 + s.polydispersity * rng.uniform(-1, 1));
        g.x.push_back(sites[i].first);
        g.y.push_back(sites[i].second);
        g.vx[i] -= mx;
        g.vy[i] = g.vy[i] - my - s.v0;
        g.radius.push_back(0.5 * d);
        g.mass.push_back(s.m_mean * (d / s.d_mean) * (d / s.d_mean));
    }
    return g;
}

PipeEngine<LinearSpringDashpot, CoulombShear> build_pipe(const PipeSpec& s) {
    const LinearSpringDashpot law = pipe_law(s.k_N, s.e_N, s.m_mean);
    return build_pipe(s, law, CoulombShear{s.mu, s.friction_normal}, pipe_time_step(s, law));
}

} // namespace granrepro

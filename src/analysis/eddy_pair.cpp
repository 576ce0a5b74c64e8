#include "analysis/eddy_pair.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/rng_stream.hpp"

namespace granrepro {

namespace {
double min_image(double d, double box) { return d - box * std::round(d / box); }
double wrap(double x, double box) {
    x = std::fmod(x, box);
    return x < 0 ? x + box : x;
}
} // namespace

double region_rotation(const std::vector<Vec2>& pos, const std::vector<Vec2>& vel, double box, Vec2 centre, double half) {
    double num = 0, den = 0;
    for (std::size_t i = 0; i < pos.size(); ++i) {
        const Vec2 r{min_image(pos[i].x - centre.x, box), min_image(pos[i].y - centre.y, box)};
        if (std::abs(r.x) >= half || std::abs(r.y) >= half) continue;
        num += cross(r, vel[i]);
        den += norm(r) * norm(vel[i]);
    }
    return den > 0 ? num / den : 0.0;
}

EddyPair find_eddy_pair(const std::vector<Vec2>& pos, const std::vector<Vec2>& vel, double box, int shifts) {
    if (pos.size() != vel.size() || !(box > 0) || shifts < 1)
        throw std::invalid_argument("find_eddy_pair: positions and velocities must match, box > 0, shifts >= 1");
    EddyPair best;
    best.strength = -INFINITY;
    const double q = 0.5 * box, h = 0.25 * box;
    for (int a = 0; a < shifts; ++a)
        for (int b = 0; b < shifts; ++b) {
            const double sx = q * a / shifts, sy = q * b / shifts;
            Vec2 c[2][2];
            double rho[2][2];
            for (int i = 0; i < 2; ++i)
                for (int j = 0; j < 2; ++j) {
                    c[i][j] = {wrap(sx + h + i * q, box), wrap(sy + h + j * q, box)};
                    rho[i][j] = region_rotation(pos, vel, box, c[i][j], h);
                }
            // Diagonal (00, 11) against (10, 01), and the reverse; both senses.
            for (int diag = 0; diag < 2; ++diag)
                for (int s : {+1, -1}) {
                    const int ai = diag ? 1 : 0, bi = diag ? 0 : 1; // pair: (ai, 0) and (bi, 1)
                    const double ra = rho[ai][0], rb = rho[bi][1], rc = rho[1 - ai][0], rd = rho[1 - bi][1];
                    const double e = std::min(s * ra, s * rb) - std::max({0.0, s * rc, s * rd});
                    if (e > best.strength) {
                        best.strength = e;
                        best.sense = s;
                        best.centre_a = c[ai][0];
                        best.centre_b = c[bi][1];
                        best.rotation_a = ra;
                        best.rotation_b = rb;
                    }
                }
        }
    return best;
}

std::vector<double> shuffled_eddy_strengths(const std::vector<Vec2>& pos, const std::vector<Vec2>& vel, double box,
                                            int n_shuffles, std::uint64_t seed, int shifts) {
    RngStream rng(seed, 0);
    std::vector<Vec2> v = vel;
    std::vector<double> out;
    for (int k = 0; k < n_shuffles; ++k) {
        for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.index(i)]); // Fisher-Yates
        out.push_back(find_eddy_pair(pos, v, box, shifts).strength);
    }
    return out;
}

} // namespace granrepro

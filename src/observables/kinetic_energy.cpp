#include "observables/kinetic_energy.hpp"

#include <stdexcept>

namespace granrepro {

double KineticEnergy::anisotropy() const {
    const double k = translational();
    return k > 0.0 ? (x - y) / k : 0.0;
}

KineticEnergy KineticEnergy::compute(std::span<const Vec2> v, std::span<const double> m) {
    if (v.size() != m.size()) throw std::invalid_argument("KineticEnergy: velocities/masses size");
    KineticEnergy k;
    for (std::size_t i = 0; i < v.size(); ++i) {
        k.x += 0.5 * m[i] * v[i].x * v[i].x;
        k.y += 0.5 * m[i] * v[i].y * v[i].y;
    }
    return k;
}

KineticEnergy KineticEnergy::compute(std::span<const Vec2> v, std::span<const double> m,
                                     std::span<const double> w, std::span<const double> inertia) {
    if (w.size() != v.size() || inertia.size() != v.size())
        throw std::invalid_argument("KineticEnergy: spins/inertia size");
    KineticEnergy k = compute(v, m);
    for (std::size_t i = 0; i < w.size(); ++i) k.rot += 0.5 * inertia[i] * w[i] * w[i];
    return k;
}

KineticEnergy KineticEnergy::compute(std::span<const Vec2> v, double mass) {
    KineticEnergy k;
    for (const Vec2& vi : v) {
        k.x += 0.5 * mass * vi.x * vi.x;
        k.y += 0.5 * mass * vi.y * vi.y;
    }
    return k;
}

} // namespace granrepro

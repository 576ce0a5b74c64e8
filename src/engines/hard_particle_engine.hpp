// What a driver may rely on from any hard-particle engine (ED, DSMC), so that one sampling loop
// serves both: a clock, running to a time while each collision is reported to an observer, the
// kinetic energy, and a plain-data state that restores the run bit for bit.
#pragma once
#include "core/collision_record.hpp"

#include <concepts>

namespace granrepro {

// The observer that costs nothing: engines test for this type and skip building records.
struct NoCollisionObserver {
    void operator()(const CollisionRecord&) const {}
};

template <class E>
concept HardParticleEngine = requires(E& e, const E& ce, double t, NoCollisionObserver& obs) {
    { ce.time() } -> std::convertible_to<double>; // [s]
    e.run_until(t, obs);                          // afterwards time() == t
    e.restore_state(ce.save_state());
    // [J]: a number, or a split by degrees of freedom with total().
    requires std::convertible_to<decltype(ce.kinetic_energy()), double> ||
        requires { { ce.kinetic_energy().total() } -> std::convertible_to<double>; };
};

// Total kinetic energy [J] of any engine.
template <HardParticleEngine E>
double total_kinetic_energy(const E& e) {
    if constexpr (std::convertible_to<decltype(e.kinetic_energy()), double>) return e.kinetic_energy();
    else return e.kinetic_energy().total();
}

} // namespace granrepro

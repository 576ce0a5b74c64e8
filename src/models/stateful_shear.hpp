// Shear laws come in two kinds. A stateless law (coulomb_shear.hpp) has
//     shear_force(NormalForce, v_S);
// a law with history (tangential_spring.hpp, Luding Eq. 13) names the state it keeps per contact
// and has
//     shear_force(NormalForce, v_S, ContactState),  hold(NormalForce, ContactState) -> ContactState,
// with d(state)/dt = v_S while the contact lasts. An engine that carries the state (FewBodyEngine)
// accepts both; one that does not (PipeEngine) refuses a stateful law at compile time.
#pragma once
#include <concepts>

#include "models/normal_force.hpp"

namespace granrepro {

template <class S>
concept StatefulShear = requires(const S& s, const NormalForce& f, typename S::ContactState c) {
    { s.shear_force(f, 0.0, c) } -> std::convertible_to<double>;
    { s.hold(f, c) } -> std::convertible_to<typename S::ContactState>;
};

} // namespace granrepro

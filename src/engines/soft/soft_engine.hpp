// What any soft-sphere (force-based, time-stepped) engine offers for free grains, so that one
// test or driver can run on FewBodyEngine (RK4 with contact switching, binary impacts) and on
// PipeEngine (velocity Verlet with a neighbour list, the many-grain pipe) alike. It is the soft
// side's counterpart of HardParticleEngine (engines/hard_particle_engine.hpp), and exists so that
// the two integrators of the same contact laws are held to one contract
// (tests/unit/soft_engine_contract_test.cpp: a binary impact shot through both gives the same Δv,
// and Eq. (4)'s e_N and t_col).
//
// For an engine e the concept promises, in SI units:
//   soft_add_free(e, r, v, radius, mass) adds a free grain with centre r [m], velocity v [m/s],
//       radius [m] and mass [kg], and returns its index (0, 1, 2, ... in the order of adding);
//   soft_ready(e)      is called once, after the last grain is added and before the first step;
//   e.step()           advances the time by one step dt;
//   e.dt(), e.time()   the time step and the time since the start [s];
//   soft_position(e, i), soft_velocity(e, i)
//                      grain i's centre [m] and velocity [m/s] at time() (PipeEngine wraps the
//                      centre's y into its periodic length).
// What else an engine holds (wall grains, rows, the pipe's walls and gravity) and how it is built
// is the engine's own business; the concept says nothing about them.
//
// The engines keep their own member names; the free functions below adapt them (found by
// ordinary lookup here and by argument-dependent lookup for a third engine in this namespace).
// The engines are only declared here: including this header does not include them.
#pragma once
#include <concepts>
#include <cstddef>

#include "core/vec2.hpp"
#include "engines/soft/soft_grain.hpp"

namespace granrepro {

template <class NormalLaw, class ShearLaw>
class FewBodyEngine;
template <class NormalLaw, class ShearLaw>
class PipeEngine;

template <class N, class S>
int soft_add_free(FewBodyEngine<N, S>& e, Vec2 r, Vec2 v, double radius, double mass) {
    return e.add_free(SoftGrain{r, v, radius, mass});
}
template <class N, class S>
void soft_ready(FewBodyEngine<N, S>&) {}
template <class N, class S>
Vec2 soft_position(const FewBodyEngine<N, S>& e, int i) { return e.grains()[std::size_t(i)].r; }
template <class N, class S>
Vec2 soft_velocity(const FewBodyEngine<N, S>& e, int i) { return e.grains()[std::size_t(i)].v; }

template <class N, class S>
int soft_add_free(PipeEngine<N, S>& e, Vec2 r, Vec2 v, double radius, double mass) {
    const int id = int(e.size());
    e.add_grain(r.x, r.y, v.x, v.y, radius, mass);
    return id;
}
template <class N, class S>
void soft_ready(PipeEngine<N, S>& e) { e.finalize(); }
template <class N, class S>
Vec2 soft_position(const PipeEngine<N, S>& e, int i) {
    return {e.x()[std::size_t(i)], e.y()[std::size_t(i)]};
}
template <class N, class S>
Vec2 soft_velocity(const PipeEngine<N, S>& e, int i) {
    return {e.vx()[std::size_t(i)], e.vy()[std::size_t(i)]};
}

template <class E>
concept SoftEngine = requires(E& e, const E& ce, Vec2 r, Vec2 v, double radius, double mass, int i) {
    { soft_add_free(e, r, v, radius, mass) } -> std::same_as<int>;
    soft_ready(e);
    e.step();
    { ce.dt() } -> std::convertible_to<double>;   // [s]
    { ce.time() } -> std::convertible_to<double>; // [s]
    { soft_position(ce, i) } -> std::same_as<Vec2>; // [m]
    { soft_velocity(ce, i) } -> std::same_as<Vec2>; // [m/s]
};

} // namespace granrepro

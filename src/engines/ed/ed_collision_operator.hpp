// What the ED engine needs of a collision operator: EdConfig's law is one (BasicEdConfig<C>),
// and the engine (BasicEdEngine<Queue, C>) uses nothing of it but this list.
//   validate()                 throws InputError when the parameters are out of range (called
//                              whenever the configuration is set up);
//   elastic_version(keep)      the operator of a collision made elastic by the TC model (Luding
//                              Eq. (7)); keep = EdConfig::tc_keep_friction;
//   against(wall)              the operator for a collision with that EdWall (body 2 of infinite
//                              mass); throws InputError when the wall's parameters do not fit;
//   q                          moment of inertia I = q m a^2 [-] of a disk (the engine's
//                              moment_of_inertia() and rotational kinetic energy);
//   frictional()               true when the tangential impulse can be non-zero: the event loop
//                              is instantiated for both forms, the smooth one skips spins;
//   collide<kFrictional>(v1, w1, m1, a1, v2, w2, m2, a2, n) -> {dP, dw1, dw2}: momentum change
//                              of body 1 [kg m/s] (body 2 receives -dP) and spin changes [1/s],
//                              n the unit normal 2 -> 1, m2 = +infinity for a wall, called only
//                              for an approaching contact; with kFrictional = false the spin
//                              changes are ignored (RoughDiskCollision documents the arguments);
//   fields(v)                  its parameters, walked by the state files (io/h5_fields.hpp).
// RoughDiskCollision (Walton-Braun, Luding Eqs. (1)-(6)) is the default operator.
#pragma once
#include "core/vec2.hpp"
#include "data/fields.hpp"
#include "engines/ed/ed_wall.hpp"

#include <concepts>

namespace granrepro {

// What collide() returns: body 1's momentum change and both spin changes.
template <class R>
concept EdCollisionResult = requires(const R& r) {
    { r.dP } -> std::convertible_to<Vec2>;
    { r.dw1 } -> std::convertible_to<double>;
    { r.dw2 } -> std::convertible_to<double>;
};

template <class C>
concept EdCollisionOperator = std::copyable<C> && std::default_initializable<C> && HasFields<C> &&
    requires(const C& c, const EdWall& wall, bool keep_friction, Vec2 v, double x) {
        c.validate();
        { c.elastic_version(keep_friction) } -> std::same_as<C>;
        { c.against(wall) } -> std::same_as<C>;
        { c.q } -> std::convertible_to<double>;
        { c.frictional() } -> std::convertible_to<bool>;
        { c.template collide<true>(v, x, x, x, v, x, x, x, v) } -> EdCollisionResult;
        { c.template collide<false>(v, x, x, x, v, x, x, x, v) } -> EdCollisionResult;
    };

} // namespace granrepro

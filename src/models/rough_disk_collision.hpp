// Walton-Braun collision operator for rough inelastic disks (Luding 1998, Eqs. (1)-(6)).
//
// Two disks 1, 2 (radii a_i = d_i/2 [m], masses m_i [kg], moments of inertia I_i = q m_i a_i^2)
// touch with unit normal n = (r_1 - r_2)/|r_1 - r_2| (from 2 to 1). With the tangent t = perp(n)
// and scalar spins w_i [1/s] (z components), Eq. (1) reads in 2D
//     v_c = v_1 - v_2 - (a_1 w_1 + a_2 w_2) t ,
// and the impulse dP on disk 1 at its contact point r_1 - a_1 n changes (Eqs. (2)-(5))
//     v_1' = v_1 + dP/m_1,  w_1' = w_1 - a_1 (n x dP)/I_1,
//     v_2' = v_2 - dP/m_2,  w_2' = w_2 - a_2 (n x dP)/I_2,      (n x dP)_z = dP.t = dP_t .
// Inserting these into Eq. (1) gives the change of the contact velocity
//     dv_c,n = dP_n / m12,               1/m12 = 1/m_1 + 1/m_2,
//     dv_c,t = dP_t / m_t,               1/m_t = (1/m_1 + 1/m_2)(1 + 1/q).
// Demanding v_c,n' = -r v_c,n and v_c,t' = -beta v_c,t yields Eq. (6) in 2D:
//     dP = -m12 (1+r) v_c,n n - m12 q/(1+q) (1+beta) v_c,t t .
// (The paper prints 2/7 = q/(1+q) for solid spheres, q = 2/5; solid disks have q = 1/2.)
// Coulomb's law |dP_t| <= mu |dP_n| caps (1+beta):
//     1 + beta_1 = mu (1+r) (m12/m_t) |v_c,n| / |v_c,t| = mu (1+r) (1 + 1/q) |v_c,n| / |v_c,t| ,
// i.e. beta_1 = -1 - mu (1+r) (1 + 1/q) cot(gamma) with cot(gamma) = v_c,n/|v_c,t| < 0 for an
// approaching pair: the paper's expression. beta = min(beta0, beta1): sticking (beta = beta0) or
// sliding with |dP_t| = mu |dP_n| exactly. A wall is body 2 with m_2 = infinity (no spin).
// Energy change (used by the tests):
//     dE = -(1-r^2)/2 m12 v_c,n^2 - (1-beta^2)/2 m_t v_c,t^2 .
// Smooth disks (mu = 0 or beta0 = -1) give dP_t = 0 exactly: (1+beta) is formed as a minimum of
// non-negative terms, one of which is exactly zero, so no round-off spin appears.
//
// It is the ED engine's default operator (engines/ed/ed_collision_operator.hpp lists what the
// engine asks of one): validate(), elastic_version() (TC, Eq. (7)) and against() (a wall) below.
#pragma once
#include "data/fields.hpp"
#include "core/input_error.hpp"
#include "core/vec2.hpp"
#include <cmath>

namespace granrepro {

struct RoughDiskCollision {
    double r = 1.0;      // normal restitution [-], 0 <= r <= 1
    double mu = 0.0;     // Coulomb friction coefficient [-], >= 0
    double beta0 = -1.0; // maximal tangential restitution [-], -1 <= beta0 <= 1
    double q = 0.4;      // I = q m a^2 [-]; 2/5 reproduces the paper's 2/7, 1/2 = solid disks

    // The one list of parameters, walked by the state files (io/h5_fields.hpp).
    GRANREPRO_FIELDS(r, mu, beta0, q)

    struct Result {
        Vec2 dP;              // momentum change of body 1 [kg m/s]; body 2 receives -dP
        double dw1 = 0.0;     // spin change of body 1 [1/s]
        double dw2 = 0.0;     // spin change of body 2 [1/s] (0 for a wall)
        double beta = -1.0;   // tangential restitution actually applied [-]
        bool sliding = false; // true when Coulomb's limit was active (beta = beta_1 < beta0)
    };

    // Throws InputError unless 0 <= r <= 1, mu >= 0, -1 <= beta0 <= 1 and q > 0.
    void validate() const {
        if (!valid()) throw InputError("ED: need 0<=r<=1, mu>=0, -1<=beta0<=1, q>0");
    }
    // The operator of a collision the TC model (Luding Eq. (7)) makes elastic: r = 1, and unless
    // keep_friction (EdConfig::tc_keep_friction) no tangential impulse (mu = 0, beta0 = -1), so
    // that the collision conserves energy exactly.
    RoughDiskCollision elastic_version(bool keep_friction) const {
        RoughDiskCollision l = *this;
        l.r = 1.0;
        if (!keep_friction) { l.mu = 0.0; l.beta0 = -1.0; }
        return l;
    }
    // The operator against a wall (EdWall: its own r_w, mu_w, beta0_w; this q); throws
    // InputError when the wall's parameters are out of range.
    template <class Wall>
    RoughDiskCollision against(const Wall& w) const {
        const RoughDiskCollision l{w.r, w.mu, w.beta0, q};
        if (!l.valid()) throw InputError("ED: wall needs 0<=r<=1, mu>=0, -1<=beta0<=1");
        return l;
    }

    // True when the tangential impulse can be non-zero; the ED loop is instantiated separately
    // for the smooth case so that it skips the tangential algebra.
    bool frictional() const { return mu > 0.0 && beta0 > -1.0; }

    // v [m/s], w [1/s], m [kg] (m2 = +infinity for a wall), a radius [m], n unit normal 2 -> 1.
    // Only meaningful for an approaching contact (v_c . n < 0); the engine guarantees that.
    template <bool kFrictional = true>
    Result collide(const Vec2& v1, double w1, double m1, double a1, const Vec2& v2, double w2,
                   double m2, double a2, const Vec2& n) const {
        const double inv1 = 1.0 / m1;
        const double inv2 = std::isinf(m2) ? 0.0 : 1.0 / m2;
        const double m12 = 1.0 / (inv1 + inv2);
        const Vec2 t = perp(n);
        Result out;
        if constexpr (!kFrictional) {
            // Centre velocities suffice: spins do not enter v_c . n.
            const double vcn = dot(v1 - v2, n);
            out.dP = n * (-m12 * (1.0 + r) * vcn);
            (void)w1; (void)w2; (void)a1; (void)a2; (void)t;
            return out;
        } else {
            const Vec2 vc = v1 - v2 - t * (a1 * w1 + a2 * w2);
            const double vcn = dot(vc, n);
            const double vct = dot(vc, t);
            const double pn = -m12 * (1.0 + r) * vcn;
            double pt = 0.0;
            out.beta = beta0;
            if (vct != 0.0 && mu > 0.0 && beta0 > -1.0) {
                const double mt = 1.0 / ((inv1 + inv2) * (1.0 + 1.0 / q));
                const double stick = mt * (1.0 + beta0) * std::fabs(vct); // |dP_t| if sticking
                const double slide = mu * std::fabs(pn);                  // Coulomb bound
                if (stick <= slide) {
                    pt = -mt * (1.0 + beta0) * vct;
                } else {
                    pt = vct > 0.0 ? -slide : slide;
                    out.beta = -1.0 + slide / (mt * std::fabs(vct));
                    out.sliding = true;
                }
            } else if (!(mu > 0.0 && beta0 > -1.0)) {
                out.beta = -1.0;
            }
            out.dP = n * pn + t * pt;
            // w' = w - a (n x dP)/I with I = q m a^2  =>  dw = -dP_t/(q m a).
            out.dw1 = -pt * inv1 / (q * a1);
            out.dw2 = inv2 == 0.0 ? 0.0 : -pt * inv2 / (q * a2);
            return out;
        }
    }

private:
    bool valid() const { return r >= 0.0 && r <= 1.0 && mu >= 0.0 && beta0 >= -1.0 && beta0 <= 1.0 && q > 0.0; }
};

} // namespace granrepro

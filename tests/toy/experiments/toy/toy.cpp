// A toy experiment, the smallest complete one: the restitution of a head-on impact of a free grain
// on a fixed wall grain under Eq. (1)'s linear spring-dashpot of Schäfer & Wolf (1995), measured
// by the RK4 engine and compared with Eq. (4), e_N = exp(-gamma_N t_col / 2). It is not part of
// granrepro: tests/toy/toy_test.sh adds it to a copy of the data files, as ARCHITECTURE.md's worked
// example adds a figure, and runs it through the whole harness (run, check, figure, list).
#include <cmath>
#include <vector>

#include "data/fields.hpp"
#include "engines/soft/few_body_engine.hpp"
#include "experiments/common/columns.hpp"
#include "harness/protocol.hpp"
#include "models/coulomb_shear.hpp"
#include "models/linear_spring_dashpot.hpp"

namespace granrepro::experiments {
namespace toy_detail {

struct ToySpec {
    double k_N = 0, m = 0, d = 0;  // [N/m], [kg], [m]
    std::vector<double> eN_list;   // [1]
    double steps_per_contact = 0;  // [1]
    GRANREPRO_FIELDS(k_N, m, d, eN_list, steps_per_contact)
};

struct Shot { // one point: the e_N asked for and the one measured
    double e_N = 0, e_N_measured = 0;
    GRANREPRO_FIELDS(e_N, e_N_measured)
};

// Its outputs, each named once, by the handle the report writes through (data/outputs.hpp).
constexpr Outputs outputs{"toy"};
const TableOut out_toy = outputs.table("toy", "measured restitution against Eq. (4)'s");
const ScalarOut out_e_N_max_rel_error = outputs.scalar("e_N_max_rel_error", "1", "largest |e_N measured / e_N - 1| over the points");

struct Toy {
    static constexpr const char* name = outputs.experiment();
    using Spec = ToySpec;
    using Outcome = Shot;
    static void validate(const ParameterSet&) {}
    static std::vector<long> points(const Spec& s) { return index_order(s.eN_list.size()); }
    static Shot compute(const Spec& s, long i, const PointContext&) {
        const double e = s.eN_list[std::size_t(i)];
        const auto law = LinearSpringDashpot::from_restitution(s.k_N, e, s.m);
        FewBodyEngine<LinearSpringDashpot, CoulombShear> eng(law, CoulombShear{}, law.collision_time(s.m) / s.steps_per_contact);
        eng.add_free({{s.d + 1e-9, 0.0}, {-1.0, 0.0}, 0.5 * s.d, s.m});
        eng.add_fixed({{0.0, 0.0}, 0.5 * s.d});
        for (long step = 0; step < 1'000'000 && eng.events().size() < 2; ++step) eng.step();
        const auto& ev = eng.events();
        return {e, ev.size() < 2 ? NAN : -ev[1].xi_dot / ev[0].xi_dot};
    }
    static Result report(const Spec&, const Swept<Shot>& swept, const RunContext&) {
        Result r;
        Table& t = r.table(out_toy);
        t.add({{"e_N", "1", column(swept.outcomes, &Shot::e_N)},
               {"e_N_measured", "1", column(swept.outcomes, &Shot::e_N_measured)}});
        double worst = 0;
        for (const Shot& o : swept.outcomes) worst = std::max(worst, std::abs(o.e_N_measured / o.e_N - 1));
        r.put(out_e_N_max_rel_error, worst);
        return r;
    }
};

} // namespace toy_detail

Experiment toy() { return protocol_experiment<toy_detail::Toy>(); }

} // namespace granrepro::experiments

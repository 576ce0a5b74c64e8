// An experiment as a typed protocol that the harness drives (issue 28). A driver states its
// parameters (Spec), its sweep points in cost order, how one point is computed and how the
// outcomes are reported; the harness reads the spec, runs the sweep (threads, MPI ranks, --points
// shards, gather, verify: harness/distributed_sweep.hpp), serializes each Outcome through its
// fields() into point files that carry a hash of the Outcome's layout (a point saved by a build
// whose Outcome had other fields is recomputed on resume, not misread), resumes, and hands the
// outcomes to report. A driver therefore includes no io/ header and never sees the exceptions that
// end a rank's or a shard's part of a sweep.
//
//   struct MyExperiment {
//       static constexpr const char* name = "my-experiment"; // subcommand, TOML, sweep label
//       using Spec = ...;    // fields(): read once from the resolved parameters (data/spec.hpp)
//       using Outcome = ...; // fields(): what one point returns; its point file holds exactly this
//       static void validate(const ParameterSet&);            // relations between parameters
//       static std::vector<long> points(const Spec&);         // every index once, costliest first
//       static Outcome compute(const Spec&, long i, const PointContext&);
//       static Result report(const Spec&, const Swept<Outcome>&, const RunContext&);
//       // optional:
//       using Shared = ...; static Shared prepare(const Spec&, const RunContext&);
//       //   work every point needs, made once per process before the sweep; then points, compute
//       //   and report take (const Spec&, const Shared&, ...)
//       static constexpr PointFiles files = PointFiles::None; // millisecond points: no point files
//       static constexpr bool distributed = false;            // rank 0 alone (no files, no shards)
//   };
//   Experiment my_experiment() { return protocol_experiment<MyExperiment>(); }
//
// A point's random streams must depend on its index and the run's seed only.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "core/stable_hash.hpp"
#include "data/spec.hpp"
#include "harness/distributed_sweep.hpp"
#include "harness/experiment.hpp"
#include "io/json_fields.hpp"

namespace granrepro {

// What compute() may use besides the spec: the run's seed, its mid-run checkpoints (RunCheckpoint
// takes it) and whether to be quiet.
using PointContext = RunContext;

// Every point's outcome, indexed by point, as read back from its JSON (bit-identical however the
// points were spread or resumed). How many were resumed the harness records itself (summary.json
// `resumed_points`), so no report writes it.
template <class Outcome>
struct Swept {
    std::vector<Outcome> outcomes;
};

namespace protocol_detail {

struct NoShared {};

template <class E>
concept HasShared = requires { typename E::Shared; };

template <class E>
struct SharedOf { using type = NoShared; };
template <HasShared E>
struct SharedOf<E> { using type = typename E::Shared; };

template <class E>
using Shared = typename SharedOf<E>::type;

template <class E>
Shared<E> prepare(const typename E::Spec& spec, const RunContext& ctx) {
    if constexpr (HasShared<E>) return E::prepare(spec, ctx);
    else return {};
}

// The protocol's three calls with or without the shared part.
template <class E>
std::vector<long> points(const typename E::Spec& spec, const Shared<E>& shared) {
    if constexpr (HasShared<E>) return E::points(spec, shared);
    else return E::points(spec);
}
template <class E>
typename E::Outcome compute(const typename E::Spec& spec, const Shared<E>& shared, long i, const PointContext& ctx) {
    if constexpr (HasShared<E>) return E::compute(spec, shared, i, ctx);
    else return E::compute(spec, i, ctx);
}
template <class E>
Result report(const typename E::Spec& spec, const Shared<E>& shared, const Swept<typename E::Outcome>& swept,
              const RunContext& ctx) {
    if constexpr (HasShared<E>) return E::report(spec, shared, swept, ctx);
    else return E::report(spec, swept, ctx);
}

template <class E>
constexpr PointFiles files() {
    if constexpr (requires { E::files; }) return E::files;
    else return PointFiles::Saved;
}
template <class E>
constexpr bool distributed() {
    if constexpr (requires { E::distributed; }) return E::distributed;
    else return files<E>() == PointFiles::Saved;
}

// The harness's run(): spec, shared work, the sweep through JSON, the report.
template <class E>
Result run(const RunContext& ctx) {
    using Outcome = typename E::Outcome;
    const auto spec = read_spec<typename E::Spec>(ctx.params);
    const Shared<E> shared = prepare<E>(spec, ctx);
    static const std::string schema = "fnv1a64:" + hex64(fnv1a64(json_fields_schema<Outcome>()));
    const SweepResult swept = distributed_sweep(
        ctx, E::name, points<E>(spec, shared),
        [&](long i) { return to_json_fields(compute<E>(spec, shared, i, ctx)); }, files<E>(), schema);
    Swept<Outcome> out;
    out.outcomes.reserve(swept.points.size());
    // `verify` aggregates the stored outcomes of an earlier build, which may lack fields added since.
    const bool stored = ctx.sweep.mode == SweepPlan::Mode::Verify;
    for (const auto& j : swept.points)
        out.outcomes.push_back(stored ? from_json_fields_lenient<Outcome>(j) : from_json_fields<Outcome>(j));
    return report<E>(spec, shared, out, ctx);
}

} // namespace protocol_detail

template <class E>
Experiment protocol_experiment() {
    return {E::name, &E::validate, &protocol_detail::run<E>, protocol_detail::distributed<E>()};
}

} // namespace granrepro

// The one sample-and-checkpoint loop of a single long run, trigger-driven as in HOOMD-blue: the
// driver declares when to sample (a trigger: sample index -> time, or none when done) and what a
// sample records; this loop advances the engine, calls the sampler, reports engine time to the
// progress line, and saves a checkpoint whenever RunCheckpoint's wall-time trigger is due.
//
// Everything the run carries between samples (traces, observer state) is the driver's `Carry`
// struct, which lists its fields once (io/h5_fields.hpp). The checkpoint file holds the engine
// state (group "engine"), the carry (group "carry"), the next sample index and the wall seconds
// spent so far, under the driver's schema name; a resumed run is bit-identical to an
// uninterrupted one because engine states restore bit for bit and the carry is walked field by
// field in both directions.
//
//   SampledRun<Trace> run(checkpoint, "granrepro-cooling-run", 3);
//   EdState saved;
//   if (run.resume(saved, trace)) engine.restore_state(saved);
//   run.run(engine, trace, [&](long i) { return i < n ? std::optional(times[i]) : std::nullopt; },
//           observer, [&](long i, double t) { ...record...; return false; /* true: stop */ });
//
// A run short enough to redo whole (a sweep point is the unit of resumption) uses the same loop
// without a checkpoint: SampledRun<> run; run.run(engine, trigger, observer, sample, t_end).
// Any engine with run_until(t, observer) fits; a time-stepped engine is given one by an adapter.
#pragma once
#include <chrono>
#include <cmath>
#include <concepts>
#include <optional>
#include <string>
#include <utility>

#include "harness/progress.hpp"
#include "harness/run_checkpoint.hpp"
#include "io/engine_state_file.hpp"
#include "io/h5_fields.hpp"

namespace granrepro {

// The carry of a run without a checkpoint.
struct NoCarry {
    template <class V>
    void fields(V&&) {}
};

template <HasFields Carry = NoCarry>
class SampledRun {
public:
    SampledRun() requires std::same_as<Carry, NoCarry> : start_(std::chrono::steady_clock::now()) {}
    SampledRun(RunCheckpoint& checkpoint, std::string schema, long version)
        : checkpoint_(&checkpoint), schema_(std::move(schema)), version_(version), start_(std::chrono::steady_clock::now()) {}

    // Loads the checkpoint, if there is one, into `engine_state` and `carry` and returns true.
    // Reads into temporaries first: a file that fails half-way leaves the fresh start intact.
    template <class State>
    bool resume(State& engine_state, Carry& carry) {
        State state;
        Carry saved;
        long next = 0;
        double wall = 0;
        const bool resumed = checkpoint_->load([&](const H5Object& root) {
            root.require_schema(schema_, version_);
            next = root.read_long_attr("next_sample");
            wall = root.read_double_attr("wall_seconds");
            read_engine_state(root.open_group("engine"), state);
            read_fields(root.open_group("carry"), saved);
        });
        if (!resumed) return false;
        engine_state = std::move(state);
        carry = std::move(saved);
        next_ = next;
        wall_before_ = wall;
        return true;
    }

    // Samples at trigger(i) for i = next_sample(), next_sample() + 1, ... until the trigger gives
    // no time or sample(i, t) returns true. observer sees every collision on the way. The progress
    // line shows t of t_report_end [s]; NaN when the trigger counts something else (collisions).
    template <class Engine, class Trigger, class Observer, class Sample>
    void run(Engine& engine, Carry& carry, Trigger&& trigger, Observer&& observer, Sample&& sample,
             double t_report_end) {
        for (long i = next_;; ++i) {
            const std::optional<double> t = trigger(i);
            if (!t) break;
            engine.run_until(*t, observer);
            if (!std::isnan(t_report_end)) report_engine_time(*t, t_report_end);
            const bool stop = sample(i, *t);
            next_ = i + 1;
            if (stop) break;
            if constexpr (!std::same_as<Carry, NoCarry>)
                if (checkpoint_->due()) save(engine, carry);
        }
    }

    template <class Engine, class Trigger, class Observer, class Sample>
    void run(Engine& engine, Trigger&& trigger, Observer&& observer, Sample&& sample, double t_report_end)
        requires std::same_as<Carry, NoCarry>
    {
        NoCarry none;
        run(engine, none, trigger, observer, sample, t_report_end);
    }

    long next_sample() const { return next_; }
    // Wall seconds of this run, earlier interrupted parts included [s].
    double wall_seconds() const {
        return wall_before_ + std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    template <class Engine>
    void save(const Engine& engine, const Carry& carry) {
        checkpoint_->save([&](const H5Object& root) {
            root.stamp_schema(schema_, version_);
            root.attr("next_sample", next_);
            root.attr("wall_seconds", wall_seconds());
            write_engine_state(root.group("engine"), engine.save_state());
            write_fields(root.group("carry"), carry);
        });
    }

    RunCheckpoint* checkpoint_ = nullptr;
    std::string schema_;
    long version_ = 0;
    long next_ = 0;
    double wall_before_ = 0;
    std::chrono::steady_clock::time_point start_;
};

} // namespace granrepro

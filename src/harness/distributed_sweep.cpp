#include "harness/distributed_sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>
#include <time.h>
#include <unistd.h>

#include "core/input_error.hpp"
#include "core/interrupt.hpp"
#include "core/stable_hash.hpp"
#include "harness/mpi_world.hpp"
#include "harness/progress.hpp"
#include "harness/run_checkpoint.hpp"
#include "harness/run_log.hpp"
#include "harness/sweep_checkpoint.hpp"

#ifdef GRANREPRO_HAVE_MPI
#include <mpi.h>
#endif

namespace granrepro {

namespace {

// Threads of a rank > 0 that fetch points, each with its own message tag (1 + thread).
int serving_threads(const RunContext& ctx) { return mpi::threads_may_call_mpi() ? std::max(1, ctx.threads) : 1; }

timespec clock_now(clockid_t clock) {
    timespec ts{};
    clock_gettime(clock, &ts);
    return ts;
}

// Seconds of `clock`. CLOCK_THREAD_CPUTIME_ID: a point's cost, unaffected by other processes
// sharing the cores (what `granrepro bench sweep` projects rank counts from).
double seconds(clockid_t clock) {
    const timespec ts = clock_now(clock);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// This process's id among the invocations that computed a sweep's points (a resumed run, shards):
// 16 hex digits from the pid and the time of the first call.
const std::string& part_id() {
    static const timespec ts = clock_now(CLOCK_REALTIME);
    static const std::string id =
        hex64(fnv1a64(std::to_string(::getpid()) + " " + std::to_string(ts.tv_sec) + "." + std::to_string(ts.tv_nsec)));
    return id;
}

// compute(i) and its cost (CPU s of this thread, wall s, start time).
std::pair<nlohmann::json, PointCost> timed(const std::function<nlohmann::json(long)>& compute, long i) {
    PointCost cost;
    cost.started_unix = seconds(CLOCK_REALTIME);
    cost.part = part_id();
    cost.rank = mpi::rank();
    const auto w0 = std::chrono::steady_clock::now();
    const double c0 = seconds(CLOCK_THREAD_CPUTIME_ID);
    nlohmann::json value = compute(i);
    cost.cpu_s = seconds(CLOCK_THREAD_CPUTIME_ID) - c0;
    cost.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    return {std::move(value), cost};
}

[[noreturn]] void point_failed(long i, const char* what) {
    std::fprintf(stderr, "granrepro: rank %d: sweep point %ld failed: %s\n", mpi::rank(), i, what);
    mpi::abort(1);
}

#ifdef GRANREPRO_HAVE_MPI
// Waits without spinning: OpenMPI's blocking calls poll at 100 % CPU, which would take a core
// from the ranks that compute.
void wait_for(MPI_Request& request) {
    for (int done = 0;;) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) return;
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
}

// The end of one sweep on every rank. Without it a rank that rank 0 has released runs ahead into
// the next experiment's sweep (`all`) and its first request would reach rank 0 while rank 0 still
// waits for this sweep's last results: rank 0 would count it as this sweep's and stop early.
// Non-blocking, so that waiting ranks do not poll a core away from those still computing.
void end_of_sweep() {
    MPI_Request request;
    MPI_Ibarrier(MPI_COMM_WORLD, &request);
    wait_for(request);
}

// Rank > 0: each thread asks rank 0 for a point, computes it, sends the result with the next
// request ("<index> <CPU seconds> <wall seconds> <start unix s> <part> <json>"), until rank 0
// answers -1.
void serve_points(const RunContext& ctx, const std::function<nlohmann::json(long)>& compute) {
    auto worker = [&](int thread) {
        const int tag = 1 + thread;
        std::string message = "-1";
        for (;;) {
            MPI_Request request;
            MPI_Isend(message.data(), int(message.size()), MPI_CHAR, 0, tag, MPI_COMM_WORLD, &request);
            wait_for(request);
            long long next = -1;
            MPI_Irecv(&next, 1, MPI_LONG_LONG, 0, tag, MPI_COMM_WORLD, &request);
            wait_for(request);
            if (next < 0) return;
            try {
                auto [value, cost] = timed(compute, long(next));
                char head[160];
                std::snprintf(head, sizeof head, "%lld %.17g %.17g %.17g %s ", next, cost.cpu_s, cost.wall_s,
                              cost.started_unix, cost.part.c_str());
                message = head + value.dump();
            } catch (const std::exception& e) {
                point_failed(long(next), e.what());
            }
        }
    };
    const int n = serving_threads(ctx);
    std::vector<std::thread> pool;
    for (int t = 1; t < n; ++t) pool.emplace_back(worker, t);
    worker(0);
    for (auto& th : pool) th.join();
}
#endif

// `verify`: compute the one point asked for (harness/verify.hpp); with aggregate, return every
// point, the others as the results stored them, else end the sweep with PointRerunDone.
SweepResult rerun_point(const RunContext& ctx, const std::string& label, long n,
                        const std::function<nlohmann::json(long)>& compute) {
    PointRerun& v = *ctx.sweep.rerun;
    if (label != v.sweep)
        throw InputError("verify: the results store sweep '" + v.sweep + "' but the experiment now sweeps '" + label + "'");
    if (v.point < 0 || v.point >= n)
        throw InputError("--point " + std::to_string(v.point) + ": the sweep " + label + " now has " + std::to_string(n) +
                         " points (0 to " + std::to_string(n - 1) + ")");
    v.count = n;
    v.inputs = sweep_point_inputs_hash(ctx, label, v.point, n, v.fingerprint_without);
    auto [value, cost] = timed(compute, v.point);
    v.outcome = nlohmann::json::parse(value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    v.cost = cost;
    v.computed = true;
    if (!v.aggregate) throw PointRerunDone{};
    SweepResult out;
    out.cpu_seconds.assign(std::size_t(n), -1.0);
    for (long i = 0; i < n; ++i) {
        if (i == v.point) out.points.push_back(v.outcome);
        else if (const auto it = v.stored.find(i); it != v.stored.end()) out.points.push_back(it->second);
        else throw InputError("verify: the results do not store point " + std::to_string(i) + " of sweep " + label);
    }
    return out;
}

// The points of one sweep as this process holds them: read from the checkpoint or computed here
// or by another rank. store() is the one place a finished point goes (thread-safe).
class SweepState {
public:
    SweepState(const RunContext& ctx, const std::string& label, long n, PointFiles files, const std::string& outcome_schema)
        : label_(label), have_(std::size_t(n), 0), costs_(std::size_t(n)) {
        if (files == PointFiles::Saved) checkpoint_.emplace(ctx, label, outcome_schema);
        out.points.resize(std::size_t(n));
        out.cpu_seconds.assign(std::size_t(n), -1.0);
        for (long i = 0; i < n; ++i)
            if (auto saved = checkpoint_ ? checkpoint_->load(i) : std::nullopt) {
                out.points[std::size_t(i)] = std::move(saved->value);
                costs_[std::size_t(i)] = saved->cost;
                have_[std::size_t(i)] = 1;
                ++out.resumed; // not computed again
            }
        if (out.resumed > 0)
            run_log().line("sweep " + label + ": " + std::to_string(out.resumed) + " of " + std::to_string(n) +
                           " points read from the checkpoint");
        // Test hook, like GRANREPRO_INTERRUPT_AFTER_CHECKPOINTS: end the job (every rank) once
        // this many points have been computed and saved, as a killed job would.
        const char* stop_env = std::getenv("GRANREPRO_INTERRUPT_AFTER_POINTS");
        stop_after_ = stop_env ? std::atol(stop_env) : 0;
    }
    bool resumed(long i) const { return have_[std::size_t(i)] != 0; }

    // The points to compute here, in cost order (a shard: every shards-th of the missing ones);
    // `gather` computes none and refuses to go on with points missing.
    std::vector<long> todo(const SweepPlan& plan, const std::vector<long>& order) const {
        const long n = long(order.size());
        std::vector<long> todo, missing;
        for (long s = 0; s < n; ++s) {
            const long i = order[std::size_t(s)];
            if (have_[std::size_t(i)]) continue;
            missing.push_back(i);
            if (plan.mode == SweepPlan::Mode::Shard && s % plan.shards != plan.shard - 1) continue;
            todo.push_back(i);
        }
        if (plan.mode != SweepPlan::Mode::Gather || missing.empty()) return todo;
        std::sort(missing.begin(), missing.end());
        std::string list;
        for (std::size_t k = 0; k < missing.size() && k < 20; ++k) list += (k ? ", " : "") + std::to_string(missing[k]);
        if (missing.size() > 20) list += ", ...";
        throw InputError(label_ + ": " + std::to_string(missing.size()) + " point" + (missing.size() == 1 ? "" : "s") +
                         " missing: " + list + " (of " + std::to_string(n) +
                         "; run the missing --points shards with the same flags, then gather again)");
    }

    void store(long i, nlohmann::json value, const PointCost& cost, Progress& progress) {
        std::lock_guard<std::mutex> lock(mutex_); // also makes the interruption hook exact
        if (checkpoint_) checkpoint_->save(i, value, cost);
        out.points[std::size_t(i)] = std::move(value);
        out.cpu_seconds[std::size_t(i)] = cost.cpu_s;
        costs_[std::size_t(i)] = cost;
        char text[160];
        std::snprintf(text, sizeof text, "sweep %s: point %ld cost %.6g CPU s (rank %d)", label_.c_str(), i, cost.cpu_s,
                      cost.rank);
        run_log().line(text);
        progress.done(i);
        if (++computed == stop_after_) {
            std::fprintf(stderr, "granrepro: %s: interrupted after point %ld (GRANREPRO_INTERRUPT_AFTER_POINTS)\n",
                         label_.c_str(), computed);
            mpi::abort(3);
        }
    }

    // Every point, computed or resumed, as the results store it (data.h5 /points).
    void record(const RunContext& ctx, PointFiles files) const {
        if (!ctx.points) return;
        const long n = long(out.points.size());
        for (long i = 0; i < n; ++i) {
            SweepPoint p;
            p.sweep = label_;
            p.index = i;
            p.inputs = sweep_point_inputs_hash(ctx, label_, i, n);
            p.outcome = out.points[std::size_t(i)];
            p.cost = costs_[std::size_t(i)];
            p.resumed = resumed(i);
            p.persisted = files == PointFiles::Saved;
            ctx.points->points.push_back(std::move(p));
        }
    }

    SweepResult out;
    long computed = 0;

private:
    std::string label_;
    std::optional<SweepCheckpoint> checkpoint_;
    std::vector<char> have_;
    std::vector<PointCost> costs_;
    long stop_after_ = 0;
    std::mutex mutex_;
};

#ifdef GRANREPRO_HAVE_MPI
// Rank 0's main thread hands out points: each request carries the sender's previous result
// ("<index> <cpu> <wall> <start> <part> <json>", or "-1" for none); the answer is the next index
// or -1. Idle, it polls with a growing pause (0.2 ms to 20 ms): points take seconds, and a fixed
// 0.2 ms poll kept this thread at 70 % of the core its own compute thread shares (mpirun binds a
// rank to one core).
void hand_out_points(const RunContext& ctx, const std::function<long()>& dispense,
                     const std::function<void(long, nlohmann::json, const PointCost&)>& store) {
    const long serving = long(ctx.sweep.ranks - 1) * serving_threads(ctx);
    auto pause = std::chrono::microseconds(200);
    for (long stopped = 0; stopped < serving;) {
        int flag = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
        if (!flag) {
            std::this_thread::sleep_for(pause);
            pause = std::min(2 * pause, std::chrono::microseconds(20000));
            continue;
        }
        pause = std::chrono::microseconds(200);
        int bytes = 0;
        MPI_Get_count(&status, MPI_CHAR, &bytes);
        std::string message(std::size_t(bytes), '\0');
        MPI_Recv(message.data(), bytes, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        std::istringstream in(message);
        long done = -1;
        in >> done;
        if (done >= 0) {
            PointCost cost;
            in >> cost.cpu_s >> cost.wall_s >> cost.started_unix >> cost.part;
            cost.rank = status.MPI_SOURCE;
            store(done, nlohmann::json::parse(in), cost);
        }
        long long give = dispense();
        MPI_Request request;
        MPI_Isend(&give, 1, MPI_LONG_LONG, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, &request);
        wait_for(request);
        if (give < 0) ++stopped;
    }
    end_of_sweep();
}
#endif

} // namespace

SweepResult distributed_sweep(const RunContext& ctx, const std::string& label, const std::vector<long>& order,
                              const std::function<nlohmann::json(long)>& compute, PointFiles files,
                              const std::string& outcome_schema) {
    const bool spread = ctx.sweep.ranks > 1;
#ifdef GRANREPRO_HAVE_MPI
    if (spread && mpi::rank() != 0) {
        serve_points(ctx, compute);
        end_of_sweep();
        throw SweepServed{};
    }
#endif
    const long n = long(order.size());
    if (ctx.sweep.mode == SweepPlan::Mode::Verify) return rerun_point(ctx, label, n, compute);
    SweepState state(ctx, label, n, files, outcome_schema);
    const SweepPlan& plan = ctx.sweep;
    const std::vector<long> todo = state.todo(plan, order);

    Progress progress(label, long(todo.size()), ctx.quiet);
    std::mutex mutex;
    std::size_t next = 0;
    std::exception_ptr error;
    // After SIGINT/SIGTERM no further point is handed out; the points under way finish and are
    // saved, so the rerun computes only the rest. A point that its engine loop stops (it did not
    // finish within kEnginePauseSeconds: a long point, a loaded machine) is abandoned and left for
    // the rerun like the points not handed out, so the run ends the same way whatever the timing.
    // (A point that saved a final checkpoint of its own ends the run with that point's message.)
    auto dispense = [&]() -> long {
        std::lock_guard<std::mutex> lock(mutex);
        return next < todo.size() && !interrupt_requested() ? todo[next++] : -1;
    };
    auto store = [&](long i, nlohmann::json value, const PointCost& cost) { state.store(i, std::move(value), cost, progress); };
    auto local = [&] {
        long i = -1;
        try {
            while ((i = dispense()) >= 0) {
                const ProgressSlot slot(&progress, i); // the point's engine time shows in the progress line
                auto [value, cost] = timed(compute, i);
                store(i, std::move(value), cost);
            }
        } catch (const EngineLoopInterrupted&) {
            std::lock_guard<std::mutex> lock(mutex);
            next = todo.size();
        } catch (const std::exception& e) {
            if (spread) point_failed(i, e.what());
            std::lock_guard<std::mutex> lock(mutex);
            if (!error) error = std::current_exception();
            next = todo.size();
        }
    };
    const int threads = std::max(1, std::min<int>(ctx.threads, int(todo.size())));
    std::vector<std::thread> pool;
    for (int t = spread ? 0 : 1; t < threads; ++t) pool.emplace_back(local);
#ifdef GRANREPRO_HAVE_MPI
    if (spread) hand_out_points(ctx, dispense, store);
    else
#endif
        local();
    for (auto& th : pool) th.join();
    if (error) std::rethrow_exception(error);
    if (state.computed < long(todo.size()))
        throw_if_interrupted("; " + std::to_string(long(todo.size()) - state.computed) + " of " + std::to_string(n) +
                             " sweep points left for the rerun");
    if (plan.mode == SweepPlan::Mode::Shard) {
        long present = 0;
        for (const auto& j : state.out.points) present += !j.is_null();
        throw ShardFinished(label + ": shard " + std::to_string(plan.shard) + "/" + std::to_string(plan.shards) + ": " +
                            std::to_string(todo.size()) + " point" + (todo.size() == 1 ? "" : "s") + " computed, " +
                            std::to_string(present) + " of " + std::to_string(n) +
                            " in the checkpoint; `granrepro gather " + label + "` with the same flags writes the results");
    }
    state.record(ctx, files);
    return std::move(state.out);
}

} // namespace granrepro

// Every sweep point of a run, as stored in its results (data.h5 `/points`, docs/schema.md): the
// point's outcome (the JSON the experiment built its tables from), a fingerprint of its inputs
// and what it cost. `granrepro verify` reruns one point and compares it with the stored outcome.
// Filled by harness/distributed_sweep (computed and resumed points alike), written by io.
#pragma once
#include <cstdint>
#include <exception>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace granrepro {

// What one point cost, where and when it was computed. Resumed points keep the cost recorded
// when they were computed (in the checkpoint file); -1 / NaN where that is not known (point files
// written before costs were recorded).
struct PointCost {
    double cpu_s = -1;        // CPU seconds of the thread that computed it
    double wall_s = -1;       // wall seconds it took
    double started_unix = -1; // when it started [s since 1970-01-01 UTC]
    std::string part;         // which invocation computed it (a process's id: 16 hex digits)
    int rank = 0;             // MPI rank that computed it
};

struct SweepPoint {
    std::string sweep;      // the sweep's label (the experiment's name for the one sweep most have)
    long index = 0;         // point index as compute(i) got it
    std::string inputs;     // "fnv1a64:<hex>" of the point's inputs (sweep_point_inputs_hash)
    nlohmann::json outcome; // compute(i)'s value
    PointCost cost;
    bool resumed = false;   // read from an earlier invocation's checkpoint
    bool persisted = true;  // false: a sweep without point files (brake-failure, emergency-brake)
};

struct SweepPoints {
    std::vector<SweepPoint> points; // in the order the sweeps ran, each sweep by index
};

// `granrepro verify`: rerun one point of a stored sweep (SweepPlan::Mode::Verify). The sweep
// computes only `point`; if `aggregate`, it returns every point (the others from `stored`) so
// the experiment builds its scalars as the run did, else it throws PointRerunDone.
struct PointRerun {
    std::string sweep;                    // the label of the sweep that holds the point
    long point = 0;
    bool aggregate = false;
    std::map<long, nlohmann::json> stored; // the other points' outcomes, for aggregate
    std::vector<std::string> fingerprint_without; // parameters left out of `inputs` (added since the results)
    // Filled by the sweep:
    bool computed = false;
    long count = 0;          // points in the sweep
    std::string inputs;      // the point's inputs fingerprint now
    nlohmann::json outcome;  // as the results store it (through JSON text)
    PointCost cost;
};

struct PointRerunDone : std::exception {
    const char* what() const noexcept override { return "sweep point recomputed"; }
};

} // namespace granrepro

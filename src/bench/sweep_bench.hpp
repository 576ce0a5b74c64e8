// `granrepro bench sweep`: what spreading a sweep over MPI ranks buys. Measures the wall time of
// one experiment's sweep with 1 rank and with --ranks ranks (medians of --repeats runs), reads
// each point's CPU cost from the 1-rank run's run.log, and projects 2 to 256 ranks from those
// costs (Amdahl: the serial part plus the makespan of handing points out longest first, which is
// bounded by the longest point). `--from-log run.log...` projects from earlier runs instead,
// e.g. paper-scale runs too long to repeat; given every experiment's run.log it projects `all`.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_options.hpp"

namespace granrepro {

struct SweepCosts {
    std::string name;         // the experiment (the run.log's folder)
    std::vector<double> cost; // per computed point [CPU s]; none for an experiment without a sweep
    double wall = 0;          // the run's wall time [s]
    double cpu = -1;          // its CPU time, all threads [s]; -1 where the log does not say
    double serial() const;    // wall time outside the points [s]
    double projected(int ranks) const; // serial + makespan on `ranks` ranks [s]
};

// The "sweep <label>: point <i> cost <s> CPU s" and "run finished: wall time <s> s, CPU <s> s" lines of a
// run.log (a finished run; an experiment without a distributed sweep has no point lines).
SweepCosts read_sweep_costs(const std::filesystem::path& run_log);
// Wall time of the points on `ranks` workers that take them longest first as they become free [s].
double projected_makespan(const std::vector<double>& cost, int ranks);
// The projection of one run or of several run one after another (`all`: one run.log each).
void print_projection(const std::vector<SweepCosts>& runs, const std::vector<int>& ranks);
void bench_sweep_report(const BenchOptions& opt);

} // namespace granrepro

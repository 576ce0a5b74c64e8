// What `granrepro bench <target>` was asked for: repeats, duration and per-target options.
#pragma once
#include <string>
#include <vector>

namespace granrepro {

struct BenchOptions {
    int repeats = 5;
    double seconds = 2.0;
    long steps = 0;     // soft: time steps of one timed run (0: the target's default)
    bool sizes = false; // soft: cost against the number of grains instead of the LAMMPS comparison
    bool speeds = false; // soft: cost and list builds against the flow speed (1, 20, 200 m/s)
    std::string experiment = "bistable-pipe"; // sweep: a sweeping experiment
    std::string scale = "quick";              // sweep: quick or paper
    int ranks = 2;                            // sweep: MPI ranks compared with one
    std::vector<std::string> from_log;        // sweep: project from these run.log files instead of running
};

} // namespace granrepro

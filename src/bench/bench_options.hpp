// What `granrepro bench <target>` was asked for: repeats, duration and per-target options.
#pragma once

namespace granrepro {

struct BenchOptions {
    int repeats = 5;
    double seconds = 2.0;
    long steps = 0;     // soft: time steps of one timed run (0: the target's default)
    int threads = 2;    // soft: threads of the multi-core comparison
    bool sizes = false; // soft: cost against the number of grains instead of the LAMMPS comparison
};

} // namespace granrepro

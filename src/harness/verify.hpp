// `granrepro verify`: rerun one stored sweep point of a results folder (paper_figures/ by default)
// with the run's recorded parameters (the experiments/<name>.toml text stored in data.h5, the
// --set overrides, seed and scale) and compare it with the stored outcome (data.h5 /points,
// schema 3). Where every other point of the sweep is stored in full, the experiment then builds
// its scalars from the recomputed point and the stored others, so a moved value is traced to
// the scalars and claims that read it. Results without stored points are refused.
// Same code version: bit for bit. Another version: value by value, with the differences.
#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace granrepro {

struct VerifyOptions {
    std::string experiment;
    std::filesystem::path out = "paper_figures";
    std::optional<long> point; // none: the cheapest stored point (by recorded CPU cost)
    bool list = false;         // list the stored points and their costs, rerun nothing
    bool point_only = false;   // compare the point alone; do not rebuild the scalars from it and the stored others
    int threads = 1;
};

// 0: reproduced (bit for bit); 1: a value differs (listed); InputError (exit 2) for bad input or
// results that cannot be verified.
int verify_experiment(const VerifyOptions& opt);

} // namespace granrepro

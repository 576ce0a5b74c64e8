#pragma once
#include <cstddef>

namespace granrepro {

// Latency [ns] of one dependent load at a random cache line of a `bytes` large block, allocated
// like the ED engine's arrays (huge pages): a pointer chase over a random cyclic permutation.
// This is the price of a cache miss at a given working set, which is what bounds the ED engine
// at large N (one event touches a random particle and its neighbours).
double dependent_load_latency_ns(std::size_t bytes);

} // namespace granrepro

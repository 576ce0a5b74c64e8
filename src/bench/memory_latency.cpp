#include "bench/memory_latency.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

#include "engines/ed/huge_page_allocator.hpp"

namespace granrepro {

double dependent_load_latency_ns(std::size_t bytes) {
    constexpr std::size_t kLine = 64 / sizeof(std::size_t);
    const std::size_t lines = std::max<std::size_t>(2, bytes / 64);
    HugeVector<std::size_t> chain(lines * kLine);
    std::vector<std::size_t> order(lines);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::shuffle(order.begin(), order.end(), std::mt19937_64(1));
    for (std::size_t k = 0; k < lines; ++k) chain[order[k] * kLine] = order[(k + 1) % lines] * kLine;
    std::size_t p = 0;
    for (std::size_t k = 0; k < lines; ++k) p = chain[p]; // warm up: one full cycle
    const long steps = 4'000'000;
    const auto t0 = std::chrono::steady_clock::now();
    for (long k = 0; k < steps; ++k) p = chain[p];
    const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (p == std::size_t(-1)) std::printf(" "); // keep the chase from being optimised away
    return dt / steps * 1e9;
}

} // namespace granrepro

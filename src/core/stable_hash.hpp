// A hash that is the same on every toolchain and every run, for names that outlive the process
// (checkpoint fingerprints, the integrity stamp of sweep-point files). std::hash may differ between
// standard libraries and versions, so a checkpoint written by one build could be ignored (or, worse,
// matched wrongly) by another.
// FNV-1a, 64 bit (Fowler, Noll, Vo; http://www.isthe.com/chongo/tech/comp/fnv/):
//   h_0 = 14695981039346656037,  h_{i+1} = (h_i XOR byte_i) * 1099511628211  (mod 2^64).
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace granrepro {

constexpr std::uint64_t kFnv1a64Start = 14695981039346656037ULL;

// `h` continues a hash over more bytes: fnv1a64(b, fnv1a64(a)) == fnv1a64(a + b), without the copy.
constexpr std::uint64_t fnv1a64(std::string_view bytes, std::uint64_t h = kFnv1a64Start) {
    for (const char c : bytes) {
        h ^= std::uint64_t(static_cast<unsigned char>(c));
        h *= 1099511628211ULL;
    }
    return h;
}

// 16 lower-case hex digits.
inline std::string hex64(std::uint64_t h) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

} // namespace granrepro

// A seeded random stream. Engines never touch a global generator: every stochastic object owns
// an RngStream derived from the run seed and a stream index, so that sweep points and threads
// draw independent, reproducible numbers (same seed + index => same sequence on the same build).
// The generator itself is GSL's MT19937; its raw state can be saved for checkpoints.
#pragma once
#include <algorithm>
#include <cstdint>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <memory>
#include <stdexcept>
#include <vector>

namespace granrepro {

// SplitMix64 finaliser: turns (seed, stream index) into a well-mixed 64-bit seed.
constexpr std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t stream) {
    std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (stream + 1);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

class RngStream {
public:
    RngStream(std::uint64_t seed, std::uint64_t stream)
        : rng_(gsl_rng_alloc(gsl_rng_mt19937), &gsl_rng_free) {
        // MT19937 takes an unsigned long seed; 0 is replaced by GSL's default, so avoid it.
        const std::uint64_t s = mix_seed(seed, stream);
        gsl_rng_set(rng_.get(), static_cast<unsigned long>(s == 0 ? 1 : s));
    }
    RngStream(const RngStream& o) : rng_(gsl_rng_clone(o.rng_.get()), &gsl_rng_free) {}
    RngStream& operator=(const RngStream& o) {
        if (this != &o) gsl_rng_memcpy(rng_.get(), o.rng_.get());
        return *this;
    }
    RngStream(RngStream&&) noexcept = default;
    RngStream& operator=(RngStream&&) noexcept = default;

    // Uniform on [0, 1).
    double uniform() { return gsl_rng_uniform(rng_.get()); }
    // Uniform on [a, b).
    double uniform(double a, double b) { return a + (b - a) * uniform(); }
    // Standard normal deviate (GSL's ziggurat).
    double normal() { return gsl_ran_gaussian_ziggurat(rng_.get(), 1.0); }
    // Uniform integer on [0, n).
    unsigned long index(unsigned long n) { return gsl_rng_uniform_int(rng_.get(), n); }

    // Raw generator state, for checkpoints.
    std::vector<unsigned char> state() const {
        const auto* p = static_cast<const unsigned char*>(gsl_rng_state(rng_.get()));
        return {p, p + gsl_rng_size(rng_.get())};
    }
    void set_state(const std::vector<unsigned char>& s) {
        if (s.size() != gsl_rng_size(rng_.get())) throw std::runtime_error("rng state size");
        auto* p = static_cast<unsigned char*>(gsl_rng_state(rng_.get()));
        std::copy(s.begin(), s.end(), p);
    }

private:
    std::unique_ptr<gsl_rng, void (*)(gsl_rng*)> rng_;
};

} // namespace granrepro

// SPDX-License-Identifier: MIT
#pragma once
// A small random generator whose output is the same with every compiler and library
// (std::*_distribution is implementation-defined, and the scenes must not change with them).

#include <cstdint>

namespace raypoint::scene {

// SplitMix64 (Steele, Lea and Flood 2014).
class Rng {
  public:
    explicit Rng(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31U);
    }

    // In [0, 1), 53 random bits.
    double uniform() { return static_cast<double>(next() >> 11U) * 0x1.0p-53; }
    double uniform(double low, double high) { return low + (high - low) * uniform(); }
    // In [low, high].
    int integer(int low, int high) {
        const auto span = static_cast<std::uint64_t>(high - low) + 1U;
        return low + static_cast<int>(next() % span);
    }
    bool chance(double p) { return uniform() < p; }

  private:
    std::uint64_t state_;
};

// Independent streams from one scene seed: background, trajectory, noise of frame i...
inline std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t stream) {
    Rng rng(seed * 0x100000001B3ULL + stream);
    return rng.next();
}

}  // namespace raypoint::scene

// SPDX-License-Identifier: MIT
#pragma once
// Writes NumPy .npz archives (a zip of .npy files, stored uncompressed) that numpy.load reads.

#include <cstdint>
#include <string>
#include <vector>

namespace raypoint::scene::tool {

struct NpyArray {
    std::string name;   // without ".npy"
    std::string dtype;  // NumPy descr: "|u1", "<i8", ...
    std::vector<std::uint64_t> shape;
    std::vector<std::uint8_t> bytes;  // C order, already in dtype's byte order
};

// Throws std::runtime_error when the file cannot be written or a member exceeds 4 GiB.
void write_npz(const std::string& path, const std::vector<NpyArray>& arrays);

}  // namespace raypoint::scene::tool

// SPDX-License-Identifier: MIT
#pragma once
// The arrays of a NumPy .npz file (a zip archive of .npy files, stored or deflated), as the
// scene folders' masks.npz: numpy.savez_compressed or raypoint-render-scene's stored writer.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace raypoint::daemon {

struct NpyArray {
    std::string dtype;                 // NumPy's descr: "|u1", "<i8", ...
    std::vector<std::uint64_t> shape;  // C order (fortran_order arrays are refused)
    std::vector<std::uint8_t> bytes;   // the raw data, shape's product x the item size
};

// Every member "NAME.npy" of the archive, by NAME. Throws InputError naming the path and what
// is wrong (not a zip, a compression other than deflate, a bad .npy header).
std::map<std::string, NpyArray> read_npz(const std::string& path);

// The array's values as integers, for small integer arrays such as masks.npz's "shape".
// Throws InputError for a dtype that is not a little-endian or one-byte integer.
std::vector<std::int64_t> integer_values(const NpyArray& array, const std::string& what);

}  // namespace raypoint::daemon

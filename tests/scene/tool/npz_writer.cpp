// SPDX-License-Identifier: MIT
#include "npz_writer.hpp"

#include <array>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace raypoint::scene::tool {
namespace {

std::uint32_t crc32(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k)
                c = (c & 1U) ? 0xEDB88320U ^ (c >> 1U) : c >> 1U;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFU;
    for (const auto* part : {&a, &b}) {
        for (const std::uint8_t byte : *part)
            c = table[(c ^ byte) & 0xFFU] ^ (c >> 8U);
    }
    return c ^ 0xFFFFFFFFU;
}

// The .npy version 1.0 header: magic, version, length, then a Python dict literal padded
// so that the data starts at a multiple of 64 bytes.
std::vector<std::uint8_t> npy_header(const NpyArray& array) {
    std::string shape = "(";
    for (const std::uint64_t n : array.shape)
        shape += std::to_string(n) + ", ";
    if (array.shape.size() > 1) shape.resize(shape.size() - 2);
    if (array.shape.size() == 1) shape.resize(shape.size() - 1);
    shape += ")";
    std::string dict =
        "{'descr': '" + array.dtype + "', 'fortran_order': False, 'shape': " + shape + ", }";
    const std::size_t unpadded = 10 + dict.size() + 1;
    dict.append((64 - unpadded % 64) % 64, ' ');
    dict += '\n';
    std::vector<std::uint8_t> h{0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0};
    h.push_back(static_cast<std::uint8_t>(dict.size() & 0xFFU));
    h.push_back(static_cast<std::uint8_t>(dict.size() >> 8U));
    h.insert(h.end(), dict.begin(), dict.end());
    return h;
}

class LittleEndian {
  public:
    explicit LittleEndian(std::ofstream& out) : out_(out) {}
    void u16(std::uint64_t v) { put(v, 2); }
    void u32(std::uint64_t v) { put(v, 4); }
    void text(const std::string& s) {
        out_.write(s.data(), static_cast<std::streamsize>(s.size()));
    }
    void bytes(const std::vector<std::uint8_t>& b) {
        out_.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
    }

  private:
    void put(std::uint64_t v, int n) {
        for (int i = 0; i < n; ++i)
            out_.put(static_cast<char>((v >> (8 * i)) & 0xFFU));
    }
    std::ofstream& out_;
};

struct Entry {
    std::string name;
    std::uint32_t crc;
    std::uint64_t size;
    std::uint64_t offset;
};

// 1980-01-01 00:00, the zip epoch: the same bytes on every run.
constexpr std::uint16_t dos_time = 0;
constexpr std::uint16_t dos_date = (1U << 5U) | 1U;

}  // namespace

void write_npz(const std::string& path, const std::vector<NpyArray>& arrays) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) throw std::runtime_error("cannot write " + path);
    LittleEndian out(file);
    std::vector<Entry> entries;
    std::uint64_t offset = 0;
    for (const NpyArray& array : arrays) {
        const std::vector<std::uint8_t> header = npy_header(array);
        Entry e{array.name + ".npy", crc32(header, array.bytes), header.size() + array.bytes.size(),
                offset};
        if (e.size >= std::numeric_limits<std::uint32_t>::max()) {
            throw std::runtime_error(path + ": " + e.name + " is too large for a zip32 member");
        }
        // Local file header, "stored" (method 0).
        out.u32(0x04034b50);
        out.u16(20), out.u16(0), out.u16(0), out.u16(dos_time), out.u16(dos_date);
        out.u32(e.crc), out.u32(e.size), out.u32(e.size);
        out.u16(e.name.size()), out.u16(0);
        out.text(e.name);
        out.bytes(header);
        out.bytes(array.bytes);
        offset += 30 + e.name.size() + e.size;
        entries.push_back(e);
    }
    const std::uint64_t directory = offset;
    for (const Entry& e : entries) {
        out.u32(0x02014b50);
        out.u16(20), out.u16(20), out.u16(0), out.u16(0), out.u16(dos_time), out.u16(dos_date);
        out.u32(e.crc), out.u32(e.size), out.u32(e.size);
        out.u16(e.name.size()), out.u16(0), out.u16(0), out.u16(0), out.u16(0), out.u32(0);
        out.u32(e.offset);
        out.text(e.name);
        offset += 46 + e.name.size();
    }
    out.u32(0x06054b50);
    out.u16(0), out.u16(0), out.u16(entries.size()), out.u16(entries.size());
    out.u32(offset - directory), out.u32(directory), out.u16(0);
    if (!file.flush()) throw std::runtime_error("cannot write " + path);
}

}  // namespace raypoint::scene::tool

// SPDX-License-Identifier: MIT
#include "npz_reader.hpp"

#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>

#include "input_error.hpp"

namespace raypoint::daemon {
namespace {

// Zip record signatures and fixed offsets (PKWARE APPNOTE 4.3.7, 4.3.12, 4.3.16).
constexpr std::uint32_t local_signature = 0x04034b50;
constexpr std::uint32_t central_signature = 0x02014b50;
constexpr std::uint32_t end_signature = 0x06054b50;
constexpr std::size_t end_size = 22;
constexpr std::size_t central_size = 46;
constexpr std::size_t local_size = 30;
constexpr std::uint32_t zip64_marker = 0xFFFFFFFF;

class Bytes {
  public:
    Bytes(const std::vector<std::uint8_t>& data, const std::string& path)
        : data_(data), path_(path) {}

    std::uint64_t get(std::size_t at, int width) const {
        need(at, static_cast<std::size_t>(width));
        std::uint64_t value = 0;
        for (int i = width - 1; i >= 0; --i)
            value = (value << 8U) | data_[at + static_cast<std::size_t>(i)];
        return value;
    }
    std::uint32_t u32(std::size_t at) const { return static_cast<std::uint32_t>(get(at, 4)); }
    std::size_t u16(std::size_t at) const { return static_cast<std::size_t>(get(at, 2)); }
    void need(std::size_t at, std::size_t count) const {
        if (at > data_.size() || count > data_.size() - at) fail("truncated zip archive");
    }
    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(path_ + ": " + what + " (expected a NumPy .npz file)");
    }
    const std::uint8_t* at(std::size_t offset) const { return data_.data() + offset; }
    std::size_t size() const { return data_.size(); }

  private:
    const std::vector<std::uint8_t>& data_;
    const std::string& path_;
};

std::vector<std::uint8_t> read_file(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path + ": cannot open: " + std::strerror(errno));
    std::vector<std::uint8_t> data((std::istreambuf_iterator<char>(file)),
                                   std::istreambuf_iterator<char>());
    if (file.bad()) throw InputError(path + ": cannot read: " + std::strerror(errno));
    return data;
}

std::vector<std::uint8_t> inflate_raw(const Bytes& bytes, std::size_t offset,
                                      std::size_t compressed, std::size_t size) {
    std::vector<std::uint8_t> out(size);
    z_stream stream{};
    // Negative window bits: a raw deflate stream, as zip members hold (no zlib header).
    if (inflateInit2(&stream, -MAX_WBITS) != Z_OK) bytes.fail("zlib inflateInit2 failed");
    stream.next_in = const_cast<Bytef*>(bytes.at(offset));
    stream.avail_in = static_cast<uInt>(compressed);
    stream.next_out = out.data();
    stream.avail_out = static_cast<uInt>(size);
    const int status = inflate(&stream, Z_FINISH);
    const auto produced = stream.total_out;
    inflateEnd(&stream);
    if (status != Z_STREAM_END || produced != size) bytes.fail("corrupt deflate data");
    return out;
}

// One member's uncompressed bytes, located through its central directory entry (the local
// header's sizes may be zip64 placeholders, as numpy writes them).
std::vector<std::uint8_t> member(const Bytes& bytes, std::size_t entry, std::string& name) {
    if (bytes.u32(entry) != central_signature) bytes.fail("bad central directory");
    const std::size_t method = bytes.u16(entry + 10);
    const std::uint32_t crc = bytes.u32(entry + 16);
    const std::uint32_t compressed = bytes.u32(entry + 20);
    const std::uint32_t size = bytes.u32(entry + 24);
    const std::size_t name_length = bytes.u16(entry + 28);
    const std::uint32_t local = bytes.u32(entry + 42);
    if (compressed == zip64_marker || size == zip64_marker || local == zip64_marker) {
        bytes.fail("zip64 members are not supported");
    }
    bytes.need(entry + central_size, name_length);
    name.assign(reinterpret_cast<const char*>(bytes.at(entry + central_size)), name_length);
    if (bytes.u32(local) != local_signature) bytes.fail("bad local header of " + name);
    const std::size_t data = local + local_size + bytes.u16(local + 26) + bytes.u16(local + 28);
    bytes.need(data, compressed);
    std::vector<std::uint8_t> out;
    if (method == 0) {
        if (compressed != size) bytes.fail("stored member " + name + " has two sizes");
        out.assign(bytes.at(data), bytes.at(data) + size);
    } else if (method == Z_DEFLATED) {
        out = inflate_raw(bytes, data, compressed, size);
    } else {
        bytes.fail(name + ": compression method " + std::to_string(method) +
                   " (only stored and deflate)");
    }
    if (crc32(0L, out.data(), static_cast<uInt>(out.size())) != crc) {
        bytes.fail(name + ": CRC mismatch");
    }
    return out;
}

// The text between `'key': ` and the next delimiter of the .npy header's dict literal.
std::string header_field(const std::string& header, const std::string& key, char end,
                         const Bytes& bytes) {
    const std::string quoted = "'" + key + "':";
    const auto at = header.find(quoted);
    if (at == std::string::npos) bytes.fail(".npy header without " + key);
    auto from = header.find_first_not_of(' ', at + quoted.size());
    if (from == std::string::npos) bytes.fail(".npy header: " + key + " has no value");
    const char open = header[from];
    if (open == '\'' || open == '(') ++from;
    const auto to = header.find(end, from);
    if (to == std::string::npos) bytes.fail(".npy header: " + key + " not closed");
    return header.substr(from, to - from);
}

// The .npy format (NumPy's NEP 1): magic, version, header length, a dict literal, the data.
NpyArray parse_npy(const std::vector<std::uint8_t>& npy, const Bytes& archive) {
    const std::string member_name = "member";
    const Bytes bytes(npy, member_name);
    static constexpr char magic[] = "\x93NUMPY";
    if (npy.size() < 10 || std::memcmp(npy.data(), magic, 6) != 0) archive.fail("not a .npy");
    const bool long_header = npy[6] >= 2;
    const std::size_t length = long_header ? bytes.u32(8) : bytes.u16(8);
    const std::size_t start = long_header ? 12 : 10;
    if (start + length > npy.size()) archive.fail("truncated .npy header");
    const std::string header(reinterpret_cast<const char*>(npy.data() + start), length);
    NpyArray array;
    array.dtype = header_field(header, "descr", '\'', archive);
    if (header_field(header, "fortran_order", ',', archive).find("False") == std::string::npos) {
        archive.fail("Fortran-order arrays are not supported");
    }
    const std::string shape = header_field(header, "shape", ')', archive);
    std::uint64_t count = 1;
    for (std::size_t i = 0; i < shape.size();) {
        char* end = nullptr;
        const unsigned long long n = std::strtoull(shape.c_str() + i, &end, 10);
        const auto used = static_cast<std::size_t>(end - (shape.c_str() + i));
        if (used == 0) {
            ++i;  // a separator: ", " or a trailing ","
            continue;
        }
        array.shape.push_back(n);
        count *= n;
        i += used;
    }
    const std::size_t item =
        array.dtype.size() >= 3 ? std::strtoul(array.dtype.c_str() + 2, nullptr, 10) : 0;
    if (item == 0) archive.fail(".npy dtype " + array.dtype + " not understood");
    if (count * item != npy.size() - start - length) archive.fail(".npy data size mismatch");
    array.bytes.assign(npy.begin() + static_cast<std::ptrdiff_t>(start + length), npy.end());
    return array;
}

}  // namespace

std::map<std::string, NpyArray> read_npz(const std::string& path) {
    const std::vector<std::uint8_t> data = read_file(path);
    const Bytes bytes(data, path);
    if (data.size() < end_size) bytes.fail("too short for a zip archive");
    // The end record sits in the last 22 bytes plus at most a 65535-byte comment.
    std::size_t end = data.size() - end_size;
    const std::size_t lowest = end > 65535 ? end - 65535 : 0;
    while (bytes.u32(end) != end_signature) {
        if (end == lowest) bytes.fail("no zip end record");
        --end;
    }
    const std::size_t entries = bytes.u16(end + 10);
    std::size_t entry = bytes.u32(end + 16);
    std::map<std::string, NpyArray> arrays;
    for (std::size_t i = 0; i < entries; ++i) {
        std::string name;
        const std::vector<std::uint8_t> npy = member(bytes, entry, name);
        entry +=
            central_size + bytes.u16(entry + 28) + bytes.u16(entry + 30) + bytes.u16(entry + 32);
        if (name.size() > 4 && name.ends_with(".npy")) {
            arrays[name.substr(0, name.size() - 4)] = parse_npy(npy, bytes);
        }
    }
    return arrays;
}

std::vector<std::int64_t> integer_values(const NpyArray& array, const std::string& what) {
    const std::string& d = array.dtype;
    const bool little =
        d.size() == 3 && (d[0] == '<' || d[0] == '|') && (d[1] == 'i' || d[1] == 'u');
    const std::size_t item = little ? static_cast<std::size_t>(d[2] - '0') : 0;
    if (item != 1 && item != 2 && item != 4 && item != 8) {
        throw InputError(what + ": dtype " + d + " is not an integer type");
    }
    std::vector<std::int64_t> values;
    for (std::size_t at = 0; at + item <= array.bytes.size(); at += item) {
        std::uint64_t value = 0;
        for (std::size_t i = item; i-- > 0;)
            value = (value << 8U) | array.bytes[at + i];
        if (d[1] == 'i' && item < 8 && (value >> (8 * item - 1)) != 0) {
            value |= std::numeric_limits<std::uint64_t>::max() << (8 * item);  // sign-extend
        }
        values.push_back(static_cast<std::int64_t>(value));
    }
    return values;
}

}  // namespace raypoint::daemon

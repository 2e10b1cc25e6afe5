#include "mat_file.h"

#include <gmcc/input/input_error.h>

#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <limits>

namespace gmcc {
namespace {

// Data types (MAT-File Format, MathWorks, table 1-1) and array classes (table 1-3).
enum : std::uint32_t {
  miINT8 = 1, miUINT8 = 2, miINT16 = 3, miUINT16 = 4, miINT32 = 5, miUINT32 = 6, miSINGLE = 7,
  miDOUBLE = 9, miINT64 = 12, miUINT64 = 13, miMATRIX = 14, miCOMPRESSED = 15, miUTF8 = 16,
  miUTF16 = 17, miUTF32 = 18
};
enum : std::uint32_t {
  mxCELL = 1, mxCHAR = 4, mxDOUBLE = 6, mxSINGLE = 7, mxINT8 = 8, mxUINT8 = 9, mxINT16 = 10,
  mxUINT16 = 11, mxINT32 = 12, mxUINT32 = 13, mxINT64 = 14, mxUINT64 = 15
};

// Deflate's largest expansion (RFC 1951: 258 bytes from a match of at least 2 bits), as for PNG.
constexpr std::size_t max_deflate_ratio = 1032;
// Cells within cells deeper than this are refused (the datasets nest names at most two deep).
constexpr int max_depth = 8;

std::size_t type_size(std::uint32_t type) {
  switch (type) {
    case miINT8: case miUINT8: case miUTF8: return 1;
    case miINT16: case miUINT16: case miUTF16: return 2;
    case miINT32: case miUINT32: case miSINGLE: case miUTF32: return 4;
    case miDOUBLE: case miINT64: case miUINT64: return 8;
    default: return 0;
  }
}

class Reader {
 public:
  Reader(const std::string& file, bool swap, std::size_t* inflated)
      : file_(file), swap_(swap), inflated_(inflated) {}

  [[noreturn]] void fail(const std::string& why) const { throw InputError(file_, 0, why); }

  std::uint32_t u32(const unsigned char* p) const {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return swap_ ? __builtin_bswap32(v) : v;
  }

  // One element's tag at [at, end): its type, its data and the offset after it (padded to 8
  // bytes unless `padded` is false, as top-level compressed elements are not).
  struct Element {
    std::uint32_t type;
    const unsigned char* data;
    std::size_t bytes;
    std::size_t next;
  };
  Element element(const unsigned char* base, std::size_t at, std::size_t end, const char* what) const {
    if (end - at < 8) fail(std::string(what) + ": truncated (an element's tag runs past the end)");
    const std::uint32_t first = u32(base + at);
    if (first >> 16) {  // the small format: 1 to 4 bytes of data inside the 8-byte tag
      const std::size_t n = first >> 16;
      if (n > 4) fail(std::string(what) + ": a small element claiming more than 4 bytes");
      return {first & 0xffff, base + at + 4, n, at + 8};
    }
    const std::size_t n = u32(base + at + 4);
    if (n > end - at - 8)
      fail(std::string(what) + ": an element claims " + std::to_string(n) + " bytes where " +
           std::to_string(end - at - 8) + " follow");
    const std::size_t padded = first == miCOMPRESSED ? n : (n + 7) / 8 * 8;
    return {first, base + at + 8, n, at + 8 + std::min(padded, end - at - 8)};
  }

  // The bytes a compressed element inflates to, within its bounds.
  std::string inflate(const unsigned char* data, std::size_t bytes) const {
    const std::size_t room = mat_max_inflated_bytes - *inflated_;
    const std::size_t bound = std::min(bytes > (room - 4096) / max_deflate_ratio ? room : max_deflate_ratio * bytes + 4096, room);
    z_stream z{};
    if (inflateInit(&z) != Z_OK) fail("zlib did not start");
    std::string out;
    z.next_in = const_cast<unsigned char*>(data);
    z.avail_in = static_cast<uInt>(std::min<std::size_t>(bytes, std::numeric_limits<uInt>::max()));
    int rc = Z_OK;
    while (rc != Z_STREAM_END) {
      if (out.size() >= bound) {
        inflateEnd(&z);
        fail("a compressed variable inflates to more than " +
             std::string(bound == room ? std::to_string(mat_max_inflated_bytes >> 20) + " MiB, the limit for a MATLAB file"
                                       : "1032 times its compressed bytes, deflate's limit"));
      }
      const std::size_t was = out.size();
      out.resize(std::min(bound, std::max<std::size_t>(was * 2, 65536)));
      z.next_out = reinterpret_cast<unsigned char*>(&out[was]);
      z.avail_out = static_cast<uInt>(out.size() - was);
      rc = ::inflate(&z, Z_NO_FLUSH);
      out.resize(out.size() - z.avail_out);
      if (rc == Z_STREAM_END) break;
      if (rc != Z_OK && !(rc == Z_BUF_ERROR && z.avail_out == 0)) {
        inflateEnd(&z);
        fail(rc == Z_BUF_ERROR ? "a compressed variable is truncated" : "a compressed variable is not valid zlib data");
      }
    }
    inflateEnd(&z);
    *inflated_ += out.size();
    return out;
  }

  // A character (`chars`) or numeric array's data element `re`, of `count` values, into `a`.
  void data_of(const Element& re, bool chars, std::size_t count, MatArray& a) const {
    const std::size_t size = type_size(re.type);
    if (size == 0 || re.bytes % size != 0) fail("an array's data is not of a numeric type");
    const std::size_t n = re.bytes / size;
    if (chars) {
      a.kind = MatArray::chars;
      if (re.type == miUTF8 ? n < count : n != count)
        fail("a character array of " + std::to_string(count) + " characters holds " + std::to_string(n));
      a.text.reserve(n);
      for (std::size_t i = 0; i < n; ++i) {
        std::uint32_t c = size == 1 ? re.data[i] : size == 2 ? (swap_ ? (re.data[2 * i] << 8 | re.data[2 * i + 1]) : (re.data[2 * i + 1] << 8 | re.data[2 * i])) : u32(re.data + 4 * i);
        a.text += c < 128 ? static_cast<char>(c) : '?';
      }
      return;
    }
    if (n != count) fail("a numeric array of " + std::to_string(count) + " values holds " + std::to_string(n));
    a.kind = MatArray::numeric;
    a.numbers.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      unsigned char b[8];
      for (std::size_t k = 0; k < size; ++k) b[k] = re.data[i * size + (swap_ ? size - 1 - k : k)];
      double v = 0;
      switch (re.type) {
        case miINT8: v = static_cast<std::int8_t>(b[0]); break;
        case miUINT8: case miUTF8: v = b[0]; break;
        case miINT16: { std::int16_t x; std::memcpy(&x, b, 2); v = x; break; }
        case miUINT16: case miUTF16: { std::uint16_t x; std::memcpy(&x, b, 2); v = x; break; }
        case miINT32: { std::int32_t x; std::memcpy(&x, b, 4); v = x; break; }
        case miUINT32: case miUTF32: { std::uint32_t x; std::memcpy(&x, b, 4); v = x; break; }
        case miSINGLE: { float x; std::memcpy(&x, b, 4); v = x; break; }
        case miDOUBLE: { std::memcpy(&v, b, 8); break; }
        case miINT64: { std::int64_t x; std::memcpy(&x, b, 8); v = static_cast<double>(x); break; }
        case miUINT64: { std::uint64_t x; std::memcpy(&x, b, 8); v = static_cast<double>(x); break; }
        default: break;
      }
      a.numbers.push_back(v);
    }
    // An imaginary part, if any, is not read (a.complex says it is there).
  }

  // The miMATRIX element whose data is [data, data + bytes): its name, and the array.
  MatArray matrix(const unsigned char* data, std::size_t bytes, std::string* name, int depth) const {
    MatArray a;
    if (bytes == 0) {  // an empty array ([] in a cell)
      a.kind = MatArray::numeric;
      a.dims = {0, 0};
      return a;
    }
    if (depth > max_depth) fail("cells nested more than " + std::to_string(max_depth) + " deep");
    Element flags = element(data, 0, bytes, "array flags");
    if (flags.type != miUINT32 || flags.bytes != 8) fail("an array's flags are not two 32-bit words");
    const std::uint32_t word = u32(flags.data);
    const std::uint32_t cls = word & 0xff;
    a.complex = (word & 0x0800) != 0;
    Element dims = element(data, flags.next, bytes, "array dimensions");
    if (dims.type != miINT32 || dims.bytes % 4 != 0 || dims.bytes < 8) fail("an array's dimensions are not two or more 32-bit integers");
    std::size_t count = 1;
    for (std::size_t k = 0; k < dims.bytes / 4; ++k) {
      const std::uint32_t d = u32(dims.data + 4 * k);
      if (d > 0x7fffffffu) fail("an array's dimension is negative");
      a.dims.push_back(d);
      // Every element needs at least a byte of the file (a cell, 8): a larger count is a lie,
      // refused before anything is made for it.
      if (d != 0 && count > bytes / d) fail("an array's dimensions (" + std::to_string(d) + " …) claim more elements than its " + std::to_string(bytes) + " bytes hold");
      count *= d;
    }
    Element nm = element(data, dims.next, bytes, "array name");
    if (nm.type != miINT8 && nm.type != miUINT8) fail("an array's name is not 8-bit text");
    if (name) name->assign(reinterpret_cast<const char*>(nm.data), nm.bytes);
    std::size_t at = nm.next;
    if (cls == mxCELL) {
      a.kind = MatArray::cell;
      if (count > (bytes - at) / 8) fail("a cell array claims " + std::to_string(count) + " cells where " + std::to_string(bytes - at) + " bytes follow");
      a.cells.reserve(count);
      for (std::size_t i = 0; i < count; ++i) {
        Element c = element(data, at, bytes, "a cell");
        if (c.type != miMATRIX) fail("a cell that is not an array");
        a.cells.push_back(matrix(c.data, c.bytes, nullptr, depth + 1));
        at = c.next;
      }
      return a;
    }
    if (cls == mxCHAR || (cls >= mxDOUBLE && cls <= mxUINT64)) {
      data_of(element(data, at, bytes, "array data"), cls == mxCHAR, count, a);
      return a;
    }
    a.kind = MatArray::other;  // struct, object, sparse, function: not read
    return a;
  }

 private:
  const std::string& file_;
  bool swap_;
  std::size_t* inflated_;
};

}  // namespace

std::size_t MatArray::count() const {
  std::size_t n = 1;
  for (std::size_t d : dims) n *= d;
  return n;
}

bool is_mat5(const std::string& bytes) {
  if (bytes.size() < 128) return false;
  const bool little = bytes[126] == 'I' && bytes[127] == 'M', big = bytes[126] == 'M' && bytes[127] == 'I';
  if (!little && !big) return false;
  const auto v0 = static_cast<unsigned char>(bytes[124]), v1 = static_cast<unsigned char>(bytes[125]);
  return little ? (v0 == 0x00 && v1 == 0x01) : (v0 == 0x01 && v1 == 0x00);
}

std::map<std::string, MatArray> read_mat5(const std::string& bytes, const std::string& file) {
  if (!is_mat5(bytes)) throw InputError(file, 0, "not a MATLAB 5 MAT-file (no 128-byte header ending in version 0x0100, IM or MI)");
  const bool big = bytes[126] == 'M';
  const std::uint16_t probe = 1;
  unsigned char first;
  std::memcpy(&first, &probe, 1);
  const bool host_little = first == 1;
  std::size_t inflated = 0;
  const Reader r(file, big == host_little, &inflated);
  const auto* base = reinterpret_cast<const unsigned char*>(bytes.data());
  std::map<std::string, MatArray> out;
  for (std::size_t at = 128; at < bytes.size();) {
    const Reader::Element e = r.element(base, at, bytes.size(), "a variable");
    std::string name;
    MatArray a;
    if (e.type == miCOMPRESSED) {
      const std::string inner = r.inflate(e.data, e.bytes);
      const auto* ib = reinterpret_cast<const unsigned char*>(inner.data());
      const Reader::Element m = r.element(ib, 0, inner.size(), "a compressed variable");
      if (m.type != miMATRIX) r.fail("a compressed element that is not an array");
      a = r.matrix(m.data, m.bytes, &name, 0);
    } else if (e.type == miMATRIX) {
      a = r.matrix(e.data, e.bytes, &name, 0);
    } else {
      at = e.next;  // not a variable (subsystem data, say): skipped
      continue;
    }
    if (!out.emplace(name, std::move(a)).second) {
      std::string shown;  // the name for a message: control characters as '?', at most 60
      for (char c : name.substr(0, 60)) shown += static_cast<unsigned char>(c) < 32 || c == 127 ? '?' : c;
      r.fail("two variables named " + shown);
    }
    at = e.next;
  }
  return out;
}

}  // namespace gmcc

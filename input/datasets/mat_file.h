#pragma once
// The variables of a MATLAB 5 MAT-file (the format of `save -v6`/`-v7`, what the NUS and
// Gehler–Shi datasets ship), read by gmcc itself from the file's bytes, every read bounded by
// them: a dimension, a name or a cell count that claims more than the bytes that follow hold is
// refused before anything is allocated for it, and a compressed variable inflates to at most
// 1032 times its compressed bytes (deflate's limit, as for PNG) and mat_max_inflated_bytes in
// all. Only what the datasets use is read: real numeric matrices (any stored integer or float
// type, converted to doubles), character arrays and cell arrays of them; other classes are kept
// as MatArray::other, an error only when asked for as numbers or text.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace gmcc {

/// The largest MAT-file read (the datasets' are tens of kilobytes).
inline constexpr std::size_t mat_max_file_bytes = std::size_t(16) << 20;

/// What a whole MAT-file may inflate to, summed over its compressed variables.
inline constexpr std::size_t mat_max_inflated_bytes = std::size_t(16) << 20;

/// One variable or cell.
struct MatArray {
  enum Kind { numeric, chars, cell, other };
  Kind kind = other;
  bool complex = false;
  std::vector<std::size_t> dims;  ///< at least two
  std::vector<double> numbers;    ///< numeric: the real part, column-major
  std::string text;               ///< chars: the characters (codes above 127 as '?')
  std::vector<MatArray> cells;    ///< cell: the cells, column-major
  std::size_t count() const;      ///< the product of dims
};

/// True if `bytes` begin like a MATLAB 5 MAT-file (a 128-byte header, version 0x0100, "IM" or
/// "MI"), as opposed to a MATLAB 7.3 (HDF5) or 4 file.
bool is_mat5(const std::string& bytes);

/// The top-level variables of the MATLAB 5 file whose bytes are `bytes`, by name; `file` names
/// it in errors.
/// \throws InputError naming the file: not a MATLAB 5 file, a truncated or inconsistent element,
///         a compressed variable that is not zlib data or inflates beyond its bound.
std::map<std::string, MatArray> read_mat5(const std::string& bytes, const std::string& file);

}  // namespace gmcc

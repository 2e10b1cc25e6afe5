#pragma once
/// \file colour_csv.h
/// Reading colour files: one linear RGB per line, numbers read exactly (docs/cli.md "Input files").

#include <gmcc/geometry/colour.h>
#include <gmcc/input/input_error.h>

#include <cstddef>
#include <string>
#include <vector>

namespace gmcc {

/// Largest colour file accepted, in bytes (a clear error instead of exhausting memory).
inline constexpr std::size_t max_colour_file_bytes = std::size_t(256) << 20;
/// Longest line accepted, in bytes: three numbers of max_number_digits need a few hundred;
/// a longer line is not a colour (a binary file, or a file with no line ends).
inline constexpr std::size_t max_colour_line_bytes = 65536;
/// Most colours accepted in one file: each costs about 1 KB of memory on its way through the
/// hulls (10^6 colours take about 1 GB and 10 s).
inline constexpr std::size_t max_colours = 1000000;

/// The colours of a file, with the line each came from.
struct ColourTable {
  std::string file;  ///< the file's name as given, for messages
  /// The rows in file order, exact: pixel colours, or chromaticity lifts when
  /// chromaticity_lifts is set (then not colours).
  std::vector<Colour> colours;
  std::vector<std::size_t> lines;  ///< 1-based source line of each colour
  /// True when the header is `r/b,g/b,1`: the colours are chromaticity lifts (x, y, 1), as
  /// `gmcc canonical` writes a 2-D gamut, usable by the 2-D perspective route only.
  bool chromaticity_lifts = false;
  std::size_t header_line = 0;  ///< 1-based line of the header, 0 without one
};

/// Parse colour-file text. Format: one colour per line as `r,g,b`; an optional header line
/// `r,g,b`, or `r/b,g/b,1` for chromaticity lifts (ColourTable::chromaticity_lifts); blank lines
/// and lines whose first non-blank character is `#` (of any length) are ignored; CRLF
/// line ends, a UTF-8 byte-order mark and spaces or tabs around numbers are accepted. Numbers
/// are decimals or `p/q`, read exactly (parse_rational). Channels must be finite and >= 0.
/// \param text  the file's content (UTF-8 or ASCII).
/// \param file  the name used in messages.
/// \throws InputError naming the file and line: malformed or non-finite numbers (including
///         numbers longer than max_number_digits), negative channels, a wrong number of
///         columns, NUL bytes, lines other than comments longer than max_colour_line_bytes, more than max_colours
///         colours, no colour at all.
ColourTable parse_colour_csv(const std::string& text, const std::string& file);

/// Refuse a table of chromaticity lifts where pixel colours are meant (every 3-D route): lifts
/// (x, y, 1) taken as colours give a feasible set of maps that means nothing, with no error.
/// \param table the colours read. \param use what needs pixel colours, for the message (e.g.
/// "the 3-D route").
/// \throws InputError naming the file and its header line.
void require_pixel_colours(const ColourTable& table, const std::string& use);

/// Read and parse a colour file (read_text_file, then parse_colour_csv): a regular file, a FIFO
/// or pipe, or a device, each read with the limits applied while reading.
/// \throws InputError if the file cannot be read, is larger than max_colour_file_bytes, holds
///         a NUL byte, is a FIFO no program writes, or its content is bad.
ColourTable read_colour_csv(const std::string& path);

}  // namespace gmcc

// Fuzz target: a MATLAB 5 MAT-file as the dataset layouts read it (input/datasets/mat_file.h,
// issue 42), on arbitrary bytes: the NUS `*_gt.mat` and the Gehler–Shi `real_illum_568.mat` and
// `threefoldCVsplit.mat` all go through read_mat5.
//
// Every input must either parse or throw gmcc::InputError whose message is one line of bounded
// length starting with the file's name. What parses: every array has at least two dimensions, a
// numeric array exactly as many values as its dimensions multiply to, a character array at least
// as many characters (exactly, unless stored as UTF-8), a cell array that many cells, each checked
// the same way; and everything read is bounded by the bytes: the values and characters of all the
// arrays together at most the file's bytes plus what its compressed variables may inflate to
// (mat_max_inflated_bytes), so no header can make the reader allocate beyond its file.

#include "fuzz_support.h"

#include "mat_file.h"

#include <gmcc/input/input_error.h>

#include <string>

namespace {

// The values, characters and cells of `a` and its cells, checked as the header says.
std::size_t check_array(const gmcc::MatArray& a) {
  FUZZ_CHECK(a.dims.size() >= 2, "an array of " + std::to_string(a.dims.size()) + " dimensions");
  std::size_t n = 1;
  for (std::size_t d : a.dims) n *= d;
  std::size_t held = 0;
  switch (a.kind) {
    case gmcc::MatArray::numeric:
      FUZZ_CHECK(a.numbers.size() == n, "a numeric array whose values differ from its dimensions");
      held = n;
      break;
    case gmcc::MatArray::chars:
      FUZZ_CHECK(a.text.size() >= n, "a character array shorter than its dimensions");
      held = a.text.size();
      break;
    case gmcc::MatArray::cell:
      FUZZ_CHECK(a.cells.size() == n, "a cell array whose cells differ from its dimensions");
      for (const gmcc::MatArray& c : a.cells) held += 1 + check_array(c);
      break;
    case gmcc::MatArray::other:
      FUZZ_CHECK(a.numbers.empty() && a.text.empty() && a.cells.empty(), "an unread class holding data");
      break;
  }
  return held;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const std::string file = "fuzz.mat";
  try {
    std::size_t held = 0;
    for (const auto& [name, array] : gmcc::read_mat5(bytes, file)) held += check_array(array);
    FUZZ_CHECK(held <= size + gmcc::mat_max_inflated_bytes,
               std::to_string(held) + " values from " + std::to_string(size) + " bytes");
  } catch (const gmcc::InputError& e) {
    const std::string message = e.what();
    FUZZ_CHECK(message.rfind(file + ": ", 0) == 0, "message does not start with the file: " + message);
    FUZZ_CHECK(message.find('\n') == std::string::npos, "a message of more than one line: " + message);
    FUZZ_CHECK(message.size() <= 400, "a message of " + std::to_string(message.size()) + " bytes");
  }
  return 0;
}

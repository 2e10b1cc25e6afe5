// Fuzz target: one line of a `gmcc select --images` scene file (cli/select_batch.h,
// parse_batch_scene), on arbitrary bytes (newlines made spaces: a line holds none).
//
// Every line must either parse or throw gmcc::InputError naming the file and the line, one line
// of bounded length (a JSON error quotes at most a bounded piece of the text). What parses: 1 to
// max_colours colours, every channel >= 0, a truth (when given) of channels >= 0. A line the
// plain reader (batch_scene_plain.h) accepts parses the same by parse_batch_scene.

#include "fuzz_support.h"

#include "batch_scene_plain.h"
#include "select_batch.h"

#include <algorithm>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  std::replace(text.begin(), text.end(), '\n', ' ');
  gmcc::cli::BatchScene scene, plain;
  scene.line = plain.line = 7;
  const bool is_plain = gmcc::cli::parse_plain_batch_scene(text, plain);
  try {
    gmcc::cli::parse_batch_scene(text, "fuzz.jsonl", scene);
  } catch (const gmcc::InputError& e) {
    FUZZ_CHECK(!is_plain, "the plain reader accepted a line parse_batch_scene refuses");
    const std::string message = e.what();
    FUZZ_CHECK(message.rfind("fuzz.jsonl:7: ", 0) == 0, "message does not name the file and line: " + message);
    FUZZ_CHECK(message.find('\n') == std::string::npos, "a message of more than one line: " + message);
    FUZZ_CHECK(message.size() <= 600, "a message of " + std::to_string(message.size()) + " bytes");
    return 0;
  }
  FUZZ_CHECK(!is_plain || (plain.colours == scene.colours && plain.truth == scene.truth && plain.id == scene.id),
             "the plain reader read the line otherwise than parse_batch_scene");
  FUZZ_CHECK(!scene.colours.empty() && scene.colours.size() <= gmcc::max_colours, "colour count");
  for (const gmcc::Colour& c : scene.colours)
    FUZZ_CHECK(sgn(c.r) >= 0 && sgn(c.g) >= 0 && sgn(c.b) >= 0, "a negative channel");
  if (scene.truth)
    FUZZ_CHECK(sgn(scene.truth->r) >= 0 && sgn(scene.truth->g) >= 0 && sgn(scene.truth->b) >= 0, "a negative truth");
  return 0;
}

#include <gmcc/input/camera_image.h>

#include <gmcc/input/raw_file.h>
#include <gmcc/input/text_file.h>

#include <mutex>

namespace gmcc {
namespace {

std::mutex& levels_mutex() {
  static std::mutex m;
  return m;
}
std::vector<ImageLevelsUsed>& levels_log() {
  static std::vector<ImageLevelsUsed> used;
  return used;
}
void record_levels(ImageLevelsUsed used) {
  const std::lock_guard<std::mutex> lock(levels_mutex());
  for (const ImageLevelsUsed& seen : levels_log())
    if (seen.path == used.path) return;
  levels_log().push_back(std::move(used));
}

}  // namespace

std::vector<ImageLevelsUsed> image_levels_used() {
  const std::lock_guard<std::mutex> lock(levels_mutex());
  return levels_log();
}

CameraImage read_camera_image(const std::string& path, const ImageLevels& levels) {
  const std::string bytes = read_binary_file(path, max_image_file_bytes, "image file");
  CameraImage out;
  if (is_raw_file_name(path) || is_raw_file_content(bytes)) {
    out.raw = decode_raw_image(bytes, path, RawLevels{levels.black, levels.saturation});
    out.black_level = 0;
    out.saturation = raw_saturated_value;
    record_levels({path, {out.raw.black.begin(), out.raw.black.end()}, out.raw.white,
                   out.raw.black_given ? "given" : "file", out.raw.white_given ? "given" : "file"});
    out.image = std::move(out.raw.image);
    out.raw.image = RgbImage{};
    return out;
  }
  out.image = decode_image(bytes, path);
  out.black_level = levels.black.value_or(levels.run_black);
  out.saturation = levels.saturation;
  record_levels({path, {out.black_level}, levels.saturation, levels.black ? "given" : "run",
                 levels.saturation ? "given" : "run"});
  return out;
}

}  // namespace gmcc

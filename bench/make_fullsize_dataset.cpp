// Full-size 16-bit stand-ins for a dataset (issue 46 item 1; docs/performance.md "A full-size
// image against decoding it"): real photographs upscaled to the size a dataset ships at, widened
// to 16 bits with seeded noise so that most pixels are distinct colours, as in a real raw image.
//
//   make_fullsize_dataset SOURCE_DIR OUT_DIR COUNT WIDTH HEIGHT [SEED]
//
// SOURCE_DIR holds linear PNGs and gt.csv whose rows are file,…,r,g,b (the file's stem first, its
// light last; a header line first). Image i of COUNT (img_0000.png, …) is source i mod n, resampled
// to WIDTH × HEIGHT by nearest neighbour; each channel's code v (8-bit codes times 257) becomes
// v + u, u uniform in [−256, 256] from the generator mt19937_64 seeded with SEED + i (default
// SEED 46), clamped to [1, 65534]; a pixel that is 0 in every channel (a mask) stays 0 and a
// channel at the source's largest code stays 65535 (saturated stays saturated). OUT_DIR gets the
// images, truths.csv (image,r,g,b: each source's light; `gmcc benchmark --truths`) and gt.csv
// (image,camera,r,g,b with the image's stem and camera `standin`: the camera folder
// bench/photo_speed.py reads). The same arguments give the same bytes.
#include <gmcc/input/image_file.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace gmcc;

namespace {

struct Source {
  RgbImage image;
  std::string light;  // "r,g,b" as the source's gt.csv gives it
};

std::vector<Source> read_sources(const std::string& dir) {
  std::ifstream gt(dir + "/gt.csv");
  if (!gt) throw std::runtime_error(dir + "/gt.csv: cannot open");
  std::string line;
  std::getline(gt, line);  // header
  std::vector<Source> sources;
  while (std::getline(gt, line)) {
    if (line.empty()) continue;
    std::vector<std::string> f;
    std::stringstream s(line);
    for (std::string field; std::getline(s, field, ',');) f.push_back(field);
    if (f.size() < 4) throw std::runtime_error(dir + "/gt.csv: a row with fewer than 4 fields: " + line);
    sources.push_back({read_image(dir + "/" + f[0] + ".png"), f[f.size() - 3] + "," + f[f.size() - 2] + "," + f.back()});
  }
  if (sources.empty()) throw std::runtime_error(dir + "/gt.csv: no image");
  return sources;
}

RgbImage stand_in(const RgbImage& src, std::size_t w, std::size_t h, std::uint64_t seed) {
  std::mt19937_64 gen(seed);
  std::uniform_int_distribution<int> noise(-256, 256);
  const int widen = src.bits == 8 ? 257 : 1;
  const std::uint32_t top = (1u << src.bits) - 1;
  RgbImage out;
  out.width = w;
  out.height = h;
  out.bits = 16;
  out.samples.resize(w * h * 3);
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      const std::uint16_t* in = &src.samples[3 * ((y * src.height / h) * src.width + x * src.width / w)];
      std::uint16_t* o = &out.samples[3 * (y * w + x)];
      const bool masked = in[0] == 0 && in[1] == 0 && in[2] == 0;
      for (int c = 0; c < 3; ++c) {
        const int u = noise(gen);  // drawn for every channel, so a pixel's noise is its index's
        if (masked) o[c] = 0;
        else if (in[c] == top) o[c] = 65535;
        else o[c] = static_cast<std::uint16_t>(std::clamp<long>(long(in[c]) * widen + u, 1, 65534));
      }
    }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 6 || argc > 7) {
    std::cerr << "usage: make_fullsize_dataset SOURCE_DIR OUT_DIR COUNT WIDTH HEIGHT [SEED]\n";
    return 2;
  }
  try {
    const std::vector<Source> sources = read_sources(argv[1]);
    const std::string out_dir = argv[2];
    const std::size_t count = std::stoul(argv[3]), w = std::stoul(argv[4]), h = std::stoul(argv[5]);
    const std::uint64_t seed = argc == 7 ? std::stoull(argv[6]) : 46;
    std::filesystem::create_directories(out_dir);
    std::ofstream truths(out_dir + "/truths.csv"), gt(out_dir + "/gt.csv");
    truths << "image,r,g,b\n";
    gt << "image,camera,r,g,b\n";
    for (std::size_t i = 0; i < count; ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "img_%04zu.png", i);
      const Source& s = sources[i % sources.size()];
      const std::string png = encode_png16(stand_in(s.image, w, h, seed + i));
      std::ofstream(out_dir + "/" + name, std::ios::binary).write(png.data(), std::streamsize(png.size()));
      truths << name << "," << s.light << "\n";
      gt << std::string(name, 8) << ",standin," << s.light << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "make_fullsize_dataset: " << e.what() << "\n";
    return 2;
  }
  return 0;
}

// Writes the test images of `gmcc estimate` (tests/cli/test_estimate.py): a Mondrian of the
// shipped sample's 8 Munsell chips under D75 (narrow-band sensors; data/samples), 120x90 pixels
// in 4x3 cells, 16-bit above a black level of 256 with the brightest channel at 60000 above it,
// and 20 draws of saturated pixels, as OUT/mondrian.png and OUT/mondrian.tif; OUT/shown.csv
// holds the exact colours of the chips the cells show (lines of the sample file, each once).
//   make_mondrian_images DATA_DIR OUT_DIR [WIDTH HEIGHT [NOISE]]   (default 120 90 0; a larger,
//   noisy image for timing, as in docs/performance-history.md "Images")
#include <gmcc/input/colour_csv.h>
#include <gmcc/input/image_file.h>
#include <gmcc/validation/mondrian.h>

#include <fstream>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 3 && argc != 5 && argc != 6) {
    std::cerr << "usage: make_mondrian_images DATA_DIR OUT_DIR [WIDTH HEIGHT [NOISE]]\n";
    return 2;
  }
  const std::string data = argv[1], out = argv[2];
  const gmcc::ColourTable chips = gmcc::read_colour_csv(data + "/samples/image_munsell_D75.csv");
  gmcc::MondrianSpec spec;
  spec.width = argc >= 5 ? std::stoul(argv[3]) : 120;
  spec.height = argc >= 5 ? std::stoul(argv[4]) : 90;
  spec.noise = argc == 6 ? static_cast<std::uint32_t>(std::stoul(argv[5])) : 0;
  spec.columns = 4;
  spec.rows = 3;
  spec.seed = 1;
  spec.black_level = 256;
  spec.peak = 60000;
  spec.saturated_pixels = 20;
  const gmcc::Mondrian m = gmcc::render_mondrian(chips.colours, spec);
  for (const auto& [name, bytes] : {std::pair<std::string, std::string>{"mondrian.png", gmcc::encode_png16(m.image)},
                                    {"mondrian.tif", gmcc::encode_tiff16(m.image)}}) {
    std::ofstream f(out + "/" + name, std::ios::binary);
    f << bytes;
    if (!f) return 1;
  }
  std::ofstream shown(out + "/shown.csv");
  std::vector<bool> seen(chips.colours.size());
  for (std::size_t s : m.surfaces)
    if (!seen[s]) {
      seen[s] = true;
      const gmcc::Colour& c = chips.colours[s];
      shown << gmcc::to_string(c.r) << "," << gmcc::to_string(c.g) << "," << gmcc::to_string(c.b)
            << "\n";
    }
  return shown ? 0 : 1;
}

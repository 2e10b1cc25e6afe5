#include "dataset.h"

#include "dataset_layouts.h"

#include <gmcc/geometry/rational.h>
#include <gmcc/input/input_error.h>

#include <map>
#include <memory>

#include "output_files.h"
#include "provenance.h"
#include "write_stdout.h"

namespace gmcc::cli {

CLI::App* add_dataset_command(CLI::App& app, DatasetOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "dataset",
      "Write what gmcc reads from a dataset as it ships (NUS, Cube+, Gehler-Shi) as the truth table "
      "`gmcc benchmark --truths` reads: image, light, black level, saturation, chart polygon, exact");
  cmd->add_option("--layout", o.layout, "nus, cube+ or gehler-shi (as gmcc benchmark --layout)")
      ->check(CLI::IsMember(dataset_layout_names()))
      ->required();
  cmd->add_option("--images", o.images_dir, "the dataset's folder (as gmcc benchmark --images)")->required();
  cmd->add_option("--folds-out", o.folds_out,
                  "also write the split the dataset ships (Gehler-Shi's threefoldCVsplit.mat) as a folds file "
                  "image,fold");
  return cmd;
}

int run_dataset(const DatasetOptions& o) {
  std::map<std::string, int> folds;
  const std::vector<TruthRow> rows = read_dataset(o.layout, o.images_dir, folds);
  std::unique_ptr<PendingFile> folds_file;
  if (!o.folds_out.empty()) {
    if (folds.empty())
      throw InputError("--folds-out", 0, "the " + o.layout + " folder holds no split (Gehler-Shi's threefoldCVsplit.mat)");
    folds_file = std::make_unique<PendingFile>(o.folds_out);
  }
  std::string table = provenance_csv_line() + "image,r,g,b,black_level,saturation,chart\n";
  for (const TruthRow& r : rows) {
    table += r.image + "," + to_string(r.light.r) + "," + to_string(r.light.g) + "," + to_string(r.light.b) + ",";
    if (r.black_level) table += std::to_string(*r.black_level);
    table += ",";
    if (r.saturation) table += std::to_string(*r.saturation);
    table += ",";
    for (std::size_t k = 0; k < r.chart.size(); ++k)
      table += (k ? " " : "") + to_string(r.chart[k].x) + " " + to_string(r.chart[k].y);
    table += "\n";
  }
  if (folds_file) {
    std::string text = provenance_csv_line() + "image,fold\n";
    for (const TruthRow& r : rows) text += r.image + "," + std::to_string(folds.at(r.image)) + "\n";
    folds_file->commit(text);
  }
  write_stdout(table);
  return 0;
}

}  // namespace gmcc::cli

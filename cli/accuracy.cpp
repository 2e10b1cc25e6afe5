#include "accuracy.h"

#include "provenance.h"

#include "integer_option.h"
#include "limit_exit.h"
#include "output_files.h"
#include "write_stdout.h"

#include <gmcc/validation/accuracy_study.h>
#include <gmcc/input/input_error.h>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace gmcc::cli {
namespace fs = std::filesystem;

CLI::App* add_accuracy_command(CLI::App& app, AccuracyOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "accuracy",
      "How accurate is the 3-D mean? Error of each route (double and certified closed form, "
      "quadrature orders 2-16, Monte Carlo 1e4-1e7 samples) against a 4096-bit certified "
      "reference, on a fixed 7-gon of width 10 down to 1e-12 (docs/accuracy.md).");
  const CLI::Validator not_empty(
      [](std::string& s) { return s.empty() ? std::string("an empty path") : std::string(); }, "");
  cmd->add_option("--csv", o.csv_path,
                  "also write the results here, long format: "
                  "width,route,parameter,error_abs,error_rel,reported_bound,extra")
      ->type_name("FILE")
      ->check(not_empty);
  cmd->add_option("--plot", o.plot_dir,
                  "write DIR/accuracy.dat and DIR/accuracy.gp, and with gnuplot on PATH "
                  "DIR/accuracy.png and DIR/accuracy.svg (DIR is created if missing)")
      ->type_name("DIR")
      ->check(not_empty);
  cmd->add_option("--seed", o.seed, "Monte Carlo: seed of the mt19937_64 generator, 0 to 2^64-1")
      ->type_name("S")
      ->capture_default_str();
  cmd->add_option("--max-samples", o.max_samples,
                  "Monte Carlo: cap on the sample counts 10^4, 10^5, 10^6, 10^7 (1 to 2^40; "
                  "a small cap makes a quick run)")
      ->type_name("N")
      ->capture_default_str();
  return cmd;
}

int run_accuracy(const AccuracyOptions& options) {
  const AccuracySettings o{integer_option("--seed", options.seed, 0, ~std::uint64_t(0)),
                           integer_option("--max-samples", options.max_samples, 1, std::uint64_t(1) << 40)};
  // Every output path is checked (its temporary file opened) before the work.
  std::optional<PendingFile> csv_file, dat_file, gp_file;
  if (!options.csv_path.empty()) csv_file.emplace(options.csv_path);
  const fs::path dir = options.plot_dir;
  if (!options.plot_dir.empty()) {
    ensure_directory(options.plot_dir);
    std::error_code ec;
    if (!options.csv_path.empty()) {
      const fs::path csv_path = fs::weakly_canonical(options.csv_path, ec);
      for (const char* name : {"accuracy.dat", "accuracy.gp", "accuracy.png", "accuracy.svg"})
        if (!ec && csv_path == fs::weakly_canonical(dir / name, ec))
          throw InputError(options.csv_path, 0, std::string("is also the plot's ") + name);
    }
    dat_file.emplace(dir / "accuracy.dat");
    gp_file.emplace(dir / "accuracy.gp");
  }

  const bool progress = ::isatty(STDERR_FILENO);
  std::vector<AccuracyWidth> results;
  for (const std::string& w : accuracy_widths()) {
    if (progress) std::cerr << "gmcc accuracy: width " << w << " ..." << std::endl;
    set_activity("measuring width " + w);
    results.push_back(measure_accuracy(w, o));
  }

  if (csv_file) csv_file->commit(provenance_csv_line() + accuracy_csv(results));
  if (dat_file) dat_file->commit(accuracy_plot_data(results, o));
  if (gp_file) gp_file->commit(accuracy_plot_script(o));
  write_stdout(accuracy_table(results, o));
  if (options.plot_dir.empty()) return 0;

  return draw_with_gnuplot(dir, "accuracy", "gmcc accuracy");
}

}  // namespace gmcc::cli

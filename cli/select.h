#pragma once
// `gmcc select`: the feasible set of one image against one canonical gamut and the three
// selection rules (docs/cli.md "gmcc select").

#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/chromaticity.h>
#include <gmcc/selection/mean_3d.h>
#include <gmcc/validation/colour_csv.h>

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace gmcc::cli {

struct SelectOptions {
  std::string canonical_path;
  std::string image_path;
  bool json = false;
  std::string expand_policy = "none";
  std::string expand_factor = "0";  // read exactly, like every number gmcc reads
  std::string mean3d_method = "analytic";
  std::string precision_bits = "0";
  std::string order = "12";  // integers are read exactly and range-checked (integer_option)
  std::string samples = "1000000";
  std::string seed = "1";
  std::string nonpositive_blue = "drop";
  std::string canonical_illuminant = "1,1,1";
  std::string illuminants_path;      // plausible lights: Finlayson's illumination constraint
  std::string on_empty = "none";     // none | grow-canonical | min-violation
  std::string space = "2d";          // 2d (perspective, the paper) | 3d (Forsyth's CRULE)
  std::string black = "include";     // 3d: add black (0,0,0) to the canonical gamut
};

/// Register the subcommand and its options on `app`; returns the subcommand.
CLI::App* add_select_command(CLI::App& app, SelectOptions& options);

/// The options of one run, parsed and checked.
struct SelectSettings {
  bool json = false;
  NonPositiveBluePolicy nonpositive_blue = NonPositiveBluePolicy::drop;
  Expansion expansion;
  Colour canonical_illuminant{1, 1, 1};
  Mean3dOptions mean3d;
  std::string on_empty = "none";  // none | grow-canonical | min-violation
};

/// Parse and check the options (numbers read exactly, integers range-checked).
/// \throws InputError naming the option.
SelectSettings select_settings(const SelectOptions& options);

/// The whole output of `gmcc select` for two parsed colour files: one JSON document (docs/cli.md "JSON output")
/// or the summary. Split from run_select so that the pipeline runs in-process (fuzz/).
/// \throws InputError when the files admit no answer (no usable colour, unbounded F).
/// `illuminants`, when given, are the plausible lights of the illumination constraint.
std::string select_output(const SelectSettings& settings, const ColourTable& canonical,
                          const ColourTable& image, const ColourTable* illuminants = nullptr);

/// Run it: options, files, select_output, then the output written at once (never a partial
/// document). Returns the exit status; bad input throws gmcc::InputError (exit 2 at the edge).
int run_select(const SelectOptions& options);

}  // namespace gmcc::cli

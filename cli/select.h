#pragma once
// `gmcc select`: the feasible set of one image (or, with --images, of many) against one canonical
// gamut and the three selection rules (docs/cli.md "gmcc select"). The pipeline is the library's
// (gmcc/selection/select_scene.h); this file reads options and files and prints.

#include "expansion_option.h"

#include <gmcc/selection/prepare_canonical.h>
#include <gmcc/selection/select_scene.h>
#include <gmcc/input/colour_csv.h>

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace gmcc::cli {

struct SelectOptions {
  std::string canonical_path;
  std::string image_path;
  std::string images_path;  // batch: JSON Lines, one scene a line (docs/cli.md "Batch selection")
  bool json = false;
  std::string expand_policy = "none";
  std::string expand_factor = "0";  // read exactly, like every number gmcc reads
  // The 3-D mean's defaults are the library's (Mean3dOptions); integers are read exactly and
  // range-checked (integer_option) against the library's ranges (mean_3d.h).
  std::string mean3d_method = to_string(Mean3dOptions{}.method);
  std::string precision_bits = std::to_string(Mean3dOptions{}.precision_bits);
  std::string order = std::to_string(Mean3dOptions{}.order);
  std::string samples = std::to_string(Mean3dOptions{}.samples);
  std::string seed = std::to_string(Mean3dOptions{}.seed);
  std::string nonpositive_blue = "drop";
  std::string canonical_illuminant = "1,1,1";
  std::string illuminants_path;      // plausible lights: Finlayson's illumination constraint
  std::string truth;                 // r,g,b of the true light: score each rule against it
  std::string on_empty = "none";     // none | grow-canonical | min-violation
  std::string space = "2d";          // 2d (perspective, the paper) | 3d (Forsyth's CRULE)
  std::string black = "include";     // 3d: add black (0,0,0) to the canonical gamut
  std::string illuminant_worst_case = "on";  // on | off: each rule's illuminant-space worst case
  bool record = false;  // --images: the record form (docs/cli.md "Record contract")
  std::string threads = "0";  // --images: worker threads (0: all cores); records do not depend on it
  /// The parsed subcommand, to tell an option given from its default (set by add_select_command;
  /// without it, an option counts as given when its value differs from the default).
  const CLI::App* command = nullptr;
};

/// One light r,g,b given as an option's text (--canonical-illuminant, --truth), read exactly,
/// every channel > 0. \throws InputError naming the option and quoting the text.
Colour light_option(const std::string& name, const std::string& text);

/// The plausible lights of an --illuminants file for the 3-D illumination constraint: pixel
/// colours, every channel > 0. \throws InputError naming the file and the line of a bad light.
std::vector<Colour> plausible_lights(const std::string& path);

/// Register the subcommand and its options on `app`; returns the subcommand.
CLI::App* add_select_command(CLI::App& app, SelectOptions& options);

/// The options of one run, parsed and checked: the library's typed options and the rest.
struct SelectSettings {
  bool json = false;
  bool record = false;                // --record: select_scene_record per scene
  unsigned threads = 0;               // --threads (0: all cores)
  SelectSceneOptions scene;           // illuminants are filled in from the file
  std::optional<Colour> truth;        // --truth
  bool canonical_illuminant_given = false;
};

/// Parse and check the options (numbers read exactly, integers range-checked, options that
/// cannot apply together rejected). Reads no file.
/// \throws InputError naming the option.
SelectSettings select_settings(const SelectOptions& options);

/// What the library's SceneInputError means for the command line: the file and line of the
/// colour at fault (or the option), with the option to use where one helps.
InputError select_input_error(const SceneInputError& error, const ColourTable& canonical,
                              const ColourTable* image, const ColourTable* illuminants);

/// The whole output of `gmcc select` for two parsed colour files: one JSON document (docs/cli.md "JSON output")
/// or the summary. Split from run_select so that the pipeline runs in-process (fuzz/).
/// \throws InputError when the files admit no answer (no usable colour, unbounded F).
/// `illuminants`, when given, are the plausible lights of the illumination constraint.
std::string select_output(const SelectSettings& settings, const ColourTable& canonical,
                          const ColourTable& image, const ColourTable* illuminants = nullptr);

/// The warning for a map c ⊘ e made with the default canonical light (docs/cli.md "gmcc select").
void warn_default_canonical_illuminant(const std::string& option);

/// Run it: options, files, select_output, then the output written at once (never a partial
/// document). Returns the exit status; bad input throws gmcc::InputError (exit 2 at the edge).
int run_select(const SelectOptions& options);

}  // namespace gmcc::cli

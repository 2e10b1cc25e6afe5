#pragma once
// The command line's own choices, written once for every command that offers them (the library's
// vocabularies, such as recovery policies or colour sets, come from its name tables instead).

#include <string>
#include <vector>

namespace gmcc::cli {

/// `--space`: 2d, the perspective route (chromaticities); 3d, diagonal maps (Forsyth's CRULE).
inline const std::vector<std::string> space_choices = {"2d", "3d"};
/// A switch such as `--illuminant-worst-case`: on or off.
inline const std::vector<std::string> switch_choices = {"on", "off"};

}  // namespace gmcc::cli

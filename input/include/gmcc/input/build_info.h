#pragma once
/// \file build_info.h
/// What this build of gmcc is: its version and the git commit it was built from, recorded in
/// every output's provenance (docs/cli.md "Provenance") and printed by `gmcc --version` and
/// `gmcc cite`. Written at build time by cmake/build_info.cmake.

#include <string_view>

namespace gmcc {

/// The release version, "major.minor.patch" (CMakeLists.txt `project(... VERSION ...)`).
std::string_view gmcc_version();
/// The full hash of the git commit built, followed by "-dirty" when tracked files differed from
/// it at build time; "unknown" when built outside a git checkout.
std::string_view gmcc_commit();
/// The committer date of that commit, YYYY-MM-DD; "unknown" outside a git checkout.
std::string_view gmcc_commit_date();

}  // namespace gmcc

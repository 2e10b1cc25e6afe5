#pragma once
/// \file gehler_shi_report.h
/// The readable table of the Gehler–Shi experiment (gehler_shi_experiment.h): the data used per
/// camera, then per group (camera, or camera and light group) and surface count the share of
/// empty feasible sets and the recovery angular error of the three rules beside grey world and
/// max-RGB on the same scenes. Deterministic text; statistics from error_statistics.h.

#include <gmcc/validation/gamut_experiment.h>
#include <gmcc/validation/gehler_shi_experiment.h>

#include <string>

namespace gmcc {

/// The table described above, for the result of run_gamut_experiment on `setup`.
/// \param result the experiment's result. \param setup what gehler_shi_setup made (its per-camera counts).
std::string gehler_shi_table(const ExperimentResult& result, const GehlerShiSetup& setup);

}  // namespace gmcc

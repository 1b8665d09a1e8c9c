#pragma once
/// @file optimal_progress.hpp
/// Where `poinsot optimize` stands, for its terminal progress line: the runs of both kinds
/// (optimal_run.hpp, multibody_optimal_run.hpp) report it through a callback.
#include <string>

#include "poinsot/optimal/direct_progress.hpp"

namespace poinsot::io {

/// The progress of a run, for a terminal display: the phase ("direct", "phased", "indirect",
/// "verification", "replay"; a multibody run: "direct", "replay") and, during the direct method, where Ipopt
/// is; during the indirect one, where Newton is.
struct OptimalProgress {
  std::string phase;
  optimal::DirectProgress direct;  ///< meaningful while phase is "direct"
  int newton_iteration = 0;        ///< phase "indirect": the Newton iterations so far (0: none yet)
  double newton_residual = 0.0;    ///< phase "indirect": the last iteration's scaled residual (max norm)
};

}  // namespace poinsot::io

#pragma once
/// @file direct_progress.hpp
/// Where a direct solve stands, for a progress display (the terminal line of `poinsot optimize`): the
/// single-body collocation (direct_collocation.hpp) and the multibody transcriptions (multibody_direct.hpp)
/// report it after every Ipopt iteration.

namespace poinsot::optimal {

/// Where a direct solve stands: the mesh, its intervals, and Ipopt's iteration on it.
struct DirectProgress {
  int mesh_iteration = 0;  ///< 1, 2, ... (the first mesh is 1)
  int intervals = 0;
  /// 0: the first Ipopt run on this mesh; then Ipopt restarted with other settings, or a stalled run retraced
  int restart = 0;
  int nlp_iteration = 0;
  double objective = 0.0;
  double infeasibility = 0.0;  ///< Ipopt's constraint violation
  /// On the first mesh, the start being solved (0 … starts − 1) of CollocationOptions::starts; 0 later.
  int start = 0;
  int starts = 1;  ///< the starts of the first mesh (1 on later meshes)
};

}  // namespace poinsot::optimal

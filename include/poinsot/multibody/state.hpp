#pragma once
/// @file state.hpp
/// The mutable state of a multibody system: per body the position of the centre of mass x (space frame, m),
/// the rotation R (body → space), the velocity v = ẋ (space frame, m/s) and the body-frame angular velocity ω
/// (rad/s, Ṙ = R j(ω)), plus the time t (s).

#include <vector>

#include "poinsot/core/types.hpp"

namespace poinsot::multibody {

struct BodyState {
  Vec3 x_space = Vec3::Zero();           ///< centre of mass, m
  Mat3 R_space_body = Mat3::Identity();  ///< rotation body → space
  Vec3 v_space = Vec3::Zero();           ///< velocity of the centre of mass, m/s
  Vec3 omega_body = Vec3::Zero();        ///< angular velocity, body frame, rad/s
};

struct State {
  double time = 0.0;  ///< s
  std::vector<BodyState> bodies;
};

}  // namespace poinsot::multibody

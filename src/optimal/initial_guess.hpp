#pragma once
/// @file initial_guess.hpp (internal)
/// The initial guess of the direct method's NLP (solve_direct): the eigenaxis turn with a transverse rate
/// bump, about the torque-free motion from a spinning start, or the momentum-dumping motion of a detumble;
/// the bump turned about the eigenaxis for each of CollocationOptions::starts.
#include <vector>

#include "collocation_nlp.hpp"

namespace poinsot::optimal::detail {

/// An initial guess of the NLP's variables, and whether it has an eigenaxis that its transverse bump can be
/// turned about (CollocationOptions::starts).
struct Guess {
  std::vector<double> z;
  bool has_eigenaxis = false;
};

/// The eigenaxis guess: q(t) = q_0 ⊗ exp(s Θ n / 2), ω = Θ n / T (body frame) plus a transverse bump turned
/// by `turn` (rad) about n, u = 0, ν = 0. From a spinning start (ω_0 ≠ 0, fixed final attitude) the same
/// about the torque-free motion R_free(t), ω_free(t): R = R_free exp(s r), r = log(R_free(T)ᵀ R_f),
/// ω = ω_free + s(ω_f − ω_free(T)) + r/T — the guess follows the spin over every turn instead of taking the
/// shortest rotation to R_f.
Guess initial_guess(const CollocationNlp& nlp, double T, double turn);

}  // namespace poinsot::optimal::detail

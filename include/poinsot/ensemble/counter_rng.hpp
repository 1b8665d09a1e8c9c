#pragma once
/// @file counter_rng.hpp
/// Random draws that depend only on (seed, sample index, stream, draw number): the counter-based generator
/// Philox4x64-10 of Salmon, Moraes, Dror & Shaw (2011, "Parallel random numbers: as easy as 1, 2, 3", SC'11;
/// Random123). Philox is a keyed bijection of a 256-bit counter; with key (seed, "poinsot") and counter
/// (sample, stream, ⌊draw/4⌋, 0) the d-th draw of a stream is word d mod 4 of one bijection. No state is
/// carried from one sample to the next, so a sample's draws are the same whichever thread, SIMD lane, process
/// or node computes it, and any sample can be recomputed alone.
///
/// Streams separate the quantities of a sample (moments, axes, ω, ...), so that adding a dispersion to one
/// quantity does not change the draws of another.
#include <array>
#include <cstdint>

namespace poinsot::ensemble {

/// The independent streams of one sample (the second word of Philox's counter).
enum class Stream : std::uint64_t {
  moments = 1,
  axes = 2,
  mass = 3,
  center_of_mass = 4,
  omega = 5,
  attitude = 6,
  torque = 7,
};

class SampleStream {
 public:
  SampleStream(std::uint64_t seed, std::uint64_t sample, Stream stream);

  /// The next raw 64-bit word (draw number draws()).
  std::uint64_t next_word();
  /// The next uniform number in the open interval (0, 1): (⌊w/2¹¹⌋ + ½)·2⁻⁵³, one draw.
  double uniform();
  /// The next standard normal number by Box–Muller, √(−2 ln u₁)·cos(2π u₂): two draws.
  double normal();
  /// How many words this stream has handed out.
  std::uint64_t draws() const { return draw_; }

 private:
  std::uint64_t seed_, sample_, stream_;
  std::uint64_t draw_ = 0;
  std::array<std::uint64_t, 4> block_{};
};

}  // namespace poinsot::ensemble

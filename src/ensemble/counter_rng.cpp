#include "poinsot/ensemble/counter_rng.hpp"

#include <cmath>
#include <numbers>

#include <Random123/philox.h>

namespace poinsot::ensemble {
namespace {
// The second key word: "poinsot" in ASCII, so that the streams differ from other users of Philox with the
// same seed.
constexpr std::uint64_t kKeyTag = 0x706f696e736f74ULL;
}  // namespace

SampleStream::SampleStream(std::uint64_t seed, std::uint64_t sample, Stream stream)
    : seed_(seed), sample_(sample), stream_(static_cast<std::uint64_t>(stream)) {}

std::uint64_t SampleStream::next_word() {
  const std::uint64_t word = draw_ % 4;
  if (word == 0) {
    const r123::Philox4x64 philox;
    const r123::Philox4x64::ctr_type counter = {{sample_, stream_, draw_ / 4, 0}};
    const r123::Philox4x64::key_type key = {{seed_, kKeyTag}};
    const auto out = philox(counter, key);
    for (std::size_t i = 0; i < 4; ++i)
      block_[i] = out.v[i];
  }
  ++draw_;
  return block_[word];
}

double SampleStream::uniform() {
  constexpr double kUlp = 1.0 / 9007199254740992.0;  // 2⁻⁵³
  return (static_cast<double>(next_word() >> 11) + 0.5) * kUlp;
}

double SampleStream::normal() {
  const double u1 = uniform();
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace poinsot::ensemble

// Fuzz harness: the multibody scenario reader (io/scenario/multibody_scenario.hpp) on arbitrary TOML text.
#include <string_view>

#include "fuzz_support.hpp"
#include "poinsot/io/scenario/multibody_scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);  // NOLINT: bytes as text
  poinsot::fuzz::expect_clean(
      [&] { poinsot::io::parse_multibody_scenario(text, "fuzz.toml", poinsot::fuzz::kNoDir); });
  return 0;
}

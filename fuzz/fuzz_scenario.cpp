// Fuzz harness: the single-body scenario reader (io/scenario/scenario.hpp) on arbitrary TOML text.
#include <string_view>

#include "fuzz_support.hpp"
#include "poinsot/io/scenario/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);  // NOLINT: bytes as text
  poinsot::fuzz::expect_clean([&] { poinsot::io::parse_scenario(text, "fuzz.toml", poinsot::fuzz::kNoDir); });
  return 0;
}

// Fuzz harness: composite body files (inertia/body_file.hpp) on arbitrary TOML text.
#include <string>

#include "fuzz_support.hpp"
#include "poinsot/inertia/body_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);  // NOLINT: bytes as text
  poinsot::fuzz::expect_clean([&] { poinsot::inertia::parse_body(text, poinsot::fuzz::kNoDir); });
  return 0;
}

// Tests of text_file.hpp: the size limit is checked before reading, devices and folders are refused, the
// environment variable raises the default.
#include "poinsot/core/text_file.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot {
namespace {

std::string message_of(const std::string& path, std::size_t limit) {
  return test::message_of<InvalidInput>([&] { read_file_limited(path, "thing", limit, "--max-thing"); },
                                        path);
}

TEST(TextFile, ReadsAFileWithinTheLimitAndRefusesALargerOne) {
  const auto path = ::poinsot::test::temp_path("poinsot_text_file_test.txt");
  {
    std::ofstream out(path, std::ios::binary);
    out << "0123456789";
  }
  EXPECT_EQ(read_file_limited(path.string(), "thing", 10, "--max-thing"), "0123456789");
  test::expect_has(message_of(path.string(), 9),
                   {"thing: \"", "is 10 bytes; the limit is 9 bytes", "raise it with --max-thing"});
  std::filesystem::remove(path);
}

TEST(TextFile, RefusesDevicesFoldersAndMissingFiles) {
  test::expect_has(message_of("/dev/zero", 100), {"\"/dev/zero\" is not a regular file"});
  test::expect_has(message_of("/", 100), {"is a folder"});
  test::expect_has(message_of("/nonexistent/poinsot/x", 100), {"cannot read \"/nonexistent/poinsot/x\""});
}

TEST(TextFile, DefaultLimitFromTheEnvironment) {
  ::unsetenv("POINSOT_MAX_FILE_BYTES");
  EXPECT_EQ(default_max_file_bytes(), std::size_t{64} << 20);
  ::setenv("POINSOT_MAX_FILE_BYTES", "1234", 1);
  EXPECT_EQ(default_max_file_bytes(), 1234u);
  ::setenv("POINSOT_MAX_FILE_BYTES", "12x", 1);  // not a number: the default
  EXPECT_EQ(default_max_file_bytes(), std::size_t{64} << 20);
  ::unsetenv("POINSOT_MAX_FILE_BYTES");
}

}  // namespace
}  // namespace poinsot

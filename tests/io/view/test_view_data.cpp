#include "../../../src/io/view/view_data.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <string>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

namespace fs = std::filesystem;

TEST(ViewFrameRows, KeepsEveryRowUpToTheLimitThenAConstantStrideAndTheLast) {
  for (long long n : {1LL, 2LL, 3LL, 10LL, 1999LL, 2000LL, 2001LL, 4001LL, 12345LL, 1000000LL}) {
    for (int frames : {2, 3, 7, 2000}) {
      const auto rows = frame_rows(n, frames);
      ASSERT_FALSE(rows.empty());
      EXPECT_LE(static_cast<long long>(rows.size()), std::max<long long>(frames, 1)) << n << " " << frames;
      EXPECT_EQ(rows.front(), 0);
      EXPECT_EQ(rows.back(), n - 1);
      if (n <= frames) {
        EXPECT_EQ(static_cast<long long>(rows.size()), n);
        continue;
      }
      const long long stride = rows[1] - rows[0];
      EXPECT_EQ(stride, (n - 1 + frames - 2) / (frames - 1));
      for (std::size_t i = 1; i + 1 < rows.size(); ++i)
        EXPECT_EQ(rows[i] - rows[i - 1], stride);
      EXPECT_GT(rows.back() - rows[rows.size() - 2], 0);
      EXPECT_LE(rows.back() - rows[rows.size() - 2], stride);
    }
  }
  EXPECT_TRUE(frame_rows(0, 10).empty());
}

TEST(ViewEquivalentShapes, ABoxAndAnEllipsoidComeBackWithTheirOwnSizes) {
  // The inertia layer's closed forms (shapes.hpp) are the oracle: the uniform box of edges (0.3, 0.1, 0.02) m
  // and the ellipsoid of semi-axes (0.5, 0.2, 0.1) m, 2 kg, give back their half-edges and semi-axes along
  // the principal axes (moments ascending: the longest dimension first).
  const double m = 2.0;
  const auto box = equivalent_shapes(inertia::box(m, {0.3, 0.1, 0.02}).inertia_com, m);
  EXPECT_NEAR(box.box_half_extents[0], 0.15, 1e-14);
  EXPECT_NEAR(box.box_half_extents[1], 0.05, 1e-14);
  EXPECT_NEAR(box.box_half_extents[2], 0.01, 1e-14);
  EXPECT_NEAR(box.axes.determinant(), 1.0, 1e-14);
  const auto ell = equivalent_shapes(inertia::ellipsoid(m, {0.1, 0.5, 0.2}).inertia_com, m);
  EXPECT_NEAR(ell.ellipsoid_semi_axes[0], 0.5, 1e-14);
  EXPECT_NEAR(ell.ellipsoid_semi_axes[1], 0.2, 1e-14);
  EXPECT_NEAR(ell.ellipsoid_semi_axes[2], 0.1, 1e-14);
  EXPECT_NEAR(std::abs(ell.axes(1, 0)), 1.0, 1e-14);  // the longest semi-axis is the body's y
  // A lamina (K singular): zero thickness, no NaN.
  const auto plate = equivalent_shapes(inertia::plate(m, 0.4, 0.2).inertia_com, m);
  EXPECT_NEAR(plate.box_half_extents[2], 0.0, 1e-7);
}

TEST(ViewCsvFrames, ReadsTheKeptRowsExactlyAndRefusesABadNumber) {
  const fs::path dir = ::poinsot::test::temp_path("poinsot_io_view_data");
  fs::create_directories(dir);
  const fs::path p = dir / "t.csv";
  {
    std::ofstream out(p);
    out << std::setprecision(17) << "# units\nt,a\n";
    for (int i = 0; i < 10; ++i)
      out << i * 0.1 << "," << 1.0 / (i + 3) << "\n";
  }
  const CsvFrames f = read_csv_frames(p.string(), 4);
  EXPECT_EQ(f.rows, 10);
  EXPECT_EQ(f.stride, 3);
  ASSERT_EQ(f.values.size(), 4u);
  EXPECT_EQ(f.values[1][1], 1.0 / 6);  // row 3, read back exactly from its 17 digits
  EXPECT_EQ(f.values[3][0], 9 * 0.1);  // the last row
  {
    std::ofstream out(p);
    out << "t,a\n0,1\n0.1,x\n";
  }
  EXPECT_THROW(read_csv_frames(p.string(), 4), InvalidInput);
  EXPECT_THROW(read_csv_frames((dir / "missing.csv").string(), 4), InvalidInput);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace poinsot::io

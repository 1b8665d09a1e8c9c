// The columns of an ensemble's per-sample table (see ensemble_table.hpp).
#include "poinsot/io/run/ensemble_table.hpp"

namespace poinsot::io {
namespace {

using Row = ensemble::SampleRow;
using Kind = SampleColumn::Kind;

std::array<double, 4> three(const Vec3& v) {
  return {v[0], v[1], v[2], 0.0};
}

std::vector<SampleColumn> make_columns() {
  std::vector<SampleColumn> c;
  c.push_back({"index", {"index"}, Kind::unsigned_integer, nullptr, [](const Row& r) { return r.index; }});
  c.push_back({"rejected",
               {"rejected"},
               Kind::integer,
               [](const Row& r) { return std::array<double, 4>{static_cast<double>(r.rejected)}; },
               nullptr});
  c.push_back({"repaired",
               {"repaired"},
               Kind::integer,
               [](const Row& r) { return std::array<double, 4>{r.repaired ? 1.0 : 0.0}; },
               nullptr});
  c.push_back(
      {"moments", {"I1", "I2", "I3"}, Kind::real, [](const Row& r) { return three(r.moments); }, nullptr});
  c.push_back({"misalignment",
               {"misalignment"},
               Kind::real,
               [](const Row& r) { return std::array<double, 4>{r.misalignment}; },
               nullptr});
  c.push_back({"omega0",
               {"omega0_x", "omega0_y", "omega0_z"},
               Kind::real,
               [](const Row& r) { return three(r.omega0); },
               nullptr});
  // One column per output; a capture-free function per index, made by a template over the index.
  const auto output = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<std::array<double, 4> (*)(const Row&), sizeof...(I)>{
        [](const Row& r) { return std::array<double, 4>{r.out[I]}; }...};
  }
  (std::make_index_sequence<ensemble::kOutputCount>{});
  for (std::size_t o = 0; o < ensemble::kOutputCount; ++o)
    c.push_back({ensemble::kOutputNames[o], {ensemble::kOutputNames[o]}, Kind::real, output[o], nullptr});
  c.push_back({"quaternion_final",
               {"q_w", "q_x", "q_y", "q_z"},
               Kind::real,
               [](const Row& r) {
                 const Quat q = r.final_state.quaternion();
                 return std::array<double, 4>{q.w(), q.x(), q.y(), q.z()};
               },
               nullptr});
  c.push_back({"omega_final",
               {"omega_x", "omega_y", "omega_z"},
               Kind::real,
               [](const Row& r) { return three(r.final_state.omega_body); },
               nullptr});
  return c;
}

}  // namespace

std::span<const SampleColumn> sample_columns() {
  static const std::vector<SampleColumn> columns = make_columns();
  return columns;
}

}  // namespace poinsot::io

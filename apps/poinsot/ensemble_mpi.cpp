#include "ensemble_mpi.hpp"

#include <climits>
#include <cstdlib>
#include <cstring>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

#ifdef POINSOT_HAVE_MPI
#include <mpi.h>
#endif

namespace poinsot::cli {

static_assert(std::is_trivially_copyable_v<ensemble::BlockNode>);

bool mpi_launched() {
#ifdef POINSOT_HAVE_MPI
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr;
#else
  return false;
#endif
}

#ifdef POINSOT_HAVE_MPI

namespace {

/// Gathers each rank's bytes on rank 0, concatenated in rank order.
std::vector<char> gather_bytes(const void* data, std::size_t bytes, int size) {
  if (bytes > static_cast<std::size_t>(INT_MAX)) {
    throw InvalidInput(
        fmt::format("ensemble: {} bytes of rows on one rank exceed MPI's 2 GB message limit; "
                    "expected per-sample output off or more ranks",
                    bytes));
  }
  const int mine = static_cast<int>(bytes);
  std::vector<int> counts(static_cast<std::size_t>(size)), displs(static_cast<std::size_t>(size));
  MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  long long total = 0;
  for (int r = 0; r < size; ++r) {
    displs[static_cast<std::size_t>(r)] = static_cast<int>(total);
    total += counts[static_cast<std::size_t>(r)];
  }
  std::vector<char> all(static_cast<std::size_t>(total));
  MPI_Gatherv(data, mine, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
  return all;
}

template <class T>
std::vector<T> gather(const std::vector<T>& mine, int size) {
  const std::vector<char> bytes = gather_bytes(mine.data(), mine.size() * sizeof(T), size);
  std::vector<T> out(bytes.size() / sizeof(T));
  if (!bytes.empty()) std::memcpy(static_cast<void*>(out.data()), bytes.data(), bytes.size());
  return out;
}

/// A bucket of output `output`'s quantile sketch, for the byte-wise gather.
struct FlatBucket {
  std::int32_t output;
  ensemble::QuantileBucket bucket;
};

/// A SampleRow as plain numbers, for the byte-wise gather (Eigen's types are not trivially copyable).
struct FlatRow {
  std::uint64_t index;
  std::int64_t rejected, repaired;
  double moments[3], misalignment, omega0[3], out[ensemble::kOutputCount], t, R[9], omega[3];
};

FlatRow flatten(const ensemble::SampleRow& r) {
  FlatRow f{};
  f.index = r.index;
  f.rejected = r.rejected;
  f.repaired = r.repaired ? 1 : 0;
  f.misalignment = r.misalignment;
  f.t = r.final_state.time;
  for (int k = 0; k < 3; ++k) {
    f.moments[k] = r.moments[k];
    f.omega0[k] = r.omega0[k];
    f.omega[k] = r.final_state.omega_body[k];
    for (int j = 0; j < 3; ++j)
      f.R[3 * k + j] = r.final_state.R_space_body(k, j);
  }
  for (int q = 0; q < ensemble::kOutputCount; ++q)
    f.out[q] = r.out[static_cast<std::size_t>(q)];
  return f;
}

ensemble::SampleRow unflatten(const FlatRow& f) {
  ensemble::SampleRow r;
  r.index = f.index;
  r.rejected = static_cast<int>(f.rejected);
  r.repaired = f.repaired != 0;
  r.misalignment = f.misalignment;
  r.final_state.time = f.t;
  for (int k = 0; k < 3; ++k) {
    r.moments[k] = f.moments[k];
    r.omega0[k] = f.omega0[k];
    r.final_state.omega_body[k] = f.omega[k];
    for (int j = 0; j < 3; ++j)
      r.final_state.R_space_body(k, j) = f.R[3 * k + j];
  }
  for (int q = 0; q < ensemble::kOutputCount; ++q)
    r.out[static_cast<std::size_t>(q)] = f.out[q];
  return r;
}

}  // namespace

MpiSession::MpiSession() {
  if (!mpi_launched()) return;
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) MPI_Init(nullptr, nullptr);
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  if (active_) MPI_Finalize();
}

ensemble::EnsembleResult run_ensemble_mpi(const MpiSession& s, const ensemble::Sampler& sampler,
                                          const ensemble::EnsembleOptions& o,
                                          std::vector<ensemble::SampleRow>* own_rows) {
  const std::uint64_t n = ensemble::block_count(o.samples);
  const auto share = [&](int r) {
    return n * static_cast<std::uint64_t>(r) / static_cast<std::uint64_t>(s.size());
  };
  std::vector<ensemble::BlockNode> nodes;  // O(log blocks) subtrees of block statistics
  ensemble::EnsembleResult mine =
      ensemble::run_ensemble_blocks(sampler, o, share(s.rank()), share(s.rank() + 1), &nodes);
  const std::vector<ensemble::BlockNode> all_nodes = gather(nodes, s.size());
  // The quantile sketches (per-sample output off, or rows kept per rank) are integer counts: merged in any
  // order, the same bits.
  if (own_rows != nullptr) {
    for (const ensemble::SampleRow& row : mine.rows)
      for (std::size_t q = 0; q < static_cast<std::size_t>(ensemble::kOutputCount); ++q)
        mine.sketches[q].add(row.out[q]);
  }
  std::vector<FlatBucket> buckets;
  for (int q = 0; q < ensemble::kOutputCount; ++q)
    for (const ensemble::QuantileBucket& b : mine.sketches[static_cast<std::size_t>(q)].buckets())
      buckets.push_back({q, b});
  const std::vector<FlatBucket> all_buckets = gather(buckets, s.size());
  // The histograms: every rank derived the same edges from the same pilot; integer counts, summed.
  std::vector<std::int64_t> histogram_counts;
  for (const ensemble::FixedHistogram& h : mine.histograms) {
    const std::vector<std::int64_t> f = h.flat_counts();
    if (h.has_edges()) histogram_counts.insert(histogram_counts.end(), f.begin(), f.end());
  }
  const std::vector<std::int64_t> all_histogram_counts = gather(histogram_counts, s.size());
  std::vector<FlatRow> flat;
  if (own_rows == nullptr) {
    flat.reserve(mine.rows.size());
    for (const ensemble::SampleRow& row : mine.rows)
      flat.push_back(flatten(row));
  }
  const std::vector<FlatRow> all_rows = gather(flat, s.size());
  const long long counts[3] = {static_cast<long long>(mine.completed),
                               static_cast<long long>(mine.body_steps), mine.interrupted ? 1LL : 0LL};
  long long totals[3] = {0, 0, 0};
  MPI_Reduce(counts, totals, 3, MPI_LONG_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
  double wall = 0.0;
  MPI_Reduce(&mine.wall_time_s, &wall, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
  if (own_rows != nullptr) *own_rows = std::move(mine.rows);
  if (s.rank() != 0) return mine;
  ensemble::EnsembleResult r;
  r.path = fmt::format("{} on {} MPI ranks", mine.path, s.size());
  r.nominal = mine.nominal;
  ensemble::set_statistics(r, all_nodes, o.samples);  // the tree of one process, bit for bit
  for (const FlatBucket& f : all_buckets)
    r.sketches[static_cast<std::size_t>(f.output)].add_bucket(f.bucket);
  for (std::size_t q = 0; q < static_cast<std::size_t>(ensemble::kOutputCount); ++q)
    if (mine.histograms[q].has_edges())
      r.histograms[q] = ensemble::FixedHistogram(mine.histograms[q].range(), mine.histograms[q].bins());
  if (all_histogram_counts.size() != histogram_counts.size() * static_cast<std::size_t>(s.size())) {
    throw InvalidInput("ensemble: the MPI ranks' histograms have different edges; expected the same pilot");
  }
  const std::span<const std::int64_t> counts_all(all_histogram_counts);
  for (std::size_t offset = 0, rank = 0; rank < static_cast<std::size_t>(s.size()); ++rank) {
    for (ensemble::FixedHistogram& h : r.histograms) {
      if (!h.has_edges()) continue;
      const std::size_t length = static_cast<std::size_t>(h.bins()) + 3;  // as flat_counts()
      h.add_flat_counts(counts_all.subspan(offset, length));
      offset += length;
    }
  }
  r.rows.reserve(all_rows.size());
  for (const FlatRow& f : all_rows)
    r.rows.push_back(unflatten(f));
  r.completed = static_cast<std::uint64_t>(totals[0]);
  r.body_steps = totals[1];
  r.wall_time_s = wall;
  r.interrupted = totals[2] > 0;
  return r;
}

#else

MpiSession::MpiSession() = default;
MpiSession::~MpiSession() = default;

ensemble::EnsembleResult run_ensemble_mpi(const MpiSession&, const ensemble::Sampler& sampler,
                                          const ensemble::EnsembleOptions& o,
                                          std::vector<ensemble::SampleRow>*) {
  return ensemble::run_ensemble(sampler, o);  // one process: the rows stay in the result
}

#endif

}  // namespace poinsot::cli

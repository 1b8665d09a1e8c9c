#include "ensemble_hdf5.hpp"

#include <array>
#include <cstdio>
#include <vector>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/io/run/ensemble_table.hpp"

#ifdef POINSOT_HAVE_HDF5
#include <hdf5.h>
#endif

namespace poinsot::cli {

bool hdf5_available() {
#ifdef POINSOT_HAVE_HDF5
  return true;
#else
  return false;
#endif
}

#ifdef POINSOT_HAVE_HDF5

namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw ComputationFailed(fmt::format("output: HDF5 failed to write {}", what));
}

/// A dataset of n rows of `columns` values of HDF5 type `type` under `group`.
void write_dataset(hid_t group, const char* name, hid_t type, const void* data, hsize_t n, hsize_t columns) {
  const hsize_t dims[2] = {n, columns};
  const hid_t space = H5Screate_simple(columns == 1 ? 1 : 2, dims, nullptr);
  const hid_t set = H5Dcreate2(group, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (set < 0) {
    H5Sclose(space);
    throw ComputationFailed(fmt::format("output: HDF5 failed to create the dataset {}", name));
  }
  const herr_t status = n > 0 ? H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
  H5Dclose(set);
  H5Sclose(space);
  check(status, name);
}

}  // namespace

void write_ensemble_hdf5(const std::string& path, const ensemble::EnsembleResult& r) {
  const std::string tmp = path + ".tmp";
  const hid_t file = H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) throw ComputationFailed(fmt::format("output: HDF5 cannot create \"{}\"", tmp));
  try {
    const hid_t group = H5Gcreate2(file, "samples", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const std::size_t n = r.rows.size();
    // One dataset per column group of io/run/ensemble_table.hpp: n rows of its width.
    for (const io::SampleColumn& c : io::sample_columns()) {
      const std::size_t width = c.csv_names.size();
      if (c.kind == io::SampleColumn::Kind::unsigned_integer) {
        std::vector<unsigned long long> values(n);
        for (std::size_t i = 0; i < n; ++i)
          values[i] = c.index(r.rows[i]);
        write_dataset(group, c.dataset.c_str(), H5T_NATIVE_ULLONG, values.data(), n, 1);
      } else if (c.kind == io::SampleColumn::Kind::integer) {
        std::vector<int> values(n * width);
        for (std::size_t i = 0; i < n; ++i) {
          const std::array<double, 4> v = c.values(r.rows[i]);
          for (std::size_t k = 0; k < width; ++k)
            values[width * i + k] = static_cast<int>(v[k]);
        }
        write_dataset(group, c.dataset.c_str(), H5T_NATIVE_INT, values.data(), n, width);
      } else {
        std::vector<double> values(n * width);
        for (std::size_t i = 0; i < n; ++i) {
          const std::array<double, 4> v = c.values(r.rows[i]);
          for (std::size_t k = 0; k < width; ++k)
            values[width * i + k] = v[k];
        }
        write_dataset(group, c.dataset.c_str(), H5T_NATIVE_DOUBLE, values.data(), n, width);
      }
    }
    H5Gclose(group);
  } catch (...) {
    H5Fclose(file);
    std::remove(tmp.c_str());
    throw;
  }
  check(H5Fclose(file), path);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw ComputationFailed(fmt::format("output: cannot rename \"{}\" to \"{}\"", tmp, path));
  }
}

#else

void write_ensemble_hdf5(const std::string& path, const ensemble::EnsembleResult&) {
  throw InvalidInput(fmt::format("output: \"{}\": poinsot was built without HDF5 (libhdf5-dev)", path));
}

#endif

}  // namespace poinsot::cli

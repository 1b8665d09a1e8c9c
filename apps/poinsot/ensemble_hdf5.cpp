#include "ensemble_hdf5.hpp"

#include <cstdio>
#include <vector>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

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
    std::vector<unsigned long long> index(n);
    std::vector<int> rejected(n), repaired(n);
    std::vector<double> misalignment(n), moments(3 * n), omega0(3 * n), omega(3 * n), q(4 * n);
    std::vector<std::vector<double>> out(ensemble::kOutputCount, std::vector<double>(n));
    for (std::size_t i = 0; i < n; ++i) {
      const ensemble::SampleRow& row = r.rows[i];
      index[i] = row.index;
      rejected[i] = row.rejected;
      repaired[i] = row.repaired ? 1 : 0;
      misalignment[i] = row.misalignment;
      const Quat qf = row.final_state.quaternion();
      const double qv[4] = {qf.w(), qf.x(), qf.y(), qf.z()};
      for (std::size_t k = 0; k < 3; ++k) {
        moments[3 * i + k] = row.moments[static_cast<Eigen::Index>(k)];
        omega0[3 * i + k] = row.omega0[static_cast<Eigen::Index>(k)];
        omega[3 * i + k] = row.final_state.omega_body[static_cast<Eigen::Index>(k)];
      }
      for (std::size_t k = 0; k < 4; ++k)
        q[4 * i + k] = qv[k];
      for (std::size_t o = 0; o < out.size(); ++o)
        out[o][i] = row.out[o];
    }
    write_dataset(group, "index", H5T_NATIVE_ULLONG, index.data(), n, 1);
    write_dataset(group, "rejected", H5T_NATIVE_INT, rejected.data(), n, 1);
    write_dataset(group, "repaired", H5T_NATIVE_INT, repaired.data(), n, 1);
    write_dataset(group, "moments", H5T_NATIVE_DOUBLE, moments.data(), n, 3);
    write_dataset(group, "misalignment", H5T_NATIVE_DOUBLE, misalignment.data(), n, 1);
    write_dataset(group, "omega0", H5T_NATIVE_DOUBLE, omega0.data(), n, 3);
    for (std::size_t o = 0; o < out.size(); ++o)
      write_dataset(group, ensemble::kOutputNames[o], H5T_NATIVE_DOUBLE, out[o].data(), n, 1);
    write_dataset(group, "quaternion_final", H5T_NATIVE_DOUBLE, q.data(), n, 4);
    write_dataset(group, "omega_final", H5T_NATIVE_DOUBLE, omega.data(), n, 3);
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

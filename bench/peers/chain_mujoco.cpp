// MuJoCo 2.2's side of the peer comparison: the chain as nested MJCF bodies with ball joints (reduced
// coordinates, a quaternion per joint), loaded with mj_loadXML from in-memory files (a VFS), stepped by
// mj_step. Integrator "Euler" (MuJoCo's default: semi-implicit Euler, implicit in joint damping only, of
// which there is none) and, as a second entry, "RK4". Nothing that adds dissipation: joint damping, armature
// and friction loss are 0 (MuJoCo's defaults, written out), contacts are disabled (there are no geoms
// anyway). The poses are read after mj_forward (not timed), because after mj_step d->xpos and friends still
// describe the state at the start of the step.
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "chain_bench.hpp"

namespace poinsot::bench {
namespace {

/// The chain as MJCF files in a VFS: "chain0.xml" holds the options and links 0..39, and its innermost body
/// includes "chain1.xml" with the next 40, and so on. (MuJoCo's XML parser, tinyxml2, refuses elements nested
/// more than 100 deep; each included file is parsed on its own, and MuJoCo allows <include> inside a body.)
void add_chain_mjcf(mjVFS& vfs, int n, const char* integrator) {
  constexpr int kPerFile = 40;
  const double m = kRodMass, l = kRodLength, r = kRodRadius;
  const double ja = m * r * r / 2.0, jt = m * (3 * r * r + l * l) / 12.0;
  char line[256];
  for (int first = 0, file = 0; first < n; first += kPerFile, ++file) {
    const int last = std::min(n, first + kPerFile);
    std::string xml = "<mujoco model=\"chain\">\n";
    if (file == 0) {
      std::snprintf(line, sizeof line,
                    "<option timestep=\"%.17g\" gravity=\"0 0 %.17g\" integrator=\"%s\">\n"
                    "<flag contact=\"disable\"/>\n</option>\n<worldbody>\n",
                    kChainDt, -kGravity, integrator);
      xml += line;
    }
    for (int i = first; i < last; ++i) {  // body frame at the pivot, centre of mass l/2 along x
      std::snprintf(line, sizeof line, "<body name=\"link%d\" pos=\"%.17g 0 0\">\n", i, i == 0 ? 0.0 : l);
      xml += line;
      xml += "<joint type=\"ball\" pos=\"0 0 0\" damping=\"0\" armature=\"0\" frictionloss=\"0\"/>\n";
      std::snprintf(line, sizeof line,
                    "<inertial pos=\"%.17g 0 0\" mass=\"%.17g\" diaginertia=\"%.17g %.17g %.17g\"/>\n",
                    l / 2.0, m, ja, jt, jt);
      xml += line;
    }
    if (last < n) xml += "<include file=\"chain" + std::to_string(file + 1) + ".xml\"/>\n";
    for (int i = first; i < last; ++i)
      xml += "</body>\n";
    xml += file == 0 ? "</worldbody>\n</mujoco>\n" : "</mujoco>\n";
    const std::string name = "chain" + std::to_string(file) + ".xml";
    mj_makeEmptyFileVFS(&vfs, name.c_str(), static_cast<int>(xml.size()));
    std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, name.c_str())], xml.data(), xml.size());
  }
}

template <bool kRk4>
class MujocoChain {
 public:
  explicit MujocoChain(int n) : n_(n) {
    mjVFS vfs;
    mj_defaultVFS(&vfs);
    add_chain_mjcf(vfs, n, kRk4 ? "RK4" : "Euler");
    char error[1000] = "";
    model_ = mj_loadXML("chain0.xml", &vfs, error, sizeof error);
    mj_deleteVFS(&vfs);
    if (model_ == nullptr) throw std::runtime_error(std::string("mujoco: ") + error);
    data_ = mj_makeData(model_);
  }
  ~MujocoChain() {
    mj_deleteData(data_);
    mj_deleteModel(model_);
  }
  MujocoChain(const MujocoChain&) = delete;
  MujocoChain& operator=(const MujocoChain&) = delete;

  void step() { mj_step(model_, data_); }
  void reset() { mj_resetData(model_, data_); }

  void poses(std::vector<BodyPose>& out) {
    mj_forward(model_, data_);
    out.resize(static_cast<std::size_t>(n_));
    for (int i = 0; i < n_; ++i) {
      const int id = i + 1;  // body 0 is the world
      BodyPose& b = out[static_cast<std::size_t>(i)];
      const mjtNum* x = data_->xipos + 3 * id;  // centre of mass and inertial frame (= body frame here)
      const mjtNum* R = data_->ximat + 9 * id;  // row major
      mjtNum vel[6];                            // [ω; v] at the centre of mass, space frame
      mj_objectVelocity(model_, data_, mjOBJ_BODY, id, vel, 0);
      b.x_space = {x[0], x[1], x[2]};
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          b.R_space_body(r, c) = R[3 * r + c];
      b.omega_space = {vel[0], vel[1], vel[2]};
      b.v_space = {vel[3], vel[4], vel[5]};
    }
  }

 private:
  int n_;
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
};

}  // namespace

void register_mujoco() {
  // 256 links: about 40 ms a step on a 2.3 GHz core (the chain's dense 768 x 768 mass matrix is factored each
  // step), so 5000 steps take minutes: one repetition.
  register_chain<MujocoChain<false>>("mujoco_euler", 256, 256);
  register_chain<MujocoChain<true>>("mujoco_rk4", 64);  // four evaluations a step: N = 256 would take minutes
}

}  // namespace poinsot::bench

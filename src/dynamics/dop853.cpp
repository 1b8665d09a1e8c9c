#include "poinsot/dynamics/dop853.hpp"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "adaptive_control.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::dynamics {
namespace {
using detail::Vec7;

constexpr int kStages = 12;    // stages of the 8th-order step
constexpr int kExtended = 16;  // with the FSAL stage f(t + h, y1) and the 3 stages of the dense output

// Nodes and coefficients of DOP853 (Hairer, Nørsett & Wanner, Solving ODEs I, §II.5, Table 5.4 and code
// DOP853). Row 12 of A is b, the weights of the 8th-order solution.
constexpr std::array<double, kExtended> C = {0.0,
                                             0.526001519587677318785587544488e-01,
                                             0.789002279381515978178381316732e-01,
                                             0.118350341907227396726757197510,
                                             0.281649658092772603273242802490,
                                             0.333333333333333333333333333333,
                                             0.25,
                                             0.307692307692307692307692307692,
                                             0.651282051282051282051282051282,
                                             0.6,
                                             0.857142857142857142857142857142,
                                             1.0,
                                             1.0,
                                             0.1,
                                             0.2,
                                             0.777777777777777777777777777778};

using Row = std::array<double, kExtended>;
constexpr std::array<Row, kExtended> A = [] {
  std::array<Row, kExtended> a{};
  a[1][0] = 5.26001519587677318785587544488e-2;
  a[2][0] = 1.97250569845378994544595329183e-2;
  a[2][1] = 5.91751709536136983633785987549e-2;
  a[3][0] = 2.95875854768068491816892993775e-2;
  a[3][2] = 8.87627564304205475450678981324e-2;
  a[4][0] = 2.41365134159266685502369798665e-1;
  a[4][2] = -8.84549479328286085344864962717e-1;
  a[4][3] = 9.24834003261792003115737966543e-1;
  a[5][0] = 3.7037037037037037037037037037e-2;
  a[5][3] = 1.70828608729473871279604482173e-1;
  a[5][4] = 1.25467687566822425016691814123e-1;
  a[6][0] = 3.7109375e-2;
  a[6][3] = 1.70252211019544039314978060272e-1;
  a[6][4] = 6.02165389804559606850219397283e-2;
  a[6][5] = -1.7578125e-2;
  a[7][0] = 3.70920001185047927108779319836e-2;
  a[7][3] = 1.70383925712239993810214054705e-1;
  a[7][4] = 1.07262030446373284651809199168e-1;
  a[7][5] = -1.53194377486244017527936158236e-2;
  a[7][6] = 8.27378916381402288758473766002e-3;
  a[8][0] = 6.24110958716075717114429577812e-1;
  a[8][3] = -3.36089262944694129406857109825;
  a[8][4] = -8.68219346841726006818189891453e-1;
  a[8][5] = 2.75920996994467083049415600797e1;
  a[8][6] = 2.01540675504778934086186788979e1;
  a[8][7] = -4.34898841810699588477366255144e1;
  a[9][0] = 4.77662536438264365890433908527e-1;
  a[9][3] = -2.48811461997166764192642586468;
  a[9][4] = -5.90290826836842996371446475743e-1;
  a[9][5] = 2.12300514481811942347288949897e1;
  a[9][6] = 1.52792336328824235832596922938e1;
  a[9][7] = -3.32882109689848629194453265587e1;
  a[9][8] = -2.03312017085086261358222928593e-2;
  a[10][0] = -9.3714243008598732571704021658e-1;
  a[10][3] = 5.18637242884406370830023853209;
  a[10][4] = 1.09143734899672957818500254654;
  a[10][5] = -8.14978701074692612513997267357;
  a[10][6] = -1.85200656599969598641566180701e1;
  a[10][7] = 2.27394870993505042818970056734e1;
  a[10][8] = 2.49360555267965238987089396762;
  a[10][9] = -3.0467644718982195003823669022;
  a[11][0] = 2.27331014751653820792359768449;
  a[11][3] = -1.05344954667372501984066689879e1;
  a[11][4] = -2.00087205822486249909675718444;
  a[11][5] = -1.79589318631187989172765950534e1;
  a[11][6] = 2.79488845294199600508499808837e1;
  a[11][7] = -2.85899827713502369474065508674;
  a[11][8] = -8.87285693353062954433549289258;
  a[11][9] = 1.23605671757943030647266201528e1;
  a[11][10] = 6.43392746015763530355970484046e-1;
  a[12][0] = 5.42937341165687622380535766363e-2;
  a[12][5] = 4.45031289275240888144113950566;
  a[12][6] = 1.89151789931450038304281599044;
  a[12][7] = -5.8012039600105847814672114227;
  a[12][8] = 3.1116436695781989440891606237e-1;
  a[12][9] = -1.52160949662516078556178806805e-1;
  a[12][10] = 2.01365400804030348374776537501e-1;
  a[12][11] = 4.47106157277725905176885569043e-2;
  a[13][0] = 5.61675022830479523392909219681e-2;
  a[13][6] = 2.53500210216624811088794765333e-1;
  a[13][7] = -2.46239037470802489917441475441e-1;
  a[13][8] = -1.24191423263816360469010140626e-1;
  a[13][9] = 1.5329179827876569731206322685e-1;
  a[13][10] = 8.20105229563468988491666602057e-3;
  a[13][11] = 7.56789766054569976138603589584e-3;
  a[13][12] = -8.298e-3;
  a[14][0] = 3.18346481635021405060768473261e-2;
  a[14][5] = 2.83009096723667755288322961402e-2;
  a[14][6] = 5.35419883074385676223797384372e-2;
  a[14][7] = -5.49237485713909884646569340306e-2;
  a[14][10] = -1.08347328697249322858509316994e-4;
  a[14][11] = 3.82571090835658412954920192323e-4;
  a[14][12] = -3.40465008687404560802977114492e-4;
  a[14][13] = 1.41312443674632500278074618366e-1;
  a[15][0] = -4.28896301583791923408573538692e-1;
  a[15][5] = -4.69762141536116384314449447206;
  a[15][6] = 7.68342119606259904184240953878;
  a[15][7] = 4.06898981839711007970213554331;
  a[15][8] = 3.56727187455281109270669543021e-1;
  a[15][12] = -1.39902416515901462129418009734e-3;
  a[15][13] = 2.9475147891527723389556272149;
  a[15][14] = -9.15095847217987001081870187138;
  return a;
}();

// Error estimators: e5 = b − b̂ (5th order), e3 = b − b̃ (3rd order, b̃ nonzero at stages 0, 8, 11).
constexpr Row E5 = [] {
  Row e{};
  e[0] = 0.1312004499419488073250102996e-1;
  e[5] = -0.1225156446376204440720569753e1;
  e[6] = -0.4957589496572501915214079952;
  e[7] = 0.1664377182454986536961530415e1;
  e[8] = -0.3503288487499736816886487290;
  e[9] = 0.3341791187130174790297318841;
  e[10] = 0.8192320648511571246570742613e-1;
  e[11] = -0.2235530786388629525884427845e-1;
  return e;
}();
constexpr Row E3 = [] {
  Row e = A[12];
  e[0] -= 0.244094488188976377952755905512;
  e[8] -= 0.733846688281611857341361741547;
  e[11] -= 0.220588235294117647058823529412e-1;
  return e;
}();

// Dense output: the 4 highest coefficients of the order-7 interpolant (Hairer's d4j..d7j).
constexpr std::array<Row, 4> D = [] {
  std::array<Row, 4> d{};
  d[0] = {-0.84289382761090128651353491142e1,
          0,
          0,
          0,
          0,
          0.56671495351937776962531783590,
          -0.30689499459498916912797304727e1,
          0.23846676565120698287728149680e1,
          0.21170345824450282767155149946e1,
          -0.87139158377797299206789907490,
          0.22404374302607882758541771650e1,
          0.63157877876946881815570249290,
          -0.88990336451333310820698117400e-1,
          0.18148505520854727256656404962e2,
          -0.91946323924783554000451984436e1,
          -0.44360363875948939664310572000e1};
  d[1] = {0.10427508642579134603413151009e2,
          0,
          0,
          0,
          0,
          0.24228349177525818288430175319e3,
          0.16520045171727028198505394887e3,
          -0.37454675472269020279518312152e3,
          -0.22113666853125306036270938578e2,
          0.77334326684722638389603898808e1,
          -0.30674084731089398182061213626e2,
          -0.93321305264302278729567221706e1,
          0.15697238121770843886131091075e2,
          -0.31139403219565177677282850411e2,
          -0.93529243588444783865713862664e1,
          0.35816841486394083752465898540e2};
  d[2] = {0.19985053242002433820987653617e2,
          0,
          0,
          0,
          0,
          -0.38703730874935176555105901742e3,
          -0.18917813819516756882830838328e3,
          0.52780815920542364900561016686e3,
          -0.11573902539959630126141871134e2,
          0.68812326946963000169666922661e1,
          -0.10006050966910838403183860980e1,
          0.77771377980534432092869265740,
          -0.27782057523535084065932004339e1,
          -0.60196695231264120758267380846e2,
          0.84320405506677161018159903784e2,
          0.11992291136182789328035130030e2};
  d[3] = {-0.25693933462703749003312586129e2,
          0,
          0,
          0,
          0,
          -0.15418974869023643374053993627e3,
          -0.23152937917604549567536039109e3,
          0.35763911791061412378285349910e3,
          0.93405324183624310003907691704e2,
          -0.37458323136451633156875139351e2,
          0.10409964950896230045147246184e3,
          0.29840293426660503123344363579e2,
          -0.43533456590011143754432175058e2,
          0.96324553959188282948394950600e2,
          -0.39177261675615439165231486172e2,
          -0.14972683625798562581422125276e3};
  return d;
}();

}  // namespace

struct Dop853Integrator::Impl {
  Impl(detail::EulerRhs rhs, const IntegratorOptions& o)
      : loop(kName, std::move(rhs), o, detail::StepController{1.0 / 8.0, 0.0, 6.0, 1.0 / 0.333}) {}
  detail::AdaptiveLoop loop;
  std::array<Vec7, kExtended> k{};  // k[0] = f(t, y) of the next step (FSAL) once a step is accepted
  // Dense output of the last accepted step: its stages, start, end, size and the interpolation coefficients.
  std::array<Vec7, kExtended> k_last{};
  Vec7 y_old = Vec7::Zero();
  Vec7 y_new = Vec7::Zero();
  double t_old = 0.0;
  double h_old = 0.0;
  bool has_step = false;
  mutable bool dense_ready = false;
  mutable std::array<Vec7, 8> rcont{};

  /// One attempt of step h from (t, y): stages 1..11, then y1 (row 12 of A is b); the scaled error of
  /// Hairer's combined 5th- and 3rd-order estimators.
  double attempt(double t, const Vec7& y, double h) {
    for (int s = 1; s <= kStages; ++s) {
      Vec7 acc = Vec7::Zero();
      for (int j = 0; j < s; ++j)
        if (A[s][j] != 0.0) acc += A[s][j] * k[j];
      if (s < kStages) {
        k[s] = loop.f(t + C[s] * h, y + h * acc);
      } else {
        y_new = y + h * acc;
      }
    }
    Vec7 err5 = Vec7::Zero();
    Vec7 err3 = Vec7::Zero();
    for (int j = 0; j < kStages; ++j) {
      err5 += E5[j] * k[j];
      err3 += E3[j] * k[j];
    }
    const Vec7 sk = detail::error_scale(y, y_new, loop.opt.rtol, loop.opt.atol);
    const double n5 = err5.cwiseQuotient(sk).squaredNorm();
    const double n3 = err3.cwiseQuotient(sk).squaredNorm();
    double deno = n5 + 0.01 * n3;
    if (!(deno > 0.0)) deno = 1.0;
    return std::abs(h) * n5 / std::sqrt(7.0 * deno);
  }

  /// Keeps the stages of the accepted step for dense output and its FSAL stage f(t + h, y1) as the next k[0].
  void accept(double t, const Vec7& y, double h) {
    k[kStages] = loop.f(t + h, y_new);
    k_last = k;
    y_old = y;
    t_old = t;
    h_old = h;
    has_step = true;
    dense_ready = false;
    k[0] = k[kStages];
  }

  void prepare_dense() const;
};

void Dop853Integrator::Impl::prepare_dense() const {
  // The three extra stages (Hairer's k14..k16) need the stages of the last step; they are computed here, at
  // the first dense output asked for in that step, into a copy so that the method's own state is untouched.
  std::array<Vec7, kExtended> kk = k_last;
  const double h = h_old;
  for (int s = kStages + 1; s < kExtended; ++s) {
    Vec7 acc = Vec7::Zero();
    for (int j = 0; j < s; ++j)
      if (A[s][j] != 0.0) acc += A[s][j] * kk[j];
    kk[s] = loop.f(t_old + C[s] * h, y_old + h * acc);
  }
  const Vec7 ydiff = y_new - y_old;
  const Vec7 bspl = h * kk[0] - ydiff;
  rcont[0] = y_old;
  rcont[1] = ydiff;
  rcont[2] = bspl;
  rcont[3] = ydiff - h * kk[kStages] - bspl;
  for (int i = 0; i < 4; ++i) {
    Vec7 acc = Vec7::Zero();
    for (int j = 0; j < kExtended; ++j)
      if (D[i][j] != 0.0) acc += D[i][j] * kk[j];
    rcont[4 + i] = h * acc;
  }
  dense_ready = true;
}

Dop853Integrator::Dop853Integrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                                   const IntegratorOptions& options)
    : impl_(std::make_unique<Impl>(detail::EulerRhs(body, std::move(torque)), options)) {}

Dop853Integrator::~Dop853Integrator() = default;

double Dop853Integrator::nominal_step() const {
  return impl_->loop.opt.dt;
}

StepResult Dop853Integrator::step(State& state, double dt) {
  Impl& m = *impl_;
  return m.loop.step(
      state, dt, m.k[0], m.y_new, [&m](double t, const Vec7& y, double h) { return m.attempt(t, y, h); },
      [&m](double t, const Vec7& y, double h) { m.accept(t, y, h); });
}

State Dop853Integrator::dense_output(double t) const {
  const Impl& m = *impl_;
  if (!m.has_step) {
    throw InvalidInput(fmt::format("dop853: dense output at t = {} s asked before any step", t));
  }
  if (!m.dense_ready) m.prepare_dense();
  const auto& r = m.rcont;
  const double s = (t - m.t_old) / m.h_old;
  const double s1 = 1.0 - s;
  const Vec7 y =
      r[0] + s * (r[1] + s1 * (r[2] + s * (r[3] + s1 * (r[4] + s * (r[5] + s1 * (r[6] + s * r[7]))))));
  State out;
  out.time = t;
  out.R_space_body = detail::rotation_of(y);
  out.omega_body = y.tail<3>();
  return out;
}

}  // namespace poinsot::dynamics

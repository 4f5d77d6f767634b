// Parallel bond of Potyondy & Cundall (Int. J. Rock Mech. Min. Sci. 41 (2004) 1329): a cemented
// disc of radius R̄ = λ̄ min(R_i, R_j) with normal and shear stiffness per area k̄n, k̄s (Pa/m).
// The normal force follows the total change of centre distance (as MUSEN does); shear force,
// twist and bending moments are incremental and turn with the bond. It fails in tension when
// σ = F_n,tension/A + |M_s| R̄/I reaches σ̄_c and in shear when τ = |F_s|/A + |M_n| R̄/J reaches τ̄_c.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "comminute/bonds/bond_law.hpp"
#include "comminute/bonds/bond_step.hpp"
#include "comminute/core/vector_clones.hpp"

namespace comminute::bonds {
namespace {

class ParallelBond final : public BondLaw {
 public:
  explicit ParallelBond(const CaseTable& t)
      : kn_(t.number("normal_stiffness", Limits::positive())),
        ks_(t.number("shear_stiffness", Limits::positive())),
        sigma_(t.number("tensile_strength", Limits::positive())),
        tau_(t.number("shear_strength", Limits::positive())),
        sigma_sd_(t.number("tensile_strength_sd", Limits::non_negative(), 0.0)),
        tau_sd_(t.number("shear_strength_sd", Limits::non_negative(), 0.0)),
        lambda_(t.number("radius_multiplier", Limits::positive(), 1.0)),
        per_kn_(1.0 / kn_),
        per_ks_(1.0 / ks_) {}

  std::string name() const override { return "parallel_bond"; }

  BondState create(double ri, double rj, double length, const Vec3& normal,
                   Rng& rng) const override {
    BondState s;
    s.normal = normal;
    s.length0 = length;
    s.radius = lambda_ * std::min(ri, rj);
    // strengths scatter normally (mean, standard deviation) per bond, redrawn when not positive
    s.tensile_strength = draw(rng, sigma_, sigma_sd_);
    s.shear_strength = draw(rng, tau_, tau_sd_);
    return s;
  }

  BondLoad update(BondState& s, const BondMotion& m) const override {
    if (s.failed != FailureMode::none) return {};
    Vec3 shear_force = s.shear_force, moment = s.moment;
    double tension = 0, energy = 0, fails = 0;
    advance(s.normal, s.radius, s.length0, s.tensile_strength, s.shear_strength, m, shear_force,
            moment, tension, energy, fails);
    s.normal = m.normal;
    s.shear_force = shear_force;
    s.moment = moment;
    s.strain_energy = energy;
    if (fails != 0) {
      fail(s, tension);
      return {};
    }
    return {-tension * m.normal + shear_force, moment};
  }

  // The arithmetic of update() for an intact bond, without branches, so that the batch of
  // update_range vectorises it: the stored shear force and moment (in, out) turned into the new
  // frame and advanced, the normal force (tension on j > 0), the strain energy, and whether the
  // bond fails (1) or not (0).
  [[gnu::always_inline]] void advance(const Vec3& last_normal, double r, double length0,
                                      double tensile_strength, double shear_strength,
                                      const BondMotion& m, Vec3& shear_force, Vec3& moment,
                                      double& tension, double& energy, double& fails) const {
    const double area = std::numbers::pi * r * r;
    const double inertia = 0.25 * area * r * r;  // I = πR̄⁴/4
    const double polar = 2 * inertia;            // J = πR̄⁴/2
    // one division: 1/A, then 1/I = 4π/A², 1/J = 2π/A²
    const double per_area = 1.0 / area;
    const double per_polar = 2 * std::numbers::pi * per_area * per_area;
    const double per_inertia = 2 * per_polar;
    // stored shear force and moment turn with the bond into the new frame
    const BondTurn turn(last_normal, m.normal);
    shear_force = turn(shear_force);
    moment = turn(moment);
    const Vec3& n = m.normal;
    const Vec3 twist = dot(m.rotation_increment, n) * n;
    const Vec3 bend = m.rotation_increment - twist;
    // Potyondy & Cundall, Int. J. Rock Mech. Min. Sci. 41 (2004) 1329: ΔF̄s = -k̄s A ΔUs, ΔM̄n = -k̄s J
    // Δθn, ΔM̄s = -k̄n I Δθs
    shear_force -= ks_ * area * m.slip_increment;
    shear_force -= dot(shear_force, n) * n;
    moment -= ks_ * polar * twist + kn_ * inertia * bend;
    // normal force on j from the total elongation (tension pulls j towards i)
    const double elongation = m.length - length0;
    tension = kn_ * area * elongation;
    const double mn = dot(moment, n);
    const Vec3 ms = moment - mn * n;
    const double fs2 = norm2(shear_force), ms2 = norm2(ms);
    // ½ (F̄n²/(k̄n A) + |F̄s|²/(k̄s A) + M̄n²/(k̄s J) + |M̄s|²/(k̄n I)), F̄n²/(k̄n A) = F̄n δ
    energy = 0.5 * (tension * elongation + fs2 * per_area * per_ks_ +
                    mn * mn * per_polar * per_ks_ + ms2 * per_inertia * per_kn_);
    // Potyondy & Cundall, Int. J. Rock Mech. Min. Sci. 41 (2004) 1329: σ = -F̄n/A + |M̄s| R̄/I, τ =
    // |F̄s|/A + |M̄n| R̄/J; σ ≥ σ̄c as |M̄s| R̄/I ≥ σ̄c − F̄n,tension/A, squared where the right side is
    // positive (no roots; stress() forms σ and τ for a bond that fails)
    const double tensile_left = tensile_strength - tension * per_area;
    const double bend_lever = r * per_inertia;
    const double shear_left = shear_strength - std::abs(mn) * r * per_polar;
    const bool tensile =
        (tensile_left <= 0) | (ms2 * bend_lever * bend_lever >= tensile_left * tensile_left);
    const bool shear = (shear_left <= 0) | (fs2 * per_area * per_area >= shear_left * shear_left);
    fails = (tensile | shear) ? 1.0 : 0.0;
  }

  // Marks bond s (its state advanced by advance(), which found it failing) failed: the mode from
  // the larger of σ/σ̄c and τ/τ̄c, the strain energy released, nothing carried any more.
  void fail(BondState& s, double tension) const {
    const double r = s.radius, area = std::numbers::pi * r * r;
    const double per_area = 1.0 / area;
    const double per_polar = 2 * std::numbers::pi * per_area * per_area;
    const double per_inertia = 2 * per_polar;
    const Vec3& n = s.normal;
    const double mn = dot(s.moment, n);
    const Vec3 ms = s.moment - mn * n;
    // Potyondy & Cundall, Int. J. Rock Mech. Min. Sci. 41 (2004) 1329: σ = -F̄n/A + |M̄s| R̄/I, τ =
    // |F̄s|/A + |M̄n| R̄/J
    const double sigma = tension * per_area + norm(ms) * r * per_inertia;
    const double tau = norm(s.shear_force) * per_area + std::abs(mn) * r * per_polar;
    const double load_t = sigma / s.tensile_strength, load_s = tau / s.shear_strength;
    s.failed = load_t >= load_s ? FailureMode::tensile : FailureMode::shear;
    s.damage = 1.0;
    s.dissipated += s.strain_energy;  // the strain energy is released when the bond fails
    s.strain_energy = 0;
    s.shear_force = {};
    s.moment = {};
  }

  BondStepSums update_range(const BondStep& step, std::size_t begin,
                            std::size_t end) const override;

  double stiffness(const BondState& s) const override {
    return std::max(kn_, ks_) * std::numbers::pi * s.radius * s.radius;
  }

 private:
  static double draw(Rng& rng, double mean, double sd) {
    if (sd <= 0) return mean;
    for (;;) {
      const double v = rng.normal(mean, sd);
      if (v > 0) return v;
    }
  }

  double kn_, ks_, sigma_, tau_, sigma_sd_, tau_sd_, lambda_;
  double per_kn_, per_ks_;  // 1/k̄n, 1/k̄s (m/Pa)
};

// update_range() runs the bonds in batches: the particles' values are gathered bond by bond into
// arrays, the arithmetic (bond_kinematics, advance) runs as one loop over the batch that the
// compiler vectorises, reading and writing the bonds' states in place (BondStates keeps them by
// component), and the loads go to the particles bond by bond, in bond order. The same operations
// in the same order as update(): vector lanes round as scalars do (no fused multiply-add, no
// reassociation), so the batch equals one update() per bond bit for bit.
constexpr std::size_t kBatch = 32;
constexpr std::size_t kAhead = 16;  // bonds ahead whose particles are fetched during the gather

struct Batch {
  // in: x_j − x_i, radii, v_j − v_i, spins, and whether the bond's state stays as it is (1: gone
  // or failed before) or not (0)
  double dx[kBatch], dy[kBatch], dz[kBatch], ri[kBatch], rj[kBatch];
  double dvx[kBatch], dvy[kBatch], dvz[kBatch];
  double wix[kBatch], wiy[kBatch], wiz[kBatch], wjx[kBatch], wjy[kBatch], wjz[kBatch];
  double keep[kBatch];
  // out: the normal force, failure (1), the load on j and the two torques
  double tension[kBatch], fails[kBatch];
  double lx[kBatch], ly[kBatch], lz[kBatch];     // force on j
  double tix[kBatch], tiy[kBatch], tiz[kBatch];  // torque_i
  double tjx[kBatch], tjy[kBatch], tjz[kBatch];  // torque_j
};

// Bond b's place in the state's arrays, by component (restrict: apart from each other and from
// the batch, so that the loop over the batch vectorises without run-time checks of overlap).
struct StateColumns {
  double* __restrict nx, * __restrict ny, * __restrict nz;
  double* __restrict fx, * __restrict fy, * __restrict fz;
  double* __restrict mx, * __restrict my, * __restrict mz;
  double* __restrict energy;
  const double* __restrict length0, * __restrict radius, * __restrict tensile, * __restrict shear;
};

StateColumns columns_at(BondStates& s, std::size_t b) {
  return {s.nx.data() + b,
          s.ny.data() + b,
          s.nz.data() + b,
          s.fx.data() + b,
          s.fy.data() + b,
          s.fz.data() + b,
          s.mx.data() + b,
          s.my.data() + b,
          s.mz.data() + b,
          s.strain_energy.data() + b,
          s.length0.data() + b,
          s.radius.data() + b,
          s.tensile_strength.data() + b,
          s.shear_strength.data() + b};
}

// The arithmetic of bonds b0 .. b0 + n (vectorised; AVX-512 and AVX2 versions besides the baseline
// one, core/vector_clones.hpp). A bond that keeps its state has it written back unchanged.
COMMINUTE_VECTOR_CLONES void advance_batch(const ParallelBond& bond_law, Batch& __restrict t,
                                           StateColumns c, std::size_t n, double dt) {
  const ParallelBond law = bond_law;  // its constants in a copy of its own: apart from the arrays
  auto [nx, ny, nz, fx, fy, fz, mx, my, mz, energy, length0, radius, tensile, shear] = c;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 last{nx[k], ny[k], nz[k]};
    const BondKinematics km = bond_kinematics(
        {t.dx[k], t.dy[k], t.dz[k]}, t.ri[k], t.rj[k], {t.dvx[k], t.dvy[k], t.dvz[k]},
        {t.wix[k], t.wiy[k], t.wiz[k]}, {t.wjx[k], t.wjy[k], t.wjz[k]}, last, dt);
    const Vec3 shear_force0{fx[k], fy[k], fz[k]}, moment0{mx[k], my[k], mz[k]};
    const double strain0 = energy[k];
    Vec3 shear_force = shear_force0, moment = moment0;
    double tension = 0, strain = 0, fails = 0;
    law.advance(last, radius[k], length0[k], tensile[k], shear[k], km.m, shear_force, moment,
                tension, strain, fails);
    const Vec3& n_now = km.m.normal;
    const Vec3 load = -tension * n_now + shear_force;
    const Vec3 ti = cross(km.lever_i, load) + moment, tj = cross(km.lever_j, load) + moment;
    const bool keep = t.keep[k] != 0;
    nx[k] = keep ? last.x : n_now.x, ny[k] = keep ? last.y : n_now.y;
    nz[k] = keep ? last.z : n_now.z;
    fx[k] = keep ? shear_force0.x : shear_force.x, fy[k] = keep ? shear_force0.y : shear_force.y;
    fz[k] = keep ? shear_force0.z : shear_force.z;
    mx[k] = keep ? moment0.x : moment.x, my[k] = keep ? moment0.y : moment.y;
    mz[k] = keep ? moment0.z : moment.z;
    energy[k] = keep ? strain0 : strain;
    t.tension[k] = tension, t.fails[k] = fails;
    t.lx[k] = load.x, t.ly[k] = load.y, t.lz[k] = load.z;
    t.tix[k] = ti.x, t.tiy[k] = ti.y, t.tiz[k] = ti.z;
    t.tjx[k] = tj.x, t.tjy[k] = tj.y, t.tjz[k] = tj.z;
  }
}

BondStepSums ParallelBond::update_range(const BondStep& st, std::size_t begin,
                                        std::size_t end) const {
  BondStepSums sums;
  Batch t;
  BondStates& state = *st.state;
  BondLoadDelivery deliver(st);
  std::array<const double*, 14> column_data;  // looked up once: not per prefetch
  std::ranges::transform(std::as_const(state).columns(), column_data.begin(),
                         [](const std::vector<double>* column) { return column->data(); });
  for (std::size_t b0 = begin; b0 < end; b0 += kBatch) {
    const std::size_t n = std::min(kBatch, end - b0);
    // the states of the next batch, one cache line of eight bonds at a time: many arrays are
    // streamed at once, more than the processor follows by itself
    for (std::size_t b = b0 + kBatch; b < std::min(b0 + 2 * kBatch, end); b += 8)
      for (const double* column : column_data) __builtin_prefetch(column + b);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t b = b0 + k;
      if (b + kAhead < end) {  // the particles of a bond further on
        const std::uint32_t i = st.slot_i[b + kAhead], j = st.slot_j[b + kAhead];
        __builtin_prefetch(st.x + i), __builtin_prefetch(st.x + j);
        __builtin_prefetch(st.v + i), __builtin_prefetch(st.v + j);
        __builtin_prefetch(st.w + i), __builtin_prefetch(st.w + j);
      }
      Vec3 d, dv, wi, wj;
      double ri, rj;
      if (!st.flag[b]) {
        const std::uint32_t i = st.slot_i[b], j = st.slot_j[b];
        d = st.x[j] - st.x[i];
        dv = st.v[j] - st.v[i];
        wi = st.w[i];
        wj = st.w[j];
        ri = st.radius[i];
        rj = st.radius[j];
      } else {  // a gone bond: finite values, its results unused
        d = state.normal(b) * state.length0[b];
        ri = rj = state.radius[b];
      }
      t.dx[k] = d.x, t.dy[k] = d.y, t.dz[k] = d.z, t.ri[k] = ri, t.rj[k] = rj;
      t.dvx[k] = dv.x, t.dvy[k] = dv.y, t.dvz[k] = dv.z;
      t.wix[k] = wi.x, t.wiy[k] = wi.y, t.wiz[k] = wi.z;
      t.wjx[k] = wj.x, t.wjy[k] = wj.y, t.wjz[k] = wj.z;
      t.keep[k] = st.flag[b] || state.failed[b] != FailureMode::none ? 1.0 : 0.0;
    }
    advance_batch(*this, t, columns_at(state, b0), n, st.dt);
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t b = b0 + k;
      if (t.keep[k] == 0 && t.fails[k] == 0) {  // intact and loaded: the common case
        sums.elastic += state.strain_energy[b];
        deliver(b, {t.lx[k], t.ly[k], t.lz[k]}, {t.tix[k], t.tiy[k], t.tiz[k]},
                {t.tjx[k], t.tjy[k], t.tjz[k]});
        continue;
      }
      if (st.flag[b]) {  // gone: nothing
        deliver.nothing(b);
        continue;
      }
      if (state.failed[b] != FailureMode::none) {  // failed before: nothing, as update_bonds()
        st.flag[b] = 2;
        ++sums.failed;
        deliver(b, {}, {}, {});
        continue;
      }
      // fails now (rare): on the whole record
      BondState whole = state.get(b);
      const double before = whole.dissipated;
      fail(whole, t.tension[k]);
      state.set(b, whole);
      sums.released += whole.dissipated - before;
      st.flag[b] = 2;
      ++sums.failed;
      deliver(b, {}, {}, {});  // zeros, as the fold of the arrays adds them
    }
  }
  return sums;
}

std::unique_ptr<BondLaw> make(const CaseTable& t) {
  return std::make_unique<ParallelBond>(t);
}
const bool registered = BondLawRegistry::add("parallel_bond", &make);

}  // namespace
}  // namespace comminute::bonds

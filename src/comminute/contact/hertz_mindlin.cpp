// Hertz–Mindlin contact with Tsuji-type damping and Coulomb friction with tangential history, the
// LIGGGHTS/EDEM formulation (docs/models.md "Contact laws"): F_n = (4/3) E* sqrt(R*) δ^1.5 (Hertz,
// J. reine angew. Math. 1882), S_t = 8 G* a (Mindlin, J. Appl. Mech. 1949), dashpots
// -2 sqrt(5/6) β sqrt(S m*) v (Tsuji, Tanaka & Ishida, Powder Technol. 1992).
// Keys of [contact]: tangential_damping (bool, default true), tangential ("mindlin_rescale_force",
// the default: incremental force, rescaled on unloading, Thornton, Cummins & Cleary, Powder
// Technol. 2013 eq. 18; "mindlin": the total form F_t = -8 G* a xi, LAMMPS `mindlin`, whose
// energy ledger does not close while loaded contacts change their radius); docs/models.md T1.
#include <algorithm>
#include <array>
#include <cmath>

#include "comminute/contact/tangential_friction.hpp"
#include "comminute/core/vector_clones.hpp"

namespace comminute {
namespace {

class HertzMindlin final : public ContactLaw {
 public:
  explicit HertzMindlin(const CaseTable& t)
      : tangential_damping_(t.boolean("tangential_damping", true)),
        rescale_(t.choice("tangential", {"mindlin_rescale_force", "mindlin"},
                          "mindlin_rescale_force") == "mindlin_rescale_force") {}
  std::string name() const override { return "hertz_mindlin"; }
  void declare(ContactStateStore& layout) override {
    slots_.declare(layout, dynamic_friction_, rescale_);
  }

  // One contact: the same steps as a batch of one (compute_batch), so both give the same bits.
  void compute(const ContactKinematics& k, const PairParameters& p, const StateRef& s,
               ContactForces& out) const override {
    const double a = std::sqrt(radius_squared(k.effective_radius, k.overlap));
    const double root = std::sqrt(stiffness_mass(p.effective_modulus, a, k.effective_mass));
    const ProjectedSpring ps = normal_and_spring(k, p, s, a, root, out);
    const Tangential co = tangential(p, a, root, out);
    coulomb_rotated(k, co.kt, co.ct, co.lim, ps.xi * restore_length(ps.before, ps.after),
                    s.vec3(slots_.spring), slots_.flag(s), out);
  }

  // compute() for every contact of the batch: batch(), in its AVX-512, AVX2 or baseline version
  // (core/vector_clones.hpp; a virtual function cannot have versions)
  void compute_batch(const ContactBatch& b) const override { batch(b); }

 private:
  // The contacts of a batch (at most kBatchSize) in stages, each a loop over the batch's contacts:
  // the square roots of the contact radius and of the dashpot each in a loop of their own
  // (independent, so they overlap and vectorise instead of each contact waiting on its own chain
  // of division and roots); the inputs read from the batch's columns and the results written to
  // them, all the arithmetic in structure-of-arrays loops that vectorise: a branch of the law (the
  // spring projected or not, sticking, capped or sliding) is computed for every contact and each
  // keeps its own (whether a contact slides is unpredictable in a flowing bed: 40 % of the contacts
  // of the drum bench). Every contact goes through the same operations as compute(),
  // coulomb_rotated() included.
  COMMINUTE_VECTOR_CLONES void batch(const ContactBatch& b) const {
    using Column = BatchColumn;
    const std::size_t n = b.size;
    const KinematicsColumns& K = *b.kinematics;
    ForceColumns& out = *b.forces;
    const PairParameters* const* P = b.parameters;
    // the inputs: the batch's normal, overlap, its rate and v_t, read in place; in columns of this
    // frame (which nothing else writes, so the loops below vectorise without checks of overlap)
    // the stored spring (after follow_stiffness()), the pair's E*, beta, G*, sqrt(4 G*/E*), mu_s,
    // mu_d, the sliding flag (0 or 1)
    const Column &nx = K.nx, &ny = K.ny, &nz = K.nz, &delta = K.overlap, &rate = K.overlap_rate;
    const Column &vx = K.vx, &vy = K.vy, &vz = K.vz;
    const double dt = K.dt;
    Column arg, a, root, sx, sy, sz;
    Column modulus, beta, shear, shear_root, mu, mu_dynamic, was;
    // the normal force's energy and its dashpot's work; the rotated spring, k_t, c_t, the Coulomb
    // limits (the forces go straight to the batch's columns)
    Column normal_energy, normal_work, rx, ry, rz, kt, ct, stick, slide;
    // the friction law's results: the stored spring, the dashpot's and the slip's work, the
    // spring's energy, the sliding flag (0 or 1)
    Column tx, ty, tz, damping, friction, energy, now;
    // the pairs' parameters: one material pair for the whole batch (the common case, a bed of one
    // material) is spread over the columns, else they are read contact by contact
    const PairParameters* p0 = P[0];
    bool one_pair = true;
    for (std::size_t c = 1; c < n; ++c) one_pair &= P[c] == p0;
    const auto parameter = [&](Column& column, double PairParameters::*field) {
      if (one_pair)
        std::fill_n(column.begin(), n, p0->*field);
      else
        for (std::size_t c = 0; c < n; ++c) column[c] = P[c]->*field;
    };
    parameter(modulus, &PairParameters::effective_modulus);
    parameter(beta, &PairParameters::damping_beta);
    parameter(shear, &PairParameters::effective_shear_modulus);
    parameter(shear_root, &PairParameters::shear_normal_root);
    parameter(mu, &PairParameters::friction);
    parameter(mu_dynamic, &PairParameters::dynamic_friction);
    for (std::size_t c = 0; c < n; ++c) arg[c] = radius_squared(K.effective_radius[c], delta[c]);
    for (std::size_t c = 0; c < n; ++c) a[c] = std::sqrt(arg[c]);
    for (std::size_t c = 0; c < n; ++c)
      arg[c] = stiffness_mass(modulus[c], a[c], K.effective_mass[c]);
    for (std::size_t c = 0; c < n; ++c) root[c] = std::sqrt(arg[c]);
    // the stored springs, first carried to this step's stiffness (rescale)
    for (std::size_t c = 0; c < n; ++c) {
      const StateRef s{b.slots, b.index[c]};
      Vec3& spring = s.vec3(slots_.spring);
      if (rescale_)
        out.friction_dissipation[c] +=
            follow_stiffness(spring, s.f64(slots_.stiffness), mindlin(shear[c], a[c]));
      sx[c] = spring.x;
      sy[c] = spring.y;
      sz[c] = spring.z;
      const float* flag = slots_.flag(s);
      was[c] = flag != nullptr ? *flag : 0.0;
    }
    // normal_and_spring() and tangential(), operation for operation; project_spring()'s two
    // cases chosen per contact, restore_length() applied
    for (std::size_t c = 0; c < n; ++c) {
      const double fel = elastic_force(modulus[c], a[c], delta[c]);
      const double gn = normal_damping(beta[c], root[c]);
      const double fd = gn * rate[c];
      const double fn = fel + fd;
      out.elastic_normal_force[c] = fel;
      out.normal_force[c] = fn;
      normal_energy[c] = elastic_energy(fel, delta[c]);
      normal_work[c] = fd * rate[c] * dt;
      const double len2 = sx[c] * sx[c] + sy[c] * sy[c] + sz[c] * sz[c];
      const double along = sx[c] * nx[c] + sy[c] * ny[c] + sz[c] * nz[c];
      const double px = sx[c] - nx[c] * along, py = sy[c] - ny[c] * along,
                   pz = sz[c] - nz[c] * along;
      const double l2 = px * px + py * py + pz * pz;
      const bool loaded = len2 > 0.0;
      const bool turned = loaded & (l2 > 0.0);
      const double restore = std::sqrt((turned ? len2 : 1.0) / (turned ? l2 : 1.0));
      rx[c] = (loaded ? px : sx[c]) * restore;
      ry[c] = (loaded ? py : sy[c]) * restore;
      rz[c] = (loaded ? pz : sz[c]) * restore;
      kt[c] = mindlin(shear[c], a[c]);
      ct[c] = gn * shear_root[c];
      stick[c] = mu[c] * std::abs(fn);  // friction_limit()
      slide[c] = mu_dynamic[c] * std::abs(fn);
    }
    if (!tangential_damping_) std::fill_n(ct.begin(), n, 0.0);  // (a loop of its own: vectorises)
    // coulomb_rotated(), operation for operation: both branches, and the cap of the sticking one,
    // for every contact (the roots and divisions of the branch not taken are thrown away, even
    // where they are not finite); a dissipation a contact's branch does not add is -0, which
    // leaves any sum as it is
    for (std::size_t c = 0; c < n; ++c) {
      const double x = rx[c] + vx[c] * dt, y = ry[c] + vy[c] * dt,
                   z = rz[c] + vz[c] * dt;  // trial = xi + v_t dt
      const double xi2 = x * x + y * y + z * z;
      const double k = kt[c];
      const double spring2 = k * k * xi2;
      const double lim2 = stick[c] * stick[c];
      const bool slides = (spring2 > lim2) | ((was[c] != 0.0) & (spring2 > slide[c] * slide[c]));
      // sticking: fs = -k_t xi, spring + dashpot capped at mu |F_n| by cutting the dashpot part
      const double fsx = x * -k, fsy = y * -k, fsz = z * -k;
      double f1 = fsx - vx[c] * ct[c], f2 = fsy - vy[c] * ct[c], f3 = fsz - vz[c] * ct[c];
      const double ft2 = f1 * f1 + f2 * f2 + f3 * f3;
      const double cap = stick[c] / std::sqrt(ft2);
      const bool capped = ft2 > lim2;
      f1 = capped ? f1 * cap : f1;
      f2 = capped ? f2 * cap : f2;
      f3 = capped ? f3 * cap : f3;
      const double dashpot = -((f1 - fsx) * vx[c] + (f2 - fsy) * vy[c] + (f3 - fsz) * vz[c]) * dt;
      // sliding: the spring cut back to mu_d |F_n|, no dashpot, the slip's work
      const double cut = slide[c] / (k * std::sqrt(xi2));
      const double cx = x * cut, cy = y * cut, cz = z * cut;
      const double ex = x - cx, ey = y - cy, ez = z - cz;
      const double slip = slide[c] * std::sqrt(ex * ex + ey * ey + ez * ez);
      tx[c] = slides ? cx : x;
      ty[c] = slides ? cy : y;
      tz[c] = slides ? cz : z;
      out.fx[c] = slides ? cx * -k : f1;
      out.fy[c] = slides ? cy * -k : f2;
      out.fz[c] = slides ? cz * -k : f3;
      damping[c] = slides ? -0.0 : dashpot;
      friction[c] = slides ? slip : -0.0;
      energy[c] = 0.5 * k * (slides ? cx * cx + cy * cy + cz * cz : xi2);
      now[c] = slides ? 1.0 : 0.0;
    }
    // the energies into the batch's columns
    for (std::size_t c = 0; c < n; ++c) {
      out.normal_elastic_energy[c] = normal_energy[c];
      out.stored_energy[c] = normal_energy[c] + energy[c];
      out.damping_dissipation[c] = normal_work[c] + damping[c];
      out.friction_dissipation[c] += friction[c];
    }
    // the springs and flags back to the contacts' slots
    for (std::size_t c = 0; c < n; ++c) {
      const StateRef s{b.slots, b.index[c]};
      if (float* flag = slots_.flag(s)) *flag = static_cast<float>(now[c]);
      s.vec3(slots_.spring) = {tx[c], ty[c], tz[c]};
    }
  }

 public:
  double normal_elastic_energy(const PairParameters& p, double r, double delta) const override {
    const double a = std::sqrt(radius_squared(r, delta));
    return elastic_energy(elastic_force(p.effective_modulus, a, delta), delta);
  }

 private:
  // R* delta, whose root is the contact radius a (m^2)
  static double radius_squared(double effective_radius, double delta) {
    return effective_radius * delta;
  }
  // S_n m* = 2 E* a m*, whose root sets the dashpots (N kg/m); E* = `modulus` (Pa)
  static double stiffness_mass(double modulus, double a, double effective_mass) {
    return 2.0 * modulus * a * effective_mass;
  }
  // The normal force and its energies into `out`; the spring carried to this step's stiffness
  // (rescale) and projected onto the tangent plane. `a`: contact radius (m), `root`:
  // sqrt(S_n m*).
  [[gnu::always_inline]] ProjectedSpring normal_and_spring(const ContactKinematics& k,
                                                           const PairParameters& p,
                                                           const StateRef& s, double a, double root,
                                                           ContactForces& out) const {
    const double delta = k.overlap;
    const double fel = elastic_force(p.effective_modulus, a, delta);
    const double fd = normal_damping(p.damping_beta, root) * k.overlap_rate;
    out.elastic_normal_force = fel;
    out.normal_force = fel + fd;
    out.normal_elastic_energy = elastic_energy(fel, delta);
    out.stored_energy = out.normal_elastic_energy;
    out.damping_dissipation = fd * k.overlap_rate * k.dt;
    if (rescale_)
      out.friction_dissipation += follow_stiffness(s.vec3(slots_.spring), s.f64(slots_.stiffness),
                                                   mindlin(p.effective_shear_modulus, a));
    return project_spring(s.vec3(slots_.spring), k.normal);
  }
  // The elastic normal force (N) at contact radius a (m) and overlap delta (m), E* = `modulus`
  // (Pa): S_n = 2 E* a, F = (2/3) S_n delta = (4/3) E* sqrt(R*) delta^1.5.
  static double elastic_force(double modulus, double a, double delta) {
    const double sn = 2.0 * modulus * a;
    const double kn = 2.0 / 3.0 * sn;
    return kn * delta;
  }
  // Its integral from 0 to delta (J): (2/5) k_n delta^2 = (2/5) F delta.
  static double elastic_energy(double force, double delta) { return 0.4 * force * delta; }
  // The normal dashpot c_n (N s/m): F_n,d = -2 sqrt(5/6) beta sqrt(S_n m*) v_n, beta <= 0 here
  // (Tsuji, Tanaka & Ishida, Powder Technol. 71 (1992) 239); `root`: sqrt(S_n m*).
  static double normal_damping(double beta, double root) {
    return -2.0 * std::sqrt(5.0 / 6.0) * beta * root;
  }
  // Mindlin S_t = 8 G* a (N/m), G* = `shear` (Pa)
  static double mindlin(double shear, double a) { return 8.0 * shear * a; }
  // The friction law's coefficients: k_t (N/m), c_t (N s/m) and the Coulomb limits (N).
  struct Tangential {
    double kt = 0, ct = 0;
    FrictionLimit lim;
  };
  Tangential tangential(const PairParameters& p, double a, double root,
                        const ContactForces& out) const {
    const double gn = normal_damping(p.damping_beta, root);
    // the same root for S_t = 8 G* a: sqrt(S_t m*) = sqrt(S_n m*) sqrt(4 G* / E*)
    const double gt = tangential_damping_ ? gn * p.shear_normal_root : 0.0;
    return {mindlin(p.effective_shear_modulus, a), gt, friction_limit(p, out.normal_force)};
  }

  bool tangential_damping_;
  bool rescale_;  // tangential = "mindlin_rescale_force"
  TangentialSlots slots_;
};

const bool registered = ContactLawRegistry::add(
    "hertz_mindlin", [](const CaseTable& t) { return std::make_unique<HertzMindlin>(t); });

}  // namespace
}  // namespace comminute

#include "comminute/pbm/ufrj_mill.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "comminute/core/error.hpp"
#include "comminute/pbm/t10_breakage_function.hpp"

namespace comminute::pbm {

UfrjMill::UfrjMill(const SizeGrid& grid, double density, UfrjParameters p)
    : n_(grid.classes()), m_(p.energy_bins), p_(std::move(p)), t10_(p_.progeny) {
  if (m_ < 4) throw Error("UfrjMill: need at least 4 energy bins");
  for (std::size_t k = 0; k < p_.sigma_by_size.size(); ++k)
    if (p_.sigma_by_size[k].first <= 0 || p_.sigma_by_size[k].second <= 0 ||
        (k > 0 && p_.sigma_by_size[k].first <= p_.sigma_by_size[k - 1].first))
      throw Error("UfrjMill: sigma_by_size needs positive sizes, increasing, and positive sigma");
  if (!std::isfinite(p_.fracture.emax_ratio))
    throw Error("UfrjMill: the fracture-energy distribution must be truncated (finite Emax/E50)");
  // Bins of ln(E/E50) from 1e−4 E50 to the upper truncation E_max/E50 (eq. U4).
  // Energy classes of both spectra in one list (U5 sums over every collision).
  all_ = p_.spectrum;
  source_.assign(all_.energy.size(), 0);
  for (std::size_t k = 0; k < p_.wall_spectrum.energy.size(); ++k) {
    all_.energy.push_back(p_.wall_spectrum.energy[k]);
    all_.frequency.push_back(p_.wall_spectrum.frequency[k]);
    source_.push_back(1);
  }
  ln_lo_ = std::log(1e-4);
  ln_step_ = (std::log(p_.fracture.emax_ratio) - ln_lo_) / static_cast<double>(m_);
  auto edge = [&](std::size_t j) { return std::exp(ln_lo_ + ln_step_ * static_cast<double>(j)); };
  virgin_ = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m_), static_cast<Eigen::Index>(n_));
  stress_.resize(n_);
  for (std::size_t i = 0; i < n_; ++i) {
    const double x = grid.pivot_size(i);
    e50_.push_back(p_.fracture.e50(x));
    size_.push_back(x);
    dist_.emplace_back(e50_[i], sigma_at(x), p_.fracture.emax_ratio);
    for (std::size_t j = 0; j < m_; ++j)  // the first bin also takes everything below it
      virgin_(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) =
          dist_[i].cdf(edge(j + 1) * e50_[i]) - (j == 0 ? 0.0 : dist_[i].cdf(edge(j) * e50_[i]));
    // Capture (docs/models.md eq. U1): N_cap = 1/4 + 3/4 (2 r_c/x)² for r_c ≥ x/2, one m* per
    // spectrum (media–media, and media–liner when a wall spectrum is given).
    for (std::size_t src = 0; src < 2; ++src) {
      const CaptureGeometry geometry = src == 0 ? p_.capture : p_.wall_capture;
      const double rc = p_.capture_radius > 0 ? p_.capture_radius
                                              : nip_capture_radius(geometry, p_.ball_radius, x);
      const double ncap = rc >= x / 2 ? 0.25 + 0.75 * std::pow(2 * rc / x, 2) : 1.0;
      mstar_[src].push_back(density * grid.pivot_volume(i) * ncap);
    }
    if (i == 0) continue;  // the finest class is the sink
    const double y = grid.pivot_volume(i);
    for (std::size_t k = 0; k < all_.energy.size(); ++k) {
      Stress s;
      s.capture_rate = all_.frequency[k] * mstar_[source_[k]][i] / p_.holdup;
      const double e = specific_energy(i, k);
      const double r = e / e50_[i];
      for (std::size_t j = 0; j < m_; ++j) {
        const double lo = edge(j), hi = edge(j + 1);
        // uniform in ln E within a bin: the part below r breaks
        const double f = r <= lo ? 0.0 : r >= hi ? 1.0 : std::log(r / lo) / ln_step_;
        s.broken.push_back(f);
        // survivors sit at the geometric centre of their part of the bin, then are damaged
        const double lo_s = std::max(lo, std::min(r, hi));
        const double eps = f < 1 ? std::sqrt(lo_s * hi) : hi;
        const double eps_d = f < 1 ? eps * (1 - p_.damage(r / eps)) : eps;
        const double pos = (std::log(eps_d) - ln_lo_) / ln_step_ - 0.5;  // in bin-centre units
        const double c = std::clamp(pos, 0.0, static_cast<double>(m_ - 1));
        const auto b = std::min(static_cast<std::size_t>(c), m_ - 2);
        s.to.push_back(b);
        s.w_lo.push_back(1 - (c - static_cast<double>(b)));
      }
      // Progeny at this energy: t10-based cumulative, lumped by mass into classes 0..i.
      const ProgenyFractions tab = progeny(i, k);
      double below = 0;
      for (std::size_t c = 0; c <= i; ++c) {
        const double upper = c == i ? 1.0 : tab.passing(std::cbrt(grid.volume_edge(c + 1) / y));
        s.progeny.push_back(upper - below);
        below = upper;
      }
      stress_[i].push_back(std::move(s));
    }
  }
}

// docs/models.md eq. U2, e_ik = η E_k / m*_i: the powder's share split equally among the captured
// particles.
double UfrjMill::specific_energy(std::size_t i, std::size_t k) const {
  return p_.energy_share * all_.energy[k] / mstar_[source_[k]][i];
}

ProgenyFractions UfrjMill::progeny(std::size_t i, std::size_t k) const {
  const double e = specific_energy(i, k);
  const double e50b = fracture::t10_median_energy(dist_[i], e, p_.e50b);  // eq. P1b
  return t10_progeny(t10_, t10_.t10(e, e50b));
}

// docs/models.md eq. U3-U5: captured mass breaks (bins below e) or is damaged and moved down.
void UfrjMill::derivative(double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const {
  dydt.setZero(y.size());
  Eigen::VectorXd born = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n_));
  for (std::size_t i = 1; i < n_; ++i) {
    const double* mi = y.data() + i * m_;
    double* di = dydt.data() + i * m_;
    for (const Stress& s : stress_[i]) {
      double broken = 0;
      for (std::size_t j = 0; j < m_; ++j) {
        const double caught = s.capture_rate * mi[j];
        const double b = caught * s.broken[j], survive = caught - b;
        broken += b;
        di[j] -= caught;
        di[s.to[j]] += survive * s.w_lo[j];
        di[s.to[j] + 1] += survive * (1 - s.w_lo[j]);
      }
      for (std::size_t c = 0; c <= i; ++c)
        born[static_cast<Eigen::Index>(c)] += broken * s.progeny[c];
    }
  }
  for (std::size_t c = 0; c < n_; ++c)
    dydt.segment(static_cast<Eigen::Index>(c * m_), static_cast<Eigen::Index>(m_)) +=
        born[static_cast<Eigen::Index>(c)] * virgin_.col(static_cast<Eigen::Index>(c));
}

Eigen::VectorXd UfrjMill::initial_state(const Eigen::VectorXd& mass) const {
  Eigen::VectorXd s(static_cast<Eigen::Index>(n_ * m_));
  for (std::size_t c = 0; c < n_; ++c)
    s.segment(static_cast<Eigen::Index>(c * m_), static_cast<Eigen::Index>(m_)) =
        mass[static_cast<Eigen::Index>(c)] * virgin_.col(static_cast<Eigen::Index>(c));
  return s;
}

Eigen::VectorXd UfrjMill::class_mass(const Eigen::VectorXd& state) const {
  Eigen::VectorXd m(static_cast<Eigen::Index>(n_));
  for (std::size_t c = 0; c < n_; ++c)
    m[static_cast<Eigen::Index>(c)] =
        state.segment(static_cast<Eigen::Index>(c * m_), static_cast<Eigen::Index>(m_)).sum();
  return m;
}

Eigen::VectorXd UfrjMill::median_fracture_energy(const Eigen::VectorXd& state) const {
  Eigen::VectorXd med(static_cast<Eigen::Index>(n_));
  for (std::size_t c = 0; c < n_; ++c) {
    const double* b = state.data() + c * m_;
    double total = 0, acc = 0;
    for (std::size_t j = 0; j < m_; ++j) total += b[j];
    std::size_t j = 0;
    while (j + 1 < m_ && acc + b[j] < 0.5 * total) acc += b[j++];
    const double frac = b[j] > 0 ? std::clamp((0.5 * total - acc) / b[j], 0.0, 1.0) : 0.5;
    med[static_cast<Eigen::Index>(c)] =
        e50_[c] * std::exp(ln_lo_ + ln_step_ * (static_cast<double>(j) + frac));
  }
  return med;
}

double UfrjMill::sigma_at(double x) const {
  const auto& t = p_.sigma_by_size;
  if (t.empty()) return p_.fracture.sigma;
  if (x <= t.front().first) return t.front().second;
  if (x >= t.back().first) return t.back().second;
  std::size_t k = 1;
  while (t[k].first < x) ++k;
  const double w = std::log(x / t[k - 1].first) / std::log(t[k].first / t[k - 1].first);
  return (1 - w) * t[k - 1].second + w * t[k].second;
}

FractureEnergyBins UfrjMill::fracture_energy_distribution(const Eigen::VectorXd& state) const {
  const auto m = static_cast<Eigen::Index>(m_), n = static_cast<Eigen::Index>(n_);
  FractureEnergyBins b{Eigen::MatrixXd(m + 1, n), Eigen::MatrixXd(m, n)};
  for (Eigen::Index c = 0; c < n; ++c) {
    b.mass.col(c) = state.segment(c * m, m);
    b.edges(0, c) = 0;  // bin 0 holds everything below its upper edge
    for (Eigen::Index j = 1; j <= m; ++j)
      b.edges(j, c) =
          e50_[static_cast<std::size_t>(c)] * std::exp(ln_lo_ + ln_step_ * static_cast<double>(j));
  }
  return b;
}

// docs/models.md eq. S5 with P = F_i of the virgin bins (eq. U1-U2, U5).
std::vector<double> UfrjMill::virgin_rates() const {
  std::vector<double> s(n_, 0.0);
  for (std::size_t i = 1; i < n_; ++i)
    for (const Stress& st : stress_[i])
      for (std::size_t j = 0; j < m_; ++j)
        s[i] += st.capture_rate * st.broken[j] *
                virgin_(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i));
  return s;
}

namespace {
// The [mill] table: spectrum_file (and wall_spectrum_file, with wall_capture), holdup,
// energy_share, capture_radius or ball_diameter (with capture = "approximate" | "ball_ball" |
// "ball_wall"), damage_gamma, damage_form, energy_bins, [mill.fracture_energy]
// (fracture::read_fracture_energy_model, plus sigma_sizes/sigma_values for σ(d)) and [mill.progeny]
// (fracture::read_t10_model, fracture::read_e50b_rule).
std::unique_ptr<MillModel> make(const CaseTable& t, const ModelContext& ctx) {
  UfrjParameters u;
  u.spectrum = read_collision_spectrum(t, "spectrum_file");
  if (t.has("wall_spectrum_file"))
    u.wall_spectrum = read_collision_spectrum(t, "wall_spectrum_file");
  u.holdup = t.number("holdup", Limits::positive());
  u.energy_share = t.number("energy_share", {0, 1, true, false}, 1.0);
  if (t.has("capture_radius")) {
    u.capture_radius = t.number("capture_radius", Limits::positive());
  } else {
    u.ball_radius = 0.5 * t.number("ball_diameter", Limits::positive());
    const std::string g =
        t.choice("capture", {"approximate", "ball_ball", "ball_wall"}, "approximate");
    if (g == "ball_ball") u.capture = CaptureGeometry::ball_ball;
    if (g == "ball_wall") u.capture = CaptureGeometry::ball_wall;
    const std::string w =
        t.choice("wall_capture", {"approximate", "ball_ball", "ball_wall"}, "ball_wall");
    if (w == "approximate") u.wall_capture = CaptureGeometry::approximate;
    if (w == "ball_ball") u.wall_capture = CaptureGeometry::ball_ball;
  }
  const CaseTable fe = t.table("fracture_energy");
  u.fracture = fracture::read_fracture_energy_model(fe);
  if (fe.has("sigma_sizes") || fe.has("sigma_values")) {
    const auto sizes = fe.numbers("sigma_sizes", Limits::positive()),
               values = fe.numbers("sigma_values", Limits::positive());
    if (sizes.size() != values.size() || sizes.empty())
      fe.fail("sigma_values", "give one sigma per entry of sigma_sizes");
    for (std::size_t k = 0; k < sizes.size(); ++k) {
      if (sizes[k] <= 0 || (k > 0 && sizes[k] <= sizes[k - 1]))
        fe.fail("sigma_sizes", "sizes must be positive and increasing (m)");
      if (values[k] <= 0) fe.fail("sigma_values", "every sigma must be positive");
      u.sigma_by_size.emplace_back(sizes[k], values[k]);
    }
  }
  if (!std::isfinite(u.fracture.emax_ratio))
    fe.fail("emax_ratio", "the UFRJ mill bins ln(E/E50) up to Emax/E50: give a finite emax_ratio");
  u.damage = fracture::read_damage_law(t);
  u.energy_bins = static_cast<std::size_t>(t.integer("energy_bins", 4, 10000, 60));
  const CaseTable progeny = t.table("progeny");
  u.progeny = fracture::read_t10_model(progeny).parameters();
  u.e50b = fracture::read_e50b_rule(progeny);
  return std::make_unique<UfrjMill>(ctx.grid, ctx.density, std::move(u));
}
const bool registered = MillRegistry::add("ufrj", &make);
}  // namespace

}  // namespace comminute::pbm

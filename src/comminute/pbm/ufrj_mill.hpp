#pragma once
// The UFRJ mechanistic ball-mill model (Tavares & de Carvalho, Minerals Eng. 22 (2009) 650;
// de Carvalho & Tavares, Minerals Eng. 43–44 (2013) 91; docs/models.md eq. U1–U5 — the equations
// are this code's reading of the papers, to be verified against them):
//  * collisions of energy class k (E_k, λ_k from the DEM) capture m*_i = m_p,i N_cap,i of size
//    class i, N_cap = 1/4 + 3/4 (2 r_c/x)² for r_c ≥ x/2 (else 1), r_c the capture radius
//    (r_c from the nip geometry of the media, pbm/capture_radius.hpp, or a constant: the
//    published capture correlation could not be retrieved)                            (eq. U1);
//  * the powder's share η E_k is split equally among the captured particles: e_ik = η E_k/m*_i
//                                                                                      (eq. U2);
//  * the captured particles whose fracture energy is below e_ik break, with the t10-based
//    progeny (fracture::T10Model, eq. P1–P2, with E50b the median fracture energy of the virgin
//    particles of the class that break at e_ik, eq. P1b; or the class E50); the others are damaged
//    (fracture::DamageLaw, eq. D1–D2) and their fracture energy E drops to
//    E(1 − D(e/E))                                                                      (eq. U3);
//  * fracture energies per size class start from the upper-truncated lognormal F_i
//    (fracture::FractureEnergyModel, eq. F1–F3) and are tracked as mass in bins of ln(E/E50,i),
//    so the distribution weakens as grinding proceeds; fragments enter their class with the
//    virgin distribution (eq. U4); σ may be given per size (a table, interpolated in ln d:
//    no published σ(d) law was retrieved). The whole binned distribution per class is
//    reported (fracture_energy_distribution), not only its median.
// Captured fraction of class i per second: λ_k m*_i/H (eq. U5), over the energy classes of the
// media–media spectrum and, when given, of the media–liner one (its own capture geometry).
// The finest class does not break.
// Registered as the mill model "ufrj" ([solver] method = "ufrj", keys in [mill]).
#include <Eigen/Dense>
#include <utility>
#include <vector>

#include "comminute/fracture/breaking_median.hpp"
#include "comminute/fracture/damage.hpp"
#include "comminute/fracture/fracture_energy_model.hpp"
#include "comminute/fracture/t10_model.hpp"
#include "comminute/pbm/capture_radius.hpp"
#include "comminute/pbm/mill_model.hpp"
#include "comminute/pbm/size_grid.hpp"

namespace comminute::pbm {

struct UfrjParameters {
  CollisionSpectrum spectrum;
  double holdup = 1;          // kg
  double energy_share = 1;    // η
  double ball_radius = 0;     // m: r_c from the nip geometry when capture_radius is 0
  double capture_radius = 0;  // m
  CaptureGeometry capture = CaptureGeometry::approximate;  // nip geometry (capture_radius.hpp)
  // Optional second spectrum, media–liner impacts, captured with its own nip geometry; its
  // collisions add to those of `spectrum` (eq. U5 is a sum over collisions).
  CollisionSpectrum wall_spectrum;
  CaptureGeometry wall_capture = CaptureGeometry::ball_wall;
  fracture::FractureEnergyModel fracture;  // emax_ratio must be finite (the bins end there)
  fracture::DamageLaw damage;              // γ and form of the damage law (eq. D1)
  fracture::T10Parameters progeny;
  fracture::E50bRule e50b = fracture::E50bRule::breaking;  // E50 of the t10 relation (eq. P1b)
  std::size_t energy_bins = 60;
  // σ(d): (size m, σ) points, sizes increasing, interpolated linearly in ln d and held beyond
  // the ends; empty: the constant fracture.sigma.
  std::vector<std::pair<double, double>> sigma_by_size;
};

class UfrjMill : public MillModel {
 public:
  UfrjMill(const SizeGrid& grid, double density, UfrjParameters p);

  std::size_t size() const override { return n_ * m_; }
  void derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const override;

  // State from mass per class (virgin fracture energies) and back.
  Eigen::VectorXd initial_state(const Eigen::VectorXd& mass) const override;
  Eigen::VectorXd class_mass(const Eigen::VectorXd& state) const override;
  // Median fracture energy (J/kg) of each class's unbroken material.
  Eigen::VectorXd median_fracture_energy(const Eigen::VectorXd& state) const override;
  // The whole distribution: mass (kg) per fracture-energy bin and class, and the bin edges
  // (J/kg); bin 0 also holds everything below its upper edge, so its lower edge is 0.
  FractureEnergyBins fracture_energy_distribution(const Eigen::VectorXd& state) const override;
  // σ of ln E* for size x (m) (the table of sigma_by_size, or the constant).
  double sigma_at(double x) const;
  // Breakage rate of virgin material, Σ_k (λ_k m*_i/H) F_i(e_ik) (1/s).
  std::vector<double> virgin_rates() const override;
  // m*_i of a media–media collision (source 0) or a media–liner one (source 1).
  double captured_mass(std::size_t i, std::size_t source = 0) const { return mstar_[source][i]; }
  // Specific energy e_ik (J/kg) and the t10 progeny of class i stressed by energy class k; k runs
  // over `spectrum` and then `wall_spectrum` (the order of spectrum()).
  double specific_energy(std::size_t i, std::size_t k) const;
  ProgenyFractions progeny(std::size_t i, std::size_t k) const override;
  const CollisionSpectrum& spectrum() const override { return all_; }

 private:
  struct Stress {                 // one (class, energy class) pair
    double capture_rate;          // λ_k m*_i / H, 1/s
    std::vector<double> broken;   // fraction broken per source bin
    std::vector<std::size_t> to;  // survivor target bin (lower of two)
    std::vector<double> w_lo;     // share to `to`, the rest to `to + 1`
    std::vector<double> progeny;  // mass fraction into each class 0..i
  };
  std::size_t n_, m_;
  double ln_lo_, ln_step_;  // bins in ln(E/E50): edges ln_lo + j·step
  std::vector<double> e50_, size_;
  std::vector<double> mstar_[2];     // captured mass per class, per source
  CollisionSpectrum all_;            // both spectra, media–media first
  std::vector<std::size_t> source_;  // source of each energy class of all_
  Eigen::MatrixXd virgin_;           // (m_ × n_) virgin bin fractions per class
  std::vector<fracture::FractureEnergyDistribution> dist_;  // virgin distribution per class
  std::vector<std::vector<Stress>> stress_;                 // [class][energy class]
  UfrjParameters p_;
  fracture::T10Model t10_;
};

}  // namespace comminute::pbm

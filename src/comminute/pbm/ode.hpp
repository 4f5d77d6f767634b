#pragma once
// An autonomous-or-not ODE system y' = f(t, y) and the linear one y' = A y that every
// discretised breakage equation of this folder becomes (A upper triangular: classes are ordered
// fine to coarse and fragments are never larger than their parent).
#include <Eigen/Dense>
#include <cstddef>

namespace comminute::pbm {

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual std::size_t size() const = 0;
  virtual void derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const = 0;
};

class LinearOde : public OdeSystem {
 public:
  explicit LinearOde(Eigen::MatrixXd a) : a_(std::move(a)) {}
  std::size_t size() const override { return static_cast<std::size_t>(a_.rows()); }
  void derivative(double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const override {
    dydt.noalias() = a_.triangularView<Eigen::Upper>() * y;
  }

 private:
  Eigen::MatrixXd a_;
};

}  // namespace comminute::pbm

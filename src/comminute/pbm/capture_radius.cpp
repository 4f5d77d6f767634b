#include "comminute/pbm/capture_radius.hpp"

#include <algorithm>
#include <cmath>

namespace comminute::pbm {

// Sphere geometry (docs/pbm.md eq. U1a-U1c): the gap at radius r from the line of centres of two
// touching spheres is 2(R − √(R² − r²)), of a sphere touching a plane R − √(R² − r²).
double nip_capture_radius(CaptureGeometry g, double ball_radius, double x) {
  const double r = ball_radius;
  double r2 = 0;
  switch (g) {
    case CaptureGeometry::approximate:
      return std::sqrt(r * x);
    case CaptureGeometry::ball_ball:
      r2 = x < 2 * r ? r * x - 0.25 * x * x : r * r;
      break;
    case CaptureGeometry::ball_wall:
      r2 = x < r ? 2 * r * x - x * x : r * r;
      break;
  }
  return std::min(std::sqrt(r2), r);
}

}  // namespace comminute::pbm

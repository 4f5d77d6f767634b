#pragma once
// Damping coefficients from a coefficient of restitution.
namespace comminute {

// beta(e) = ln e / sqrt(ln^2 e + pi^2): exact for the linear spring–dashpot, and used for
// Hertz with Tsuji-type damping as in LIGGGHTS/EDEM (see hertz_restitution).
double damping_beta(double restitution);

// Rebound/impact speed ratio of a Hertz impact with Tsuji-type damping, F = k δ^{3/2} +
// 2 sqrt(5/6)|β| sqrt(2E* sqrt(R* δ) m*) δ̇, for a given beta (<= 0). In units where the impact
// speed and the Hertz time are 1 the motion is x'' = -x^{3/2} - sqrt(5)|β| x^{1/4} x', which does
// not depend on the impact speed; it is integrated numerically (RK4). Used to verify beta(e).
double hertz_restitution(double beta);

}  // namespace comminute

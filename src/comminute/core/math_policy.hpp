#pragma once
// Boost.Math evaluation policy for hot paths: double precision throughout. By default Boost
// promotes double arguments to long double internally, which is several times slower (every
// fragment draws a strength with erf_inv; every breakage evaluates five incomplete betas).
#include <boost/math/policies/policy.hpp>

namespace comminute {
using DoublePrecision = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
}  // namespace comminute

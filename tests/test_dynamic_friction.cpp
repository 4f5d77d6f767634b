// Issue 8, point 8: static and dynamic friction coefficients set separately.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "comminute/contact/tangential_friction.hpp"
#include "comminute/particles/material.hpp"

using namespace comminute;

// mu_s = 0.5, mu_d = 0.3, |F_n| = 1 N, a steady tangential motion of 0.07 N of spring per step:
// the contact sticks up to 0.49 N (past mu_d, below mu_s), slides at the dynamic limit 0.3 N from
// the step the spring would exceed 0.5 N, and keeps sliding at 0.3 N. Without a flag (mu_d = mu_s
// everywhere) it is the single-coefficient limit. Tolerances: round-off of a few additions.
TEST(Friction, StaticLimitStartsSlidingDynamicLimitWhileSliding) {
  PairParameters p;
  p.friction = 0.5;
  p.dynamic_friction = 0.3;
  ContactKinematics k;
  k.normal = {0, 0, 1};
  k.tangential_velocity = {0.7e-3, 0, 0};
  k.dt = 1e-3;
  const double kt = 1e5;  // N/m
  Vec3 stored;
  float sliding = 0;
  std::vector<double> f;
  for (int s = 0; s < 20; ++s) {
    ContactForces out;
    coulomb_tangential(k, kt, 0.0, friction_limit(p, 1.0), stored, &sliding, out);
    f.push_back(norm(out.tangential_force));
  }
  EXPECT_NEAR(f[6], 0.49, 1e-9);  // sticking, 7 steps of 0.07 N
  EXPECT_NEAR(f[7], 0.3, 1e-12);  // the trial 0.56 N exceeds mu_s: slides at mu_d
  for (std::size_t s = 8; s < f.size(); ++s) EXPECT_NEAR(f[s], 0.3, 1e-12) << "step " << s;
  EXPECT_EQ(sliding, 1.0f);
  // Stopping: the spring holds its force and the contact sticks again.
  k.tangential_velocity = {};
  ContactForces out;
  coulomb_tangential(k, kt, 0.0, friction_limit(p, 1.0), stored, &sliding, out);
  EXPECT_NEAR(norm(out.tangential_force), 0.3, 1e-12);
  EXPECT_EQ(sliding, 0.0f);
  // Equal coefficients, no flag: the single limit 0.5 N.
  p.dynamic_friction = 0.5;
  k.tangential_velocity = {0.7e-3, 0, 0};
  stored = {};
  for (int s = 0; s < 20; ++s)
    coulomb_tangential(k, kt, 0.0, friction_limit(p, 1.0), stored, nullptr, out);
  EXPECT_NEAR(norm(out.tangential_force), 0.5, 1e-12);
}

// dynamic_friction defaults to the static coefficient, so results do not change; only a pair
// with mu_d != mu_s asks the law for the sliding flag.
TEST(Friction, DynamicCoefficientDefaultsToTheStaticOne) {
  MaterialTable m;
  m.add({"rock", 2700, 70e9, 0.25});
  PairInput in;
  in.friction = 0.6;
  m.set_pair(0, 0, in);
  EXPECT_EQ(m.pair(0, 0).dynamic_friction, 0.6);
  EXPECT_FALSE(m.has_dynamic_friction());
  in.dynamic_friction = 0.4;
  m.set_pair(0, 0, in);
  EXPECT_EQ(m.pair(0, 0).dynamic_friction, 0.4);
  EXPECT_TRUE(m.has_dynamic_friction());
}

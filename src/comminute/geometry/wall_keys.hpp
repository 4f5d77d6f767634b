#pragma once
// Reading helpers shared by the wall factories.
#include <string_view>

#include "comminute/core/case_table.hpp"
#include "comminute/core/vec3.hpp"

namespace comminute {

// A direction key ([x, y, z], default `fallback`), normalised; fails on the zero vector.
Vec3 read_unit_vector(const CaseTable& t, std::string_view key, const Vec3& fallback);

}  // namespace comminute

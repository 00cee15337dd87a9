// Mathematical constants, each written once (double precision, correctly rounded).
#pragma once

namespace kiln {

constexpr double Pi = 3.14159265358979323846;
constexpr double InvPi = 0.31830988618379067154;
/// pi / 2.
constexpr double HalfPi = 1.5707963267948966;
/// 1 / sqrt(pi).
constexpr double InvSqrtPi = 0.56418958354775628695;

}  // namespace kiln

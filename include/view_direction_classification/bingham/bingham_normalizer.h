#pragma once

#include <Eigen/Core>

namespace vdc {

// The normaliser of the Bingham distribution on S^3 and its gradient.
//
// For concentrations z = (z1, z2, z3), all <= 0 (the fourth concentration, that of the mode, is 0)
//   F(z) = integral over S^3 of exp(z1 x1^2 + z2 x2^2 + z3 x3^2) dx,
// so F(0,0,0) = 2 pi^2, the area of S^3. It is computed from Wood's one-dimensional integral
//   F(z) = 2 pi^2 int_0^1 e^{t max(z1,z2)} I0e(t |z1-z2| / 2) e^{(1-t) max(z3,0)} I0e((1-t)|z3|/2)
//   dt
// (split S^3 into two circles of squared radii t and 1-t; t is uniform on [0,1]) by adaptive
// Gauss-Kronrod quadrature with global error control, so that the relative error stays below
// 1e-9 for every concentration from 0 down to -1e5 (and beyond): no lookup table, no clamping.
// The order of z does not matter.

struct BinghamNormalizer {
  double value = 0.0;        // F(z)
  Eigen::Vector3d gradient;  // dF/dz_i = integral of x_i^2 exp(...): F times E[x_i^2]
};

// F(z). Throws vdc::Error for a non-finite or positive concentration.
double binghamNormalizer(const Eigen::Vector3d& z);

// F(z) and dF/dz together (one quadrature). Throws vdc::Error as binghamNormalizer.
BinghamNormalizer binghamNormalizerWithGradient(const Eigen::Vector3d& z);

// An upper bound on log F(z) that needs no quadrature: F grows in every concentration, so with z
// sorted (z1 <= z2 <= z3 <= 0), F(z) <= F(z2, z2, 0) = 2 pi^2 (1 - e^{z2}) / -z2. Mixture
// products use it to skip pairs whose weight cannot matter. Same preconditions as F.
double binghamLogNormalizerUpperBound(const Eigen::Vector3d& z);

// Exponentially scaled modified Bessel functions of the first kind, e^{-x} I_0(x) and
// e^{-x} I_1(x), for x >= 0. Finite for every finite x (I_0 itself overflows beyond x ~ 700).
double besselI0Scaled(double x);
double besselI1Scaled(double x);

}  // namespace vdc

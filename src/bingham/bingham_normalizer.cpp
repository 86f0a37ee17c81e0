#include "view_direction_classification/bingham/bingham_normalizer.h"

#include "view_direction_classification/common/error.h"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/bessel.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <sstream>
#include <vector>

namespace vdc {
namespace {

constexpr double kTwoPiSquared = 2.0 * M_PI * M_PI;

// Beyond this argument e^x overflows soon; the asymptotic series is accurate to machine precision
// long before (its terms fall like k! / (8x)^k).
constexpr double kAsymptoticBesselArgument = 500.0;
// Boost promotes double arguments to long double by default; the x87 long-double Bessel and
// expl then cost most of every normaliser (measured: 65 % of a mixture product). Double
// precision is accurate to ~1e-16 relative, far inside the quadrature's 1e-9 target.
using DoublePrecisionPolicy =
    boost::math::policies::policy<boost::math::policies::promote_double<false>>;

// Hankel's asymptotic series e^{-x} I_nu(x) ~ (2 pi x)^{-1/2} sum_k (-1)^k a_k(nu) / x^k with
// a_k = prod_{j=1..k} (4 nu^2 - (2j-1)^2) / (k! 8^k).
double besselScaledAsymptotic(int order, double x) {
  const double mu = 4.0 * order * order;
  double term = 1.0;
  double sum = 1.0;
  for (int k = 1; k < 30; ++k) {
    const double odd = 2.0 * k - 1.0;
    term *= -(mu - odd * odd) / (k * 8.0 * x);
    sum += term;
    if (std::abs(term) < 1e-17 * std::abs(sum)) break;
  }
  return sum / std::sqrt(2.0 * M_PI * x);
}

void checkConcentrations(const Eigen::Vector3d& z) {
  if (!z.allFinite() || (z.array() > 0.0).any()) {
    std::ostringstream message;
    message << "Bingham concentrations must be finite and <= 0, but got (" << z.transpose() << ").";
    throw Error(message.str());
  }
}

// The Gauss-Kronrod 7/15 rule (QUADPACK's qk15), nodes and weights from Boost.
struct KronrodRule {
  static constexpr int kPoints = 15;
  std::array<double, kPoints> nodes;  // on [-1, 1]
  std::array<double, kPoints> kronrod_weights;
  std::array<double, kPoints> gauss_weights;  // zero at the Kronrod-only nodes

  KronrodRule() {
    const auto& abscissa = boost::math::quadrature::gauss_kronrod<double, 15>::abscissa();
    const auto& kweights = boost::math::quadrature::gauss_kronrod<double, 15>::weights();
    const auto& gweights = boost::math::quadrature::gauss<double, 7>::weights();
    // Boost stores the non-negative half in ascending order, abscissa[0] = 0; the 7 Gauss nodes
    // are the Kronrod abscissae of even index.
    int n = 0;
    for (std::size_t i = 0; i < abscissa.size(); ++i) {
      const double g = (i % 2 == 0) ? gweights[i / 2] : 0.0;
      nodes[n] = abscissa[i];
      kronrod_weights[n] = kweights[i];
      gauss_weights[n] = g;
      ++n;
      if (i > 0) {
        nodes[n] = -abscissa[i];
        kronrod_weights[n] = kweights[i];
        gauss_weights[n] = g;
        ++n;
      }
    }
  }
};

const KronrodRule& kronrodRule() {
  static const KronrodRule rule;
  return rule;
}

// e^shift I_0(x) and e^shift I_1(x) for x >= 0 and shift <= 0, with shift + x <= 0 (so both are
// at most 1). Below the asymptotic range the unscaled Bessel functions are finite and one
// exponential serves both; the scaled functions would spend one more on each.
struct ShiftedBessel {
  double i0, i1;
};
ShiftedBessel shiftedBessel(double shift, double x, bool with_i1) {
  if (x >= kAsymptoticBesselArgument) {
    const double scale = std::exp(shift + x);
    return {scale * besselI0Scaled(x), with_i1 ? scale * besselI1Scaled(x) : 0.0};
  }
  const double scale = std::exp(shift);
  return {scale * boost::math::cyl_bessel_i(0, x, DoublePrecisionPolicy()),
          with_i1 ? scale * boost::math::cyl_bessel_i(1, x, DoublePrecisionPolicy()) : 0.0};
}

// The integrand of Wood's formula (without 2 pi^2) and, when wanted, those of dF/dz_i. With
// u on the first circle (squared radius t) and v on the second (squared radius 1-t):
//   E_u[exp(a u1^2 + b u2^2)]      = e^{(a+b)/2} I0(|a-b|/2)
//   E_u[u1^2 exp(a u1^2 + b u2^2)] = e^{(a+b)/2} (I0(|a-b|/2) + sign(a-b) I1(|a-b|/2)) / 2
// and x1^2 = t u1^2, x3^2 = (1-t) v1^2.
struct Integrand {
  Eigen::Vector3d z;
  bool with_gradient;

  // values(0) = F integrand, values(1..3) = dF/dz_i integrands.
  Eigen::Vector4d operator()(double t) const {
    const double s = 1.0 - t;
    const double a = t * z(0), b = t * z(1);
    const double c = s * z(2);  // paired with the mode's concentration 0
    const ShiftedBessel first_circle =
        shiftedBessel(0.5 * (a + b), 0.5 * std::abs(a - b), with_gradient);
    const ShiftedBessel second_circle = shiftedBessel(0.5 * c, 0.5 * std::abs(c), with_gradient);
    const double first = first_circle.i0;
    const double second = second_circle.i0;
    Eigen::Vector4d values(first * second, 0.0, 0.0, 0.0);
    if (with_gradient) {
      const double sign_ab = a >= b ? 1.0 : -1.0;
      const double sign_c = c >= 0.0 ? 1.0 : -1.0;
      values(1) = t * 0.5 * (first + sign_ab * first_circle.i1) * second;
      values(2) = t * 0.5 * (first - sign_ab * first_circle.i1) * second;
      values(3) = s * 0.5 * (second + sign_c * second_circle.i1) * first;
    }
    return values;
  }
};

struct Interval {
  double lower, upper;
  Eigen::Vector4d integral;
  double error;  // the largest component error relative to that component's running total
  Eigen::Vector4d component_error;
  bool operator<(const Interval& other) const { return error < other.error; }
};

Interval integrateInterval(const Integrand& f, double lower, double upper) {
  const KronrodRule& rule = kronrodRule();
  const double half = 0.5 * (upper - lower);
  const double centre = 0.5 * (upper + lower);
  Eigen::Vector4d kronrod = Eigen::Vector4d::Zero();
  Eigen::Vector4d gauss = Eigen::Vector4d::Zero();
  for (int i = 0; i < KronrodRule::kPoints; ++i) {
    const Eigen::Vector4d value = f(centre + half * rule.nodes[i]);
    kronrod += rule.kronrod_weights[i] * value;
    gauss += rule.gauss_weights[i] * value;
  }
  Interval interval;
  interval.lower = lower;
  interval.upper = upper;
  interval.integral = half * kronrod;
  interval.component_error = (half * (kronrod - gauss)).cwiseAbs();
  interval.error = 0.0;
  return interval;
}

// The |K15 - G7| difference overestimates the K15 error by orders of magnitude for smooth
// integrands, so asking it for 1e-11 leaves a wide margin below the 1e-9 promise.
constexpr double kRelativeTolerance = 1e-11;
constexpr int kMaxIntervals = 4000;

BinghamNormalizer integrate(const Eigen::Vector3d& z, bool with_gradient) {
  checkConcentrations(z);
  if (z.isZero(0.0)) {
    // The uniform distribution, exactly: every default-constructed distribution asks for it.
    BinghamNormalizer uniform;
    uniform.value = kTwoPiSquared;
    uniform.gradient = Eigen::Vector3d::Constant(with_gradient ? kTwoPiSquared / 4.0 : 0.0);
    return uniform;
  }
  const Integrand f{z, with_gradient};

  // The integrand is log-convex in t (a product of Laplace transforms), so it peaks only at
  // t = 0 or t = 1, in layers as thin as 1 / |z|. Seed the adaptive subdivision with breakpoints
  // that grow geometrically away from both ends so no layer can be missed by the first rule.
  // Near t = 1 the integrand varies on the scale 1 / max(|z1|, |z2|), near t = 0 on 1 / |z3|.
  const double scale_at_one = std::max(std::abs(z(0)), std::abs(z(1)));
  const double scale_at_zero = std::abs(z(2));
  std::vector<double> breakpoints{0.0, 0.5, 1.0};
  for (double width = 1.0 / std::max(scale_at_zero, 1.0); width < 0.5; width *= 8.0) {
    breakpoints.push_back(width);
  }
  for (double width = 1.0 / std::max(scale_at_one, 1.0); width < 0.5; width *= 8.0) {
    breakpoints.push_back(1.0 - width);
  }
  std::sort(breakpoints.begin(), breakpoints.end());

  std::vector<Interval> intervals;
  for (std::size_t i = 0; i + 1 < breakpoints.size(); ++i) {
    intervals.push_back(integrateInterval(f, breakpoints[i], breakpoints[i + 1]));
  }
  const int components = with_gradient ? 4 : 1;
  for (int guard = 0; guard < kMaxIntervals; ++guard) {
    Eigen::Vector4d total = Eigen::Vector4d::Zero();
    Eigen::Vector4d total_error = Eigen::Vector4d::Zero();
    for (const Interval& interval : intervals) {
      total += interval.integral;
      total_error += interval.component_error;
    }
    // The relative error of each wanted component, and which interval contributes most to it.
    double worst = 0.0;
    std::size_t worst_interval = 0;
    for (int c = 0; c < components; ++c) {
      const double relative = total_error(c) / std::max(total(c), 1e-300);
      if (relative <= kRelativeTolerance) continue;
      for (std::size_t i = 0; i < intervals.size(); ++i) {
        const double share = intervals[i].component_error(c) / std::max(total(c), 1e-300);
        if (share > worst) {
          worst = share;
          worst_interval = i;
        }
      }
    }
    if (worst == 0.0) {
      BinghamNormalizer result;
      result.value = kTwoPiSquared * total(0);
      result.gradient = kTwoPiSquared * total.tail<3>();
      if (!with_gradient) result.gradient.setZero();
      return result;
    }
    const Interval split = intervals[worst_interval];
    const double middle = 0.5 * (split.lower + split.upper);
    intervals[worst_interval] = integrateInterval(f, split.lower, middle);
    intervals.push_back(integrateInterval(f, middle, split.upper));
  }
  std::ostringstream message;
  message << "The Bingham normaliser did not reach its accuracy for concentrations ("
          << z.transpose() << ").";
  throw Error(message.str());
}

}  // namespace

double besselI0Scaled(double x) {
  x = std::abs(x);
  if (x >= kAsymptoticBesselArgument) return besselScaledAsymptotic(0, x);
  return boost::math::cyl_bessel_i(0, x, DoublePrecisionPolicy()) * std::exp(-x);
}

double besselI1Scaled(double x) {
  const double sign = x < 0.0 ? -1.0 : 1.0;
  x = std::abs(x);
  if (x >= kAsymptoticBesselArgument) return sign * besselScaledAsymptotic(1, x);
  return sign * boost::math::cyl_bessel_i(1, x, DoublePrecisionPolicy()) * std::exp(-x);
}

double binghamLogNormalizerUpperBound(const Eigen::Vector3d& z) {
  checkConcentrations(z);
  Eigen::Vector3d sorted = z;
  std::sort(sorted.data(), sorted.data() + 3);
  const double middle = sorted(1);
  const double log_uniform = std::log(kTwoPiSquared);
  // (1 - e^m) / -m -> 1 as m -> 0; below 1e-12 the difference is lost in rounding anyway.
  if (middle > -1e-12) return log_uniform;
  return log_uniform + std::log(-std::expm1(middle)) - std::log(-middle);
}

double binghamNormalizer(const Eigen::Vector3d& z) { return integrate(z, false).value; }

BinghamNormalizer binghamNormalizerWithGradient(const Eigen::Vector3d& z) {
  return integrate(z, true);
}

}  // namespace vdc

// Wendland C2 kernel in 3-D, support 2h (solver/sph/kernel.hpp; physics.md §1, thesis eq. 2.11):
//   W(r,h) = 21/(16 pi h^3) (1 - q/2)^4 (2q + 1),  q = r/h.
// Every expected value below is a quadrature, a lattice sum, a finite difference or
// the closed form written out here, never a number taken from the code under test.
#include "sph/kernel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

namespace {

using namespace sphdem;

constexpr double kPi = 3.14159265358979323846;

// Composite Simpson rule on [a, b] with n (even) intervals.
double simpson(const std::function<double(double)>& f, double a, double b, int n) {
  const double dx = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + i * dx);
  return s * dx / 3.0;
}

// Radial integral 4 pi \int_0^{2h} r^2 g(r) dr of a radial function g.
double radial_integral(const std::function<double(double)>& g, double h) {
  return simpson([&](double r) { return 4.0 * kPi * r * r * g(r); }, 0.0, 2.0 * h, 2000);
}

// dW/dr from the gradient: grad_a W = grad_factor * (r_a - r_b), so dW/dr = grad_factor * r.
double dw_dr(double r, double h) {
  return kernel::grad_factor(r * r, h) * r;
}

// Sum of W(x - x0) dx^3 over a cubic lattice of spacing dx with an arbitrary offset x0.
double lattice_sum(double h, double dx, const double x0[3]) {
  const int n = static_cast<int>(std::ceil(2.0 * h / dx)) + 1;
  double s = 0.0;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -n; k <= n; ++k) {
        const double rx = i * dx - x0[0], ry = j * dx - x0[1], rz = k * dx - x0[2];
        s += kernel::w(rx * rx + ry * ry + rz * rz, h);
      }
  return s * dx * dx * dx;
}

const double kH[] = {1.0, 0.37, 3.0e-4};  // unit, odd, and the thesis' h = 1.5 x 200 µm

// ---- normalisation --------------------------------------------------------------

TEST(Kernel, RadialIntegralIsOne) {
  for (double h : kH) {
    const double I = radial_integral([h](double r) { return kernel::w(r * r, h); }, h);
    // Integrand is a degree-7 polynomial in r; Simpson with 2000 intervals: error ~1e-13.
    EXPECT_NEAR(I, 1.0, 1e-10) << "h = " << h;
  }
}

TEST(Kernel, LatticeSumIsOne) {
  const double x0[3] = {0.123, 0.456, 0.789};  // lattice offset in units of dx
  for (double h : {1.0, 0.37}) {
    for (double per_h : {6.0, 10.0}) {
      const double dx = h / per_h;
      const double off[3] = {x0[0] * dx, x0[1] * dx, x0[2] * dx};
      // Poisson summation: error = W's Fourier transform at 2 pi/dx, decaying as (dx/h)^6
      // (W has an |r|^3 term at r = 0); ~3e-8 at dx = h/6, so 1e-6 still catches a wrong norm.
      EXPECT_NEAR(lattice_sum(h, dx, off), 1.0, 1e-6) << "h = " << h << ", dx = h/" << per_h;
    }
  }
}

// \int x dW/dx dV = -\int W dV = -1 (integration by parts): checks the gradient's scale.
TEST(Kernel, GradientFirstMomentIsMinusOne) {
  for (double h : kH) {
    const double I = radial_integral([h](double r) { return dw_dr(r, h) * r / 3.0; }, h);
    EXPECT_NEAR(I, -1.0, 1e-10) << "h = " << h;  // polynomial integrand, Simpson exact to ~1e-13
  }
}

// \int dW/dh dV = d/dh \int W dV = 0.
TEST(Kernel, SmoothingLengthDerivativeIntegratesToZero) {
  for (double h : kH) {
    const double I = radial_integral([h](double r) { return kernel::dw_dh(r * r, h); }, h);
    // scale of dW/dh is W/h, so compare h*I with 0 (Simpson error ~1e-13)
    EXPECT_NEAR(I * h, 0.0, 1e-10) << "h = " << h;
  }
}

// ---- point values ---------------------------------------------------------------

TEST(Kernel, CentralValue) {
  for (double h : kH) {
    const double expected = 21.0 / (16.0 * kPi * h * h * h);
    // 1/h, h^3 and the products: at most ~6 roundings
    EXPECT_NEAR(kernel::w(0.0, h), expected, 8 * std::numeric_limits<double>::epsilon() * expected);
  }
}

TEST(Kernel, ClosedFormAtSeveralRadii) {
  const double h = 0.37;
  for (double q : {0.1, 0.5, 1.0, 1.5, 1.9}) {
    const double r = q * h;
    const double expected =
        21.0 / (16.0 * kPi * std::pow(h, 3)) * std::pow(1.0 - q / 2.0, 4) * (2.0 * q + 1.0);
    EXPECT_NEAR(kernel::w(r * r, h), expected, 1e-13 * kernel::w(0.0, h))
        << "q = " << q;  // a few roundings
  }
}

TEST(Kernel, VanishesAtAndBeyondSupport) {
  for (double h : kH) {
    const double inv_h = 1.0 / h;
    for (double q : {2.0, 2.0 + 1e-12, 2.5, 10.0}) {
      EXPECT_EQ(kernel::w_q(q, inv_h), 0.0) << "q = " << q;
      EXPECT_EQ(kernel::grad_factor_q(q, inv_h), 0.0) << "q = " << q;
      EXPECT_EQ(kernel::dw_dh_q(q, inv_h), 0.0) << "q = " << q;
    }
    for (double q : {2.0 + 1e-12, 2.5, 10.0}) {
      const double r2 = (q * h) * (q * h);
      EXPECT_EQ(kernel::w(r2, h), 0.0) << "q = " << q;
      EXPECT_EQ(kernel::grad_factor(r2, h), 0.0) << "q = " << q;
      EXPECT_EQ(kernel::dw_dh(r2, h), 0.0) << "q = " << q;
    }
    // r = 2h through r^2: sqrt(r^2)/h may round to 2 - 1 ulp, leaving (1e-16)^3 at most.
    const double r2 = (2.0 * h) * (2.0 * h), w0 = kernel::w(0.0, h);
    EXPECT_LE(kernel::w(r2, h), 1e-40 * w0);
    EXPECT_LE(std::abs(kernel::grad_factor(r2, h)) * h * h, 1e-40 * w0);
    EXPECT_LE(std::abs(kernel::dw_dh(r2, h)) * h, 1e-40 * w0);
    // Continuous at the edge: just inside, W ~ C (1e-6/2)^4 * 5 / h^3.
    const double r = (2.0 - 1e-6) * h;
    EXPECT_LT(kernel::w(r * r, h), 1e-20 * w0);
    EXPECT_LT(std::abs(dw_dr(r, h)) * h, 1e-15 * w0);
  }
}

// ---- derivatives against finite differences -------------------------------------

TEST(Kernel, GradientMatchesFiniteDifference) {
  for (double h : kH) {
    const double scale = kernel::w(0.0, h) / h;  // typical |dW/dr|
    const double step = 1e-5 * h;
    for (double q : {0.05, 0.3, 0.7, 1.0, 1.3, 1.7, 1.95}) {
      const double r = q * h;
      const double fd =
          (kernel::w((r + step) * (r + step), h) - kernel::w((r - step) * (r - step), h)) /
          (2 * step);
      // truncation step^2 W'''/6 ~ 1e-10 scale; round-off eps W/step ~ 1e-11 scale
      EXPECT_NEAR(dw_dr(r, h), fd, 1e-8 * scale) << "h = " << h << ", q = " << q;
    }
  }
}

TEST(Kernel, SmoothingLengthDerivativeMatchesFiniteDifference) {
  for (double h : kH) {
    const double scale = kernel::w(0.0, h) / h;
    const double step = 1e-5 * h;
    for (double q : {0.0, 0.3, 0.7, 1.0, 1.3, 1.7, 1.95}) {
      const double r2 = (q * h) * (q * h);
      const double fd = (kernel::w(r2, h + step) - kernel::w(r2, h - step)) / (2 * step);
      EXPECT_NEAR(kernel::dw_dh(r2, h), fd, 1e-8 * scale)
          << "h = " << h << ", q = " << q;  // as above
    }
  }
}

// ---- q forms --------------------------------------------------------------------

TEST(Kernel, QFormsAgreeWithR2Forms) {
  for (double h : kH) {
    const double inv_h = 1.0 / h;
    for (double q : {0.0, 0.25, 0.8, 1.2, 1.99, 2.0, 2.2}) {
      const double r = q * h;
      const double qq = r / h;  // as a caller would form it
      // same arithmetic up to r/h vs sqrt(r^2)/h: a few ulps, amplified <= 10x by the polynomial
      const double tol = 1e-14;
      EXPECT_NEAR(kernel::w_q(qq, inv_h), kernel::w(r * r, h), tol * kernel::w(0.0, h));
      EXPECT_NEAR(kernel::grad_factor_q(qq, inv_h), kernel::grad_factor(r * r, h),
                  tol * kernel::w(0.0, h) / (h * h));
      EXPECT_NEAR(kernel::dw_dh_q(qq, inv_h), kernel::dw_dh(r * r, h), tol * kernel::w(0.0, h) / h);
    }
  }
}

}  // namespace

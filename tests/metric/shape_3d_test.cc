// tests/metric/shape_3d_test.cc
// The 3D shape residuals: the default deviatoric form r = sqrt(mu) w / |w| (exact, accurate
// near the minimiser, Gauss-Newton model at the minimiser); the polar form r = c vec(S - R): the
// polar rotation and its derivative, the
// rotation-fixed Jacobian, J^t r against the gradient with R held fixed, and the Gauss-Newton
// model along element rotations; the cofactor residual form of the same metrics. Also the
// small-matrix kernels they rely on.
#include "tmop/metric/shape_3d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "tests/metric/metric_test_util.h"
#include "tmop/metric/small_matrix.h"

namespace tmop {
namespace {

using metric_test::central_jacobian;
using metric_test::eval;
using metric_test::Mat;
using metric_test::random_matrix;
using metric_test::random_rotation;
using metric_test::scaled_error;
using Vec9 = Eigen::Matrix<double, 9, 1>;

struct PolarForm {
  Shape3dForm form;
  double c2;  // r = sqrt(c2) vec(S - R)
};
const PolarForm kPolarForms[] = {{Shape3dForm::kBarrier, 2.0 / 3.0},
                                 {Shape3dForm::kCubicBarrier, 1.0},
                                 {Shape3dForm::kConditionBarrier, 2.0 / 3.0},
                                 {Shape3dForm::kConditionSquaredBarrier, 4.0 / 3.0}};

Mat polar_rotation(const Mat& T) {
  Mat R(3, 3);
  EXPECT_TRUE(small_matrix::polar_rotation_3(T.data(), R.data()));
  return R;
}

TEST(SmallMatrix, DeterminantAndCofactorMatchEigen) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    for (int d = 2; d <= 3; ++d) {
      const Mat T = Mat::Random(d, d);
      Mat C(d, d);
      double det;
      if (d == 2) {
        small_matrix::cofactor<2>(T.data(), C.data());
        det = small_matrix::det<2>(T.data());
      } else {
        small_matrix::cofactor<3>(T.data(), C.data());
        det = small_matrix::det<3>(T.data());
      }
      EXPECT_NEAR(det, T.determinant(), 1e-14);
      EXPECT_LT((C - det * Mat(T.inverse().transpose())).norm(), 1e-12);
    }
  }
}

// x^(-1/3) without a division: within a few ulp of 1/cbrt(x) over the range the metrics see
// (tau from 1e-30 to 1e30, every mantissa), and the fallback outside it (subnormal, huge, inf).
TEST(SmallMatrix, InverseCubeRootIsAccurateEverywhere) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> exponent(-690.0, 690.0);
  double worst = 0.0;
  for (int trial = 0; trial < 200000; ++trial) {
    const double x = std::exp(exponent(rng));
    const long double exact = 1.0L / std::cbrt(static_cast<long double>(x));
    const double got = small_matrix::inv_cbrt_positive(x);
    worst = std::max(worst, static_cast<double>(std::fabs((got - exact) / exact)));
  }
  EXPECT_LT(worst, 4e-16);
  for (const double x : {1.0, 8.0, 0.125, 27.0, 1e-300, 1e300, 1e-310, 4.9e-324, 1.7e308}) {
    const long double exact = 1.0L / std::cbrt(static_cast<long double>(x));
    EXPECT_NEAR(small_matrix::inv_cbrt_positive(x) / exact, 1.0, 4e-16) << x;
  }
  EXPECT_EQ(small_matrix::inv_cbrt_positive(8.0), 0.5);
  EXPECT_EQ(small_matrix::inv_cbrt_positive(HUGE_VAL), 0.0);
}

TEST(SmallMatrix, CofactorDerivativeMatchesCentralDifferences) {
  const Mat T = Mat::Random(3, 3);
  Mat H(9, 9);
  small_matrix::cofactor_derivative_3(T.data(), H.data());
  const Mat Hn = central_jacobian(
      [](const Mat& X) {
        Vec9 c;
        small_matrix::cofactor<3>(X.data(), c.data());
        return Eigen::VectorXd(c);
      },
      T, 9);
  EXPECT_LT(scaled_error(H, Hn), 1e-8);
}

TEST(SmallMatrix, PolarRotationMatchesSvdUpToIllConditioning) {
  std::mt19937 rng(11);
  for (double cond : {1.0, 10.0, 1e3, 1e6}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Mat T = random_matrix(3, rng, false, 1.0, cond);
      const Mat R = polar_rotation(T);
      Eigen::JacobiSVD<Mat> svd(T, Eigen::ComputeFullU | Eigen::ComputeFullV);
      const Mat expected = svd.matrixU() * svd.matrixV().transpose();
      EXPECT_LT((R - expected).norm(), 1e-12 * cond) << "cond " << cond;
      EXPECT_LT((R.transpose() * R - Mat::Identity(3, 3)).norm(), 1e-14);
      const Mat P = R.transpose() * T;
      EXPECT_LT((P - P.transpose()).norm(), 1e-12 * P.norm());
    }
  }
  Mat inverted = Mat::Identity(3, 3);
  inverted(2, 2) = -1.0;
  double R[9];
  EXPECT_FALSE(small_matrix::polar_rotation_3(inverted.data(), R));
}

TEST(SmallMatrix, PolarRotationDerivativeMatchesCentralDifferences) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const Mat S = random_matrix(3, rng, false, 0.2, 5.0);
    const Mat R = polar_rotation(S);
    Mat L(9, 9);
    small_matrix::polar_rotation_derivative_3(S.data(), R.data(), L.data());
    const Mat Ln = central_jacobian(
        [](const Mat& X) {
          const Mat RX = polar_rotation(X);
          return Eigen::VectorXd(Eigen::Map<const Vec9>(RX.data()));
        },
        S, 9);
    EXPECT_LT(scaled_error(L, Ln), 1e-7);
  }
}

TEST(PolarShape, RotationFixedJacobianMatchesDifferencesWithRFixed) {
  std::mt19937 rng(13);
  for (const PolarForm& f : kPolarForms) {
    std::unique_ptr<Metric> m = make_shape_3d_metric(f.form, Shape3dResidual::kPolarRotationFixed);
    const double c = std::sqrt(f.c2);
    for (int trial = 0; trial < 20; ++trial) {
      const Mat T = random_matrix(3, rng);
      const Mat R = polar_rotation(T);
      Eigen::VectorXd r;
      Mat J;
      ASSERT_TRUE(eval(*m, T, &r, &J));
      // r_R(X) = c (X det(X)^(-1/3) - R) with R the rotation of T, frozen.
      auto fixed = [&](const Mat& X) -> Eigen::VectorXd {
        return c * (Eigen::Map<const Vec9>(X.data()) / std::cbrt(X.determinant()) -
                    Eigen::Map<const Vec9>(R.data()));
      };
      EXPECT_LT((fixed(T) - r).cwiseAbs().maxCoeff(), 1e-12) << m->name();
      EXPECT_LT(scaled_error(J, central_jacobian(fixed, T, 9)), 1e-6) << m->name();
    }
  }
}

TEST(PolarShape, JtRIsTheGradientWithRotationHeldFixed) {
  std::mt19937 rng(14);
  for (const PolarForm& f : kPolarForms) {
    for (Shape3dResidual residual :
         {Shape3dResidual::kPolar, Shape3dResidual::kPolarRotationFixed}) {
      std::unique_ptr<Metric> m = make_shape_3d_metric(f.form, residual);
      const double c = std::sqrt(f.c2);
      for (int trial = 0; trial < 20; ++trial) {
        const Mat T = random_matrix(3, rng, false, 0.2, 5.0);
        const Mat R = polar_rotation(T);
        Eigen::VectorXd r;
        Mat J;
        ASSERT_TRUE(eval(*m, T, &r, &J));
        auto half_squared = [&](const Mat& X) -> Eigen::VectorXd {
          const Vec9 rx = c * (Eigen::Map<const Vec9>(X.data()) / std::cbrt(X.determinant()) -
                               Eigen::Map<const Vec9>(R.data()));
          return Eigen::VectorXd::Constant(1, 0.5 * rx.squaredNorm());
        };
        const Mat g = (J.transpose() * r).transpose();
        EXPECT_LT(scaled_error(g, central_jacobian(half_squared, T, 1)), 1e-6) << m->name();
      }
    }
  }
}

TEST(PolarShape, ExactJacobianHasNoStiffnessAlongRotationsAtTheMinimum) {
  std::mt19937 rng(15);
  for (const PolarForm& f : kPolarForms) {
    std::unique_ptr<Metric> exact = make_shape_3d_metric(f.form, Shape3dResidual::kPolar);
    std::unique_ptr<Metric> fixed =
        make_shape_3d_metric(f.form, Shape3dResidual::kPolarRotationFixed);
    const Mat T = 1.7 * random_rotation(3, rng);  // a minimiser
    Mat W = Mat::Random(3, 3);
    W = W - Mat(W.transpose());  // skew: dT = W T rotates the element
    const Mat dT = W * T;
    const Eigen::Map<const Vec9> dt(dT.data());
    Eigen::VectorXd r;
    Mat J;
    ASSERT_TRUE(eval(*exact, T, &r, &J));
    EXPECT_LT((J * dt).norm(), 1e-12 * dt.norm()) << exact->name();
    ASSERT_TRUE(eval(*fixed, T, &r, &J));
    EXPECT_GT((J * dt).norm(), 0.1 * dt.norm()) << fixed->name();
  }
}

TEST(PolarShape, MinimisersAgreeWithThePublishedMetric) {
  std::mt19937 rng(16);
  for (const PolarForm& f : kPolarForms) {
    std::unique_ptr<Metric> m = make_shape_3d_metric(f.form);
    for (int trial = 0; trial < 20; ++trial) {
      // On s R both vanish; off it both are positive.
      const Mat on = std::exp(trial / 5.0 - 2.0) * random_rotation(3, rng);
      Eigen::VectorXd r;
      ASSERT_TRUE(eval(*m, on, &r, nullptr));
      EXPECT_LT(r.norm(), 1e-10);
      EXPECT_NEAR(m->value(on.data()), 0.0, 1e-12);
      const Mat off = random_matrix(3, rng);
      ASSERT_TRUE(eval(*m, off, &r, nullptr));
      EXPECT_GT(r.norm(), 1e-6);
      EXPECT_GT(m->value(off.data()), 1e-10);
    }
  }
}

TEST(CofactorShape, JacobianMatchesCentralDifferences) {
  std::mt19937 rng(17);
  for (const PolarForm& f : kPolarForms) {
    std::unique_ptr<Metric> m = make_shape_3d_metric(f.form, Shape3dResidual::kCofactor);
    for (int trial = 0; trial < 30; ++trial) {
      const Mat T = random_matrix(3, rng, false, trial < 20 ? 0.3 : 0.1, trial < 20 ? 3.0 : 10.0);
      Eigen::VectorXd r;
      Mat J;
      ASSERT_TRUE(eval(*m, T, &r, &J));
      const Mat Jn = central_jacobian(
          [&](const Mat& X) {
            Eigen::VectorXd rx;
            EXPECT_TRUE(eval(*m, X, &rx, nullptr));
            return rx;
          },
          T, 9);
      EXPECT_LT(scaled_error(J, Jn), 1e-6) << m->name();
    }
  }
}

TEST(CofactorShape, SameMinimisersInvariancesAndSecondOrderAgreement) {
  std::mt19937 rng(18);
  for (const PolarForm& f : kPolarForms) {
    std::unique_ptr<Metric> m = make_shape_3d_metric(f.form, Shape3dResidual::kCofactor);
    std::unique_ptr<Metric> polar = make_shape_3d_metric(f.form, Shape3dResidual::kPolar);
    EXPECT_EQ(m->name(), polar->name());
    EXPECT_FALSE(m->exact_residuals());
    for (int trial = 0; trial < 20; ++trial) {
      const Mat Q1 = random_rotation(3, rng), Q2 = random_rotation(3, rng);
      const double s = std::exp(trial / 5.0 - 2.0);
      Eigen::VectorXd r;
      ASSERT_TRUE(eval(*m, Mat(s * Q1), &r, nullptr));
      EXPECT_LT(r.norm(), 1e-12);
      const Mat T = random_matrix(3, rng);
      ASSERT_TRUE(eval(*m, T, &r, nullptr));
      const double rr = r.squaredNorm();
      EXPECT_GT(rr, 1e-8);
      for (const Mat& X : {Mat(Q1 * T), Mat(T * Q2), Mat(s * T)}) {
        Eigen::VectorXd rx;
        ASSERT_TRUE(eval(*m, X, &rx, nullptr));
        EXPECT_NEAR(rx.squaredNorm(), rr, 1e-10 * rr);
      }
      // Second order at the minimiser: (mu - 0) / |r|^2 -> 1.
      const Mat E = Mat::Random(3, 3);
      for (double eps : {1e-3, 1e-4}) {
        const Mat X = s * Q1 * (Mat::Identity(3, 3) + eps * E) * Q2;
        ASSERT_TRUE(eval(*m, X, &r, nullptr));
        EXPECT_NEAR(m->value(X.data()) / r.squaredNorm(), 1.0, 20 * eps) << m->name();
      }
    }
  }
}

TEST(CofactorShape, IsABarrier) {
  std::mt19937 rng(19);
  for (const PolarForm& f : kPolarForms) {
    std::unique_ptr<Metric> m = make_shape_3d_metric(f.form, Shape3dResidual::kCofactor);
    Mat T = random_matrix(3, rng, true);
    double r[9], J[81];
    EXPECT_FALSE(m->residuals(T.data(), r, J));
    double previous = 0.0;
    for (double delta : {1e-1, 1e-3, 1e-5, 1e-7}) {
      Mat D = Mat::Identity(3, 3);
      D(2, 2) = delta;
      T = random_rotation(3, rng) * D;
      ASSERT_TRUE(m->residuals(T.data(), r, J));
      const double rr = Eigen::Map<const Vec9>(r).squaredNorm();
      EXPECT_GT(rr, previous);
      previous = rr;
    }
    EXPECT_GT(previous, 1e5);
  }
}

// The published formulas in long double, without the cancellation-free rewriting of shape_3d.cc.
long double published_mu(Shape3dForm form, const Mat& T) {
  long double t[9];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t[3 * i + j] = T(i, j);
  const long double k[9] = {
      t[4] * t[8] - t[5] * t[7], t[5] * t[6] - t[3] * t[8], t[3] * t[7] - t[4] * t[6],
      t[2] * t[7] - t[1] * t[8], t[0] * t[8] - t[2] * t[6], t[1] * t[6] - t[0] * t[7],
      t[1] * t[5] - t[2] * t[4], t[2] * t[3] - t[0] * t[5], t[0] * t[4] - t[1] * t[3]};
  const long double tau = t[0] * k[0] + t[1] * k[1] + t[2] * k[2];
  long double f = 0, fk = 0;
  for (int n = 0; n < 9; ++n) {
    f += t[n] * t[n];
    fk += k[n] * k[n];
  }
  switch (form) {
    case Shape3dForm::kBarrier:
      return f / (3 * std::cbrt(tau * tau)) - 1;
    case Shape3dForm::kCubicBarrier:
      return f * std::sqrt(f) / (3 * std::sqrt(3.0L) * tau) - 1;
    case Shape3dForm::kConditionBarrier:
      return std::sqrt(f * fk) / (3 * tau) - 1;
    default:
      return f * fk / (9 * tau * tau) - 1;
  }
}

// The deviatoric form: 5 residuals whose squared norm is mu itself, for all four barrier forms.
TEST(DeviatoricShape, FiveResidualsWhoseSquaredNormIsMu) {
  std::mt19937 rng(20);
  for (const PolarForm& f : kPolarForms) {
    std::unique_ptr<Metric> m = make_shape_3d_metric(f.form);
    EXPECT_EQ(m->num_residuals(), 5);
    EXPECT_TRUE(m->exact_residuals());
    for (int trial = 0; trial < 50; ++trial) {
      const Mat T = random_matrix(3, rng, false, trial < 25 ? 0.3 : 0.02, trial < 25 ? 3.0 : 50.0);
      Eigen::VectorXd r;
      ASSERT_TRUE(eval(*m, T, &r, nullptr));
      const double mu = static_cast<double>(published_mu(f.form, T));
      // Singular values 0.02..50 make det T itself uncertain to ~1e-11 relative.
      const double tol = trial < 25 ? 1e-12 : 1e-9;
      EXPECT_NEAR(r.squaredNorm(), mu, tol * mu) << m->name();
      EXPECT_NEAR(m->value(T.data()), mu, tol * mu) << m->name();
    }
  }
}

// Near the minimiser the published formulas cancel (mu = |T|^2 / (3 tau^(2/3)) - 1 loses all
// digits of mu below 1e-16); the rewritten ones keep mu, and |r|^2, to a few ulps.
TEST(DeviatoricShape, MuIsAccurateNearTheMinimiser) {
  std::mt19937 rng(21);
  for (const PolarForm& f : kPolarForms) {
    std::unique_ptr<Metric> m = make_shape_3d_metric(f.form);
    for (double eps : {1e-3, 1e-5, 1e-7}) {
      const Mat E = Mat::Random(3, 3);
      const Mat T = 2.5 * random_rotation(3, rng) * (Mat::Identity(3, 3) + eps * E);
      const long double exact = published_mu(f.form, T);  // 64-bit mantissa: ~1e-19 absolute
      ASSERT_GT(exact, 0);
      const double v = m->value(T.data());
      // mu ~ eps^2: 1e-14 at eps = 1e-7, where a double evaluation of the published formula has
      // an absolute error ~1e-16, i.e. 1 % of mu; the tolerances are the reference's own error.
      const double tol = eps > 1e-4 ? 1e-10 : (eps > 1e-6 ? 1e-7 : 1e-4);
      EXPECT_NEAR(v / static_cast<double>(exact), 1.0, tol) << m->name() << " eps " << eps;
      // The residuals the solver sees are as accurate as the reported value.
      Eigen::VectorXd r;
      ASSERT_TRUE(eval(*m, T, &r, nullptr));
      EXPECT_NEAR(r.squaredNorm() / static_cast<double>(exact), 1.0, tol)
          << m->name() << " eps " << eps;
    }
  }
}

// At the minimiser J^t J is half the Hessian of mu (the Gauss-Newton model is exact there), and
// the Jacobian is continuous at an ideal T (w = 0).
TEST(DeviatoricShape, GaussNewtonModelIsHalfTheHessianAtTheMinimiser) {
  std::mt19937 rng(22);
  for (const PolarForm& f : kPolarForms) {
    std::unique_ptr<Metric> m = make_shape_3d_metric(f.form);
    const Mat T0 = 1.3 * random_rotation(3, rng);
    Eigen::VectorXd r;
    Mat J;
    ASSERT_TRUE(eval(*m, T0, &r, &J));
    EXPECT_LT(r.norm(), 1e-14);
    // Hessian of mu by central differences of the exact gradient 2 J^t r.
    const Mat H = central_jacobian(
        [&](const Mat& X) -> Eigen::VectorXd {
          Eigen::VectorXd rx;
          Mat Jx;
          EXPECT_TRUE(eval(*m, X, &rx, &Jx));
          return 2.0 * Jx.transpose() * rx;
        },
        T0, 9, 1e-5);
    const Mat JtJ = J.transpose() * J;
    EXPECT_LT((JtJ - 0.5 * H).norm(), 1e-6 * H.norm()) << m->name();
    // Just off the minimiser the Jacobian is close to the ideal one.
    const Mat T1 = T0 * (Mat::Identity(3, 3) + 1e-7 * Mat::Random(3, 3));
    Eigen::VectorXd r1;
    Mat J1;
    ASSERT_TRUE(eval(*m, T1, &r1, &J1));
    EXPECT_LT((J1.transpose() * J1 - JtJ).norm(), 1e-5 * JtJ.norm()) << m->name();
  }
}

}  // namespace
}  // namespace tmop

// Screw motion and dual quaternions (engine/dual/screw.h, dual_quaternion.h; issue 31 item 2):
// exact checks (the dual Rodrigues formula is exp of the dual skew tensor and moves lines as
// the rigid motion does, dual orthogonality, composition = product of dual quaternions, round
// trips) and a numeric one against the matrix exponential on SE(3) (Eigen's MatrixFunctions).
#include <cmath>

#include <Eigen/Dense>
#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

#include "symrep/core/error.h"
#include "symrep/dual/dual.h"
#include "symrep/dual/dual_quaternion.h"
#include "symrep/dual/screw.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/vector/vector.h"

using namespace symrep;
using GiNaC::ex;

namespace {

const ex& eps = dual::dual_unit();

// Both parts of a - b proved 0 by the exact zero test (trigonometric identities included).
::testing::AssertionResult proved_equal(const ex& a, const ex& b) {
    const dual::dual_parts d = dual::parts(a - b);
    for (const ex& x : {d.primal, d.dual}) {
        const truth z = decide_zero_vector(x).is_zero;  // vectors and scalars, by components
        if (z != truth::yes)
            return ::testing::AssertionFailure() << "not proved equal: " << to_string(a) << "\n and " << to_string(b)
                                                 << "\n difference part " << to_string(x);
    }
    return ::testing::AssertionSuccess();
}

GiNaC::matrix I3() { return GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3)); }

ex lit(const ex& x, const ex& y, const ex& z) { return vector_literal(x, y, z); }

Eigen::Vector3d num(const ex& v) {
    const ex l = dual::components_of(v, "v");
    Eigen::Vector3d r;
    for (int i = 0; i < 3; ++i) r[i] = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(l.op(i))).to_double();
    return r;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& w) {
    Eigen::Matrix3d S;
    S << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    return S;
}

}  // namespace

TEST(Screw, DualRodriguesIsTheExponentialOfTheDualSkewTensor) {
    // abstract axis direction u (normalized inside), point p and line x^ = x + eps x1; a > 0
    GiNaC::possymbol a("a");
    GiNaC::realsymbol d("d");
    const ex u = vector_symbol("u"), p = vector_symbol("p"), x = vector_symbol("x"), x1 = vector_symbol("x1");
    const dual::screw s{u, p, a, d};
    const ex xh = dual::make_dual(x, x1);
    const ex q = dual::screw_apply(s, xh);
    // the twist a^ u^ = a u + eps (a p x u + d u) (u unit) exponentiated
    const ex uh = dual::dual_axis(s);
    EXPECT_TRUE(proved_equal(q, dual::exp_dual_skew(dual::reduce(dual::dual_angle(s) * uh), xh)));
    // not the opposite screw
    const dual::screw back{u, p, -a, d};
    EXPECT_FALSE(proved_equal(q, dual::screw_apply(back, xh)));
}

TEST(Screw, MovesLinesAsTheRigidMotion) {
    // Q^ (x + eps q x x) = R x + eps ((dv + R q) x R x), R the rotation by a about u,
    // dv = (I - R) p + d u: abstract x, q, p; u = [0, 0, 1]
    GiNaC::realsymbol a("a"), d("d");
    const ex u = lit(0, 0, 1), p = vector_symbol("p"), x = vector_symbol("x"), q = vector_symbol("q");
    const auto R = [&](const ex& y) {
        return GiNaC::cos(a) * y + GiNaC::sin(a) * cross(u, y) + (1 - GiNaC::cos(a)) * dot(u, y) * u;
    };
    const ex dv = p - R(p) + d * u;
    const ex moved = dual::make_dual(R(x), cross(dv + R(q), R(x)));
    EXPECT_TRUE(proved_equal(dual::screw_apply({u, p, a, d}, dual::make_dual(x, cross(q, x))), moved));
}

TEST(Screw, DualOrthogonality) {
    // Q^ x^ . Q^ y^ = x^ . y^ and Q^ (x^ x y^) = Q^ x^ x Q^ y^ (Q^T Q = I, det Q^ = 1)
    GiNaC::realsymbol a("a"), d("d");
    const dual::screw s{lit(1, 2, 2), lit(1, -1, 0), a, d};
    const ex x = dual::make_dual(vector_symbol("x"), vector_symbol("x1"));
    const ex y = dual::make_dual(vector_symbol("y"), vector_symbol("y1"));
    const ex qx = dual::screw_apply(s, x), qy = dual::screw_apply(s, y);
    EXPECT_TRUE(proved_equal(dual::dual_dot(qx, qy), dual::dual_dot(x, y)));
    EXPECT_TRUE(proved_equal(dual::dual_cross(qx, qy), dual::screw_apply(s, dual::dual_cross(x, y))));
}

TEST(Screw, PureTranslationAndZeroTwist) {
    GiNaC::realsymbol d("d");
    const ex x = vector_symbol("x"), x1 = vector_symbol("x1"), v = vector_symbol("v");
    const ex xh = dual::make_dual(x, x1);
    // a = 0: the line moves by d u, its moment changes by d u x x
    const ex moved = dual::screw_apply({lit(0, 0, 1), 0, 0, d}, xh);
    EXPECT_TRUE(proved_equal(moved, dual::make_dual(x, x1 + d * cross(lit(0, 0, 1), x))));
    // exp(eps V) = I + eps V
    EXPECT_TRUE(proved_equal(dual::exp_dual_skew(eps * v, xh), dual::make_dual(x, x1 + cross(v, x))));
    EXPECT_THROW(dual::screw_apply({0, 0, 1, 0}, xh), type_error);
}

TEST(Screw, ParametersRoundTrip) {
    // u = [1, 2, 2]/3 through p, a = pi/3, d = 2: to (R, d) and back (p the point nearest 0)
    const ex u = lit(GiNaC::numeric(1, 3), GiNaC::numeric(2, 3), GiNaC::numeric(2, 3));
    const ex p0 = lit(1, 0, 3);
    const ex p = lit(1 - dot(u, p0) * GiNaC::numeric(1, 3), -dot(u, p0) * GiNaC::numeric(2, 3),
                     3 - dot(u, p0) * GiNaC::numeric(2, 3));  // p0 - (u . p0) u
    const dual::rigid_motion m = dual::motion_of_screw({lit(1, 2, 2), p0, GiNaC::Pi / 3, 2});
    const dual::screw s = dual::screw_of_motion(m);
    EXPECT_TRUE(proved_equal(s.axis, u));
    EXPECT_TRUE(proved_equal(s.point, p));
    EXPECT_TRUE((s.angle - GiNaC::Pi / 3).is_zero()) << s.angle;
    EXPECT_TRUE(proved_equal(s.translation, 2));
    // a pure translation, a half turn, the identity
    const dual::screw t = dual::screw_of_motion({I3(), lit(0, 3, 4)});
    EXPECT_TRUE(proved_equal(t.axis, lit(0, GiNaC::numeric(3, 5), GiNaC::numeric(4, 5))));
    EXPECT_TRUE(t.angle.is_zero() && proved_equal(t.translation, 5));
    const dual::rigid_motion h = dual::motion_of_screw({lit(0, 1, 1), lit(1, 0, 0), GiNaC::Pi, 3});
    const dual::screw hs = dual::screw_of_motion(h);
    EXPECT_TRUE(proved_equal(hs.axis, lit(0, 1 / GiNaC::sqrt(ex(2)), 1 / GiNaC::sqrt(ex(2)))));
    EXPECT_TRUE(proved_equal(hs.point, lit(1, 0, 0)));
    EXPECT_TRUE((hs.angle - GiNaC::Pi).is_zero() && proved_equal(hs.translation, 3));
    EXPECT_THROW(dual::screw_of_motion({I3(), lit(0, 0, 0)}), domain_error);
    // not a rotation: a reflection, a shear
    EXPECT_THROW(dual::screw_of_motion({GiNaC::matrix(3, 3, GiNaC::lst{1, 0, 0, 0, 1, 0, 0, 0, -1}), lit(0, 0, 0)}),
                 domain_error);
    EXPECT_THROW(dual::screw_of_motion({GiNaC::matrix(3, 3, GiNaC::lst{1, 1, 0, 0, 1, 0, 0, 0, 1}), lit(0, 0, 0)}),
                 domain_error);
}

TEST(Screw, DualQuaternionsExact) {
    GiNaC::realsymbol a("a"), d("d"), b("b"), e("e");
    const dual::screw s1{lit(0, 0, 1), lit(1, 2, 0), a, d}, s2{lit(1, 0, 0), lit(0, 1, 3), b, e};
    const ex x = dual::make_dual(vector_symbol("x"), vector_symbol("x1"));
    const dual::dual_quaternion q1 = dual::dq_of_screw(s1), q2 = dual::dq_of_screw(s2);
    // unit, the same action as the dual tensor, composition = product
    EXPECT_NO_THROW(dual::require_unit(q1, "test"));
    EXPECT_TRUE(proved_equal(dual::dq_apply(q1, x), dual::screw_apply(s1, x)));
    EXPECT_TRUE(proved_equal(dual::dq_apply(dual::dq_product(q1, q2), x),
                             dual::screw_apply(s1, dual::screw_apply(s2, x))));
    EXPECT_FALSE(proved_equal(dual::dq_apply(dual::dq_product(q2, q1), x),
                              dual::screw_apply(s1, dual::screw_apply(s2, x))));
    // q q* = 1
    const dual::dual_quaternion one = dual::dq_product(q1, dual::dq_conjugate(q1));
    EXPECT_TRUE(proved_equal(one.scalar, 1));
    EXPECT_TRUE(proved_equal(one.vector, 0));
    EXPECT_THROW(dual::dq_apply(dual::make_dual_quaternion(2, 0), x), domain_error);
}

TEST(Screw, DualQuaternionsAndMotionsRoundTrip) {
    for (const ex& ang : {GiNaC::Pi / 3, ex(GiNaC::Pi), ex(0), 2 * GiNaC::Pi / 3}) {
        const dual::screw s{lit(2, 1, 2), lit(0, 1, -1), ang, GiNaC::numeric(1, 2)};
        const dual::rigid_motion m = dual::motion_of_screw(s);
        const dual::dual_quaternion q = dual::dq_of_motion(m);
        const dual::rigid_motion back = dual::motion_of_dq(q);
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = 0; j < 3; ++j) EXPECT_TRUE(proved_equal(back.R(i, j), m.R(i, j))) << ang;
        EXPECT_TRUE(proved_equal(back.d, m.d)) << ang;
        // q of the motion is +- q of the screw; both act alike on lines
        const ex line = dual::make_dual(lit(1, 0, 0), lit(0, 0, 5));
        EXPECT_TRUE(proved_equal(dual::dq_apply(q, line), dual::screw_apply(s, line))) << ang;
        EXPECT_TRUE(proved_equal(dual::motion_apply(m, line), dual::screw_apply(s, line))) << ang;
    }
}

TEST(Screw, AgainstTheMatrixExponentialOnSE3) {
    // Tolerance 1e-12: Eigen's exp (Pade with scaling and squaring) of 4x4 and 6x6 matrices of
    // norm < 5 is accurate to a few units of 1e-16; the exact side is evaluated at 16+ digits.
    const ex U = lit(1, -2, 2), P = lit(GiNaC::numeric(1, 2), 1, -1);
    const ex A = GiNaC::numeric(7, 5), D = GiNaC::numeric(-3, 4);
    const dual::rigid_motion m = dual::motion_of_screw({U, P, A, D});
    const Eigen::Vector3d u = num(U).normalized(), p = num(P);
    const double a = 1.4, d = -0.75;
    const Eigen::Vector3d w = a * u, v = a * p.cross(u) + d * u;  // the twist a^ u^
    Eigen::Matrix4d xi = Eigen::Matrix4d::Zero();
    xi.topLeftCorner<3, 3>() = skew(w);
    xi.topRightCorner<3, 1>() = v;
    const Eigen::Matrix4d g = xi.exp();
    Eigen::Matrix3d R;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) R(i, j) = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(m.R(i, j))).to_double();
    EXPECT_LT((g.topLeftCorner<3, 3>() - R).norm(), 1e-12);
    EXPECT_LT((g.topRightCorner<3, 1>() - num(m.d)).norm(), 1e-12);
    // the dual tensor as a 6x6 matrix: exp([[W, 0], [V, W]]) = [[R, 0], [skew(d) R, R]]
    Eigen::Matrix<double, 6, 6> X = Eigen::Matrix<double, 6, 6>::Zero();
    X.topLeftCorner<3, 3>() = X.bottomRightCorner<3, 3>() = skew(w);
    X.bottomLeftCorner<3, 3>() = skew(v);
    const Eigen::Matrix<double, 6, 6> G = X.exp();
    EXPECT_LT((G.bottomLeftCorner<3, 3>() - skew(num(m.d)) * R).norm(), 1e-12);
    // and on a line: exp_dual_skew and the dual quaternion against G
    const ex line = dual::make_dual(lit(0, 1, 1), lit(2, 0, 0));
    Eigen::Matrix<double, 6, 1> l;
    l << 0, 1, 1, 2, 0, 0;
    const Eigen::Matrix<double, 6, 1> gl = G * l;
    const ex twist = dual::make_dual(vector_literal(A * U.op(0) / 3, A * U.op(1) / 3, A * U.op(2) / 3),
                                     dual::components_of(A * cross(P, U) / 3 + D * U / 3, "v"));
    for (const ex& moved : {dual::exp_dual_skew(twist, line), dual::dq_apply(dual::dq_of_screw({U, P, A, D}), line)}) {
        const dual::dual_parts mp = dual::parts(moved);
        EXPECT_LT((num(mp.primal) - gl.head<3>()).norm(), 1e-12);
        EXPECT_LT((num(mp.dual) - gl.tail<3>()).norm(), 1e-12);
    }
}

// symrep/lang/builtins_relative_pose.cpp -- relative_pose(...): the exact full-body relative
// orbital motion of mechanics/relative_pose.h ([C23]) in the language.
//
// Each body's attitude motion is its angular velocity w(t) in its own body components, an
// expression in the time symbol of the last argument t = T, read as the most special class
// that holds it: constant, a fixed axis s(t) u (its angle int_0^t s in closed form), a
// regular precession c u1 + R_u1(-c t) v (mechanics/turning_frame.h readers), else numeric
// (Magnus on SO(3)); or the string "orbital" (locked to its own LVLH frame).
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include "symrep/lang/builtins.h"
#include "symrep/lang/values.h"
#include "symrep/mechanics/relative_motion.h"
#include "symrep/mechanics/relative_pose.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/numeric/evaluator.h"
#include "symrep/numeric/reference.h"
#include "symrep/numeric/se3.h"
#include "symrep/output/printer.h"
#include "symrep/vector/vector.h"

namespace symrep::lang {

using GiNaC::ex;
using args_t = std::vector<value>;

namespace {

const char* const section = "Vectors and mechanics";

// A value as an expression: a list [a, b, c] of expressions is the vector literal.
ex vector_value(const value& v, const builtin& b, const std::string& what) {
    if (v.is_list() && v.as_list().size() == 3 && v.as_list()[0].is_ex() && v.as_list()[1].is_ex() &&
        v.as_list()[2].is_ex())
        return vector_literal(v.as_list()[0].as_ex(), v.as_list()[1].as_ex(), v.as_list()[2].as_ex());
    if (!v.is_ex() || (!v.as_ex().is_zero() && !is_vector_literal(v.as_ex())))
        throw type_error(b.name + ": " + what + " must be a vector [x, y, z] (usage: " + b.signature + ")");
    return v.as_ex().is_zero() ? vector_literal(0, 0, 0) : v.as_ex();
}

Eigen::Vector3d numbers3(const ex& v, const builtin& b, const std::string& what) {
    return {to_double(v.op(0), b, what), to_double(v.op(1), b, what), to_double(v.op(2), b, what)};
}

Eigen::Vector3d number_vector(const value& v, const builtin& b, const std::string& what) {
    return numbers3(vector_value(v, b, what), b, what);
}

// A rotation: a 3x3 matrix, a list of three rows, or a unit quaternion [w, x, y, z].
Eigen::Matrix3d rotation_value(const value& v, const builtin& b, const std::string& what) {
    Eigen::Matrix3d R;
    auto refuse = [&]() -> Eigen::Matrix3d {
        throw type_error(b.name + ": " + what + " must be a rotation: a 3x3 matrix [[..], [..], [..]] or a unit "
                         "quaternion [w, x, y, z]");
    };
    if (v.is_list() && v.as_list().size() == 4) {
        double q[4];
        for (int i = 0; i < 4; ++i) {
            if (!v.as_list()[i].is_ex()) return refuse();
            q[i] = to_double(v.as_list()[i].as_ex(), b, what);
        }
        const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(std::abs(n - 1) < 1e-9))
            throw domain_error(b.name + ": " + what + " as a quaternion must have norm 1 (it has " +
                               std::to_string(n) + ")");
        return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
    }
    if (v.is_list() && v.as_list().size() == 3) {
        for (int i = 0; i < 3; ++i) {
            const value& row = v.as_list()[i];
            const ex r = row.is_list() ? vector_value(row, b, what) : (row.is_ex() ? row.as_ex() : ex(0));
            if (!is_vector_literal(r)) return refuse();
            R.row(i) = numbers3(r, b, what).transpose();
        }
        return R;
    }
    if (v.is_ex() && GiNaC::is_a<GiNaC::matrix>(v.as_ex())) {
        const GiNaC::matrix& m = GiNaC::ex_to<GiNaC::matrix>(v.as_ex());
        if (m.rows() != 3 || m.cols() != 3) return refuse();
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = 0; j < 3; ++j) R(i, j) = to_double(m(i, j), b, what);
        return R;
    }
    return refuse();
}

std::function<double(double)> scalar_function(const ex& e, const ex& t) {
    auto f = std::make_shared<num::compiled_function>(num::compile(e, {t}));
    return [f](double x) {
        double out;
        f->eval(&x, &out);
        return out;
    };
}

// An attitude motion: "orbital" or w(t) (body components) in the time symbol t.
mechanics::attitude_motion attitude_value(const value& v, const ex& t, const builtin& b, const std::string& who) {
    using mechanics::attitude_motion;
    if (v.is_string()) {
        if (v.as_string() == "orbital") return attitude_motion::orbital();
        throw type_error(b.name + ": the " + who + "'s attitude motion is w(t) or \"orbital\", not \"" +
                         v.as_string() + "\"");
    }
    const std::string what = "the " + who + "'s angular velocity w(t)";
    const ex w = vector_value(v, b, what);
    try {
        if (!w.has(t)) return attitude_motion::constant(numbers3(w, b, what));
        if (const auto fd = mechanics::fixed_direction(w, t)) {
            const auto& [s, u] = *fd;
            if (is_vector_literal(u) && !u.has(t))
                if (const auto a = mechanics::rotation_angle(s, u, t, false)) {
                    const Eigen::Vector3d uu = numbers3(u, b, what);
                    const double n = uu.norm();
                    // w = s u = (s |u|) (u/|u|), alpha = |u| int_0^t s
                    return attitude_motion::fixed_axis(uu, scalar_function(s * num::from_double(n), t),
                                                       scalar_function(*a, t));
                }
        }
        if (const auto p = mechanics::regular_precession(w, t))
            if (is_vector_literal(p->u1) && is_vector_literal(p->v) && !p->c.has(t))
                return attitude_motion::precession(numbers3(p->u1, b, what), to_double(p->c, b, what),
                                                   numbers3(p->v, b, what));
        auto f = std::make_shared<num::compiled_function>(num::compile(w, {t}));
        return attitude_motion::numeric([f, what](double x) {
            const Eigen::Vector3d y = f->eval3(&x);
            if (!y.allFinite()) throw domain_error(what + " has no finite value at t = " + std::to_string(x));
            return y;
        });
    } catch (const type_error& e) {
        const std::string m = e.what();
        if (m.rfind(b.name + ": ", 0) == 0) throw;
        throw type_error(b.name + ": " + what + " must be a vector of numbers and " + output::print_ex(t) +
                         " only: " + m);
    }
}

value number(double x) { return value(ex(num::from_double(x))); }

value triple(const Eigen::Vector3d& x) { return value(list{number(x.x()), number(x.y()), number(x.z())}); }

value matrix_value(const Eigen::Matrix3d& R) {
    GiNaC::matrix m(3, 3);
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned j = 0; j < 3; ++j) m(i, j) = num::from_double(R(i, j));
    return value(ex(m));
}

// The exact side of (*) (mechanics::closed_attitude_tensor): each closed rotation tensor derived
// and checked, and the attitude A = Q_L A0 Q_D^T of the closed forms at the times against the
// numbers returned (evaluated apart: Eigen's Rodrigues, VI.2.12, A B). 1e-12: both are at
// rounding (1e-15) over the hundreds of turns of an example; a wrong sign of a rate is O(1).
std::string exact_attitudes(const args_t& a, const ex& t, const mechanics::relative_pose_problem& P,
                            const std::vector<double>& times, const std::vector<mechanics::pose_state>& poses,
                            const builtin& b) {
    using K = mechanics::attitude_motion::kind;
    std::ostringstream os;
    std::optional<mechanics::closed_attitude> Q[2];
    const mechanics::attitude_motion* m[2] = {&P.leader, &P.deputy};
    const char* who[2] = {"Q_L", "Q_D"};
    for (int k = 0; k < 2; ++k) {
        const K how = m[k]->how;
        os << "relative_pose: " << who[k] << " (" << m[k]->name() << "): ";
        if (how == K::orbital) {
            os << "through the body's Kepler orbit (its LVLH axes), numeric\n";
            continue;
        }
        if (how == K::numeric || !(Q[k] = mechanics::closed_attitude_tensor(vector_value(a[6 + k], b, "w"), t))) {
            os << "no closed form (Magnus on SO(3)), numeric\n";
            continue;
        }
        if (!Q[k]->proved) throw internal_error(b.name + ": the closed form of " + who[k] + " is not proved to solve "
                                                "Q' + W Q = 0, Q(0) = I; nothing returned");
        os << "closed form, each column proved to solve y' + w x y = 0, y(0) = e_i"
           << (Q[k]->rounding > 0 ? " (up to rounding: floats in w)" : " (exactly)") << "\n";
    }
    if (!Q[0] && !Q[1]) return os.str();
    // the closed forms at each time (I for a body without one is not used: compared only when both are closed)
    if (Q[0] && Q[1]) {
        double worst = 0;
        for (std::size_t n = 0; n < times.size(); ++n) {
            Eigen::Matrix3d QL, QD;
            for (unsigned i = 0; i < 3; ++i)
                for (unsigned j = 0; j < 3; ++j) {
                    const ex T = num::from_double(times[n]);
                    QL(i, j) = to_double(Q[0]->Q.op(3 * i + j).subs(t == T), b, "Q_L");
                    QD(i, j) = to_double(Q[1]->Q.op(3 * i + j).subs(t == T), b, "Q_D");
                }
            worst = std::max(worst, (QL * P.start.attitude * QD.transpose() - poses[n].attitude).cwiseAbs().maxCoeff());
        }
        if (!(worst <= 1e-12))
            throw internal_error(b.name + ": the attitude differs from Q_L A0 Q_D^T of the proved closed forms by " +
                                 std::to_string(worst) + "; nothing returned");
        os << "relative_pose: the attitude A is Q_L A0 Q_D^T of the proved closed forms (to 1e-12 at the times)\n";
    }
    return os.str();
}

value builtin_relative_pose(const builtin& b, const args_t& a, context& c) {
    mechanics::relative_pose_problem P;
    P.mu = to_double(arg_ex(a, 0, b), b, "mu");
    if (!(P.mu > 0)) throw type_error(b.name + ": mu must be positive");
    P.R0 = number_vector(a[1], b, "R0");
    P.V0 = number_vector(a[2], b, "V0");
    P.start.position = number_vector(a[3], b, "rho0");
    P.start.velocity = number_vector(a[4], b, "rho0'");
    P.start.attitude = rotation_value(a[5], b, "the initial relative attitude A0");
    // the time: t = T or t = [T1, T2, ...]
    const ex& tr = arg_ex(a, 8, b);
    if (!GiNaC::is_a<GiNaC::relational>(tr) || !GiNaC::is_a<GiNaC::symbol>(tr.lhs()))
        throw type_error(b.name + ": argument 9 must be t = T (usage: " + b.signature + ")");
    const ex t = tr.lhs(), T = tr.rhs();
    const bool several = GiNaC::is_a<GiNaC::lst>(T) || GiNaC::is_a<GiNaC::matrix>(T);
    std::vector<double> times;
    for (std::size_t k = 0; k < (several ? T.nops() : 1); ++k) {
        const double x = to_double(several ? T.op(k) : T, b, "the time");
        if (!(x >= 0) || !std::isfinite(x)) throw type_error(b.name + ": the times must be finite and >= 0");
        times.push_back(x);
    }
    P.leader = attitude_value(a[6], t, b, "leader");
    P.deputy = attitude_value(a[7], t, b, "deputy");
    if (const value* o = c.named_option("leader_attitude"))
        P.leader_offset = rotation_value(*o, b, "leader_attitude");
    const std::vector<mechanics::pose_state> poses = mechanics::relative_pose(P, times);
    std::ostringstream os;
    os << "relative_pose: leader attitude " << P.leader.name() << ", deputy attitude " << P.deputy.name() << "\n";
    os << exact_attitudes(a, t, P, times, poses, b);
    c.report_fields(b.name, os.str(),
                    std::string("\"leader\": \"") + P.leader.name() + "\", \"deputy\": \"" + P.deputy.name() + "\"");
    list out;
    for (const auto& p : poses)
        out.push_back(value(list{triple(p.position), triple(p.velocity), matrix_value(p.attitude), triple(p.rate)}));
    return several ? value(out) : out[0];
}

value builtin_pose_dual_quaternion(const builtin& b, const args_t& a, context&) {
    const Eigen::Matrix3d R = rotation_value(a[0], b, "R");
    if ((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-9 || R.determinant() < 0)
        throw domain_error(b.name + ": R is not a rotation matrix (R^T R = I and det R = 1 to 1e-9)");
    const num::dual_quaternion q = num::to_dual_quaternion({R, number_vector(a[1], b, "d")});
    const auto quaternion = [](const Eigen::Quaterniond& x) {
        return value(list{number(x.w()), number(x.x()), number(x.y()), number(x.z())});
    };
    return value(list{quaternion(q.r), quaternion(q.e)});
}

}  // namespace

void register_relative_pose_builtins(registry& r) {
    add_builtins(
        r, section,
        {
            {"relative_pose", "relative_pose(mu, R0, V0, rho0, rho0', A0, wL, wD, t = T [, leader_attitude = B])",
             "Exact full-body relative orbital motion: the pose of a deputy rigid body in the body frame of a leader, "
             "both on Keplerian orbits (gravitational parameter mu; the leader's inertial state R0, V0 at t = 0). "
             "The leader's body axes at t = 0 are its LVLH axes (x radial, y along the track, z normal), turned by "
             "the rotation B when leader_attitude = B is given. rho0, rho0' the deputy's position and its rate in the "
             "leader's body components, A0 the deputy's axes in the leader's body components (a 3x3 rotation matrix "
             "or a unit quaternion [w, x, y, z]). wL, wD each body's angular velocity in its own body components, an "
             "expression in t: read as constant, fixed axis s(t) u, regular precession c u1 + R_u1(-c t) v (closed "
             "forms) or else integrated by Magnus on SO(3); or \"orbital\" (the body keeps its attitude in its own LVLH "
             "frame). The pose is Q_L (I + eps skew(psi)) A0 Q_D^T with psi the difference of the two inertial Kepler "
             "orbits (universal variables, 50 digits): no linearization, no Euler angles, no secular terms; with "
             "wL = \"orbital\" rho is relative_motion's. Returns [rho, rho', A, w_rel] at T (A the deputy's axes, "
             "w_rel = A w_D - w_L, A' = W_rel A; a list of them for a list of times) and reports which class each "
             "attitude motion was read as. A closed rotation tensor is derived symbolically and each of its columns "
             "checked as the solution of y' + w x y = 0, y(0) = e_i (exactly, or up to rounding with floats); with "
             "both closed, the attitude returned is compared with Q_L A0 Q_D^T of the proved forms (1e-12).",
             "[C23]; Thm VI.3.2.1 (VI.2.12, VI.3.117)",
             "relative_pose(398600.4418, [7000, 0, 0], [0, 7.546, 0], [0.1, 0, 0], [0, 0, 0], [1, 0, 0, 0], "
             "[0, 0, 0.001], [0.01*cos(0.03*t), 0.01*sin(0.03*t), 0.05], t = 600)",
             9, 9, builtin_relative_pose, {"leader_attitude"}},
            {"pose_dual_quaternion", "pose_dual_quaternion(R, d)",
             "The unit dual quaternion q + eps (1/2) (0, d) q of the rigid motion (I + eps skew(d)) R (rotate by R, "
             "then translate by d), q the unit quaternion of R with w >= 0: returns [[w, x, y, z], [w', x', y', z']]. "
             "For the pose A, rho that relative_pose returns.",
             "[C23]", "pose_dual_quaternion([[0, -1, 0], [1, 0, 0], [0, 0, 1]], [1, 2, 3])", 2, 2,
             builtin_pose_dual_quaternion},
        });
}

}  // namespace symrep::lang

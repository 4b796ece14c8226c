// symrep/mechanics/orbit_decisions.cpp -- bounded and planar orbits (orbit_decisions.h).
#include "symrep/mechanics/orbit_decisions.h"

#include <cmath>

#include "symrep/core/error.h"
#include "symrep/mechanics/first_integrals.h"
#include "symrep/mechanics/turning_frame.h"
#include "symrep/scalar/equality.h"
#include "symrep/scalar/scalar.h"
#include "symrep/vector/vector.h"

namespace symrep::mechanics {

using GiNaC::ex;

namespace {

// zero: proved 0; nonzero: a number (no symbol left) seen nonzero at 40 and 80 digits; else neither
truth zero_truth(const ex& x) {
    if (equal(x, 0)) return truth::yes;
    if (is_vector(x) && vector_symbols(x).empty()) {  // a component that is a nonzero number
        const ex c = subs_components(x, {});
        for (unsigned i = 0; i < 3; ++i) {
            const int s = decided_sign(c.op(i));
            if (s == 1 || s == -1) return truth::no;
        }
    }
    if (has_symbol(x)) return truth::unknown;
    const ex d = is_vector(x) ? dot(x, x) : x;
    return decided_sign(d) == 2 ? truth::unknown : truth::no;
}

std::string cannot_decide(const std::string& who, const std::string& what, const ex& x) {
    return who + ": cannot decide " + what + " = " + to_string(x) +
           " (neither proved 0 nor a number whose sign is established): give values for its symbols";
}

}  // namespace

int decided_sign(const ex& x0) {
    const ex x = GiNaC::normal(x0);
    if (equal(x, 0)) return 0;
    if (!has_symbol(x)) {
        GiNaC::numeric a, b;
        if (!evaluate_numeric(x, 40, a) || !evaluate_numeric(x, 80, b)) return 2;
        if (!a.is_real() || !b.is_real()) return 2;
        const double da = a.to_double(), db = b.to_double();
        if (std::abs(da) < 1e-25 || std::abs(da - db) > 1e-15 * std::abs(da)) return 2;
        return da > 0 ? 1 : -1;
    }
    if (x.info(GiNaC::info_flags::positive)) return 1;
    if (x.info(GiNaC::info_flags::negative)) return -1;
    return 2;
}

orbit_decision bounded(const cauchy_problem& P, const parameter_values& values) {
    const std::string who = "bounded";
    const central_motion C = read_central_motion(P, who);
    // Kepler's field: U = -k/|r| (Consequence VI.3.3.2)
    const ex k = C.potential ? GiNaC::normal(-*C.potential * norm(C.r)) : ex(0);
    if (!C.potential || k.has(C.r) || depends_on_time(k, C.t) || k.is_zero())
        throw domain_error(who + ": Consequence VI.3.3.2 is about Kepler's field k r/|r|^3; the problem's field is " +
                           to_string(C.central));
    const ex kv = put_values(k, values);
    if (decided_sign(kv) != 1)
        throw domain_error(cannot_decide(who, "whether the field is attractive: k", kv) +
                           " (Consequence VI.3.3.2 needs k > 0)");
    const ex w0 = frame_rate_at_zero(C);
    const ex p0 = C.v0 + cross(w0, C.r0);
    const ex E = put_values(dot(p0, p0) / 2 - k / norm(C.r0), values);  // (VI.3.154)
    const int s = decided_sign(E);
    if (s == 2) throw domain_error(cannot_decide(who, "the sign of the energy (VI.3.154) E", E));
    if (s < 0) return {true, E, "E < 0 (VI.3.154): |r| = |psi| <= k/|E|, an ellipse turned by Q"};
    const truth radial = zero_truth(put_values(cross(C.r0, p0), values));
    if (radial == truth::no)
        return {false, E, std::string(s == 0 ? "E = 0: a parabola" : "E > 0: a hyperbola") + " (VI.3.154), |r| = |psi| grows without bound"};
    if (radial == truth::unknown)
        throw domain_error(cannot_decide(who, "whether the motion is radial: r0 x (v0 + w(0) x r0)",
                                         put_values(cross(C.r0, p0), values)));
    const int out = decided_sign(put_values(dot(C.r0, p0), values));
    if (out == 2)
        throw domain_error(cannot_decide(who, "the radial velocity r0 . (v0 + w(0) x r0)", put_values(dot(C.r0, p0), values)));
    if (out < 0)
        throw domain_error(who + ": the motion is radial (r0 x (v0 + w(0) x r0) = 0) and falls into the centre at a "
                                 "finite time: the solution ends there, bounded or not is not the question");
    return {false, E, "E >= 0 and a radial motion outwards: |r| grows without bound"};
}

orbit_decision planar(const cauchy_problem& P, const parameter_values& values) {
    const std::string who = "planar";
    const central_motion C = read_central_motion(P, who);
    if (!C.u)
        throw domain_error(who + ": the criterion (VI.3.282-284) is for w of fixed direction; w(t) = " + to_string(C.w) +
                           " turns");
    const ex w0 = frame_rate_at_zero(C);
    const ex u = put_values(*C.u, values);
    const ex r0 = put_values(C.r0, values), v0 = put_values(C.v0, values);
    const ex L0 = put_values(cross(C.r0, C.v0 + cross(w0, C.r0)), values);  // L_c0/m (VI.3.279)
    // (VI.3.284) r0 . u = 0 and v0 . u = 0: r0 and p0 = v0 + w(0) x r0 normal to u, so psi stays in the
    // plane normal to u and Q turns about u: planar in every case (L_c0 = 0 too)
    if (zero_truth(dot(r0, u)) == truth::yes && zero_truth(dot(v0, u)) == truth::yes)
        return {true, cross(u, L0), "r0 . u = 0 and v0 . u = 0 (VI.3.284): the plane through the centre normal to u"};
    const truth radial = zero_truth(L0);
    if (radial == truth::unknown)
        throw domain_error(cannot_decide(who, "whether L_c0/m = r0 x (v0 + w(0) x r0) is 0", L0));
    if (radial == truth::yes) {
        if (zero_truth(cross(r0, u)) == truth::yes)
            return {true, cross(u, L0), "L_c0 = 0 and r0 along u: the motion stays on the axis"};
        throw domain_error(who + ": L_c0 = 0 (a radial motion) with r0 not along u and not both r0 . u = 0 and "
                                 "v0 . u = 0 proved: the line turns about u; (VI.3.282) does not decide it");
    }
    const ex X = cross(u, L0);
    const truth z = zero_truth(X);
    if (z == truth::unknown) throw domain_error(cannot_decide(who, "u x L_c0 (VI.3.282)", X));
    if (z == truth::yes)
        return {true, X, "u x L_c0 = 0 (VI.3.282), L_c0 != 0: the plane through the centre normal to u"};
    return {false, X, "u x L_c0 != 0 (VI.3.282): the plane normal to L_c = F_(-w)(L_c0) turns about u"};
}

}  // namespace symrep::mechanics

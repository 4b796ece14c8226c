// symrep/scalar/limit.h -- the limit of a closed form at a point where putting the
// values in divides by zero (a removable singularity).
//
// The solutions the engine derives are continuous in their parameters, but their
// closed forms divide by quantities that vanish at special values: |w| = 0 in
// sin(|w| t)/|w|, the double root c^2 = 4 k in sin(sqrt(4 k - c^2) t/2)/sqrt(4 k - c^2),
// a resonance w0 = nu in 1/(w0^2 - nu^2). There the value is the limit of the
// expression as every parameter approaches its value.
//
// Method: along a line p = p0 + lambda d through the point the expression is a
// function of lambda alone, and GiNaC's series in lambda at 0 gives its limit
// (the lambda^0 coefficient, with the negative powers proved 0). lambda is mu
// (mu > 0) with both signs of d, so that each side of the point is approached;
// where a root of a quantity that vanishes linearly makes that a Puiseux series
// (sqrt(4 k - c^2) on a line through c = 2, k = 1), lambda = mu^2, so that the
// root is a power series in mu. The limit is taken along a generic direction d
// from both sides and along a second direction from one side (three half-lines),
// and accepted only where the three values are proved equal (the exact zero
// test, scalar/equality.h); a limit that differs between them (|k|/k at 0,
// x y/(x^2 + y^2) at 0), a pole, an expansion GiNaC cannot do (an essential
// singularity, a root that is not a power series in mu) or an equality that
// cannot be decided is refused with the reason.
//
// With one parameter moving that is a proof. With several, lines are not
// (x^2 y/(x^4 + y^2) is 0 on every line through 0, 1/2 on y = x^2): the value of
// the lines must then be proved through the one quantity Q that vanishes (the
// singular bases, up to constant factors, or Q's one irreducible factor that
// vanishes): with Q = q, the offsets symbolic and, where needed, one parameter
// eliminated by Q(v) = q (implicit function theorem), the expression must be
// regular away from q and have no negative power of mu (q = +-mu^2) identically
// in the offsets; else refused ("not a proof"). docs/numeric.md, "Removable
// singularities".
#pragma once

#include <functional>
#include <vector>

#include <ginac/ginac.h>

namespace symrep {

/// The expression at the point moved by the given offsets, one per parameter (a
/// scalar, or a matrix whose entries are taken one by one). It throws (GiNaC's
/// pole_error, domain_error "division by zero") where that divides by zero.
using near_point = std::function<GiNaC::ex(const std::vector<GiNaC::ex>& offsets)>;

/// True for the errors that putting values into an expression raises where it
/// divides by zero (GiNaC's pole_error, domain_error "division by zero").
bool is_division_by_zero(const std::exception& x);

/// The limit at the point (offsets 0) of the expression near(offsets), n
/// parameters, taken as described above. Throws domain_error naming why where it
/// is not established (the message begins "the limit cannot be found" or "there is no limit").
GiNaC::ex limit_at_point(std::size_t n, const near_point& near);

}  // namespace symrep

// symrep/scalar/floats.cpp -- the one model of floats (floats.h).
#include "symrep/scalar/floats.h"

#include <cln/complex.h>
#include <cln/float.h>
#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>
#include <cmath>
#include <sstream>
#include <string>

namespace symrep {

namespace {

/// |q| = m 10^k with m an integer of exactly `digits` digits (rounded half to even), q != 0.
void decimal_digits(const cln::cl_RA& a, long digits, cln::cl_I& m, long& k) {
    k = long(std::floor(double(cln::integer_length(cln::floor1(a))) * 0.30103)) - digits;
    if (cln::zerop(cln::floor1(a)))  // below 1: from the denominator's size
        k = -long(std::ceil(double(cln::integer_length(cln::floor1(cln::recip(a)))) * 0.30103)) - digits;
    auto scaled = [&](long kk) -> cln::cl_RA {
        // (expt_pos needs a positive exponent: at 0 it does not return)
        if (kk == 0) return a;
        return kk > 0 ? a / cln::expt_pos(cln::cl_I(10), kk) : a * cln::expt_pos(cln::cl_I(10), -kk);
    };
    m = cln::round1(scaled(k));
    const cln::cl_I limit = cln::expt_pos(cln::cl_I(10), digits);
    while (m >= limit) m = cln::round1(scaled(++k));
    while (m > 0 && m * 10 < limit) m = cln::round1(scaled(--k));
}

/// Mantissa bits of the float format CLN uses for `digits` decimal digits.
auto bits_for_digits(long digits) {
    return cln::float_digits(cln::cl_float(cln::cl_I(1), cln::float_format(digits)));
}

/// A real float at the working precision (the format of the current Digits).
bool at_working_precision(const cln::cl_R& r) {
    if (GiNaC::numeric(cln::cl_N(r)).is_rational()) return false;
    return cln::float_digits(cln::the<cln::cl_F>(r)) == bits_for_digits(GiNaC::Digits);
}

/// The decimal m 10^k (sign in m) a working-precision float r != 0 prints as: D digits, trailing zeros dropped.
void working_decimal(const cln::cl_R& r, cln::cl_I& m, long& k) {
    const cln::cl_RA q = cln::rational(r);
    decimal_digits(cln::abs(q), GiNaC::Digits, m, k);
    while (!cln::zerop(m) && cln::zerop(cln::mod(m, cln::cl_I(10)))) {
        m = cln::exquo(m, cln::cl_I(10));
        ++k;
    }
    if (cln::minusp(q)) m = -m;
}

cln::cl_RA decimal_value(const cln::cl_I& m, long k) {
    if (k == 0) return m;  // (expt_pos needs a positive exponent: at 0 it does not return)
    return k > 0 ? cln::cl_RA(m * cln::expt_pos(cln::cl_I(10), k)) : m / cln::expt_pos(cln::cl_I(10), -k);
}

/// The exact value of the shortest decimal that reads back to the float r at its precision
/// (CLN prints it: -1.25E-7, 3.0, 1.0E300).
cln::cl_RA shortest_decimal(const cln::cl_R& r) {
    if (GiNaC::numeric(cln::cl_N(r)).is_rational()) return cln::the<cln::cl_RA>(r);
    std::ostringstream os;
    os << GiNaC::numeric(cln::cl_N(r));
    const std::string text = os.str();
    cln::cl_I mantissa = 0;
    long exponent = 0;
    std::size_t i = 0;
    bool negative = false, point = false;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) negative = text[i++] == '-';
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (c >= '0' && c <= '9') {
            mantissa = mantissa * 10 + (c - '0');
            if (point) --exponent;
        } else if (c == '.') {
            point = true;
        } else if (c == 'e' || c == 'E') {
            exponent += std::stol(text.substr(i + 1));
            break;
        } else {
            return cln::rational(r);  // not a plain decimal: its exact value
        }
    }
    const cln::cl_RA m = negative ? cln::cl_RA(-mantissa) : cln::cl_RA(mantissa);
    return cln::the<cln::cl_RA>(m * decimal_value(1, exponent));
}

}  // namespace

GiNaC::numeric round_float_digits(const GiNaC::numeric& x, long digits) {
    const cln::cl_R r = cln::the<cln::cl_R>(x.to_cl_N());
    if (cln::zerop(r) || x.is_rational()) return x;
    const cln::cl_RA q = cln::rational(r);
    cln::cl_I m;
    long k = 0;
    decimal_digits(cln::abs(q), digits, m, k);
    // the decimal m 10^k exactly, rounded once to the binary format of `read` digits; more
    // digits than D in D's own format (evalf(pi, 18) at D = 17) would print as D: then the
    // next format up, where the model prints every digit
    cln::cl_RA v = decimal_value(m, k);
    if (cln::minusp(q)) v = -v;
    long read = digits;
    while (read > GiNaC::Digits && bits_for_digits(read) == bits_for_digits(GiNaC::Digits)) ++read;
    return GiNaC::numeric(cln::cl_N(cln::cl_float(v, cln::float_format(read))));
}

std::string float_text(const GiNaC::numeric& x) {
    const cln::cl_R r = cln::the<cln::cl_R>(x.to_cl_N());
    if (x.is_rational() || cln::zerop(r) || !at_working_precision(r)) {
        std::ostringstream os;
        os << x;  // CLN: the shortest decimal that reads back at the float's own precision
        return os.str();
    }
    cln::cl_I m;
    long k = 0;
    working_decimal(r, m, k);
    std::ostringstream ds;
    ds << GiNaC::numeric(cln::abs(m));
    const std::string d = ds.str();
    const long n = long(d.size()), E = k + n - 1;  // |x| = d[0].d[1..] 10^E
    std::string out = cln::minusp(m) ? "-" : "";
    if (E >= -3 && E < 7) {  // CLN's fixed range: 0.001 .. 1000000.0
        if (k >= 0) return out + d + std::string(std::size_t(k), '0') + ".0";
        if (E >= 0) return out + d.substr(0, std::size_t(E + 1)) + "." + d.substr(std::size_t(E + 1));
        return out + "0." + std::string(std::size_t(-E - 1), '0') + d;
    }
    return out + d.substr(0, 1) + "." + (n > 1 ? d.substr(1) : "0") + "E" + std::to_string(E);
}

GiNaC::numeric float_decimal(const GiNaC::numeric& x) {
    if (x.is_crational()) return x;
    auto part = [](const cln::cl_R& r) -> cln::cl_RA {
        if (GiNaC::numeric(cln::cl_N(r)).is_rational()) return cln::the<cln::cl_RA>(r);
        if (cln::zerop(r) || !at_working_precision(r)) return shortest_decimal(r);
        cln::cl_I m;
        long k = 0;
        working_decimal(r, m, k);
        return decimal_value(m, k);
    };
    const cln::cl_N z = x.to_cl_N();
    return GiNaC::numeric(cln::complex(part(cln::realpart(z)), part(cln::imagpart(z))));
}

GiNaC::ex floats_as_decimals(const GiNaC::ex& e) {
    struct decimals : GiNaC::map_function {
        GiNaC::ex operator()(const GiNaC::ex& x) override {
            if (GiNaC::is_a<GiNaC::numeric>(x)) return float_decimal(GiNaC::ex_to<GiNaC::numeric>(x));
            return x.map(*this);
        }
    } f;
    return has_float(e) ? f(e) : e;
}

bool has_float(const GiNaC::ex& e) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::numeric>(*it) && !GiNaC::ex_to<GiNaC::numeric>(*it).is_crational()) return true;
    return false;
}

}  // namespace symrep

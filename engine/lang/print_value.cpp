// symrep/lang/print_value.cpp -- values as text and LaTeX (see print_value.h).
#include "symrep/lang/print_value.h"

#include "symrep/output/formats.h"
#include "symrep/output/printer.h"

namespace symrep::lang {

using output::latex_element;
using output::latex_ex;
using output::print_element;
using output::print_ex;
using output::quote_string;

std::string print_value(const value& v, bool quote_strings) {
    if (v.is_none()) return "";
    if (v.is_bool()) return v.as_bool() ? "true" : "false";
    if (v.is_ex()) return print_ex(v.as_ex());
    if (v.is_string()) return quote_strings ? quote_string(v.as_string()) : v.as_string();
    if (v.is_list()) {
        std::string s = "[";
        const list& l = v.as_list();
        for (std::size_t i = 0; i < l.size(); ++i) s += (i ? ", " : "") + print_value(l[i], true);
        return s + "]";
    }
    if (v.is_algebra()) return v.as_algebra()->name();
    if (v.is_problem()) {
        const mechanics::cauchy_problem& P = v.as_problem();
        std::string s = "ode(" + print_ex(P.expression) + " = 0";
        for (std::size_t m = 0; m < P.initial.size(); ++m)
            s += ", " + P.unknown_name(m) + "(0) = " + print_ex(P.initial[m]);
        return s + ")";
    }
    if (v.is_reduction()) {
        const reduction& r = v.as_reduction();
        return (r.derivative ? "the derivative in t of: " : "") + r.solution->to_string();
    }
    return print_element(v.as_element());
}


std::string latex_value(const value& v) {
    if (v.is_none()) return "";
    if (v.is_bool()) return v.as_bool() ? "\\mathrm{true}" : "\\mathrm{false}";
    if (v.is_ex()) return latex_ex(v.as_ex());
    if (v.is_string()) {
        std::string s;
        for (char c : v.as_string()) {
            if (c == '\\') s += "\\textbackslash{}";
            else if (std::string("{}_&%$#").find(c) != std::string::npos) s += std::string("\\") + c;
            else s += c;
        }
        return "\\text{" + s + "}";
    }
    if (v.is_list()) {
        std::string s = "\\left[";
        const list& l = v.as_list();
        for (std::size_t i = 0; i < l.size(); ++i) s += (i ? ", " : "") + latex_value(l[i]);
        return s + "\\right]";
    }
    if (v.is_element()) return latex_element(v.as_element());
    return "\\texttt{" + print_value(v, false) + "}";
}

}  // namespace symrep::lang

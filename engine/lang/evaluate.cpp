// symrep/lang/evaluate.cpp -- evaluation of syntax nodes: names, calls of builtins, operators, indexing.
#include "symrep/lang/interpreter.h"
#include "symrep/core/interrupt.h"
#include "symrep/lang/statement_clock.h"

#include <algorithm>
#include <functional>
#include <optional>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "symrep/dual/dual.h"
#include "symrep/scalar/scalar.h"
#include "symrep/syntax/parser.h"
#include "symrep/output/printer.h"
#include "symrep/vector/vector.h"
#include "symrep/lang/print_value.h"
#include "symrep/output/formats.h"

namespace symrep::lang {

using output::json_quote;
using output::print_ex;

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

value session::eval(const node& n) {
    if (interrupt_requested().load(std::memory_order_relaxed))
        throw script_error("interrupted", {current_file(), n.line, n.column});
    if (opts_.time_limit > 0 && (++ticks_ & 63) == 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - statement_start_).count() > opts_.time_limit) {
        std::ostringstream os;
        os << "time limit: the statement ran longer than " << opts_.time_limit << " s (--time-limit)";
        throw script_error(os.str(), {current_file(), n.line, n.column});
    }
    try {
        return eval_inner(n);
    } catch (const script_error&) {
        throw;
    } catch (const allocation_interrupted& e) {  // Ctrl-C or the time limit, inside a library call
        throw script_error(e.what(), {current_file(), n.line, n.column},
                           std::make_exception_ptr(symrep::error(e.what())));
    } catch (const std::bad_alloc&) {
        throw script_error(out_of_memory_message, {current_file(), n.line, n.column},
                           std::make_exception_ptr(size_error(out_of_memory_message)));
    } catch (const symrep::error& e) {
        throw script_error(e.what(), {current_file(), n.line, n.column}, std::current_exception());
    } catch (const std::exception& e) {
        throw script_error(clear_message(e.what()), {current_file(), n.line, n.column}, std::current_exception());
    } catch (...) {
        throw script_error("unknown internal error", {current_file(), n.line, n.column}, std::current_exception());
    }
}

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> d(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) d[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t prev = d[0];
        d[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cur = d[j];
            d[j] = std::min({d[j] + 1, d[j - 1] + 1, prev + (a[i - 1] == b[j - 1] ? 0 : 1)});
            prev = cur;
        }
    }
    return d[b.size()];
}

/// Float literals: 1e999999999 would make CLN work for hours.
void check_float_exponent(const std::string& text) {
    const std::size_t e = text.find_first_of("eE");
    if (e == std::string::npos) return;
    std::size_t i = e + 1;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    while (i < text.size() && text[i] == '0') ++i;
    const std::string digits = text.substr(i);
    if (digits.size() > 6 || (!digits.empty() && std::stol(digits) > 100000))
        throw size_error("the exponent of the number " + text + " is too large (the limit is 10^5 in absolute value)");
}

long index_value(const value& v, std::size_t size) {
    if (!v.is_ex() || !is_a<numeric>(v.as_ex()) || !ex_to<numeric>(v.as_ex()).is_integer())
        throw type_error("an index must be an integer, not " + (v.is_ex() ? print_ex(v.as_ex()) : v.a_kind()));
    const numeric k = ex_to<numeric>(v.as_ex());
    if (k.is_negative() || k >= numeric(static_cast<long>(size)))
        throw type_error("index " + print_ex(k) + " out of range: valid indices are 0.." +
                         (size == 0 ? std::string("(none, it is empty)") : std::to_string(size - 1)));
    return k.to_long();
}

/// The unary operators |a| (norm, absolute value), +a and -a.
value unary_op(const std::string& op, const value& a) {
    if (op == "|") {  // |a|: the norm sqrt(a . a) of a vector, the absolute value of a scalar
        if (is_triple(a)) return value(norm(as_literal(a)));  // |[3, 4, 12]|
        if (a.is_ex() && is_vector(a.as_ex())) return value(norm(a.as_ex()));
        if (a.is_ex() && !is_a<GiNaC::relational>(a.as_ex()) && !is_a<GiNaC::matrix>(a.as_ex()))
            return value(GiNaC::abs(a.as_ex()));
        throw type_error("|...| needs a vector or a scalar expression, not " + a.a_kind());
    }
    if (op == "+") {
        if (a.is_ex() || a.is_element() || a.is_list()) return a;
        throw type_error("unary '+' needs a number, expression, element or list, not " + a.a_kind());
    }
    return negate(a);
}

}  // namespace

std::vector<std::string> similar_builtin_names(const registry& r, const std::string& name, std::size_t limit) {
    std::vector<std::pair<std::size_t, std::string>> near;
    for (const builtin* c : r.all()) {
        const std::size_t d = edit_distance(name, c->name);
        const bool prefix = name.size() >= 3 && c->name.rfind(name, 0) == 0;
        if (d <= std::max<std::size_t>(1, name.size() / 3) || prefix) near.emplace_back(prefix ? 0 : d, c->name);
    }
    std::sort(near.begin(), near.end());
    std::vector<std::string> out;
    for (std::size_t i = 0; i < near.size() && i < limit; ++i) out.push_back(near[i].second);
    return out;
}

value session::call(const node& n) {
    const builtin* b = reg_.find(n.text);
    if (!b) {
        const std::vector<std::string> near = similar_builtin_names(reg_, n.text);
        std::string msg = "unknown function '" + n.text + "'";
        if (!near.empty()) {
            msg += "; did you mean ";
            for (std::size_t i = 0; i < near.size(); ++i) msg += (i ? ", " : "") + near[i];
            msg += "?";
        } else {
            msg += " (help() lists all functions)";
        }
        throw type_error(msg);
    }
    if (b->name == "ode") return ode_form(n);
    // seq(e, k, ...) and sum(e, k, ...) evaluate e once per value of k (so that
    // seq(diff(f, x, k), k, 0, 3) sees k as a number, not as a symbol).
    if ((b->name == "seq" || b->name == "sum") && (n.kids.size() == 3 || n.kids.size() == 4) &&
        n.kids[1]->kind == node::ident)
        return iterate(*b, n);
    std::vector<value> args;
    std::vector<std::pair<std::string, value>> named;  // name = value for a name in b->options
    args.reserve(n.kids.size());
    for (const auto& k : n.kids) {
        if (k->kind == node::binary && k->text == "=" && k->kids.size() == 2 && k->kids[0]->kind == node::ident &&
            std::find(b->options.begin(), b->options.end(), k->kids[0]->text) != b->options.end()) {
            for (const auto& o : named)
                if (o.first == k->kids[0]->text)
                    throw type_error(b->name + ": the option " + o.first + " is given twice");
            named.emplace_back(k->kids[0]->text, eval(*k->kids[1]));
            continue;
        }
        args.push_back(eval(*k));
    }
    if (args.size() < b->min_args || args.size() > b->max_args) {
        std::string expected;
        if (b->min_args == b->max_args) expected = std::to_string(b->min_args);
        else if (b->max_args == SIZE_MAX) expected = "at least " + std::to_string(b->min_args);
        else expected = std::to_string(b->min_args) + " to " + std::to_string(b->max_args);
        throw type_error(b->name + ": expects " + expected + " argument" + (expected == "1" ? "" : "s") +
                         ", got " + std::to_string(args.size()) + " (usage: " + b->signature + ")");
    }
    struct options_scope {  // the options of this call only (a nested call has its own)
        context& c;
        std::vector<std::pair<std::string, value>> saved;
        options_scope(context& c, std::vector<std::pair<std::string, value>> o) : c(c), saved(std::move(c.named_options)) {
            c.named_options = std::move(o);
        }
        ~options_scope() { c.named_options = std::move(saved); }
    } scope(*this, std::move(named));
    return reduce_dual(b->fn(args, *this));  // sin(a + eps*b) = sin(a) + eps*b*cos(a) (dual/dual.h)
}

value session::iterate(const builtin& b, const node& n) {
    const std::string& k = n.kids[1]->text;
    list values;
    if (n.kids.size() == 3) {
        value l = eval(*n.kids[2]);
        if (!l.is_list())
            throw type_error(b.name + ": argument 3 must be a list of values for " + k + " (usage: " + b.signature + ")");
        values = l.as_list();
    } else {
        const std::vector<value> a{value(), value(), eval(*n.kids[2]), eval(*n.kids[3])};
        const long lo = arg_int(a, 2, b, -1000000000L, 1000000000L);
        const long hi = arg_int(a, 3, b, -1000000000L, 1000000000L);
        if (hi - lo > 10000000) throw size_error(b.name + ": more than 10^7 values asked for");
        for (long i = lo; i <= hi; ++i) values.push_back(ex(i));
    }
    // k is bound as a variable while e is evaluated, then restored.
    std::optional<value> saved;
    if (const value* old = get(k)) saved = *old;
    auto restore = [&] {
        if (saved) vars_[k] = *saved;
        else vars_.erase(k);
    };
    list out;
    try {
        for (const value& kv : values) {
            vars_[k] = kv;
            out.push_back(eval(*n.kids[0]));
        }
    } catch (...) {
        restore();
        throw;
    }
    restore();
    if (b.name == "seq") return out;
    if (out.empty()) return ex(0);
    value acc = out[0];
    for (std::size_t i = 1; i < out.size(); ++i) acc = binary_op("+", acc, out[i]);
    return acc;
}

value session::eval_inner(const node& n) {
    switch (n.kind) {
        case node::number: {
            const bool is_float = n.text.find_first_of(".eE") != std::string::npos;
            if (!is_float) return ex(numeric(n.text.c_str()));
            check_float_exponent(n.text);
            return ex(numeric(n.text.c_str()).evalf());
        }
        case node::string: return n.text;
        case node::boolean: return n.text == "true";
        case node::ident: {
            if (const auto f = failed_.find(n.text); f != failed_.end())
                throw type_error(n.text + " has no value: its assignment at " + f->second + " failed");
            if (const value* v = get(n.text)) return *v;
            if (n.text == "pi") return ex(GiNaC::Pi);
            if (n.text == "eps") return dual::dual_unit();  // the dual unit, eps^2 = 0 (dual/dual.h)
            if (n.text == "I") return ex(GiNaC::I);
            if (n.text == "Euler") return ex(GiNaC::Euler);
            if (n.text == "Catalan") return ex(GiNaC::Catalan);
            // w' of a name w that holds a value: its derivative in t (a given w(t)
            // inside ode(...), VI.2-VI.3); w'' the second, and so on
            if (const auto q = n.text.find('\''); q != std::string::npos && q > 0 &&
                                                  n.text.find_first_not_of('\'', q) == std::string::npos) {
                if (const value* base = get(n.text.substr(0, q)); base && (base->is_ex() || base->is_list())) {
                    ex d = base->is_list() ? vector_operand("'", *base, "derivative") : base->as_ex();
                    for (std::size_t k = q; k < n.text.size(); ++k) d = diff_t(d, symbol("t"));
                    return d;
                }
                // w' of a declared vector function w(t) (vector w(t)): its derivative symbol
                if (!get(n.text.substr(0, q))) {
                    ex d = symbol(n.text.substr(0, q));
                    if (is_vector_symbol(d) && !diff_t(d, symbol("t")).is_zero()) {
                        for (std::size_t k = q; k < n.text.size(); ++k) d = derivative(d);
                        return d;
                    }
                }
                // s' of a solution by reduction: r' = Q psi' - w x r (evaluated numerically)
                if (const value* base = get(n.text.substr(0, q)); base && base->is_reduction()) {
                    reduction r = base->as_reduction();
                    r.derivative += int(n.text.size() - q);
                    if (r.derivative > 1)
                        throw type_error(n.text + ": a solution by reduction has its first derivative only (" +
                                         n.text.substr(0, q) + "'), not higher ones");
                    return value(r);
                }
            }
            return ex(symbol(n.text));
        }
        case node::result: {
            const std::size_t count = results_.size();
            std::size_t k = 0;  // 1-based number of the result asked for
            if (n.text == "%" || n.text == "%%") {
                const std::size_t back = n.text == "%" ? 1 : 2;
                if (count < back)
                    throw type_error(n.text + " has no value yet: " + n.text +
                                     (back == 1 ? " is the last printed result" : " is the result before the last") +
                                     ", and " + (count == 0 ? "none has" : "only one has") + " been printed");
                k = count + 1 - back;
            } else {
                const std::string digits = n.text.substr(1);
                if (digits.size() > 18 || std::stoull(digits) == 0 || std::stoull(digits) > count)
                    throw type_error("no result " + n.text + ": " +
                                     (count == 0 ? std::string("none has been printed yet")
                                                 : "the results so far are %1.." + std::string("%") + std::to_string(count)));
                k = std::stoull(digits);
            }
            return results_[k - 1];
        }
        case node::unary: {
            const value a = eval(*n.kids[0]);
            return reduce_dual(unary_op(n.text, a));  // |a + eps*b| = |a| + eps*(a . b)/|a| (dual/dual.h)
        }
        case node::binary: {
            value a = eval(*n.kids[0]);
            value b = eval(*n.kids[1]);
            return binary_op(n.text, a, b);
        }
        case node::chain: {
            // A run of plain scalars (no matrix, relation, list or vector) is
            // collected and built as one GiNaC sum or product at once: adding
            // the terms one by one costs O(N^2) for N terms (each a + b copies
            // the sum so far). Anything else goes through binary_op, in order.
            const bool sum = n.text.find_first_of("+-") != std::string::npos;
            const auto plain = [](const value& v) {
                if (!v.is_ex()) return false;
                const ex& e = v.as_ex();
                return !is_a<GiNaC::relational>(e) && !is_a<GiNaC::lst>(e) && !has_matrix(e) &&
                       vector_symbols(e).empty() && !dual::has_dual_unit(e);  // dual: reduced by binary_op
            };
            value acc = eval(*n.kids[0]);
            std::optional<bool> acc_plain;  // plain(acc), computed once per value of acc
            GiNaC::exvector run;  // the collected operands (acc not yet updated with them)
            const auto flush = [&] {
                if (run.empty()) return;
                run.insert(run.begin(), acc.as_ex());
                acc = sum ? ex(GiNaC::dynallocate<GiNaC::add>(run)) : ex(GiNaC::dynallocate<GiNaC::mul>(run));
                run.clear();
            };
            for (std::size_t i = 0; i < n.text.size(); ++i) {
                value b = eval(*n.kids[i + 1]);
                const char op = n.text[i];
                if (!acc_plain) acc_plain = plain(acc);
                if (*acc_plain && plain(b) && !(op == '/' && b.as_ex().is_zero())) {
                    const ex& e = b.as_ex();
                    run.push_back(op == '+' || op == '*' ? e : op == '-' ? -e : GiNaC::pow(e, -1));
                    continue;
                }
                flush();
                acc_plain.reset();
                try {
                    acc = binary_op(std::string(1, n.text[i]), acc, b);
                } catch (const std::exception& e) {
                    throw script_error(message_of(e), {current_file(), n.op_pos[i].first, n.op_pos[i].second},
                                       std::current_exception());
                }
            }
            flush();
            return acc;
        }
        case node::call: return call(n);
        case node::index: {
            value a = eval(*n.kids[0]);
            value k = eval(*n.kids[1]);
            if (a.is_list()) return a.as_list()[index_value(k, a.as_list().size())];
            if (a.is_element()) return a.as_element()[index_value(k, a.as_element().dim())];
            if (a.is_ex() && is_a<GiNaC::matrix>(a.as_ex())) {
                const auto& m = ex_to<GiNaC::matrix>(a.as_ex());
                const long r = index_value(k, m.rows());
                list row;
                for (unsigned c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
                return row;
            }
            if (a.is_ex() && is_a<GiNaC::lst>(a.as_ex())) return a.as_ex().op(index_value(k, a.as_ex().nops()));
            throw type_error("cannot index " + a.a_kind() + " (indexing works on lists, elements and matrices)");
        }
        case node::list: {
            list l;
            l.reserve(n.kids.size());
            for (const auto& k : n.kids) {
                value v = eval(*k);
                if (v.is_none()) throw type_error("a list entry has no value");
                l.push_back(std::move(v));
            }
            return l;
        }
        case node::assign:
            throw type_error("an assignment ':=' is a statement, not an expression");
        case node::declare:
            throw type_error("a declaration is a statement, not an expression");
    }
    throw type_error("unknown syntax node");
}

}  // namespace symrep::lang

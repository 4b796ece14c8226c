// symrep/lang/interpreter.cpp -- the session: running scripts and statements, error reports, declarations and assignment.
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

#include "symrep/mechanics/cauchy_problem.h"
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

// ---------------------------------------------------------------------------
// session

session::session(std::ostream& out, std::ostream& err)
    : out_(&out), err_(&err), digits_at_start_(GiNaC::Digits), notation_at_start_(symrep::vector_notation()) {
    register_all_builtins(reg_);
}
session::session() : session(std::cout, std::cerr) {}
session::~session() {  // Digits := n and notation(...) are per session
    GiNaC::Digits = digits_at_start_;
    symrep::set_vector_notation(notation_at_start_);
}

GiNaC::ex session::symbol(const std::string& name) {
    auto it = symbols_.find(name);
    if (it != symbols_.end()) return it->second;
    // Script symbols are real: the algebras of symrep are real algebras, and
    // real_part/conjugate of expressions in them must simplify.
    GiNaC::ex s = GiNaC::realsymbol(name);
    symbols_.emplace(name, s);
    return s;
}

void session::forget_failed(const std::string& name, const std::string& where) {
    vars_.erase(name);
    failed_[name] = where;
}

void session::set(const std::string& name, value v) {
    failed_.erase(name);
    vars_[name] = std::move(v);
}

const value* session::get(const std::string& name) const {
    auto it = vars_.find(name);
    return it == vars_.end() ? nullptr : &it->second;
}

std::string session::resolve_path(const std::string& path) const {
    namespace fs = std::filesystem;
    fs::path p(path);
    if (p.is_absolute()) return path;
    const std::string& dir = dirs_.empty() ? base_dir_ : dirs_.back();
    if (dir.empty()) return path;
    return (fs::path(dir) / p).string();
}

std::string source_line(const std::string& text, int line) {
    std::size_t start = 0;
    for (int l = 1; l < line; ++l) {
        start = text.find('\n', start);
        if (start == std::string::npos) return {};
        ++start;
    }
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (end > start && text[end - 1] == '\r') --end;
    return text.substr(start, end - start);
}

namespace {

bool utf8_continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

/// Byte offset of (line, column) in text (both 1-based; columns count
/// characters, as the lexer does: UTF-8 continuation bytes do not), clamped to
/// the text.
std::size_t offset_of(const std::string& text, int line, int column) {
    std::size_t p = 0;
    for (int l = 1; l < line; ++l) {
        p = text.find('\n', p);
        if (p == std::string::npos) return text.size();
        ++p;
    }
    for (int c = 1; c < column && p < text.size() && text[p] != '\n'; ++c)
        for (++p; p < text.size() && utf8_continuation(text[p]);) ++p;
    return p;
}

/// s with its control bytes (other than tab and newline) written \xNN, so that
/// binary input does not reach the terminal raw in echoes and messages.
std::string escape_controls(const std::string& s) {
    std::string r;
    r.reserve(s.size());
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if ((u < 0x20 && c != '\t' && c != '\n') || u == 0x7F) {
            static const char* hex = "0123456789ABCDEF";
            r += "\\x";
            r += hex[u >> 4];
            r += hex[u & 15];
        } else {
            r += c;
        }
    }
    return r;
}

/// msg with each run of more than 60 digits shortened to its first and last 20
/// digits and the count ("12345...67890 (19800 digits)"): a message names a
/// number, it does not print it whole.
std::string shorten_numbers(const std::string& msg) {
    std::string r;
    std::size_t i = 0;
    while (i < msg.size()) {
        if (!std::isdigit(static_cast<unsigned char>(msg[i]))) { r += msg[i++]; continue; }
        std::size_t j = i;
        while (j < msg.size() && std::isdigit(static_cast<unsigned char>(msg[j]))) ++j;
        const std::size_t n = j - i;
        if (n > 60)
            r += msg.substr(i, 20) + "..." + msg.substr(j - 20, 20) + " (" + std::to_string(n) + " digits)";
        else
            r += msg.substr(i, n);
        i = j;
    }
    return r;
}

std::string trimmed(const std::string& s) {
    const std::size_t a = s.find_first_not_of(" \t\r\n;");
    if (a == std::string::npos) return {};
    const std::size_t b = s.find_last_not_of(" \t\r\n;");
    return s.substr(a, b - a + 1);
}

}  // namespace


std::string reported_message(const std::string& message) { return escape_controls(shorten_numbers(message)); }

std::string caret_text(const std::string& line, int column) {
    if (line.empty() || column < 1 || static_cast<std::size_t>(column) > line.size() + 1) return {};
    std::string pad;  // one blank per character before the column (tabs kept)
    for (std::size_t i = 0; i < offset_of(line, 1, column); ++i)
        if (!utf8_continuation(line[i])) pad += line[i] == '\t' ? '\t' : ' ';
    return "    " + escape_controls(line) + "\n    " + pad + "^\n";
}

void session::report(const source_location& where, const std::string& message) {
    ++failures_;
    const std::string msg = reported_message(message);
    if (opts_.stop_on_error) stopped_ = true;
    reported_error r{msg, where, {}, std::current_exception()};  // null outside a handler
    if (auto it = sources_.find(where.file); it != sources_.end()) {
        const int first = source_line_.count(where.file) ? source_line_[where.file] : 1;
        if (where.line >= first) r.source_line = source_line(it->second, where.line - first + 1);
    }
    errors_.push_back(r);
    if (on_error_) on_error_(errors_.back());
    if (opts_.format == output_options::json) {
        *err_ << "{\"error\": " << json_quote(msg) << ", \"file\": " << json_quote(where.file)
              << ", \"line\": " << where.line << ", \"column\": " << where.column << "}\n";
        err_->flush();
        return;
    }
    *err_ << where.file << ":" << where.line << ":" << where.column << ": error: " << msg << "\n";
    if (opts_.caret) *err_ << caret_text(r.source_line, where.column);
    err_->flush();
}

int session::run_file(const std::string& path) {
    if (stopped_) return 0;
    const std::string full = resolve_path(path);
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(full, ec)) {
        report({path, 1, 1}, "cannot run '" + full + "': it is a directory, not a script");
        return 1;
    }
    std::ifstream in(full, std::ios::binary);
    if (!in) {
        report({path, 1, 1}, "cannot open file '" + full + "'");
        return 1;
    }
    std::string dir = fs::path(full).parent_path().string();
    dirs_.push_back(dir);
    int failed = 0;
    try {
        // top-level files keep the name they were given; loaded files show
        // the resolved path, so that the report says where they are
        failed = run_stream(in, dirs_.size() > 1 ? full : path);
    } catch (...) {
        dirs_.pop_back();
        throw;
    }
    dirs_.pop_back();
    return failed;
}

int session::run_string(const std::string& text, const std::string& name) { return run_text(text, name, 1); }

int session::run_stream(std::istream& in, const std::string& name) {
    const int before = failures_;
    if (stopped_) return 0;
    std::streambuf* buf = in.rdbuf();
    const std::size_t limit = std::max<std::size_t>(opts_.max_statement, 1);
    line_tracker tracker;
    std::string pending, line;
    int line_no = 1, first = 1;  // the number of the next line to read; of pending's first line
    bool at_eof = false;
    // Reads one line into `line` (without '\n'), at most `cap` bytes; returns
    // false when the line was cut at the cap.
    const auto read_line = [&](std::size_t cap) {
        line.clear();
        for (;;) {
            const int c = buf->sbumpc();
            if (c == std::char_traits<char>::eof()) { at_eof = true; return true; }
            if (c == '\n') return true;
            if (line.size() >= cap) { buf->sungetc(); return false; }
            line += static_cast<char>(c);
        }
    };
    while (!at_eof && !stopped_) {
        const std::size_t room = limit > pending.size() ? limit - pending.size() : 0;
        if (!read_line(room)) {
            // too long: report, then skip to the end of the statement (the next
            // line end); give up on the input if no line end comes within another
            // max(limit, 64 MiB) bytes (binary input, /dev/zero)
            sources_.erase(name);  // no caret: the statement was not kept
            const std::size_t skip_budget = std::max<std::size_t>(limit, std::size_t(64) << 20);
            report({name, first, 1}, "statement longer than " + std::to_string(limit) +
                                         " bytes (the limit of one statement, --max-statement); skipped up to the next line end");
            pending.clear();
            tracker.reset();
            bool ended = false;
            while (!ended && !at_eof) {
                std::size_t skipped = 0;
                bool found = false;
                for (;;) {  // to the next line end, at most skip_budget bytes
                    const int c = buf->sbumpc();
                    if (c == std::char_traits<char>::eof()) { at_eof = true; break; }
                    if (c == '\n') { found = true; break; }
                    if (++skipped > skip_budget) break;
                }
                if (!found && !at_eof) {
                    report({name, line_no, 1}, "no line end within " + std::to_string(skip_budget) +
                                                   " bytes after an over-long statement: the rest of the input is not read");
                    at_eof = true;
                    break;
                }
                ++line_no;
                ended = true;
            }
            first = line_no;
            continue;
        }
        if (at_eof && line.empty()) break;
        tracker.feed(line);
        pending += line;
        pending += '\n';
        ++line_no;
        if (tracker.complete()) {
            run_text(pending, name, first);
            out_->flush();
            pending.clear();
            first = line_no;
        }
    }
    if (!pending.empty() && !stopped_) run_text(pending, name, first);
    out_->flush();
    return failures_ - before;
}

int session::run_text(const std::string& text, const std::string& name, int first_line) {
    const int before = failures_;
    if (stopped_) return 0;
    parser p(text, name, first_line);
    files_.push_back(name);
    // a file that loads itself replaces the text of the caller's statement:
    // put it back at the end, for the caret of the caller's later errors
    const auto saved = sources_.count(name) ? std::optional<std::pair<std::string, int>>(
                                                  {sources_[name], source_line_.count(name) ? source_line_[name] : 1})
                                            : std::nullopt;
    sources_[name] = text;
    source_line_[name] = first_line;
    while (!p.at_end() && !stopped_) {
        node_ptr s;
        try {
            s = p.next_statement();
        } catch (const syntax_error& e) {
            if (!p.assigned_name().empty()) forget_failed(p.assigned_name(), name + ":" + std::to_string(p.statement_begin().first));
            report(e.where, std::string("syntax error: ") + e.what());
            p.recover();
            continue;
        }
        if (!s) continue;
        const source_location here{name, s->line, s->column};
        if (opts_.echo) {
            const auto [bl, bc] = p.statement_begin();
            const auto [el, ec] = p.statement_end();
            const std::size_t a = offset_of(text, bl - first_line + 1, bc);
            std::size_t b = offset_of(text, el - first_line + 1, ec);
            if (b <= a) b = text.find('\n', a) == std::string::npos ? text.size() : text.find('\n', a);
            *out_ << "> " << escape_controls(trimmed(text.substr(a, b - a))) << "\n";
        }
        try {
            try {
                exec(*s, true);
            } catch (...) {
                // a name whose assignment failed must not read as a free symbol later,
                // nor as the value it had before (a stale value in a later result)
                if (s->kind == node::assign) forget_failed(s->text, name + ":" + std::to_string(s->line));
                throw;
            }
        } catch (const script_error& e) {
            report(e.where, e.what());
        } catch (const std::bad_alloc& e) {
            report(here, allocation_failure_message(e, out_of_memory_message));
        } catch (const symrep::error& e) {
            report(here, e.what());
        } catch (const std::exception& e) {
            report(here, clear_message(e.what()));
        } catch (...) {
            report(here, "unknown internal error");
        }
    }
    files_.pop_back();
    if (saved) {
        sources_[name] = saved->first;
        source_line_[name] = saved->second;
    }
    out_->flush();
    return failures_ - before;
}

value session::evaluate(const std::string& text) {
    parser p(text, "<evaluate>");
    files_.push_back("<evaluate>");
    value last;
    try {
        while (!p.at_end()) {
            node_ptr s;
            try {
                s = p.next_statement();
            } catch (const syntax_error& e) {
                throw script_error(std::string("syntax error: ") + e.what(), e.where, std::current_exception());
            }
            if (!s) continue;
            if (s->kind == node::assign) {
                exec(*s, false);
                last = *get(s->text);
            } else if (s->kind == node::declare) {
                exec(*s, false);
                last = value();
            } else {
                const statement_clock clock(opts_.time_limit, statement_start_);
                last = eval(*s);
            }
        }
    } catch (...) {
        files_.pop_back();
        throw;
    }
    files_.pop_back();
    return last;
}

// vector a, b: a and b are vectors from now on (thesis Ch. VI); vector w(t): w is a
// vector function of t, unspecified (w' its derivative: results in terms of w(t));
// positive k: k is a positive real symbol from now on (earlier expressions keep
// the real symbol they were built with).
void session::declare(const node& n) {
    for (const auto& k : n.kids) {
        if (get(k->text))
            throw script_error("cannot declare '" + k->text + "': it is a variable (assigned with :=)",
                               {current_file(), k->line, k->column});
        if (k->text == "eps")  // the constant eps would still be read, not the declared name
            throw script_error("cannot declare 'eps': it is the dual unit (eps^2 = 0); assign eps := ... first to "
                               "use the name for something else, or choose another name",
                               {current_file(), k->line, k->column});
        if (n.text == "vector") {
            if (!k->kids.empty()) {  // vector w(t): a vector function of t
                try {
                    register_vector_function(symbol(k->text), symbol("t"));
                } catch (const type_error& e) {
                    throw script_error(std::string("cannot declare '") + k->text + "(t)': " + e.what(),
                                       {current_file(), k->line, k->column});
                }
            } else {
                register_vector(symbol(k->text));
            }
        } else {
            if (is_vector_symbol(symbol(k->text)))
                throw script_error("cannot declare '" + k->text + "' positive: it is a vector",
                                   {current_file(), k->line, k->column});
            symbols_[k->text] = GiNaC::possymbol(k->text);
        }
    }
}

// ode(...)'s equation E = lhs - rhs into P, evaluated with the unknown and its derivatives
// (the order is the number of initial values) bound as x, x', ...; `at` is the equation's place.
void session::ode_equation(mechanics::cauchy_problem& P, const node& eq, bool vector, const source_location& at) {
    const std::size_t M = P.initial.size();
    P.is_vector = vector;
    P.unknowns.clear();
    if (vector) {
        GiNaC::ex x = GiNaC::realsymbol(P.name);
        register_vector_function(x, P.t);
        P.unknowns.push_back(x);
        for (std::size_t m = 1; m <= M; ++m) P.unknowns.push_back(derivative(P.unknowns.back()));
    } else {
        for (std::size_t m = 0; m <= M; ++m) P.unknowns.push_back(GiNaC::realsymbol(P.unknown_name(m)));
    }
    std::map<std::string, std::optional<value>> saved;
    for (std::size_t m = 0; m <= M; ++m) {
        const std::string nm = P.unknown_name(m);
        const value* old = get(nm);
        saved[nm] = old ? std::optional<value>(*old) : std::nullopt;
        vars_[nm] = value(P.unknowns[m]);
    }
    auto restore = [&] {
        for (auto& [nm, v] : saved) {
            if (v) vars_[nm] = *v;
            else vars_.erase(nm);
        }
    };
    value lhs, rhs;
    try {
        lhs = eval(*eq.kids[0]);
        rhs = eval(*eq.kids[1]);
    } catch (...) {
        restore();
        throw;
    }
    restore();
    const value E = binary_op("-", lhs, rhs);
    if (!E.is_ex())
        throw script_error("ode: the equation must be between expressions, not " + lhs.a_kind() + " and " +
                               rhs.a_kind(), at);
    P.expression = E.as_ex();
    if (vector && !E.as_ex().is_zero() && !is_vector(E.as_ex()))
        throw script_error("ode: the equation is scalar but the initial values are vectors", at);
}

// ode(EQUATION, x(0) = X0, x'(0) = X1, ...): the unknown x is a function of t;
// it is a vector when an initial value is. The equation is evaluated with x,
// x', ... bound to the unknown and its derivatives.
value session::ode_form(const node& n) {
    const std::string usage = " (usage: ode(x'' + a x' + b x = f, x(0) = x0, x'(0) = v0))";
    auto where = [&](const node& k) {
        return source_location{current_file(), k.line, k.column};
    };
    if (n.kids.size() < 2) throw type_error("ode: expects an equation and initial conditions" + usage);
    const node& eq = *n.kids[0];
    if (eq.kind != node::binary || eq.text != "=")
        throw script_error("ode: the first argument must be an equation lhs = rhs" + usage, where(eq));
    mechanics::cauchy_problem P;
    std::vector<bool> seen;
    std::vector<value> init;
    for (std::size_t i = 1; i < n.kids.size(); ++i) {
        const node& c = *n.kids[i];
        if (c.kind != node::binary || c.text != "=" || c.kids[0]->kind != node::call || c.kids[0]->kids.size() != 1)
            throw script_error("ode: argument " + std::to_string(i + 1) + " must be an initial condition such as " +
                                   "x(0) = x0 or x'(0) = v0" + usage, where(c));
        const std::string& f = c.kids[0]->text;
        std::size_t k = 0;  // the number of primes
        while (k < f.size() && f[f.size() - 1 - k] == '\'') ++k;
        const std::string base = f.substr(0, f.size() - k);
        if (P.name.empty()) P.name = base;
        if (base != P.name)
            throw script_error("ode: initial conditions for two functions, " + P.name + " and " + base, where(c));
        const value t0 = eval(*c.kids[0]->kids[0]);
        if (!t0.is_ex() || !t0.as_ex().is_zero())
            throw script_error("ode: initial conditions are given at t = 0", where(*c.kids[0]->kids[0]));
        if (k >= seen.size()) { seen.resize(k + 1, false); init.resize(k + 1); }
        if (seen[k]) throw script_error("ode: " + f + "(0) is given twice", where(c));
        seen[k] = true;
        init[k] = eval(*c.kids[1]);
    }
    for (std::size_t k = 0; k < seen.size(); ++k)
        if (!seen[k])
            throw type_error("ode: the initial condition " + P.name + std::string(k, '\'') + "(0) is missing" + usage);
    P.t = symbol("t");
    if (P.name == "t") throw type_error("ode: the unknown cannot be named t (t is the independent variable)");
    for (const value& v : init)
        if (!v.is_ex() && !is_triple(v))
            throw type_error("ode: an initial value must be an expression or a vector, not " + v.a_kind());
    P.is_vector = false;
    for (const value& v : init)
        if ((v.is_ex() && is_vector(v.as_ex())) || v.is_list()) P.is_vector = true;
    for (const value& v : init) {
        const ex e = v.is_list() ? vector_operand("ode", v, "initial") : v.as_ex();
        if (P.is_vector && !e.is_zero() && !is_vector(e))
            throw type_error("ode: the initial values mix vectors and scalars: " + print_ex(e));
        P.initial.push_back(e);
    }
    const std::size_t M = init.size();
    // a derivative of higher order than the conditions allow is an error at its place
    std::function<void(const node&)> scan = [&](const node& k) {
        if (k.kind == node::ident && k.text.size() > P.name.size() + M && k.text.rfind(P.name, 0) == 0 &&
            k.text.find_first_not_of('\'', P.name.size()) == std::string::npos)
            throw script_error("ode: " + k.text + " appears, but " + std::to_string(M) + " initial condition" +
                                   (M == 1 ? "" : "s") + " make an equation of order " + std::to_string(M),
                               where(k));
        for (const auto& c : k.kids) scan(*c);
    };
    scan(eq);
    // initial values that are all 0 leave the kind open: a vector if the equation is one
    const bool open = !P.is_vector && std::all_of(P.initial.begin(), P.initial.end(), [](const ex& e) { return e.is_zero(); });
    if (open) {
        try {
            ode_equation(P, eq, true, where(eq));
        } catch (const std::exception&) {
            ode_equation(P, eq, false, where(eq));
        }
    } else {
        ode_equation(P, eq, P.is_vector, where(eq));
    }
    // read once, now: errors point at ode(...), and solve() uses the result
    mechanics::read_problem(P);
    return value(std::make_shared<const mechanics::cauchy_problem>(std::move(P)));
}

void session::report_fields(const std::string& from, const std::string& prose, const std::string& fields) {
    if (opts_.format != output_options::json) {
        *out_ << prose;
        return;
    }
    *out_ << "{\"file\": " << json_quote(current_file()) << ", \"line\": " << statement_line_
          << ", \"kind\": \"report\", \"from\": " << json_quote(from) << (fields.empty() ? "" : ", ") << fields
          << "}\n";
}

void session::exec(const node& stmt, bool echo) {
    const statement_clock clock(opts_.time_limit, statement_start_);
    statement_line_ = stmt.line;
    if (stmt.kind == node::declare) {
        declare(stmt);
        return;
    }
    if (stmt.kind == node::assign) {
        value v = eval(*stmt.kids[0]);
        if (v.is_none())
            throw script_error("cannot assign nothing to '" + stmt.text + "': the right side has no value",
                               {current_file(), stmt.line, stmt.column});
        if (stmt.text == "Digits") {
            // Digits := n sets the precision of floats (evalf, float literals)
            if (!v.is_ex() || !is_a<numeric>(v.as_ex()) || !ex_to<numeric>(v.as_ex()).is_pos_integer() ||
                ex_to<numeric>(v.as_ex()) > 100000)
                throw script_error("Digits must be a positive integer (at most 100000), not " +
                                       (v.is_ex() ? print_ex(v.as_ex()) : v.a_kind()),
                                   {current_file(), stmt.line, stmt.column});
            GiNaC::Digits = ex_to<numeric>(v.as_ex()).to_long();
        }
        set(stmt.text, std::move(v));
        return;
    }
    value v = eval(stmt);
    if (!echo || v.is_none()) return;
    results_.push_back(v);
    if (on_result_) on_result_(v);
    if (!opts_.print_results) return;
    switch (opts_.format) {
        case output_options::text:
            if (labels_) *out_ << "%" << results_.size() << " = ";
            *out_ << print_value(v, true) << "\n";
            break;
        case output_options::latex: *out_ << latex_value(v) << "\n"; break;
        case output_options::json:
            *out_ << "{\"file\": " << json_quote(current_file())
                  << ", \"line\": " << stmt.line << ", \"kind\": " << json_quote(v.kind())
                  << ", \"value\": " << json_quote(print_value(v, false)) << "}\n";
            break;
    }
}

std::atomic<bool>& interrupt_requested() { return symrep::interrupt_flag(); }

std::vector<std::string> session::variable_names() const {
    std::vector<std::string> names;
    for (const auto& [k, v] : vars_) names.push_back(k);
    return names;
}

}  // namespace symrep::lang

// tests/test_examples.cpp -- the example derivation scripts of examples/*.symrep.
//
// 1. Every script in examples/ runs through the symrep program with exit status 0
//    and nothing on stderr (each script checks its own results with expect()).
// 2. Selected printed results are parsed back (GiNaC::parser; basis names such as
//    eps, j, u0, i0 become symbols, so an element reads as a polynomial in them) and
//    compared BY VALUE with an independent computation in C++: the same algebra
//    rebuilt here from its multiplication table in the thesis (a structure-constant
//    algebra that uses only the general methods of algebra.h, never the family's fast
//    paths), exp by its Taylor series in 50-digit floats, idempotents and components by
//    their defining formulas. Closed forms with exp/cos/atan are compared numerically
//    (30 digits, tolerance 1e-25) after substituting rational values for the symbols.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include <ginac/ginac.h>
#include <ginac/parser.h>
#include <Eigen/Dense>

#include "algebra/algebra.h"
#include "algebra/multicomplex.h"
#include "algebra/sobrero.h"
#include "algebra/walsh.h"
#include "algebra/walsh_complex.h"
#include "test_util.h"

using namespace symrep;
using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::numeric;

namespace {

// ---------------------------------------------------------------------------------
// running a script

struct run_result {
    std::string out, err;
    int status = -1;
    double seconds = 0;
};

std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

std::string examples_dir() { return std::string(SYMREP_SOURCE_DIR) + "/examples"; }

/// Runs one script through SYMREP_BINARY --format json (stdout, stderr, exit status); cached per process.
const run_result& run_script(const std::string& name) {
    static std::map<std::string, run_result> cache;
    auto it = cache.find(name);
    if (it != cache.end()) return it->second;
    static int counter = 0;
    // Unique names: ctest runs the tests of this file in parallel processes.
    const std::string err_path = ::testing::TempDir() + "/symrep_examples_" +
                                 std::to_string(getpid()) + "_" + std::to_string(counter++) +
                                 "_err.txt";
    // results as JSON lines (read by result_after), the text of print() as it is
    const std::string cmd = std::string("'") + SYMREP_BINARY + "' --format json '" + examples_dir() + "/" +
                            name + "' 2>'" + err_path + "' </dev/null";
    run_result r;
    const auto t0 = std::chrono::steady_clock::now();
    FILE* p = popen(cmd.c_str(), "r");
    if (p) {
        char buf[4096];
        std::size_t n;
        while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
        const int st = pclose(p);
        r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.err = slurp(err_path);
    std::remove(err_path.c_str());
    return cache.emplace(name, std::move(r)).first->second;
}

using symrep::test::lines_of;

/// The string field `key` of a one-line JSON object as `symrep --format json` writes a result
/// ({"file": ..., "line": n, "kind": "...", "value": "..."}, docs/language.md), unescaped;
/// false when the line is no such object or has no such field.
bool json_string_field(const std::string& line, const std::string& key, std::string& value) {
    if (line.empty() || line.front() != '{' || line.back() != '}') return false;
    const std::string quoted = "\"" + key + "\": \"";
    std::size_t at = line.find(quoted);
    if (at == std::string::npos) return false;
    value.clear();
    for (at += quoted.size(); at < line.size() && line[at] != '"'; ++at) {
        if (line[at] != '\\') {
            value += line[at];
            continue;
        }
        if (++at >= line.size()) return false;
        switch (line[at]) {
            case 'n': value += '\n'; break;
            case 't': value += '\t'; break;
            case 'r': value += '\r'; break;
            case 'b': value += '\b'; break;
            case 'f': value += '\f'; break;
            case 'u': {  // \u00XX: the control characters json_quote escapes
                if (at + 4 >= line.size()) return false;
                const unsigned long c = std::stoul(line.substr(at + 1, 4), nullptr, 16);
                if (c >= 0x80) return false;
                value += char(c);
                at += 4;
                break;
            }
            default: value += line[at];  // \" \\ \/
        }
    }
    return at < line.size();
}

/// The result printed right after the print()ed heading line `heading` (exactly equal): under
/// --format json a result is one JSON line; its kind must be `kind`, and its value (the canonical
/// printer's text) is returned.
std::string result_after(const std::string& out, const std::string& heading, const std::string& kind) {
    const auto ls = lines_of(out);
    for (std::size_t k = 0; k + 1 < ls.size(); ++k) {
        if (ls[k] != heading) continue;
        std::string got_kind, value;
        if (!json_string_field(ls[k + 1], "kind", got_kind) || !json_string_field(ls[k + 1], "value", value)) {
            ADD_FAILURE() << "after '" << heading << "' no JSON result line but: " << ls[k + 1];
            return "0";
        }
        EXPECT_EQ(got_kind, kind) << "the result after '" << heading << "': " << value;
        return value;
    }
    ADD_FAILURE() << "no line '" << heading << "' in the output";
    return "0";
}

/// In the line starting with `prefix`, the text after `label` (after the prefix when no
/// label is given) up to the next double space: print() items are separated that way.
std::string inline_value(const std::string& out, const std::string& prefix,
                         const std::string& label = "") {
    for (const auto& l : lines_of(out))
        if (l.rfind(prefix, 0) == 0) {
            std::size_t at = prefix.size();
            if (!label.empty()) {
                at = l.find(label);
                if (at == std::string::npos) break;
                at += label.size();
            }
            std::string rest = l.substr(at);
            const auto cut = rest.find("  ");
            return cut == std::string::npos ? rest : rest.substr(0, cut);
        }
    ADD_FAILURE() << "no line starting with '" << prefix << "' (with '" << label << "') in the output";
    return "0";
}

// ---------------------------------------------------------------------------------
// reading printed values back

/// Symbols of a script (real) and of basis names, shared by the parser and the C++ side.
struct symbols {
    std::map<std::string, ex> table;
    ex operator()(const std::string& name) {
        auto it = table.find(name);
        if (it == table.end()) it = table.emplace(name, GiNaC::realsymbol(name)).first;
        return it->second;
    }
    /// The symbol itself (a reference: copying it into a GiNaC::symbol would slice the
    /// realsymbol into a different type that no longer compares equal).
    const GiNaC::realsymbol& sym(const std::string& name) {
        (*this)(name);
        return ex_to<GiNaC::realsymbol>(table.at(name));
    }
};

/// Parses printed text; every name must be known to S (strict: a stray name is an error).
ex parse(symbols& S, const std::string& text) {
    GiNaC::symtab tab;
    for (const auto& [k, v] : S.table) tab[k] = v;
    tab["pi"] = GiNaC::Pi;
    GiNaC::parser p(tab, /*strict=*/true);
    try {
        return p(text);
    } catch (const std::exception& e) {
        ADD_FAILURE() << "cannot parse '" << text << "': " << e.what();
        return GiNaC::symbol("unparsable");
    }
}

/// Splits "[a, [b, c], d]" at the top-level commas (the text without the outer brackets).
std::vector<std::string> split_list(const std::string& text) {
    std::string s = text;
    while (!s.empty() && s.front() == ' ') s.erase(s.begin());
    while (!s.empty() && s.back() == ' ') s.pop_back();
    EXPECT_TRUE(s.size() >= 2 && s.front() == '[' && s.back() == ']') << "not a list: " << text;
    s = s.substr(1, s.size() - 2);
    std::vector<std::string> parts;
    int depth = 0;
    std::string cur;
    for (char c : s) {
        if (c == '(' || c == '[') ++depth;
        if (c == ')' || c == ']') --depth;
        if (c == ',' && depth == 0) {
            parts.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    if (!cur.empty()) parts.push_back(cur);
    return parts;
}

std::vector<ex> parse_list(symbols& S, const std::string& text) {
    std::vector<ex> v;
    for (const auto& p : split_list(text)) v.push_back(parse(S, p));
    return v;
}

/// "matrix([[a, b], [c, d]])" -> rows.
std::vector<std::vector<ex>> parse_matrix(symbols& S, const std::string& text) {
    const std::string head = "matrix(";
    EXPECT_EQ(text.rfind(head, 0), 0u) << text;
    const std::string inner = text.substr(head.size(), text.size() - head.size() - 1);
    std::vector<std::vector<ex>> rows;
    for (const auto& r : split_list(inner)) rows.push_back(parse_list(S, r));
    return rows;
}

// ---------------------------------------------------------------------------------
// the algebras, rebuilt from their multiplication tables

/// A structure-constant algebra: only the product is given, everything else is the
/// general method of algebra.h (canonical matrix, charpoly, Krylov minpoly, inverse).
/// basis_monomial(k) is how basis element k prints, as a monomial in basis symbols.
class table_algebra : public algebra {
public:
    /// `unit`: the coordinates of the identity when it is not basis element 0.
    table_algebra(std::string name, std::vector<std::vector<coeffs>> gamma, std::vector<ex> monomials,
                  coeffs unit = {})
        : name_(std::move(name)), gamma_(std::move(gamma)), mono_(std::move(monomials)),
          unit_(std::move(unit)) {}
    std::string name() const override { return name_; }
    std::size_t dim() const override { return gamma_.size(); }
    coeffs unit() const override { return unit_.empty() ? algebra::unit() : unit_; }
    coeffs multiply(const coeffs& a, const coeffs& b) const override {
        coeffs r(dim(), ex(0));
        for (std::size_t i = 0; i < dim(); ++i) {
            if (a[i].is_zero()) continue;
            for (std::size_t j = 0; j < dim(); ++j) {
                if (b[j].is_zero()) continue;
                for (std::size_t k = 0; k < dim(); ++k)
                    if (!gamma_[i][j][k].is_zero()) r[k] += a[i] * b[j] * gamma_[i][j][k];
            }
        }
        for (auto& x : r) x = GiNaC::expand(x);
        return r;
    }
    const ex& monomial(std::size_t k) const { return mono_[k]; }
    /// The element as a polynomial in the basis symbols (how symrep prints it).
    ex as_polynomial(const coeffs& c) const {
        ex p = 0;
        for (std::size_t k = 0; k < dim(); ++k) p += c[k] * mono_[k];
        return p;
    }
    /// The coordinates of a printed element (a polynomial in the basis symbols).
    coeffs coords_of(const ex& printed, const std::vector<ex>& basis_symbols) const {
        const ex e = GiNaC::expand(printed);
        coeffs c(dim());
        for (std::size_t k = 0; k < dim(); ++k) {
            ex x = e;
            for (const auto& s : basis_symbols) x = x.coeff(s, mono_[k].degree(s));
            c[k] = x;
        }
        EXPECT_TRUE(GiNaC::expand(as_polynomial(c) - e).is_zero())
            << "the printed element " << printed << " has a term outside the basis of " << name_;
        return c;
    }

private:
    std::string name_;
    std::vector<std::vector<coeffs>> gamma_;
    std::vector<ex> mono_;
    coeffs unit_;
};

using table_ptr = std::shared_ptr<const table_algebra>;

/// Generalized Sobrero algebra (III.2.4): index k is eps^k, index n+1+k is j eps^k;
/// (j^a eps^k)(j^b eps^l) = (-1)^(ab) j^(a xor b) eps^(k+l), eps^(n+1) = 0.
table_ptr sobrero_table(unsigned n, symbols& S) {
    const std::size_t N = 2 * (n + 1);
    std::vector<std::vector<coeffs>> g(N, std::vector<coeffs>(N));
    std::vector<ex> mono(N);
    for (std::size_t x = 0; x < N; ++x) {
        const unsigned a = x > n, k = unsigned(x % (n + 1));
        mono[x] = GiNaC::pow(S("j"), a) * GiNaC::pow(S("eps"), k);
        for (std::size_t y = 0; y < N; ++y) {
            const unsigned b = y > n, l = unsigned(y % (n + 1));
            g[x][y] = coeffs(N, ex(0));
            if (k + l <= n) g[x][y][(a ^ b) * (n + 1) + k + l] = (a && b) ? -1 : 1;
        }
    }
    return std::make_shared<table_algebra>("sobrero_table", g, mono);
}

/// Product of u_k over the set bits of p, bit 2^(bits-1-k) standing for name+k.
ex bit_monomial(std::size_t p, unsigned bits, const std::string& name, symbols& S) {
    ex m = 1;
    for (unsigned k = 0; k < bits; ++k)
        if (p >> (bits - 1 - k) & 1) m *= S(name + std::to_string(k));
    return m;
}

/// Walsh algebra W (III.3.6): w_p w_q = w_(p xor q); basis names u0 (most significant bit) ...
/// With complex = true, the real form of W* (III.3.51): (i0^a w_p)(i0^b w_q) =
/// (-1)^(ab) i0^(a xor b) w_(p xor q), index 2^n + p is i0 w_p.
table_ptr walsh_table(unsigned n, bool complex, symbols& S) {
    const std::size_t h = std::size_t(1) << n, N = complex ? 2 * h : h;
    std::vector<std::vector<coeffs>> g(N, std::vector<coeffs>(N));
    std::vector<ex> mono(N);
    for (std::size_t x = 0; x < N; ++x) {
        const std::size_t a = x / h, p = x % h;
        mono[x] = GiNaC::pow(S("i0"), unsigned(a)) * bit_monomial(p, n, "u", S);
        for (std::size_t y = 0; y < N; ++y) {
            const std::size_t b = y / h, q = y % h;
            g[x][y] = coeffs(N, ex(0));
            g[x][y][(a ^ b) * h + (p ^ q)] = (a && b) ? -1 : 1;
        }
    }
    return std::make_shared<table_algebra>(complex ? "walsh_complex_table" : "walsh_table", g, mono);
}

/// Multicomplex algebra (x)C^(n+1) (III.1.7): e_p e_q = (-1)^<p,q> e_(p xor q), e_p =
/// i0^p0 ... in^pn with p0 the most significant of n+1 bits.
table_ptr multicomplex_table(unsigned n, symbols& S) {
    const std::size_t N = std::size_t(2) << n;
    std::vector<std::vector<coeffs>> g(N, std::vector<coeffs>(N));
    std::vector<ex> mono(N);
    for (std::size_t p = 0; p < N; ++p) {
        mono[p] = bit_monomial(p, n + 1, "i", S);
        for (std::size_t q = 0; q < N; ++q) {
            g[p][q] = coeffs(N, ex(0));
            g[p][q][p ^ q] = std::popcount(p & q) % 2 ? -1 : 1;
        }
    }
    return std::make_shared<table_algebra>("multicomplex_table", g, mono);
}

std::vector<ex> basis_symbols(symbols& S, std::initializer_list<const char*> names) {
    std::vector<ex> v;
    for (const char* n : names) v.push_back(S(n));
    return v;
}

// ---------------------------------------------------------------------------------
// comparisons

using symrep::test::same;

/// GiNaC::Digits for a scope, restored after it: a test that leaves 50 digits behind changes the
/// tests that run after it in the same process (MovingFrame's verify failed after these).
struct digits_for_scope {
    long saved = GiNaC::Digits;
    explicit digits_for_scope(long d) { GiNaC::Digits = d; }
    ~digits_for_scope() { GiNaC::Digits = saved; }
};

/// |a - b| <= tol after evaluation at 50 digits (complex values allowed).
::testing::AssertionResult near(const ex& a, const ex& b, double tol = 1e-25) {
    const digits_for_scope digits(50);
    const ex d = GiNaC::evalf(a - b);
    if (!GiNaC::is_a<numeric>(d)) return ::testing::AssertionFailure() << "not numeric: " << d;
    const double m = GiNaC::abs(ex_to<numeric>(d)).to_double();
    if (m <= tol) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << a << " vs " << b << " differ by " << m;
}

::testing::AssertionResult near_coeffs(const coeffs& a, const coeffs& b, double tol = 1e-25) {
    if (a.size() != b.size()) return ::testing::AssertionFailure() << "sizes differ";
    for (std::size_t k = 0; k < a.size(); ++k) {
        auto r = near(a[k], b[k], tol);
        if (!r) return r << " (coordinate " << k << ")";
    }
    return ::testing::AssertionSuccess();
}

coeffs subs_all(const coeffs& c, const GiNaC::exmap& m) {
    coeffs r;
    for (const auto& x : c) r.push_back(x.subs(m));
    return r;
}

/// exp(w) by its Taylor series in 50-digit floats (w numeric).
coeffs exp_series(const table_algebra& A, const coeffs& w) {
    const digits_for_scope digits(50);
    coeffs wf;
    for (const auto& x : w) wf.push_back(GiNaC::evalf(x));
    coeffs term = A.unit(), sum = A.unit();
    for (int k = 1; k <= 400; ++k) {
        term = algebra::scale(numeric(1, k), A.multiply(term, wf));
        for (auto& x : term) x = GiNaC::evalf(x);
        sum = algebra::add(sum, term);
        static const numeric tiny("1e-45");
        bool small = true;
        for (const auto& x : term)
            if (GiNaC::abs(ex_to<numeric>(x)) > tiny) small = false;
        if (small && k > 10) break;
    }
    return sum;
}

struct ScriptRun : ::testing::TestWithParam<std::string> {};

std::vector<std::string> example_scripts() {
    std::vector<std::string> v;
    for (const auto& f : std::filesystem::directory_iterator(examples_dir()))
        if (f.path().extension() == ".symrep") v.push_back(f.path().filename().string());
    std::sort(v.begin(), v.end());
    return v;
}

}  // namespace

// ---------------------------------------------------------------------------------
// 1. every script runs cleanly

TEST(Examples, TheFolderHasTheFamilyScripts) {
    const auto v = example_scripts();
    for (const char* s : {"sobrero.symrep", "walsh.symrep", "multicomplex.symrep", "algebras.symrep"})
        EXPECT_NE(std::find(v.begin(), v.end(), s), v.end()) << s;
}

// The tables written out above from the thesis are the engine's algebras (same products
// and basis names), so a mismatch in the value tests below points at a result, not a table.
TEST(Examples, TablesAreTheEngineFamilies) {
    symbols S;
    const std::vector<std::pair<algebra_ptr, table_ptr>> pairs{
        {sobrero::make(2), sobrero_table(2, S)},
        {walsh::make(2), walsh_table(2, false, S)},
        {walsh_complex::make(2), walsh_table(2, true, S)},
        {multicomplex::make(1), multicomplex_table(1, S)},
        {multicomplex::make(2), multicomplex_table(2, S)}};
    for (const auto& [F, T] : pairs) {
        ASSERT_EQ(F->dim(), T->dim()) << F->name();
        for (std::size_t i = 0; i < F->dim(); ++i) {
            EXPECT_TRUE(same(parse(S, F->basis_name(i)), T->monomial(i))) << F->name() << " basis " << i;
            for (std::size_t j = 0; j < F->dim(); ++j)
                EXPECT_TRUE(same(F->basis_product(i, j), T->basis_product(i, j)))
                    << F->name() << " e" << i << " e" << j;
        }
    }
}

TEST_P(ScriptRun, ExitsZeroWithEmptyStderr) {
    const run_result& r = run_script(GetParam());
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_FALSE(r.out.empty());
    // the scripts take well under 2 s; a generous bound catches a pathological slowdown
    EXPECT_LT(r.seconds, 20.0);
}

INSTANTIATE_TEST_SUITE_P(AllScripts, ScriptRun, ::testing::ValuesIn(example_scripts()),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                             std::string n = i.param.substr(0, i.param.find('.'));
                             for (auto& c : n)
                                 if (!isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

// ---------------------------------------------------------------------------------
// 2. printed results, by value

TEST(ExamplesSobrero, PrintedResultsByValue) {
    const run_result& r = run_script("sobrero.symrep");
    ASSERT_EQ(r.status, 0) << r.err;
    symbols S;
    auto A = sobrero_table(2, S);
    const auto B = basis_symbols(S, {"eps", "j"});
    auto elem = [&](const std::string& text) { return A->coords_of(parse(S, text), B); };
    const coeffs w{S("a0"), S("a1"), S("a2"), S("b0"), S("b1"), S("b2")};
    const GiNaC::realsymbol& X = S.sym("X");
    S("t");

    // (III.2.6) the element and (III.2.9) its canonical matrix
    EXPECT_TRUE(same(elem(result_after(r.out, "(III.2.6) w =", "element")), w));
    const auto M = parse_matrix(S, result_after(r.out, "(III.2.9) [w] =", "expression"));
    const GiNaC::matrix Mw = A->canonical_matrix(w);
    ASSERT_EQ(M.size(), 6u);
    for (unsigned i = 0; i < 6; ++i)
        for (unsigned k = 0; k < 6; ++k) EXPECT_TRUE(same(M[i][k], Mw(i, k))) << i << "," << k;

    // (III.2.12) characteristic polynomial, against det(X I - [w]) of the table algebra
    EXPECT_TRUE(same(parse(S, result_after(r.out, "(III.2.12) charpoly(w, X) =", "expression")), A->charpoly(w, X)));
    EXPECT_TRUE(same(parse(S, result_after(r.out, "det [w] =", "expression")), A->determinant(w)));

    // inverse and minimal polynomials of numeric elements (general linear algebra)
    const coeffs v = elem(inline_value(r.out, "v = "));
    EXPECT_TRUE(same(v, {1, 2, 3, 1, 0, -1}));
    EXPECT_TRUE(same(elem(result_after(r.out, "inverse(v) =", "element")), A->inverse(v)));
    EXPECT_TRUE(same(parse(S, result_after(r.out, "minpoly(v, X) =", "expression")), A->minpoly(v, X)));
    const coeffs u{1, 0, 5, 1, 0, 0};
    const ex mu = parse(S, result_after(r.out, "minpoly(1 + j + 5*eps^2, X) =", "expression"));
    EXPECT_TRUE(same(mu, A->minpoly(u, X)));
    EXPECT_EQ(mu.degree(X), 4);

    // (III.2.16-18) semiexponential form: A_k = |xi_k| exactly, phi_k in [0, 2 pi) numerically
    const auto se = split_list(result_after(r.out, "(III.2.16) semiexponential(v) = [rho, theta] =", "list"));
    ASSERT_EQ(se.size(), 2u);
    const coeffs rho = elem(se[0]), theta = elem(se[1]);
    for (unsigned k = 0; k < 3; ++k) {
        EXPECT_TRUE(same(rho[k], GiNaC::sqrt(v[k] * v[k] + v[3 + k] * v[3 + k]))) << k;
        EXPECT_TRUE(rho[3 + k].is_zero() && theta[k].is_zero());
        const ex phi = GiNaC::evalf(theta[3 + k]);
        EXPECT_TRUE(phi >= 0 && phi < GiNaC::evalf(2 * GiNaC::Pi)) << phi;
        EXPECT_TRUE(near(rho[k] * GiNaC::cos(theta[3 + k]), v[k]));
        EXPECT_TRUE(near(rho[k] * GiNaC::sin(theta[3 + k]), v[3 + k]));
    }

    // Thm III.2.2.1: the product of the two special-type elements, by the table
    const coeffs w1 = elem(inline_value(r.out, "w1 = "));
    const coeffs w2 = elem(inline_value(r.out, "w1 = ", "w2 = "));
    const coeffs w12 = elem(inline_value(r.out, "w1*w2 = "));
    const coeffs w1e{1, 2, 1, 1, 2, 1}, w2e{0, 0, 0, 3, 0, 1};
    EXPECT_TRUE(same(w1, w1e));
    EXPECT_TRUE(same(w2, w2e));
    EXPECT_TRUE(same(w12, A->multiply(w1e, w2e)));

    // (III.2.24) the decomposition of c: sums to c, each part on one line through 0
    const coeffs c = elem(inline_value(r.out, "c = "));
    const auto parts = split_list(result_after(r.out, "(III.2.24) special_type_decomposition(c) =", "list"));
    ASSERT_EQ(parts.size(), 2u);
    const coeffs d0 = elem(parts[0]), d1 = elem(parts[1]);
    EXPECT_TRUE(same(algebra::add(d0, d1), c));
    for (const coeffs* d : {&d0, &d1})
        for (unsigned k = 0; k < 3; ++k)
            for (unsigned l = 0; l < 3; ++l)
                EXPECT_TRUE(same((*d)[k] * (*d)[3 + l], (*d)[l] * (*d)[3 + k]));

    // exp(w t): at rational values of the symbols, against the Taylor series of exp
    const ex E = parse(S, result_after(r.out, "exp(w t) =", "element"));
    const GiNaC::exmap at{{S("a0"), numeric(1, 3)}, {S("a1"), numeric(-2, 5)}, {S("a2"), numeric(3, 4)},
                          {S("b0"), numeric(5, 4)}, {S("b1"), numeric(1, 2)}, {S("b2"), numeric(-1, 3)},
                          {S("t"), numeric(7, 10)}};
    const coeffs wt = algebra::scale(numeric(7, 10), subs_all(w, at));
    EXPECT_TRUE(near_coeffs(subs_all(A->coords_of(E, B), at), exp_series(*A, wt)));

    // log(v): the Taylor series of exp at the printed logarithm gives back v
    const coeffs L = elem(result_after(r.out, "log(v) =", "element"));
    EXPECT_TRUE(near_coeffs(exp_series(*A, L), v));

    // (III.4.13) the generating element and its minimal polynomial, by the general method
    const coeffs g = elem(inline_value(r.out, "(III.4.13) d = "));
    EXPECT_TRUE(same(g, {0, 1, 0, 1, 0, 0}));
    EXPECT_TRUE(same(parse(S, inline_value(r.out, "(III.4.13) d = ", "minpoly(d, X) = ")),
                     A->minpoly(g, X)));
}

namespace {
/// <p, q> with the thesis's bits: popcount of p & q (independent of the bit order).
int hadamard_sign(std::size_t p, std::size_t q) { return std::popcount(p & q) % 2 ? -1 : 1; }
}  // namespace

TEST(ExamplesWalsh, PrintedResultsByValue) {
    const run_result& r = run_script("walsh.symrep");
    ASSERT_EQ(r.status, 0) << r.err;
    symbols S;
    auto A = walsh_table(2, false, S);
    auto As = walsh_table(2, true, S);
    const auto B = basis_symbols(S, {"u0", "u1", "i0"});
    auto elem = [&](const std::string& text) { return A->coords_of(parse(S, text), B); };
    auto elem_s = [&](const std::string& text) { return As->coords_of(parse(S, text), B); };
    const GiNaC::realsymbol& X = S.sym("X");
    S("t");
    const coeffs f{S("f0"), S("f1"), S("f2"), S("f3")};

    // (III.3.7) the idempotents, against (III.3.22) e_p = 2^-n sum_q (-1)^<p,q> w_q
    const auto e = split_list(result_after(r.out, "(III.3.7) e_0 .. e_3 =", "list"));
    ASSERT_EQ(e.size(), 4u);
    for (std::size_t p = 0; p < 4; ++p) {
        coeffs expect(4);
        for (std::size_t q = 0; q < 4; ++q) expect[q] = numeric(hadamard_sign(p, q), 4);
        const coeffs ep = elem(e[p]);
        EXPECT_TRUE(same(ep, expect)) << p;
        EXPECT_TRUE(same(A->multiply(ep, ep), ep)) << p;
    }

    // (III.3.25) components a_p = sum_q (-1)^<p,q> f_q
    const auto a = parse_list(S, result_after(r.out, "(III.3.25) components a_p =", "list"));
    ASSERT_EQ(a.size(), 4u);
    for (std::size_t p = 0; p < 4; ++p) {
        ex ap = 0;
        for (std::size_t q = 0; q < 4; ++q) ap += hadamard_sign(p, q) * f[q];
        EXPECT_TRUE(same(a[p], ap)) << p;
    }

    // canonical matrix, det (III.3.28), charpoly (III.3.34) by the general methods
    const auto M = parse_matrix(S, result_after(r.out, "[f] =", "expression"));
    const GiNaC::matrix Mf = A->canonical_matrix(f);
    ASSERT_EQ(M.size(), 4u);
    for (unsigned i = 0; i < 4; ++i)
        for (unsigned k = 0; k < 4; ++k) EXPECT_TRUE(same(M[i][k], Mf(i, k)));
    EXPECT_TRUE(same(parse(S, result_after(r.out, "(III.3.28) det [f] =", "expression")), A->determinant(f)));
    EXPECT_TRUE(same(parse(S, result_after(r.out, "(III.3.34) charpoly(f, X) =", "expression")), A->charpoly(f, X)));

    // (III.3.44) exp(f t) against the Taylor series at rational values
    const ex E = parse(S, result_after(r.out, "(III.3.44) exp(f t) =", "element"));
    const GiNaC::exmap at{{S("f0"), numeric(1, 3)}, {S("f1"), numeric(-2, 5)}, {S("f2"), numeric(3, 4)},
                          {S("f3"), numeric(5, 4)}, {S("t"), numeric(-9, 10)}};
    EXPECT_TRUE(near_coeffs(subs_all(A->coords_of(E, B), at),
                            exp_series(*A, algebra::scale(numeric(-9, 10), subs_all(f, at)))));

    // inverse and minimal polynomial of g
    const coeffs g = elem(inline_value(r.out, "g = "));
    EXPECT_TRUE(same(g, {3, 1, 1, 0}));
    EXPECT_TRUE(same(elem(result_after(r.out, "inverse(g) =", "element")), A->inverse(g)));
    const ex mg = parse(S, result_after(r.out, "minpoly(g, X) =", "expression"));
    EXPECT_TRUE(same(mg, A->minpoly(g, X)));
    EXPECT_EQ(GiNaC::expand(mg).degree(X), 3);

    // zero divisor z: the printed ranks are the p with z e_p = 0
    const coeffs z = elem(inline_value(r.out, "z = "));
    const auto ranks = parse_list(S, inline_value(r.out, "z = ", "zero-divisor ranks: "));
    std::vector<ex> expect_ranks;
    for (std::size_t p = 0; p < 4; ++p) {
        ex ap = 0;
        for (std::size_t q = 0; q < 4; ++q) ap += hadamard_sign(p, q) * z[q];
        if (same(ap, 0)) expect_ranks.push_back(numeric(long(p)));
    }
    ASSERT_EQ(ranks.size(), expect_ranks.size());
    for (std::size_t k = 0; k < ranks.size(); ++k) EXPECT_TRUE(same(ranks[k], expect_ranks[k]));

    // (III.3.40) log(h) in W: exp of the printed logarithm gives back h
    const coeffs h = elem(inline_value(r.out, "h = "));
    EXPECT_TRUE(same(h, {4, 1, 1, 0}));
    EXPECT_TRUE(near_coeffs(exp_series(*A, elem(result_after(r.out, "(III.3.40) log(h) =", "element"))), h));

    // W*: the components of y (III.3.62-63), its inverse, and the logarithms (III.3.67)
    const coeffs y = elem_s(inline_value(r.out, "y = "));
    EXPECT_TRUE(same(y, {1, 2, 0, 0, 3, 0, 0, 1}));
    const auto cy = parse_list(S, inline_value(r.out, "y = ", "(III.3.61) components: "));
    ASSERT_EQ(cy.size(), 4u);
    for (std::size_t p = 0; p < 4; ++p) {
        ex c = 0;
        for (std::size_t q = 0; q < 4; ++q) c += hadamard_sign(p, q) * (y[q] + GiNaC::I * y[4 + q]);
        EXPECT_TRUE(same(cy[p], c)) << p;
    }
    EXPECT_TRUE(same(elem_s(inline_value(r.out, "inverse(y) = ")), As->inverse(y)));
    const coeffs ks{1, 2, 0, 0, 0, 0, 0, 0};
    EXPECT_TRUE(near_coeffs(exp_series(*As, elem_s(result_after(r.out, "(III.3.67) log(1 + 2*u1) in W* =", "element"))), ks));
    EXPECT_TRUE(near_coeffs(exp_series(*As, elem_s(result_after(r.out, "(III.3.67) log(y) =", "element"))), y));

    // (III.4.15-18) the generating element: minimal polynomial by the general method
    const coeffs d = elem(inline_value(r.out, "(III.4.15) d = "));
    EXPECT_TRUE(same(d, {0, 2, 1, 0}));
    const ex md = parse(S, inline_value(r.out, "(III.4.15) d = ", "minpoly(d, X) = "));
    EXPECT_TRUE(same(md, A->minpoly(d, X)));
    EXPECT_TRUE(same(md, A->charpoly(d, X)));
}

namespace {
/// The components a_p + I b_p of w in (x)C^(n+1), from the definition w e_p = (a_p + i0 b_p) e_p
/// with e_p built by (III.1.15) in the table algebra: a_p and b_p are 2^n times the
/// coordinates of w e_p at 1 and at i0 (e_p has 2^-n at 1 and 0 at i0; i0 e_p the reverse).
ex multicomplex_idempotent_poly(unsigned n, std::size_t p, symbols& S) {
    ex e = 1;
    for (unsigned k = 1; k <= n; ++k) {
        const int bit = (p >> (n - k)) & 1;
        e *= 1 - (bit ? -1 : 1) * S("i0") * S("i" + std::to_string(k));
    }
    return e / GiNaC::pow(2, n);
}
}  // namespace

TEST(ExamplesMulticomplex, PrintedResultsByValue) {
    const run_result& r = run_script("multicomplex.symrep");
    ASSERT_EQ(r.status, 0) << r.err;
    symbols S;
    auto A1 = multicomplex_table(1, S);
    auto A2 = multicomplex_table(2, S);
    const auto B = basis_symbols(S, {"i0", "i1", "i2"});
    auto elem1 = [&](const std::string& text) { return A1->coords_of(parse(S, text), B); };
    auto elem2 = [&](const std::string& text) { return A2->coords_of(parse(S, text), B); };
    const GiNaC::realsymbol& X = S.sym("X");
    S("t");
    // an element given as a polynomial in i0, i1, i2, multiplied out in the table algebra
    auto from_poly = [&](const table_algebra& A, const ex& poly) {
        // poly is a sum of products of the i_k: evaluate it by the table's product
        std::function<coeffs(const ex&)> ev = [&](const ex& x) -> coeffs {
            if (GiNaC::is_a<GiNaC::add>(x)) {
                coeffs s = A.zero();
                for (const auto& op : x) s = algebra::add(s, ev(op));
                return s;
            }
            if (GiNaC::is_a<GiNaC::mul>(x)) {
                coeffs m = A.unit();
                for (const auto& op : x) m = A.multiply(m, ev(op));
                return m;
            }
            if (GiNaC::is_a<GiNaC::power>(x)) {
                coeffs m = A.unit();
                const coeffs b = ev(x.op(0));
                for (long k = 0; k < ex_to<numeric>(x.op(1)).to_long(); ++k) m = A.multiply(m, b);
                return m;
            }
            for (std::size_t k = 0; k < A.dim(); ++k)
                if (A.monomial(k).is_equal(x)) return algebra::scale(1, A.basis_vector(k));
            return algebra::scale(x, A.unit());  // a scalar
        };
        return ev(GiNaC::expand(poly));
    };
    auto components = [&](const table_algebra& A, unsigned n, const coeffs& w) {
        std::vector<ex> c;
        const std::size_t i0 = std::size_t(1) << n;  // i0 = e_(2^n)
        for (std::size_t p = 0; p < (std::size_t(1) << n); ++p) {
            const coeffs we = A.multiply(w, from_poly(A, multicomplex_idempotent_poly(n, p, S)));
            c.push_back(GiNaC::pow(2, n) * (we[0] + GiNaC::I * we[i0]));
        }
        return c;
    };

    // (III.1.15) the idempotents of multicomplex(2), against the product formula
    const auto e = split_list(result_after(r.out, "(III.1.15) e_0 .. e_3 in multicomplex(2) =", "list"));
    ASSERT_EQ(e.size(), 4u);
    for (std::size_t p = 0; p < 4; ++p)
        EXPECT_TRUE(same(elem2(e[p]), from_poly(*A2, multicomplex_idempotent_poly(2, p, S)))) << p;

    // (III.1.39) the components of w, from w e_p = (a_p + i0 b_p) e_p
    const coeffs w{S("x0"), S("x1"), S("x2"), S("x3")};
    EXPECT_TRUE(same(elem1(inline_value(r.out, "w = ")), w));
    const auto c = parse_list(S, result_after(r.out, "(III.1.39) components a_p + I*b_p =", "list"));
    const auto cw = components(*A1, 1, w);
    ASSERT_EQ(c.size(), 2u);
    for (std::size_t p = 0; p < 2; ++p) EXPECT_TRUE(same(c[p], cw[p])) << p;

    // (III.1.59) charpoly by the general method
    EXPECT_TRUE(same(parse(S, result_after(r.out, "(III.1.59) charpoly(w, X) =", "expression")), A1->charpoly(w, X)));

    // corrected minimal polynomials (III.1.59-60), by the Krylov method of the table algebra
    const coeffs one_i0 = from_poly(*A1, 1 + S("i0"));
    const ex m1 = parse(S, inline_value(r.out, "(III.1.59 corrected) minpoly(1 + i0, X) = "));
    EXPECT_TRUE(same(m1, A1->minpoly(one_i0, X)));
    EXPECT_TRUE(same(m1, X * X - 2 * X + 2));
    const coeffs z = from_poly(*A1, 1 + S("i0") * S("i1"));
    const ex mz = parse(S, inline_value(r.out, "(III.1.60 corrected) minpoly(z, X) = "));
    EXPECT_TRUE(same(mz, A1->minpoly(z, X)));
    EXPECT_TRUE(same(mz.subs(X == 0), 0));  // the extra factor X
    const coeffs zz = elem2(inline_value(r.out, "zz = "));
    const auto czz = components(*A2, 2, zz);
    EXPECT_TRUE(same(czz[0], 0));
    EXPECT_TRUE(same(czz[1], 1 + GiNaC::I));
    EXPECT_TRUE(same(czz[2], 2));
    EXPECT_TRUE(same(czz[3], 3 * GiNaC::I));
    const ex mzz = parse(S, result_after(r.out, "minpoly(zz, X) =", "expression"));
    EXPECT_TRUE(same(mzz, A2->minpoly(zz, X)));
    EXPECT_EQ(GiNaC::expand(mzz).degree(X), 6);

    // (III.1.57) inverse of y, and y's components
    const coeffs y = elem2(inline_value(r.out, "y = "));
    const auto cy = components(*A2, 2, y);
    const auto cyp = parse_list(S, inline_value(r.out, "y = ", "components: "));
    ASSERT_EQ(cyp.size(), 4u);
    for (std::size_t p = 0; p < 4; ++p) EXPECT_TRUE(same(cyp[p], cy[p])) << p;
    EXPECT_TRUE(same(elem2(result_after(r.out, "(III.1.57) inverse(y) =", "element")), A2->inverse(y)));

    // (III.1.52) exp(w t) against the Taylor series at rational values
    const ex E = parse(S, result_after(r.out, "(III.1.52) exp(w t) =", "element"));
    const GiNaC::exmap at{{S("x0"), numeric(1, 3)}, {S("x1"), numeric(-2, 5)}, {S("x2"), numeric(3, 4)},
                          {S("x3"), numeric(5, 4)}, {S("t"), numeric(6, 5)}};
    EXPECT_TRUE(near_coeffs(subs_all(A1->coords_of(E, B), at),
                            exp_series(*A1, algebra::scale(numeric(6, 5), subs_all(w, at)))));

    // (III.1.53) log(y): exp of it gives back y; (III.1.72) rho exp(theta) = y
    EXPECT_TRUE(near_coeffs(exp_series(*A2, elem2(result_after(r.out, "(III.1.53) log(y) =", "element"))), y));
    const auto se = split_list(result_after(r.out, "(III.1.72) semiexponential(y) = [rho, theta] =", "list"));
    ASSERT_EQ(se.size(), 2u);
    EXPECT_TRUE(near_coeffs(A2->multiply(elem2(se[0]), exp_series(*A2, elem2(se[1]))), y));

    // Thm III.1.3.1: the decomposition sums to y and each term has components of one modulus
    const auto parts = split_list(result_after(r.out, "(III.1.91) special_type_decomposition(y) =", "list"));
    ASSERT_GE(parts.size(), 1u);
    ASSERT_LE(parts.size(), 4u);
    coeffs sum = A2->zero();
    for (const auto& part : parts) {
        const coeffs d = elem2(part);
        sum = algebra::add(sum, d);
        const auto cd = components(*A2, 2, d);
        for (std::size_t p = 1; p < 4; ++p)
            EXPECT_TRUE(same(GiNaC::abs(cd[p]), GiNaC::abs(cd[0]))) << part;
        EXPECT_FALSE(same(cd[0], 0)) << part;
    }
    EXPECT_TRUE(same(sum, y));

    // (III.4.5-9) the generating element's minimal polynomial equals its characteristic one
    const coeffs g = elem2(inline_value(r.out, "(III.4.5) d = "));
    const ex mg = parse(S, inline_value(r.out, "(III.4.5) d = ", "minpoly(d, X) = "));
    EXPECT_TRUE(same(mg, A2->minpoly(g, X)));
    EXPECT_TRUE(same(mg, A2->charpoly(g, X)));
}

// The one result walsh.symrep states without running it (an error would make the script
// exit 1): log in W of an element with a negative root fails, names the root and points to
// W*, where the same element has a logarithm.
TEST(ExamplesWalsh, LogWithANegativeRootPointsToWStar) {
    const std::string err_path = ::testing::TempDir() + "/symrep_examples_" +
                                 std::to_string(getpid()) + "_neglog_err.txt";
    const std::string cmd = std::string("'") + SYMREP_BINARY +
                            "' --format json -e 'log(element(walsh(2), [1, 2, 0, 0]))'"
                            " -e 'log(element(walsh_complex(2), [1, 2, 0, 0, 0, 0, 0, 0]))'"
                            " 2>'" + err_path + "' </dev/null";
    std::string out;
    FILE* p = popen(cmd.c_str(), "r");
    ASSERT_NE(p, nullptr);
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    const int st = pclose(p);
    const std::string err = slurp(err_path);
    std::remove(err_path.c_str());
    EXPECT_EQ(WIFEXITED(st) ? WEXITSTATUS(st) : -1, 1);
    // the error: one JSON line on stderr
    const auto errs = lines_of(err);
    ASSERT_EQ(errs.size(), 1u) << err;
    std::string message;
    ASSERT_TRUE(json_string_field(errs[0], "error", message)) << err;
    EXPECT_NE(message.find("a_1 = -1"), std::string::npos) << message;
    EXPECT_NE(message.find("walsh_complex(2)"), std::string::npos) << message;
    // the logarithm in W*, by value: exp of it (Taylor series) is 1 + 2 u1
    symbols S;
    auto As = walsh_table(2, true, S);
    const auto B = basis_symbols(S, {"u0", "u1", "i0"});
    const auto ls = lines_of(out);
    ASSERT_EQ(ls.size(), 1u) << out;
    std::string kind, value;
    ASSERT_TRUE(json_string_field(ls[0], "kind", kind) && json_string_field(ls[0], "value", value)) << ls[0];
    EXPECT_EQ(kind, "element");
    EXPECT_TRUE(near_coeffs(exp_series(*As, As->coords_of(parse(S, value), B)), {1, 2, 0, 0, 0, 0, 0, 0}));
}

namespace {
/// R[X]/(p) with the cyclic basis 1, v, ..., v^(n-1): v^i v^j = rem(X^(i+j), p).
table_ptr polynomial_table(const ex& p, const GiNaC::realsymbol& X, symbols& S) {
    const int n = GiNaC::expand(p).degree(X);
    std::vector<std::vector<coeffs>> g(n, std::vector<coeffs>(n));
    std::vector<ex> mono(n);
    for (int i = 0; i < n; ++i) {
        mono[i] = GiNaC::pow(S("v"), i);
        for (int j = 0; j < n; ++j) {
            const ex r = GiNaC::rem(GiNaC::pow(X, i + j), GiNaC::expand(p), X);
            g[i][j] = coeffs(n);
            for (int k = 0; k < n; ++k) g[i][j][k] = GiNaC::expand(r).coeff(X, k);
        }
    }
    return std::make_shared<table_algebra>("polynomial_table", g, mono);
}

/// A table given as nested integer lists, with basis symbols `names` (the empty name: 1).
table_ptr integer_table(const std::vector<std::vector<std::vector<int>>>& G,
                        const std::vector<std::string>& names, symbols& S, coeffs unit = {}) {
    std::vector<std::vector<coeffs>> g;
    for (const auto& row : G) {
        g.emplace_back();
        for (const auto& cell : row) g.back().push_back(coeffs(cell.begin(), cell.end()));
    }
    std::vector<ex> mono;
    for (const auto& n : names) mono.push_back(n.empty() ? ex(1) : S(n));
    return std::make_shared<table_algebra>("integer_table", g, mono, std::move(unit));
}
}  // namespace

TEST(ExamplesAlgebras, PrintedResultsByValue) {
    const run_result& r = run_script("algebras.symrep");
    ASSERT_EQ(r.status, 0) << r.err;
    symbols S;
    const GiNaC::realsymbol& X = S.sym("X");
    const ex t = S("t");
    // R + R[eps]/(eps^2), the table of the script written out again
    auto A = integer_table({{{1, 0, 0}, {0, 0, 0}, {0, 0, 0}},
                            {{0, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                            {{0, 0, 0}, {0, 0, 1}, {0, 0, 0}}},
                           {"e0", "e1", "e2"}, S, {1, 1, 0});
    const auto BA = basis_symbols(S, {"e0", "e1", "e2"});
    auto elem = [&](const std::string& text) { return A->coords_of(parse(S, text), BA); };
    // the unit is e0 + e1, not e_0
    const coeffs one = A->unit();
    EXPECT_TRUE(same(A->multiply(one, {S("x"), S("y"), S("z")}), {S("x"), S("y"), S("z")}));
    EXPECT_TRUE(same(elem(inline_value(r.out, "A = ", "one(A) = ")), one));

    // (II.1.3-4) canonical matrix and (II.1.20) charpoly by the general methods
    const coeffs w{S("x"), S("y"), S("z")};
    const auto M = parse_matrix(S, result_after(r.out, "(II.1.3) [w] =", "expression"));
    const GiNaC::matrix Mw = A->canonical_matrix(w);
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned k = 0; k < 3; ++k) EXPECT_TRUE(same(M[i][k], Mw(i, k)));
    EXPECT_TRUE(same(parse(S, result_after(r.out, "(II.1.20) charpoly(w, X) =", "expression")), A->charpoly(w, X)));
    EXPECT_TRUE(same(parse(S, inline_value(r.out, "(II.1.21) det [w] = ")), A->determinant(w)));

    // the inverse by the general method (the linear system v u = 1, with the true unit)
    const coeffs v = elem(inline_value(r.out, "v = "));
    EXPECT_TRUE(same(elem(result_after(r.out, "inverse(v) =", "element")), A->inverse(v)));

    // Thm III.4.1: the generator has a minimal polynomial of degree 3 (Krylov, with the true unit)
    const coeffs d = elem(inline_value(r.out, "(Thm III.4.1) d = "));
    const coeffs d2 = A->multiply(d, d);
    const ex md = parse(S, inline_value(r.out, "(Thm III.4.1) d = ", "minpoly(d, X) = "));
    EXPECT_TRUE(same(md, A->minpoly(d, X)));
    EXPECT_EQ(GiNaC::expand(md).degree(X), 3);

    // exp(d t), the fundamental system and the power-basis change (III.4.4)
    const GiNaC::exmap at{{t, numeric(4, 5)}};
    const coeffs expected = exp_series(*A, algebra::scale(numeric(4, 5), d));
    EXPECT_TRUE(near_coeffs(subs_all(elem(result_after(r.out, "(Thm II.2.3) exp(d t) =", "element")), at), expected));
    const auto F = parse_list(S, result_after(r.out, "(Thm II.2.3) fundamental_system(d, t) =", "list"));
    EXPECT_TRUE(near_coeffs(subs_all(coeffs(F.begin(), F.end()), at), expected));
    const auto P = parse_matrix(S, result_after(r.out, "(III.4.4) power_basis_change(A, d) =", "expression"));
    ASSERT_EQ(P.size(), 3u);
    const coeffs* powers[3] = {&one, &d, &d2};
    for (unsigned k = 0; k < 3; ++k) EXPECT_TRUE(same(coeffs(P[k].begin(), P[k].end()), *powers[k])) << k;

    // log(v): exp of it gives back v
    EXPECT_TRUE(near_coeffs(exp_series(*A, elem(result_after(r.out, "log(v) =", "element"))), v));

    // the non-polynomial algebra N: the generic minimal polynomial, by Krylov on its table
    auto N = integer_table({{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                            {{0, 1, 0}, {0, 0, 0}, {0, 0, 0}},
                            {{0, 0, 1}, {0, 0, 0}, {0, 0, 0}}},
                           {"", "x", "y"}, S);
    EXPECT_TRUE(same(parse(S, inline_value(r.out, "N polynomial: ", "minpoly(a + b*x + c*y, X) = ")),
                     N->minpoly({S("a"), S("b"), S("c")}, X)));

    // the Frobenius matrix of P3 = the canonical matrix of v in R[X]/(p), by polynomial remainders
    const ex p = GiNaC::pow(X, 3) + S("a1") * GiNaC::pow(X, 2) + S("a2") * X + S("a3");
    auto P3 = polynomial_table(p, X, S);
    const auto Fr = parse_matrix(S, result_after(r.out, "frobenius_matrix(P3) =", "expression"));
    const GiNaC::matrix Mv = P3->canonical_matrix({0, 1, 0});
    ASSERT_EQ(Fr.size(), 3u);
    for (unsigned i = 0; i < 3; ++i)
        for (unsigned k = 0; k < 3; ++k) EXPECT_TRUE(same(Fr[i][k], Mv(i, k))) << i << "," << k;

    // the fundamental system of d = 2v in R[X]/(X^3 - 3X + 2), its characteristic polynomial,
    // and the Euler-type formulas (II.2), numerically against the Taylor series
    auto Q = polynomial_table(GiNaC::pow(X, 3) - 3 * X + 2, X, S);
    const coeffs dq{0, 2, 0};
    EXPECT_TRUE(same(parse(S, inline_value(r.out, "d = 2v in R[X]/(X^3 - 3X + 2):", "charpoly(d, X) = ")),
                     Q->charpoly(dq, X)));
    const auto Fq = parse_list(S, result_after(r.out, "fundamental_system(d, t) =", "list"));
    EXPECT_TRUE(near_coeffs(subs_all(coeffs(Fq.begin(), Fq.end()), at),
                            exp_series(*Q, algebra::scale(numeric(4, 5), dq))));
    const auto Bv = basis_symbols(S, {"v"});
    auto C = polynomial_table(GiNaC::pow(X, 2) + 1, X, S);
    const ex Ei = parse(S, inline_value(r.out, "(II.2) d^2 = -1: exp(d t) = "));
    EXPECT_TRUE(near_coeffs(subs_all(C->coords_of(Ei, Bv), at), exp_series(*C, {0, numeric(-4, 5)})));
    auto D3 = polynomial_table(GiNaC::pow(X, 3), X, S);
    const ex En = parse(S, inline_value(r.out, "(II.2) d^3 = 0: exp(d t) = "));
    EXPECT_TRUE(near_coeffs(subs_all(D3->coords_of(En, Bv), at), exp_series(*D3, {0, numeric(8, 5), 0})));
}

// The table of an algebra is validated: a non-commutative table is refused, naming the pair.
TEST(ExamplesAlgebras, InvalidTableIsNamed) {
    const std::string err_path = ::testing::TempDir() + "/symrep_examples_" +
                                 std::to_string(getpid()) + "_table_err.txt";
    const std::string cmd = std::string("'") + SYMREP_BINARY +
                            "' --format json -e 'algebra_from_table([[[1, 0], [0, 1]], [[0, 0], [1, 0]]])'"
                            " 2>'" + err_path + "' </dev/null >/dev/null";
    const int st = std::system(cmd.c_str());
    const std::string err = slurp(err_path);
    std::remove(err_path.c_str());
    EXPECT_EQ(WIFEXITED(st) ? WEXITSTATUS(st) : -1, 1);
    const auto errs = lines_of(err);
    ASSERT_EQ(errs.size(), 1u) << err;
    std::string message;
    ASSERT_TRUE(json_string_field(errs[0], "error", message)) << err;
    EXPECT_NE(message.find("commutative"), std::string::npos) << message;
}

// ---------------------------------------------------------------------------------
// the remarks of Chapter VI (examples/remarks.symrep, issue 29 item 11): each printed value
// against an independent computation here (formulas worked by hand, a classical RK4)

namespace {
double to_double(const ex& e) { return ex_to<numeric>(GiNaC::evalf(e)).to_double(); }

/// v' = (q/m) v x B(t), B = [sin t, cos 2t, 1/2], by classical RK4 (step h: error O(h^4)).
std::vector<double> larmor_rk4(double qm, std::vector<double> v, double T, int n) {
    auto f = [qm](double t, const std::vector<double>& y) {
        const double B[3] = {std::sin(t), std::cos(2 * t), 0.5};
        return std::vector<double>{qm * (y[1] * B[2] - y[2] * B[1]), qm * (y[2] * B[0] - y[0] * B[2]),
                                   qm * (y[0] * B[1] - y[1] * B[0])};
    };
    auto axpy = [](const std::vector<double>& y, const std::vector<double>& k, double c) {
        return std::vector<double>{y[0] + c * k[0], y[1] + c * k[1], y[2] + c * k[2]};
    };
    const double h = T / n;
    double t = 0;
    for (int i = 0; i < n; ++i, t += h) {
        const auto k1 = f(t, v), k2 = f(t + h / 2, axpy(v, k1, h / 2)), k3 = f(t + h / 2, axpy(v, k2, h / 2)),
                   k4 = f(t + h, axpy(v, k3, h));
        for (int c = 0; c < 3; ++c) v[c] += h / 6 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
    }
    return v;
}
}  // namespace

TEST(ExamplesRemarks, PrintedResultsByValue) {
    const run_result& r = run_script("remarks.symrep");
    ASSERT_EQ(r.status, 0) << r.err;
    symbols S;
    const ex t = S("t"), R = S("R"), a = S("a"), b = S("b"), X = S("X");

    // (VI.1.63 remarks) q = 1, m = 2, B = [0, 0, 2], E = [1, 0, 3], v0 = [1, 2, -1]:
    // centre E x B/|B|^2 = [0, -1/2, 0]; radius |v0_perp - centre| = |[1, 5/2, 0]|;
    // pitch = (q/m) (E . B)/|B| times the period 2 pi m/(q |B|) = 2 pi 6/4
    EXPECT_TRUE(same(parse_list(S, result_after(r.out, "centre of the helix (E x B/|B|^2) =", "expression")),
                     {0, numeric(-1, 2), 0}));
    EXPECT_TRUE(same(parse(S, result_after(r.out, "radius^2 =", "expression")), numeric(29, 4)));
    EXPECT_TRUE(same(parse(S, result_after(r.out, "pitch (advance of v . B/|B| over one period) =", "expression")),
                     3 * GiNaC::Pi));

    // (VI.2.47-49) B = (2 + sin t) b u, u = e3: v0 turned by -alpha about e3,
    // alpha = (q/m) b int_0^t (2 + sin) = (3/2)(1/2)(3 + 1 - cos(3/2)); tolerance 1e-14 (double output)
    const auto vl = parse_list(S, result_after(
        r.out, "at q = 3, m = 2, b = 1/2, u = [0, 0, 1], v0 = [1, 2, -1], t = 3/2: v =", "list"));
    ASSERT_EQ(vl.size(), 3u);
    const double al = 0.75 * (4 - std::cos(1.5));
    EXPECT_NEAR(to_double(vl[0]), std::cos(al) + 2 * std::sin(al), 1e-14);
    EXPECT_NEAR(to_double(vl[1]), -std::sin(al) + 2 * std::cos(al), 1e-14);
    EXPECT_NEAR(to_double(vl[2]), -1.0, 1e-15);

    // (VI.3.162) the turning field: RK4 with 6000 steps on [0, 3/2] (error ~1e-13); tolerance 1e-10
    const auto vt = parse_list(S, result_after(r.out, "at q = 3, m = 2, v0 = [1, 2, -1], t = 3/2: v =", "list"));
    ASSERT_EQ(vt.size(), 3u);
    const auto ref = larmor_rk4(1.5, {1, 2, -1}, 1.5, 6000);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(to_double(vt[c]), ref[c], 1e-10) << c;

    // (VI.3.236) r = F_(-a e1)(R [cos bt, sin bt, 0]): the rotation by -a t about e1, worked by hand
    const auto rd = parse_list(S, result_after(r.out, "(VI.3.236) r =", "expression"));
    EXPECT_TRUE(same(rd, {R * GiNaC::cos(b * t), R * GiNaC::sin(b * t) * GiNaC::cos(a * t),
                         -R * GiNaC::sin(b * t) * GiNaC::sin(a * t)}));
    // X^2 - 2 printed irreducible over Q: no linear factor
    const ex fx = parse(S, result_after(r.out, "a/b = 1/sqrt(2): (b/a)^2 = 2, and X^2 - 2 has no rational root:",
                                        "expression"));
    EXPECT_TRUE(same(fx, GiNaC::pow(X, 2) - 2));

    // (Thm V.3.4) the transform of the weighting function over sobrero(2) at d = s0 + eps, s0 = 2 + 5 j:
    // sum_k eps^k H^(k)(s0)/k! (V.3.46), H = (s + 3)/(s^2 + 2 s + 5), j read as the imaginary unit
    const ex eps = S("eps"), j = S("j");
    const ex HS = parse(S, result_after(r.out, "h = L^-1[(s + 3)/(s^2 + 2 s + 5)] is the transmittance H(d) =",
                                        "element"));
    const GiNaC::symbol sv("s");
    const ex H = (sv + 3) / (sv * sv + 2 * sv + 5);
    ex expected = 0;
    for (int k = 0; k <= 2; ++k) {
        const ex c = GiNaC::expand(GiNaC::normal(H.diff(sv, k).subs(sv == 2 + 5 * GiNaC::I) / GiNaC::factorial(k)));
        expected += GiNaC::pow(eps, k) * (GiNaC::real_part(c) + j * GiNaC::imag_part(c));
    }
    EXPECT_TRUE(same(GiNaC::expand(HS), GiNaC::expand(expected)));
}

// examples/two_body.symrep: the modified energy T + V (VI.3.248, 252) of the two bodies, printed at
// t = 0 and at t = 5 (on the states from the decoupled reductions), against the value computed here
// from the initial data with w(0) = [0, 0.2, 0.5], m1 = 1, m2 = 1/2, G = 1. Tolerance 1e-11 relative:
// the t = 5 states carry the reductions' ~1e-13 (Magnus, universal variables).
TEST(ExamplesTwoBody, PrintedResultsByValue) {
    const run_result& r = run_script("two_body.symrep");
    ASSERT_EQ(r.status, 0) << r.err;
    std::string v = result_after(
        r.out, "T + V at t = 0 and at t = 5 on the bodies' states (x_i, v_i = x_i') from the decoupled solutions", "list");
    for (char& c : v)
        if (c == '[' || c == ']' || c == ',') c = ' ';
    std::istringstream in(v);
    double a = 0, b = 0;
    ASSERT_TRUE(in >> a >> b) << v;
    const Eigen::Vector3d w0(0, 0.2, 0.5), x1(1, 0, 0), x2(-0.5, 0.2, 0), v1(0, 0.2, 0.05), v2(0.1, -0.2, 0);
    const double m1 = 1, m2 = 0.5;
    const double T = m1 / 2 * (v1 + w0.cross(x1)).squaredNorm() + m2 / 2 * (v2 + w0.cross(x2)).squaredNorm();
    const double E = T - m1 * m2 / (x1 - x2).norm();
    EXPECT_NEAR(a, E, 1e-14 * std::abs(E));
    EXPECT_NEAR(b, E, 1e-11 * std::abs(E));
}

// examples/transforms.symrep, the Ch. V theory part (issue 29 item 5): the printed values against
// independent ones (mpmath's quadrature at 30 digits for the ramp; exact forms otherwise).
TEST(ExamplesTransforms, TheoryResultsByValue) {
    const run_result& r = run_script("transforms.symrep");
    ASSERT_EQ(r.status, 0) << r.err;
    symbols S;
    S("t");
    S("eps");
    S.table["I"] = GiNaC::I;
    const GiNaC::realsymbol& eps = S.sym("eps");
    // T delta'' = d^2 at d = 2 + eps
    EXPECT_TRUE(same(parse(S, result_after(r.out, "T dirac(t, 2) over sobrero(2) at 2 + eps =", "element")),
                     GiNaC::pow(2 + eps, 2).expand()));
    // the windowed ramp's components F(4 i), F(2 i) (tolerance: the reference's digits)
    const auto W = split_list(result_after(r.out, "a windowed ramp 3 (1 - t/2) step(2 - t), exact: components F(4 i), F(2 i) =", "list"));
    ASSERT_EQ(W.size(), 2u);
    const ex w0 = GiNaC::evalf(parse(S, W[0])), w1 = GiNaC::evalf(parse(S, W[1]));
    EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(GiNaC::real_part(w0)).to_double(), 0.107390628169557518050, 1e-14);
    EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(GiNaC::imag_part(w0)).to_double(), -0.657247664379057958330, 1e-14);
    EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(GiNaC::real_part(w1)).to_double(), 0.620116357823854467990, 1e-14);
    EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(GiNaC::imag_part(w1)).to_double(), -1.78380093574047309426, 1e-14);
    // the Gaussian on the line: sqrt(pi)/2 (e^(-(W - 3)^2/4) + e^(-(W + 3)^2/4)) at W = 4, 2
    const auto G = split_list(result_after(r.out, "two-sided exp(-t^2) cos 3t, exact (Gaussian integral): components "
                                                  "sqrt(pi)/2 (e^(-(W-3)^2/4) + e^(-(W+3)^2/4)) =", "list"));
    ASSERT_EQ(G.size(), 2u);
    EXPECT_TRUE(same(parse(S, G[0]), GiNaC::sqrt(GiNaC::Pi) / 2 * (GiNaC::exp(ex(-1) / 4) + GiNaC::exp(ex(-49) / 4))));
    EXPECT_TRUE(same(parse(S, G[1]), GiNaC::sqrt(GiNaC::Pi) / 2 * (GiNaC::exp(ex(-1) / 4) + GiNaC::exp(ex(-25) / 4))));
    // Parseval: int_0^oo t e^(-t) e^(-t) sin 2t dt = Im 1/(2 - 2i)^2 = 1/8 on both sides
    const auto P = split_list(result_after(r.out, "(Thm V.2.4, V.2.44-49) Parseval over multicomplex(1): [<f, g>, (1/2 pi "
                                                  "i0) int_A T f (T g)^* dd, quadrature, report] =", "list"));
    ASSERT_EQ(P.size(), 4u);
    EXPECT_TRUE(same(parse(S, P[0]), ex(1) / 8));
    EXPECT_TRUE(same(parse(S, P[1]), ex(1) / 8));
    // the inversions give the signals back
    const GiNaC::realsymbol& t = S.sym("t");
    EXPECT_TRUE(same(parse(S, result_after(r.out, "(Thm V.2.3) the algebra-valued inversion: the components of T(d), "
                                                  "d = u i0 + v i1, give back f =", "expression")),
                     GiNaC::exp(-t) * GiNaC::cos(2 * t)));
    EXPECT_TRUE(same(parse(S, result_after(r.out, "(Thm V.3.3) over sobrero(2), d = x + eps:", "expression")),
                     t * GiNaC::exp(-t) * GiNaC::sin(t)));
}

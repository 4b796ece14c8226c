"""A Pygments lexer for the symrep language (docs/language.md, engine/syntax/lexer.cpp).

Used by the docs site (docs/conf.py loads this file by its path, so it works without the
compiled module), by nbconvert and by Jupyter (the kernel's pygments_lexer "symrep"; the
package registers it as the entry point pygments.lexers: symrep = symrep.lexer:SymrepLexer).

    >>> from pygments import highlight
    >>> from pygments.formatters import HtmlFormatter
    >>> from symrep.lexer import SymrepLexer
    >>> html = highlight('w := element(multicomplex(0), [1, 2])', SymrepLexer(), HtmlFormatter())

The tokens follow the language's own lexer: comments (# to the end of the line), strings
("..." with \\n, \\t, \\", \\\\), exact and decimal numbers (3, 3/4 is 3 / 4, 0.5, 1e-3),
names with primes (r', r'': derivatives), previous results (%, %%, %3), the declarations
`vector w, r0` and `positive w0` (the declared names are variables), assignments `name :=`,
the constants (pi, I, Euler, Catalan, true, false), the builtins (BUILTINS, the registry's
names: tests/python/test_docs_site.py checks that the list equals the registry), and the
operators, among them the cross product `x` (the name x after an operand, as the parser reads
it) and the scalar product `.`, their Unicode forms, the prime ' and the comparisons. A
character the language does not have (`$`, `{`, `@`, a non-ASCII letter, an unterminated
string) is an Error token, as the language's lexer makes it an error.
"""

from pygments.lexer import RegexLexer, bygroups, default, words
from pygments.token import (Comment, Error, Keyword, Name, Number, Operator, Punctuation, String,
                            Text, Whitespace)

__all__ = ["SymrepLexer", "BUILTINS", "CONSTANTS"]

# The builtin names of the registry (lang/builtins*.cpp), sorted. When a builtin is added:
#   PYTHONPATH=build/python python3 -m symrep.lexer
# prints the current list (tests/python/test_docs_site.py fails until it is pasted here).
BUILTINS = (
    "F", "F_adjoint", "abs", "acos", "algebra_from_table", "algebra_of", "amplitude_modulated",
    "annihilator", "append", "asin", "atan", "atan2", "basis", "binomial", "block_pulse_matrix",
    "bounded", "canonical_matrix", "ccode", "charpoly", "check", "clohessy_wiltshire", "coeff",
    "collect", "components", "conjugate", "coords", "cos", "cosh", "cross", "degree", "denom",
    "det", "diff", "digits", "dim", "dirac", "dot", "dq_apply", "dq_conjugate", "dq_motion",
    "dq_product", "dual", "dual_part", "dual_quaternion", "element", "energy", "eval", "evalf",
    "evaluate", "exp", "expand", "expect", "expect_near", "factor", "factorial", "find_generator",
    "first_integrals", "fourier_inversion", "frequency_response", "frobenius_matrix",
    "from_components", "fundamental_system", "generalized_potentials", "generating_element", "gray",
    "gray_basis", "help", "hodograph", "hypercomplex_conjugate", "idempotent", "idempotents",
    "identify", "identify_points", "imag_part", "imag_unit", "inner_product", "inverse",
    "inverse_laplace", "inverse_transform", "is_polynomial", "is_special_type", "is_zero_divisor",
    "laplace", "latex", "ldegree", "length", "lhs", "load", "load_rules", "log", "matrix",
    "minpoly", "model", "modulation", "monogenic", "motion_apply", "moving_frame", "multicomplex",
    "norm", "normal", "notation", "numer", "ode", "one", "operational_matrix", "parseval", "planar",
    "plot", "polynomial_algebra", "pose_dual_quaternion", "power_basis_change", "primal", "print",
    "pycode", "range", "rank", "real_part", "relative_motion", "relative_pose", "represent",
    "represent_product", "represent_sequence", "response", "response_over", "rewrite", "rhs",
    "rigid_motion", "rotation_operator", "rules", "sampled_fourier", "sampling", "screw",
    "screw_parameters", "semiexponential", "seq", "sequence", "sequence_annihilator",
    "sequence_formula", "sequence_response", "series", "sigma", "sign", "signal", "simplify",
    "simulate_system", "sin", "sinh", "skew", "sobrero", "sobrero_eps", "sobrero_j",
    "sobrero_subalgebra", "solve", "special_type_decomposition", "sqrt", "step",
    "structure_constants", "subs", "sum", "tan", "tanh", "trajectory", "transform", "transmittance",
    "transpose", "triple", "tschauner_hempel", "twist_exp", "two_body", "type",
    "vector_first_integrals", "vector_series", "verify", "walsh", "walsh_blocks",
    "walsh_coefficients", "walsh_complex", "walsh_generator", "walsh_i0", "yamanaka_ankersen",
    "z_transform", "zero_divisor_ranks",
)

# The names the evaluator reads as constants (lang/evaluate.cpp) and the booleans (the parser).
CONSTANTS = ("pi", "I", "Euler", "Catalan", "true", "false")

_IDENT = r"[A-Za-z_][A-Za-z0-9_]*"
# tokens after which the name x is the cross product (the end of an operand)
_OPERAND_END = (Name, Name.Builtin, Name.Variable, Name.Constant, Keyword.Constant, Number.Integer,
                Number.Float, String.Double, Name.Variable.Magic)


class SymrepLexer(RegexLexer):
    """The symrep language (scripts *.symrep, notebook cells of the symrep kernel)."""

    name = "symrep"
    aliases = ["symrep"]
    filenames = ["*.symrep"]
    mimetypes = ["text/x-symrep"]

    tokens = {
        "root": [
            (r"[ \t\r\f]+", Whitespace),
            (r"\n", Whitespace),
            (r"\\\r?\n", Text),                    # explicit line continuation
            (r"#.*?$", Comment.Single),
            (r'"', String.Double, "string"),
            # declarations: vector w, r0, v0   positive w0   vector q(t)
            (r"(vector|positive)([ \t]+)(?=[A-Za-z_])", bygroups(Keyword.Declaration, Whitespace), "declared"),
            # assignment: name :=
            (r"(" + _IDENT + r")([ \t]*)(:=)", bygroups(Name.Variable, Whitespace, Operator)),
            (r"\d+\.\d+(?:[eE][+-]?\d+)?", Number.Float),
            (r"\d+\.(?![A-Za-z_])(?:[eE][+-]?\d+)?", Number.Float),
            (r"\.\d+(?:[eE][+-]?\d+)?", Number.Float),
            (r"\d+[eE][+-]?\d+", Number.Float),
            (r"\d+", Number.Integer),
            (r"%(?:%|\d+)?", Name.Variable.Magic),   # previous results
            (words(CONSTANTS, prefix=r"\b", suffix=r"\b(?!')"), Keyword.Constant),
            (words(BUILTINS, prefix=r"\b", suffix=r"\b(?!')"), Name.Builtin),
            (_IDENT, Name),
            (r"'+", Operator),                     # primes: r', r'' (derivatives)
            (r":=|==|!=|<=|>=|[-+*/^=<>.|]|\u00d7|\u00b7|\u22c5", Operator),
            (r"[()\[\],;]", Punctuation),
        ],
        "string": [
            (r'\\[nt"\\]', String.Escape),
            (r"\\.", String.Double),
            (r'[^"\\\n]+', String.Double),
            (r'"', String.Double, "#pop"),
            (r"\n", Error, "#pop"),                # an unterminated string
        ],
        "declared": [
            (r"[ \t]+", Whitespace),
            (_IDENT, Name.Variable),
            (r"(\()([ \t]*)(t)([ \t]*)(\))", bygroups(Punctuation, Whitespace, Name, Whitespace, Punctuation)),
            (r",", Punctuation),
            default("#pop"),
        ],
    }

    def get_tokens_unprocessed(self, text, stack=("root",)):
        # The name x after an operand (a name, a number, a string, ')' or ']', a prime) is the
        # cross product, as the parser reads it (syntax/parser.cpp); elsewhere it is a name.
        previous = None
        for index, token, value in RegexLexer.get_tokens_unprocessed(self, text, stack):
            if token is Name and value == "x" and previous is not None and (
                    previous[0] in _OPERAND_END or (previous[0] is Punctuation and previous[1] in ")]")
                    or (previous[0] is Operator and previous[1].startswith("'"))):
                token = Operator.Word
            if token not in (Whitespace, Text, Comment.Single):
                previous = (token, value)
            yield index, token, value


def _current_builtins():
    """The registry's builtin names, sorted as BUILTINS (needs the compiled module)."""
    from symrep import Session
    return tuple(sorted(Session().builtin_names()))


if __name__ == "__main__":
    import textwrap
    body = ", ".join('"%s"' % n for n in _current_builtins()) + ","
    print("BUILTINS = (\n" + textwrap.fill(body, 100, initial_indent="    ", subsequent_indent="    ",
                                           break_on_hyphens=False) + "\n)")

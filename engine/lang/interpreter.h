// symrep/lang/interpreter.h -- the evaluator of the symrep language.
//
// lang/ is the top floor: the session (interpreter.cpp: scripts, statements,
// errors, assignment), evaluation of syntax trees (evaluate.cpp), the
// operators on values (operators.cpp), the statement clock, the values
// (value.h, values.h, print_value.h) and the builtins of every module
// (builtins_*.cpp), each a thin layer over its module. It may include every
// folder of engine/ (docs/architecture.md).
//
// A session holds the variables, the real symbols (one GiNaC realsymbol per
// name), the builtin registry and the output streams. It runs scripts statement
// by statement: a statement that fails is reported on the error stream as
//     FILE:LINE:COL: error: MESSAGE
// and the run goes on with the next statement. See docs/language.md.
#pragma once

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "symrep/syntax/ast.h"
#include "symrep/lang/builtins.h"
#include "symrep/core/error.h"
#include "symrep/core/interrupt.h"
#include "symrep/lang/value.h"
#include "symrep/scalar/equality.h"
#include "symrep/vector/vector.h"

namespace symrep::rules {
class rule_set;
}

namespace symrep::lang {

/// An error raised while evaluating a statement, with the place of the construct
/// that failed. what() is the bare message; `original` is the exception first
/// thrown (a symrep::error subclass, a GiNaC std::exception, ...), so that
/// library users can rethrow it to test its type.
class script_error : public error {
public:
    script_error(const std::string& msg, source_location loc, std::exception_ptr orig = nullptr)
        : error(msg), where(std::move(loc)), original(std::move(orig)) {}
    source_location where;
    std::exception_ptr original;
};

/// How a session shows results and errors (the command-line options of symrep).
struct output_options {
    enum format_t { text, latex, json };
    /// text: the canonical printer; latex: latex_value(); json: one object per
    /// result {"file", "line", "kind", "value"} on out(), errors as
    /// {"error", "file", "line", "column"} on err(), one per line.
    format_t format = text;
    /// Print each statement's source text (prefixed "> ") before its result.
    bool echo = false;
    /// After a failed statement, run nothing more (every later run_string/run_file returns at once).
    bool stop_on_error = false;
    /// Follow each text error report with its source line and a caret under the column.
    bool caret = false;
    /// Expression statements write their value to out(); off, they are only recorded in
    /// results() and passed to the result observer (front-ends that show them themselves).
    bool print_results = true;
    /// Seconds a statement may run (0: no limit); checked at every evaluation step
    /// of the language, so one long library call is not cut short.
    double time_limit = 0;
    /// The longest statement (bytes) the stream reader takes; a longer one is
    /// reported ("statement longer than ... bytes") and skipped to its end.
    std::size_t max_statement = std::size_t(16) << 20;
};

class session : public context {
public:
    /// A session writing results to `out` and error reports to `err`; all
    /// builtins of register_all_builtins are registered.
    explicit session(std::ostream& out, std::ostream& err);
    /// A session writing to std::cout / std::cerr.
    session();
    ~session() override;

    // --- context -------------------------------------------------------------
    GiNaC::ex symbol(const std::string& name) override;
    std::ostream& out() override { return *out_; }
    std::ostream& err() { return *err_; }

    // --- running scripts -----------------------------------------------------
    /// Runs the statements of `text`; `name` is the FILE shown in error reports
    /// ("<stdin>", "<command line>", a path). Expression statements print their
    /// value to out(). Returns how many statements failed (including failures in
    /// files it load()s).
    int run_string(const std::string& text, const std::string& name);
    /// Runs a script file (relative paths: relative to the folder of the script
    /// being run, else to the base directory). An unreadable file counts as one
    /// failure, reported as "FILE:1:1: error: cannot open ..." (a directory too).
    int run_file(const std::string& path);
    /// Reads `in` statement by statement (a statement ends at the end of a line
    /// where no bracket is open, see syntax/lexer.h) and runs each as soon as it
    /// ends, flushing out() after it: a program driving symrep through a pipe
    /// gets each answer at once. One statement is at most
    /// options().max_statement bytes. Returns how many statements failed.
    int run_stream(std::istream& in, const std::string& name);
    /// Evaluates the statements of `text` silently (no echo; print() still
    /// writes to out()) and returns the value of the last one. Throws
    /// script_error (syntax errors too) at the first failure.
    value evaluate(const std::string& text);
    /// Total number of failed statements since the session started.
    int failures() const { return failures_; }
    /// Output options (format, echo, stop on error, caret); default: plain text.
    output_options& options() { return opts_; }
    const output_options& options() const { return opts_; }
    /// True once a statement failed with options().stop_on_error set.
    bool stopped() const { return stopped_; }

    // --- for front-ends (the Python module, the Jupyter kernel) ----------------
    /// One error report, as written to err(): the bare message, its place and the source line
    /// it points into (empty when unknown).
    struct reported_error {
        std::string message;
        source_location where;
        std::string source_line;
        std::exception_ptr original;  ///< the exception reported (its type: the Python class), or null
    };
    /// Every error reported so far, in order (errors().size() == failures()).
    const std::vector<reported_error>& errors() const { return errors_; }
    /// Every file a builtin wrote so far (plot, trajectory, hodograph), full paths, in order.
    const std::vector<std::string>& files_written() const { return files_written_; }
    void report_fields(const std::string& from, const std::string& prose, const std::string& fields) override;
    void wrote_file(const std::string& path) override {
        files_written_.push_back(path);
        if (on_file_) on_file_(path);
    }
    /// Observers for front-ends that show a cell's output in order (the Jupyter kernel):
    /// called with each printed result (before it is written to out()), each error report
    /// and each file written. Empty functions: none.
    void observe(std::function<void(const value&)> on_result, std::function<void(const reported_error&)> on_error,
                 std::function<void(const std::string&)> on_file) {
        on_result_ = std::move(on_result);
        on_error_ = std::move(on_error);
        on_file_ = std::move(on_file);
    }
    /// Lets a session stopped by options().stop_on_error run again (a front-end that stops
    /// each cell at its first error).
    void resume() { stopped_ = false; }

    // --- previous results ------------------------------------------------------
    /// The values printed by expression statements so far, in order: results()[k-1]
    /// is %k in the language; % is the last one, %% the one before. Every printed
    /// value counts (scripts and the interactive prompt alike); assignments,
    /// declarations and statements without a value do not.
    const std::vector<value>& results() const { return results_; }
    /// When on, printed results are labelled with their number: "%3 = x^2"
    /// (the interactive prompt turns this on).
    void set_result_labels(bool on) { labels_ = on; }
    /// Names of the assigned variables (sorted).
    std::vector<std::string> variable_names() const;

    // --- state ---------------------------------------------------------------
    void set(const std::string& name, value v);
    /// Removes a variable (a front-end's temporaries); false when it was not assigned.
    bool erase(const std::string& name) { return vars_.erase(name) > 0; }
    /// The variable's value, or nullptr when unassigned.
    const value* get(const std::string& name) const;
    /// The builtins; tests and embedders may add their own.
    registry& builtins() { return reg_; }
    const registry& builtins() const { return reg_; }
    /// Folder against which relative paths of load()/run_file are resolved when
    /// no script is running (default: the current working directory).
    void set_base_directory(const std::string& dir) { base_dir_ = dir; }
    /// Resolves a path given in a script: relative to the running script's folder.
    std::string resolve_path(const std::string& path) const;
    /// Depth of nested run_file/load calls (load refuses beyond 64).
    std::size_t load_depth() const { return dirs_.size(); }

    /// The session's rewrite rules: the shipped rules (rules/vector.rules, read
    /// on first use; see rules/rules.h) plus those added by load_rules().
    /// Throws syntax_error / domain_error if the shipped file cannot be read.
    symrep::rules::rule_set& rewrite_rules();

    /// Evaluates one expression node (used by builtins that take unevaluated
    /// arguments; public for tests).
    value eval(const node& n);

private:
    value eval_inner(const node& n);
    value call(const node& n);
    value iterate(const builtin& b, const node& n);
    void declare(const node& n);
    value ode_form(const node& n);
    void ode_equation(mechanics::cauchy_problem& P, const node& eq, bool vector, const source_location& at);
    void report(const source_location& where, const std::string& msg);
    void exec(const node& stmt, bool echo);

    std::ostream* out_;
    std::ostream* err_;
    registry reg_;
    std::map<std::string, value> vars_;
    std::map<std::string, GiNaC::ex> symbols_;
    std::vector<std::string> dirs_;   ///< folders of the scripts being run
    std::vector<std::string> files_;  ///< names of the scripts being run
    /// The name of the script being run ("<string>" for text run directly): the file of every
    /// source_location the session reports.
    std::string current_file() const { return files_.empty() ? "<string>" : files_.back(); }
    int statement_line_ = 0;          ///< the line of the statement being executed (reports)
    std::string base_dir_;
    int failures_ = 0;
    output_options opts_;
    bool stopped_ = false;
    long digits_at_start_;  ///< GiNaC::Digits, restored by the destructor
    symrep::notation notation_at_start_;  ///< symrep::vector_notation(), restored by the destructor
    std::map<std::string, std::string> sources_;  ///< script texts by name (for the caret)
    std::map<std::string, int> source_line_;      ///< the line number of the first line in sources_
    std::map<std::string, std::string> failed_;   ///< names whose last assignment failed: FILE:LINE
    /// After a failed assignment to `name` at `where`: its old value is dropped and a
    /// use of the name is an error naming `where`, until it is assigned again.
    void forget_failed(const std::string& name, const std::string& where);
    int run_text(const std::string& text, const std::string& name, int first_line);
    std::vector<value> results_;  ///< %1, %2, ...
    std::vector<reported_error> errors_;
    std::function<void(const value&)> on_result_;
    std::function<void(const reported_error&)> on_error_;
    std::function<void(const std::string&)> on_file_;
    std::vector<std::string> files_written_;
    std::chrono::steady_clock::time_point statement_start_;  ///< for options().time_limit
    unsigned ticks_ = 0;
    bool labels_ = false;
    std::shared_ptr<symrep::rules::rule_set> rules_;  ///< created by rewrite_rules()
};

/// Set to true (from a SIGINT handler, say) to stop the running evaluation:
/// while it is true, session::eval throws a script_error "interrupted" at the
/// next syntax node it evaluates, so the statement (and the rest of the input
/// being run) fails. Whoever sets it clears it before running new input.
/// The numeric integrator (every right-hand side evaluation) and the rewrite
/// rules (every step) check it too. A single long operation inside GiNaC/CLN
/// (one huge expand, say) is not interrupted: the flag is seen when it returns.
/// The same flag as symrep::interrupt_flag() (core/error.h).
std::atomic<bool>& interrupt_requested();

/// Line `line` (1-based) of `text`, without its line end ("" past the end).
std::string source_line(const std::string& text, int line);
/// The caret lines of an error report (--caret): the source line and a caret under `column`,
/// each indented by four blanks and ended by a newline; "" when the column is not in the line.
std::string caret_text(const std::string& line, int column);

/// Names of builtins close to `name` (small edit distance, or starting with it),
/// best first, at most `limit`: the "did you mean" suggestions.
std::vector<std::string> similar_builtin_names(const registry& r, const std::string& name, std::size_t limit = 5);

/// Registers every builtin of the engine (builtins_all.cpp).
void register_all_builtins(registry& r);

/// Markdown reference of all builtins, one section per registry section (the
/// output of `symrep --doc`, included verbatim in docs/language.md).
std::string reference_markdown(const registry& r);

/// The value arithmetic of the language, shared with builtins: op is one of
/// + - * / ^ = == != < > <= >=. Throws type_error / algebra_error.
value binary_op(const std::string& op, const value& a, const value& b);
value negate(const value& a);
/// v with every expression in the dual unit eps reduced modulo eps^2 (dual/dual.h), lists item by item.
value reduce_dual(const value& v);
/// True for a list of three expressions: the vector literal [x, y, z] where a vector is expected.
bool is_triple(const value& v);
/// The vector literal (a 3x1 matrix) of such a list.
GiNaC::ex as_literal(const value& v);
/// The vector operand of `op` on `side` ("left", "right"): an expression or a triple; type_error otherwise.
GiNaC::ex vector_operand(const std::string& op, const value& v, const char* side);
/// Language equality (==): exact for expressions (normal(a - b) == 0), elements, lists.
/// The three-valued comparison of two values (==): yes (proved equal), no
/// (proved different: different kinds or shapes, or a witness point where the
/// difference is not 0; scalar/equality.h) or unknown, with the difference
/// that could not be decided.
struct equality {
    truth result = truth::unknown;
    std::string undecided;  ///< for unknown: the difference, printed
    std::string witness;    ///< for no: where the difference is not 0 ("at x = 1/2"), may be empty
};
equality compare_values(const value& a, const value& b);
/// == as the language says it: true, false, or domain_error naming the undecided difference.
bool values_equal(const value& a, const value& b);

}  // namespace symrep::lang

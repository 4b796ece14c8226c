// tests/test_interactive.cpp -- the interactive prompt of the symrep program,
// driven through a pseudo-terminal made by tmux (skipped when tmux is missing),
// and the previous-result references % %% %N of the language.
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "lang/interpreter.h"
#include "core/interrupt.h"
#include "syntax/lexer.h"
#include "numeric/integrate.h"
#include "test_util.h"

namespace {

using symrep::lang::session;

// --- % %% %N in scripts (no terminal needed) --------------------------------------

TEST(Results, LexerReadsPercentTokens) {
    const auto t = symrep::lang::tokenize("%% + %12*%");
    ASSERT_EQ(t.size(), 6u);
    EXPECT_EQ(t[0].kind, symrep::lang::tok::result);
    EXPECT_EQ(t[0].text, "%%");
    EXPECT_EQ(t[2].text, "%12");
    EXPECT_EQ(t[2].column, 6);
    EXPECT_EQ(t[4].text, "%");
}

TEST(Results, PercentRefersToPrintedValues) {
    std::ostringstream out, err;
    session s(out, err);
    s.run_string("a := 5\n2*a\n% + 1\n%%\n%1 * %2\n", "<t>");
    EXPECT_EQ(out.str(), "10\n11\n10\n110\n");
    EXPECT_EQ(err.str(), "");
    ASSERT_EQ(s.results().size(), 4u);
}

TEST(Results, LabelsAndErrors) {
    std::ostringstream out, err;
    session s(out, err);
    s.run_string("%\n", "<t>");
    EXPECT_NE(err.str().find("<t>:1:1: error: % has no value yet"), std::string::npos) << err.str();
    s.set_result_labels(true);
    s.run_string("x^2\n%3\n%%\n", "<t>");
    EXPECT_EQ(out.str(), "%1 = x^2\n");
    EXPECT_NE(err.str().find("<t>:2:1: error: no result %3: the results so far are %1..%1"), std::string::npos)
        << err.str();
    EXPECT_NE(err.str().find("<t>:3:1: error: %% has no value yet"), std::string::npos) << err.str();
    s.run_string("%1 := 3\n", "<t>");
    EXPECT_NE(err.str().find("<t>:1:4: error: syntax error: ':=' assigns to a name only"), std::string::npos)
        << err.str();
}

// --- the interruption flag (set by Ctrl-C at the prompt) ----------------------------

TEST(Interrupt, EvaluatorAndIntegratorStop) {
    std::ostringstream out, err;
    session s(out, err);
    symrep::lang::interrupt_requested().store(true);
    s.run_string("1 + 2\n", "<t>");
    const std::string what = symrep::test::what_of([] {
        symrep::num::integrate([](double, const double* y, double* d) { d[0] = -y[0]; }, 0.0,
                               std::vector<double>{1.0}, {1.0});
    });
    symrep::lang::interrupt_requested().store(false);
    EXPECT_EQ(err.str(), "<t>:1:3: error: interrupted\n");
    EXPECT_EQ(what, "interrupted");
    s.run_string("1 + 2\n", "<t>");
    EXPECT_EQ(out.str(), "3\n");
}

// --- the interactive program in tmux ----------------------------------------------

#ifdef SYMREP_BINARY

std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string run(const std::string& cmd) {
    std::string out;
    FILE* p = popen((cmd + " 2>/dev/null").c_str(), "r");
    if (!p) return out;
    char buf[4096];
    std::size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    pclose(p);
    return out;
}

bool have_tmux() { return std::system("command -v tmux >/dev/null 2>&1") == 0; }

/// A temporary HOME folder, removed at the end.
struct temp_home {
    std::string path;
    temp_home() {
        std::string t = ::testing::TempDir() + "/symrep_home_XXXXXX";
        path = mkdtemp(t.data()) ? t : std::string();
    }
    ~temp_home() {
        std::error_code ec;
        if (!path.empty()) std::filesystem::remove_all(path, ec);
    }
};

/// symrep running in a tmux pane of its own server (unique socket file, removed at the end).
class terminal {
public:
    explicit terminal(const std::string& home, const std::string& cwd = ".",
                      const std::string& env = "NO_COLOR=1 TERM=xterm", const std::string& args = "") {
        static int counter = 0;
        socket_ = ::testing::TempDir() + "/symrep_tmux_" + std::to_string(getpid()) + "_" + std::to_string(counter++);
        const std::string cmd = "env " + env + " HOME=" + quote(home) + " " + quote(SYMREP_BINARY) + args;
        run(tmux() + " new-session -d -s t -x 160 -y 50 -c " + quote(cwd) + " " + quote(cmd));
    }
    ~terminal() {
        run(tmux() + " kill-server");
        std::remove(socket_.c_str());
    }
    /// Types `text` literally (no Enter).
    void type(const std::string& text) { run(tmux() + " send-keys -t t -l " + quote(text)); }
    /// Presses keys by tmux name: Enter, Tab, Up, C-c, C-d.
    void key(const std::string& name) { run(tmux() + " send-keys -t t " + name); }
    void line(const std::string& text) {
        type(text);
        key("Enter");
    }
    std::string screen() { return run(tmux() + " capture-pane -p -J -t t -S -200"); }
    /// The screen with its colour escapes.
    std::string screen_escapes() { return run(tmux() + " capture-pane -p -e -J -t t -S -200"); }
    bool alive() { return std::system((tmux() + " has-session -t t >/dev/null 2>&1").c_str()) == 0; }
    /// Polls the screen until `needle` appears `times` times, or the deadline passes.
    bool wait_for(const std::string& needle, int times = 1, double seconds = 6) {
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (std::chrono::steady_clock::now() < end) {
            if (count(screen(), needle) >= times) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(40));
        }
        return false;
    }
    bool wait_exit(double seconds = 6) {
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (std::chrono::steady_clock::now() < end) {
            if (!alive()) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(40));
        }
        return false;
    }
    /// Waits for the banner and the first prompt.
    bool ready() { return wait_for("Ctrl-D to leave") && wait_for("> "); }
    static int count(const std::string& hay, const std::string& needle) {
        int n = 0;
        for (std::size_t p = hay.find(needle); p != std::string::npos; p = hay.find(needle, p + needle.size())) ++n;
        return n;
    }

private:
    std::string tmux() const { return "tmux -f /dev/null -S " + quote(socket_); }  // a socket of our own
    std::string socket_;
};

#define REQUIRE_TMUX() \
    if (!have_tmux()) GTEST_SKIP() << "tmux is not installed: the interactive tests need it (apt-get install tmux)"

TEST(Interactive, HistoryPersistsAcrossSessions) {
    REQUIRE_TMUX();
    temp_home home;
    ASSERT_FALSE(home.path.empty());
    {
        terminal t(home.path);
        ASSERT_TRUE(t.ready()) << t.screen();
        t.line("hist_probe := 4242");
        t.line("quit");
        ASSERT_TRUE(t.wait_exit()) << t.screen();
    }
    const std::string saved = symrep::test::slurp(home.path + "/.symrep_history");
    EXPECT_NE(saved.find("hist_probe := 4242"), std::string::npos) << saved;
    terminal t(home.path);
    ASSERT_TRUE(t.ready()) << t.screen();
    t.key("Up");  // quit
    t.key("Up");  // the assignment of the first session
    ASSERT_TRUE(t.wait_for("> hist_probe := 4242")) << t.screen();
    t.key("Enter");
    t.line("hist_probe + 1");
    EXPECT_TRUE(t.wait_for("%1 = 4243")) << t.screen();
    t.key("C-d");
    EXPECT_TRUE(t.wait_exit()) << t.screen();
}

TEST(Interactive, HistoryFileUnwritableIsNotFatal) {
    REQUIRE_TMUX();
    terminal t("/nonexistent/symrep/home");
    ASSERT_TRUE(t.ready()) << t.screen();
    t.line("3*4");
    EXPECT_TRUE(t.wait_for("%1 = 12")) << t.screen();
}

TEST(Interactive, TabCompletesFunctionName) {
    REQUIRE_TMUX();
    temp_home home;
    terminal t(home.path);
    ASSERT_TRUE(t.ready()) << t.screen();
    t.type("minpo");
    t.key("Tab");
    ASSERT_TRUE(t.wait_for("> minpoly(")) << t.screen();
    t.line("element(multicomplex(1), [2, 0, 0, 0]), X)");
    EXPECT_TRUE(t.wait_for("%1 = ")) << t.screen();
}

// issue 13: the declarations complete with a space, as the names they declare follow
TEST(Interactive, TabCompletesDeclarationsWithASpace) {
    REQUIRE_TMUX();
    temp_home home;
    terminal t(home.path);
    ASSERT_TRUE(t.ready()) << t.screen();
    t.line("vector qa, qb");  // "vect" is ambiguous (vector, vector_series): readline stops at "vector"
    t.type("posi");
    t.key("Tab");
    t.line("pk");
    ASSERT_TRUE(t.wait_for("> positive pk")) << t.screen();
    t.line("sqrt(pk^2) + 0*qa . qb");
    EXPECT_TRUE(t.wait_for("%1 = pk")) << t.screen();
}

TEST(Interactive, TabCompletesFileNameInLoad) {
    REQUIRE_TMUX();
    temp_home home;
    std::ofstream(home.path + "/probe_script.symrep") << "70 + 7\n";
    terminal t(home.path, home.path);
    ASSERT_TRUE(t.ready()) << t.screen();
    t.type("load(\"probe_sc");
    t.key("Tab");
    ASSERT_TRUE(t.wait_for("> load(\"probe_script.symrep\"")) << t.screen();
    t.line(")");
    EXPECT_TRUE(t.wait_for("%1 = 77")) << t.screen();
}

TEST(Interactive, QuestionMarkShowsHelp) {
    REQUIRE_TMUX();
    temp_home home;
    terminal t(home.path);
    ASSERT_TRUE(t.ready()) << t.screen();
    t.line("?inverse");
    ASSERT_TRUE(t.wait_for("Example: inverse(")) << t.screen();
    const std::string s = t.screen();
    EXPECT_NE(s.find("inverse(w)"), std::string::npos) << s;
    EXPECT_NE(s.find("Thesis: (II.1.22"), std::string::npos) << s;
    t.line("help invrse");
    EXPECT_TRUE(t.wait_for("no function named 'invrse'; did you mean inverse?")) << t.screen();
    t.line("help");
    EXPECT_TRUE(t.wait_for("Multicomplex")) << t.screen();
}

TEST(Interactive, PercentAndNumberedResults) {
    REQUIRE_TMUX();
    temp_home home;
    terminal t(home.path);
    ASSERT_TRUE(t.ready()) << t.screen();
    t.line("6*7");
    ASSERT_TRUE(t.wait_for("%1 = 42")) << t.screen();
    t.line("% + 1");
    ASSERT_TRUE(t.wait_for("%2 = 43")) << t.screen();
    t.line("%1 * 2");
    ASSERT_TRUE(t.wait_for("%3 = 84")) << t.screen();
    t.line("%% - %");
    EXPECT_TRUE(t.wait_for("%4 = -41")) << t.screen();
}

TEST(Interactive, CtrlCInterruptsComputation) {
    REQUIRE_TMUX();
    temp_home home;
    terminal t(home.path);
    ASSERT_TRUE(t.ready()) << t.screen();
    t.line("slow := 1");
    // about 2.7e7 evaluation steps: tens of seconds if not interrupted
    t.line("sum(sum(sum(j*k*l, j, 1, 300), k, 1, 300), l, 1, 300)");
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    EXPECT_EQ(terminal::count(t.screen(), "%1 ="), 0) << t.screen();
    t.key("C-c");
    ASSERT_TRUE(t.wait_for("<stdin>:1:")) << t.screen();
    EXPECT_TRUE(t.wait_for("error: interrupted")) << t.screen();
    EXPECT_TRUE(t.alive());
    ASSERT_TRUE(t.wait_for("^\n>")) << t.screen();  // a new prompt after the error and its caret line
    t.line("slow + 1");
    EXPECT_TRUE(t.wait_for("%1 = 2")) << t.screen();
    // Ctrl-C at the prompt clears the line
    t.type("this is discarded");
    ASSERT_TRUE(t.wait_for("> this is discarded")) << t.screen();
    t.key("C-c");
    ASSERT_TRUE(t.wait_for("> this is discarded\n>")) << t.screen();
    t.line("slow + 2");
    EXPECT_TRUE(t.wait_for("%2 = 3")) << t.screen();
}

TEST(Interactive, CtrlCStopsALibraryCall) {
    REQUIRE_TMUX();
    temp_home home;
    terminal t(home.path);
    ASSERT_TRUE(t.ready()) << t.screen();
    // one GiNaC expand of about half a minute, which sees no check_interrupt():
    // operator new (core/allocation_interrupt.cpp) stops it
    t.line("e := expand((a+b+c+d+f+g+h)^40)");
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    t.key("C-c");
    EXPECT_TRUE(t.wait_for("<stdin>:1:6: error: interrupted")) << t.screen();
    EXPECT_TRUE(t.alive());
    EXPECT_EQ(terminal::count(t.screen(), "press Ctrl-C once more"), 0) << t.screen();
    t.line("1 + 1");
    EXPECT_TRUE(t.wait_for("= 2")) << t.screen();
}

TEST(Interactive, ErrorsShowFileLineColumn) {
    REQUIRE_TMUX();
    temp_home home;
    terminal t(home.path);
    ASSERT_TRUE(t.ready()) << t.screen();
    t.line("1 + nosuchfn(2)");
    EXPECT_TRUE(t.wait_for("<stdin>:1:5: error: unknown function 'nosuchfn'")) << t.screen();
    t.line("[1,");
    t.line("  2 +]");
    EXPECT_TRUE(t.wait_for("<stdin>:2:6: error: syntax error")) << t.screen();
}

TEST(Interactive, ColourOnlyWhenAllowed) {
    REQUIRE_TMUX();
    temp_home home;
    const std::string red = "\033[31m";
    for (const char* env : {"TERM=xterm", "NO_COLOR=1 TERM=xterm", "TERM=dumb"}) {
        terminal t(home.path, ".", std::string("-u NO_COLOR ") + env);
        ASSERT_TRUE(t.ready()) << t.screen();
        t.line("nosuchfn(1)");
        ASSERT_TRUE(t.wait_for("error: unknown function")) << t.screen();
        const bool coloured = t.screen_escapes().find(red) != std::string::npos;
        EXPECT_EQ(coloured, std::string(env) == "TERM=xterm") << env;
    }
}

// At a UTF-8 terminal the products print as × and · (and read back); in
// another locale, or with --ascii, as x and .
TEST(Interactive, UnicodeNotationInAUtf8Locale) {
    REQUIRE_TMUX();
    temp_home home;
    struct setting {
        const char* env;
        const char* args;
        bool unicode;
    };
    for (const setting& c : {setting{"LC_ALL=C.UTF-8", "", true}, setting{"LC_ALL= LC_CTYPE= LANG=en_US.utf8", "", true},
                             setting{"LC_ALL=C", "", false}, setting{"LC_ALL=C.UTF-8", " --ascii", false}}) {
        terminal t(home.path, ".", std::string("NO_COLOR=1 TERM=xterm ") + c.env, c.args);
        ASSERT_TRUE(t.ready()) << t.screen();
        t.line("vector a, b; a x b; (a . b)*a");
        ASSERT_TRUE(t.wait_for("%2 = ")) << t.screen();
        const std::string s = t.screen();
        const bool unicode = s.find("%1 = a \xC3\x97 b\n%2 = (a \xC2\xB7 b)*a") != std::string::npos;
        const bool ascii = s.find("%1 = a x b\n%2 = (a . b)*a") != std::string::npos;
        EXPECT_TRUE(c.unicode ? unicode : ascii) << c.env << c.args << "\n" << s;
        t.line("a \xC3\x97 b == a x b");
        EXPECT_TRUE(t.wait_for("%3 = true")) << t.screen();
    }
}

#endif  // SYMREP_BINARY

}  // namespace

// The floors of docs/architecture.md, enforced: every #include "..." under
// engine/, repl/ and bench/ goes to the file's own folder or to a folder its row
// allows. The table is read from the document itself, so the map and the rule
// cannot disagree. The engine writes its includes in the installed form,
// "symrep/<part>/x.h" (docs/library.md; tests/install/rewrite_includes.py), which
// resolves in the build tree and under PREFIX/include alike; the programs and
// tests beside it may also write "<part>/x.h" (engine/ is on their path).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

struct floor_row {
    std::string floor;                ///< "0".."6", or "-" (programs beside the engine)
    std::string main_header;          ///< e.g. "core/error.h"; may be empty
    std::set<std::string> may_include;  ///< folders, each with its trailing '/'
};

std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

/// The rows of the floors table: | floor | `folder/` | `main header` | holds | `a/` `b/` |.
std::map<std::string, floor_row> read_table(const std::string& md) {
    std::map<std::string, floor_row> rows;
    std::istringstream in(md);
    std::string line;
    const std::regex row(R"(^\|\s*([0-9]+|-)\s*\|\s*`([a-z_]+/)`\s*\|([^|]*)\|[^|]*\|([^|]*)\|\s*$)");
    const std::regex tick("`([^`]+)`");
    while (std::getline(in, line)) {
        std::smatch m;
        if (!std::regex_match(line, m, row)) continue;
        floor_row r;
        r.floor = m[1];
        const std::string header = m[3], allowed = m[4];
        std::smatch h;
        if (std::regex_search(header, h, tick)) r.main_header = h[1];
        for (auto it = std::sregex_iterator(allowed.begin(), allowed.end(), tick); it != std::sregex_iterator(); ++it)
            r.may_include.insert((*it)[1]);
        rows[m[2]] = r;
    }
    return rows;
}

/// The folder a source file belongs to: "core/" for engine/core/x.h, "repl/" for repl/main.cpp.
std::string folder_of(const fs::path& rel) {
    auto it = rel.begin();
    const std::string top = it->string();
    if (top == "engine" && std::next(it) != rel.end()) return std::next(it)->string() + "/";
    return top + "/";
}

/// Every include of the tree under `root` that the table does not allow, as
/// "FILE:LINE: message".
std::vector<std::string> include_violations(const fs::path& root) {
    const std::map<std::string, floor_row> table = read_table(read_text(root / "docs" / "architecture.md"));
    std::vector<std::string> out;
    if (table.empty()) {
        out.push_back("docs/architecture.md: no floors table found");
        return out;
    }
    const std::regex include(R"(^\s*#\s*include\s*"([^"]+)\")");
    std::vector<fs::path> files;
    for (const char* top : {"engine", "repl", "bench"}) {
        if (!fs::exists(root / top)) continue;
        for (const auto& e : fs::recursive_directory_iterator(root / top)) {
            const std::string ext = e.path().extension().string();
            if (e.is_regular_file() && (ext == ".h" || ext == ".cpp")) files.push_back(e.path());
        }
    }
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
        const fs::path rel = fs::relative(file, root);
        const std::string from = folder_of(rel);
        const auto row = table.find(from);
        if (row == table.end()) {
            out.push_back(rel.string() + ":1: the folder " + from + " has no row in docs/architecture.md");
            continue;
        }
        std::istringstream in(read_text(file));
        std::string line;
        for (int n = 1; std::getline(in, line); ++n) {
            std::smatch m;
            if (!std::regex_search(line, m, include)) continue;
            const std::string written = m[1];
            const std::string where = rel.string() + ":" + std::to_string(n) + ": #include \"" + written + "\": ";
            // "symrep/<part>/x.h" is <part>/x.h through the include root; symrep/version.h is
            // generated (engine/version.h.in) and belongs to no floor
            const bool rooted = written.rfind("symrep/", 0) == 0;
            const std::string target = rooted ? written.substr(7) : written;
            if (rooted && target == "version.h") continue;
            const std::size_t slash = target.find('/');
            if (slash == std::string::npos) {  // a neighbour in the same directory
                if (!fs::exists(file.parent_path() / target))
                    out.push_back(where + "no such file beside " + rel.filename().string());
                continue;
            }
            const std::string to = target.substr(0, slash + 1);
            if (!rooted && rel.begin()->string() == "engine" && table.count(to)) {
                out.push_back(where + "write \"symrep/" + target +
                              "\" (the installed form; tests/install/rewrite_includes.py)");
                continue;
            }
            if (to == from) continue;
            if (!table.count(to)) {
                out.push_back(where + to + " is not a folder of docs/architecture.md");
            } else if (!row->second.may_include.count(to)) {
                out.push_back(where + from + " (floor " + row->second.floor + ") may not include " + to + " (floor " +
                              table.at(to).floor + "; docs/architecture.md)");
            }
        }
    }
    return out;
}

fs::path source_root() { return fs::path(SYMREP_SOURCE_DIR); }

std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += x + "\n";
    return s;
}

TEST(Architecture, IncludesGoDownTheFloors) {
    const std::vector<std::string> v = include_violations(source_root());
    EXPECT_TRUE(v.empty()) << joined(v);
}

TEST(Architecture, TheTableGoesDown) {
    const auto table = read_table(read_text(source_root() / "docs" / "architecture.md"));
    ASSERT_GE(table.size(), 10u) << "the floors table of docs/architecture.md was not read";
    for (const auto& [folder, row] : table) {
        for (const std::string& to : row.may_include) {
            ASSERT_TRUE(table.count(to)) << folder << " may include " << to << ", which has no row";
            const std::string& f = table.at(to).floor;
            EXPECT_NE(f, "-") << folder << " may include the program folder " << to;
            if (row.floor != "-") {
                EXPECT_LT(std::stoi(f), std::stoi(row.floor)) << folder << " may include " << to << " on its floor or above";
            }
        }
    }
    EXPECT_TRUE(table.at("core/").may_include.empty()) << "core/ includes no other folder";
}

TEST(Architecture, EveryEngineFolderHasARowAndAMainHeaderThatSaysWhatItIsFor) {
    const auto table = read_table(read_text(source_root() / "docs" / "architecture.md"));
    for (const auto& e : fs::directory_iterator(source_root() / "engine")) {
        if (!e.is_directory()) continue;
        const std::string folder = e.path().filename().string() + "/";
        ASSERT_TRUE(table.count(folder)) << "engine/" << folder << " has no row in docs/architecture.md";
        const std::string& header = table.at(folder).main_header;
        ASSERT_FALSE(header.empty()) << folder;
        const std::string text = read_text(source_root() / "engine" / header);
        ASSERT_FALSE(text.empty()) << "engine/" << header << " (the main header of " << folder << ") is missing";
        // the opening comment names the folder and what it is for
        const std::size_t code = text.find("#pragma once");
        EXPECT_NE(text.substr(0, code).find(folder), std::string::npos)
            << "engine/" << header << " does not open with a paragraph on " << folder;
    }
}

// The checker finds what it should: a probe tree with an upward include, an
// include into an unknown folder and a folder without a row.
TEST(Architecture, AnUpwardIncludeIsFoundWithItsFileAndLine) {
    const fs::path root = fs::temp_directory_path() / ("symrep_arch_probe_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "docs");
    fs::copy_file(source_root() / "docs" / "architecture.md", root / "docs" / "architecture.md");
    fs::create_directories(root / "engine" / "scalar");
    fs::create_directories(root / "engine" / "lang");
    fs::create_directories(root / "engine" / "attic");
    fs::create_directories(root / "repl");
    std::ofstream(root / "engine" / "scalar" / "probe.h") << "#pragma once\n#include \"symrep/core/error.h\"\n"
                                                          << "#include \"symrep/lang/value.h\"\n#include \"symrep/nowhere/x.h\"\n"
                                                          << "#include \"core/error.h\"\n#include \"symrep/version.h\"\n";
    std::ofstream(root / "engine" / "lang" / "ok.cpp") << "#include \"symrep/scalar/probe.h\"\n#include \"symrep/lang/ok.h\"\n";
    std::ofstream(root / "engine" / "attic" / "old.cpp") << "#include \"symrep/core/error.h\"\n";
    // the programs beside the engine may write either form
    std::ofstream(root / "repl" / "main.cpp") << "#include \"lang/ok.h\"\n#include \"symrep/lang/ok.h\"\n"
                                              << "#include \"symrep/version.h\"\n";
    const std::vector<std::string> v = include_violations(root);
    fs::remove_all(root);
    ASSERT_EQ(v.size(), 4u) << joined(v);
    EXPECT_EQ(v[0], "engine/attic/old.cpp:1: the folder attic/ has no row in docs/architecture.md");
    EXPECT_EQ(v[1], "engine/scalar/probe.h:3: #include \"symrep/lang/value.h\": scalar/ (floor 1) may not include lang/ "
                    "(floor 6; docs/architecture.md)");
    EXPECT_EQ(v[2], "engine/scalar/probe.h:4: #include \"symrep/nowhere/x.h\": nowhere/ is not a folder of docs/architecture.md");
    EXPECT_EQ(v[3], "engine/scalar/probe.h:5: #include \"core/error.h\": write \"symrep/core/error.h\" (the installed form; "
                    "tests/install/rewrite_includes.py)");
}

}  // namespace

// symrep/output/plot.h -- pictures of sampled curves, drawn by gnuplot.
//
// write_plot() writes the samples to a temporary directory, generates a gnuplot
// script there and runs gnuplot on it (posix_spawnp, no shell: the user's file
// name never reaches a shell or the script; gnuplot draws into the temporary
// directory and the picture is then copied to `path`). The extension of `path`
// chooses the terminal: .png (pngcairo where gnuplot has it, else png) or .svg.
// When `path` already holds exactly the new picture it is not rewritten, so
// drawing twice gives the same file and works in a read-only folder.
//
// The program is $SYMREP_GNUPLOT, or "gnuplot" on the PATH; when it cannot be
// started the symrep::error says so (Debian: apt-get install gnuplot-nox).
#pragma once

#include <string>
#include <vector>

namespace symrep::output {

struct plot_spec {
    bool three_d = false;  ///< false: curves y_k(t); true: one space curve (x, y, z)(t)
    std::string title;
    std::string xlabel, ylabel, zlabel;
    /// 2-D: the abscissa; 3-D: unused.
    std::vector<double> t;
    /// 2-D: one column per curve (each t.size() values); 3-D: exactly the x, y, z columns.
    std::vector<std::vector<double>> columns;
    /// 2-D: the legend of each curve (no legend for a single curve); 3-D: unused.
    std::vector<std::string> names;
    /// 2-D: sets of points (x_k, y_k) drawn as marks over the curves, each with its legend
    /// (a table such as identify_points' against the curve it estimates).
    struct point_set {
        std::string name;
        std::vector<double> x, y;
    };
    std::vector<point_set> points;
};

/// "gnuplot", or the value of the environment variable SYMREP_GNUPLOT.
std::string gnuplot_program();

/// Draws `spec` into `path` (.png or .svg). Every failure (bad extension, no finite
/// sample, gnuplot missing or failing, file not writable) throws symrep::error whose
/// message starts with `who` (e.g. "plot").
void write_plot(const plot_spec& spec, const std::string& path, const std::string& who);

}  // namespace symrep::output

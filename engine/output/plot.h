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
// A space curve (three_d) is drawn in the view chosen from the data (choose_view): the
// extents of the sampled points along their principal directions (the eigenvectors of
// their covariance) decide. When the curve is nearly planar -- its extent across the
// plane is at most planar_fraction (5%) of its largest extent -- it is drawn in 2-D:
// in a coordinate plane when it is that flat along a coordinate axis (a pendulum seen
// from above: x-y), else projected on its principal plane (axes u, v named by their
// directions); otherwise in 3-D. The title says which. Ticks are chosen here (at most
// about six per axis, so labels never overprint), an axis whose values are tiny, huge
// or crowded around an offset is drawn scaled, its label saying so ("z (x 1e-3)",
// "z - 2 (x 1e-6)"), and axes share one scale only when their extents are within
// 1:4 (equal_scale_ratio); otherwise the label says "not to scale".
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
    /// 3-D: "auto" (chosen from the data), "xy" (or "top"), "xz", "yz", "plane" (the
    /// principal plane) or "3d".
    std::string view = "auto";
    /// 3-D view direction in degrees: azimuth about z, elevation above the x-y plane.
    double azimuth = 30, elevation = 30;
};

/// A curve is nearly planar when its extent across its plane is at most this fraction of
/// its largest extent.
inline constexpr double planar_fraction = 0.05;
/// Axes share one scale when their extents are within this ratio.
inline constexpr double equal_scale_ratio = 4;

/// The view of a space curve: "xy", "xz", "yz" (coordinate planes), "plane" (the
/// principal plane, `u` and `v` its unit axes) or "3d"; `caption` the words the title
/// gets ("seen from above (x-y)", "projected on the plane of the motion", ...).
struct view_choice {
    std::string kind;
    std::string caption;
    double u[3] = {1, 0, 0}, v[3] = {0, 1, 0};
};

/// The view of spec (three_d): spec.view, or from the data when it is "auto". Throws
/// symrep::error for an unknown view name.
view_choice choose_view(const plot_spec& spec, const std::string& who);

/// The gnuplot script (and the data files, written into `dir`) that draws spec into
/// dir/out.<format> (format "png" or "svg"). write_plot runs it; tests read it.
std::string gnuplot_script(const plot_spec& spec, const std::string& format, const std::string& dir,
                           const std::string& who);

/// "gnuplot", or the value of the environment variable SYMREP_GNUPLOT.
std::string gnuplot_program();

/// Draws `spec` into `path` (.png or .svg). Every failure (bad extension, no finite
/// sample, gnuplot missing or failing, file not writable) throws symrep::error whose
/// message starts with `who` (e.g. "plot").
void write_plot(const plot_spec& spec, const std::string& path, const std::string& who);

}  // namespace symrep::output

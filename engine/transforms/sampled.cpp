// symrep/transforms/sampled.cpp -- see sampled.h.
#include "symrep/transforms/sampled.h"

#include <cmath>
#include <unsupported/Eigen/FFT>

#include "symrep/core/error.h"

namespace symrep::transforms {

std::vector<std::complex<double>> sampled_fourier(const std::vector<double>& samples, double h) {
    if (samples.size() < 2) throw domain_error("sampled_fourier: at least 2 samples are needed");
    if (!(h > 0) || !std::isfinite(h)) throw domain_error("sampled_fourier: the step h must be positive and finite");
    Eigen::FFT<double> fft;
    std::vector<std::complex<double>> out;
    fft.fwd(out, samples);  // sum_k f_k e^(-2 pi i m k / N), all N bins
    for (std::complex<double>& x : out) x = h * (x - samples[0] / 2);
    return out;
}

}  // namespace symrep::transforms

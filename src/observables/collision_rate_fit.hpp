// Fits of the paper's three forms for P(N_c) (Luding 1998 Sec. 4.3) to a RateHistogram:
//   Eq. (20) Poisson:     P(N_c) = P_o(N_c Dt, chi) Dt,  P_o(C, chi) = exp(-chi) chi^C / C!
//                         parameter chi (dimensionless mean count per window; chi/Dt the rate)
//   Eq. (21) exponential: P_e(N_c, A) = (1/A) exp(-N_c/A),   parameter A [1/s]
//   Eq. (22) power law:   P_p(N_c, B) = B / (B + N_c)^2,     parameter B [1/s]
// Each form is normalised for any parameter value (paper, below Eq. 22), so each fit has exactly
// one free parameter and no free amplitude: the expected count of a bin is
// mu_i = total * integral_bin P dN_c (exact integrals, no centre-point approximation).
//
// Method: binned Poisson maximum likelihood (Baker & Cousins 1984). The bin counts n_i are
// Poisson with mean mu_i, and the tails the paper is about (large N_c, Figs 12 and 14) hold few
// or no counts, where least squares on P (or on log P) is biased and cannot use empty bins. We
// minimise the deviance D = 2 sum [mu_i - n_i + n_i ln(n_i/mu_i)] with gsl_multifit_nlinear by
// handing it the deviance residuals sign(n_i - mu_i) sqrt(D_i), whose sum of squares is D. The
// parameter is fitted as its logarithm so it stays positive. Standard error: Cramer-Rao,
// 1/sqrt(I) with the Fisher information I = sum_i (d mu_i/d theta)^2 / mu_i. Goodness of fit:
// Pearson chi^2 = sum (n_i - mu_i)^2 / mu_i over the bins used, divided by dof = bins - 1.
// Only bins lying entirely inside the caller's range [lo, hi] enter.
#pragma once
#include "observables/rate_histogram.hpp"

namespace granrepro {

struct CollisionRateFit {
    enum class Model { Poisson, Exponential, PowerLaw }; // Eqs (20), (21), (22)

    Model model = Model::Exponential;
    double value = 0.0;        // chi (Poisson) [-], A [1/s] or B [1/s]
    double error = 0.0;        // its standard error, same units
    double chi2_reduced = 0.0; // Pearson chi^2 / dof (NaN when dof = 0)
    double deviance = 0.0;     // Poisson deviance at the optimum
    int bins = 0;              // bins used
    int dof = 0;               // bins - 1
    bool converged = false;

    // Fits `model` to the bins of h inside [lo, hi] [1/s]. Throws std::invalid_argument if no bin
    // lies in the range or the histogram is empty.
    static CollisionRateFit fit(const RateHistogram& h, Model model, double lo, double hi);

    // Model density P(N_c) [s] at rate N_c [1/s]; dt [s] is used by the Poisson form only
    // (C = N_c dt, via lgamma for non-integer C).
    static double density(Model model, double param, double rate, double dt);
    // Probability mass of the bin [a, b) [1/s]. For the Poisson form, the sum of P_o(C, chi)
    // over the counts C whose rate double(C)/dt falls into the bin by h.bin_of().
    static double bin_probability(const RateHistogram& h, std::size_t bin, Model model, double param);
};

} // namespace granrepro

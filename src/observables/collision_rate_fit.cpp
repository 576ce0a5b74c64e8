#include "observables/collision_rate_fit.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace granrepro {

namespace {
using Model = CollisionRateFit::Model;

// gsl_set_error_handler is process-global; fits from several threads must not interleave their
// save/restore of it.
std::mutex& gsl_handler_mutex() {
    static std::mutex m;
    return m;
}
} // namespace

double CollisionRateFit::density(Model m, double p, double x, double dt) {
    switch (m) {
    case Model::Exponential: return x < 0.0 ? 0.0 : std::exp(-x / p) / p;
    case Model::PowerLaw: return x < 0.0 ? 0.0 : p / ((p + x) * (p + x));
    case Model::Poisson: {
        const double c = x * dt;
        if (c < 0.0) return 0.0;
        return std::exp(-p + c * std::log(p) - std::lgamma(c + 1.0)) * dt;
    }
    }
    return 0.0;
}

double CollisionRateFit::bin_probability(const RateHistogram& h, std::size_t k, Model m, double p) {
    const double a = std::max(0.0, h.edges[k]), b = h.edges[k + 1];
    if (b <= a) return 0.0;
    switch (m) {
    case Model::Exponential: return std::exp(-a / p) - std::exp(-b / p);
    case Model::PowerLaw: return p / (p + a) - p / (p + b); // CDF F(x) = x / (B + x)
    case Model::Poisson: {
        // Enumerate the counts near the bin and keep those the histogram itself would put there.
        const double dt = h.window;
        const auto c0 = static_cast<long>(std::max(0.0, std::floor(a * dt) - 1.0));
        const auto c1 = static_cast<long>(std::ceil(b * dt) + 1.0);
        double s = 0.0;
        for (long c = c0; c <= c1; ++c)
            if (h.bin_of(static_cast<double>(c) / dt) == static_cast<int>(k))
                s += gsl_ran_poisson_pdf(static_cast<unsigned int>(c), p);
        return s;
    }
    }
    return 0.0;
}

namespace {

struct Problem {
    const RateHistogram* h;
    Model model;
    std::vector<std::size_t> bins;
    double total;
    double mu(std::size_t b, double param) const {
        return std::max(1e-300, total * CollisionRateFit::bin_probability(*h, b, model, param));
    }
};

// Deviance residual of one bin: its square is the bin's contribution to D.
double deviance_residual(double n, double mu) {
    const double d = 2.0 * (mu - n + (n > 0.0 ? n * std::log(n / mu) : 0.0));
    return (n >= mu ? 1.0 : -1.0) * std::sqrt(std::max(0.0, d));
}

int residuals(const gsl_vector* x, void* data, gsl_vector* f) {
    const auto* pr = static_cast<const Problem*>(data);
    const double param = std::exp(gsl_vector_get(x, 0));
    for (std::size_t i = 0; i < pr->bins.size(); ++i) {
        const std::size_t b = pr->bins[i];
        gsl_vector_set(f, i, deviance_residual(static_cast<double>(pr->h->counts[b]), pr->mu(b, param)));
    }
    return GSL_SUCCESS;
}

double total_deviance(const Problem& pr, double param) {
    double d = 0.0;
    for (std::size_t b : pr.bins) {
        const double r = deviance_residual(static_cast<double>(pr.h->counts[b]), pr.mu(b, param));
        d += r * r;
    }
    return d;
}

// A starting value from the histogram's own mean or median, in the model's parameter.
double moment_guess(const RateHistogram& h, Model m) {
    double n = 0.0, s = 0.0;
    for (std::size_t k = 0; k < h.counts.size(); ++k) {
        n += static_cast<double>(h.counts[k]);
        s += static_cast<double>(h.counts[k]) * h.centres[k];
    }
    const double mean = n > 0.0 ? s / n : 1.0;
    if (m == Model::Poisson) return std::max(1e-3, mean * h.window);
    if (m == Model::Exponential) return std::max(1e-12, mean);
    // Power law: the median of B/(B+x)^2 is B.
    double acc = 0.0;
    for (std::size_t k = 0; k < h.counts.size(); ++k) {
        acc += static_cast<double>(h.counts[k]);
        if (acc >= 0.5 * n) return std::max(1e-12, h.centres[k]);
    }
    return std::max(1e-12, mean);
}

} // namespace

CollisionRateFit CollisionRateFit::fit(const RateHistogram& h, Model model, double lo, double hi) {
    if (h.total == 0) throw std::invalid_argument("CollisionRateFit: empty histogram");
    if (model == Model::Poisson && !(h.window > 0.0))
        throw std::invalid_argument("CollisionRateFit: Poisson fit needs the histogram window");
    Problem pr{&h, model, {}, static_cast<double>(h.total)};
    for (std::size_t k = 0; k + 1 < h.edges.size(); ++k)
        if (h.edges[k] >= lo && h.edges[k + 1] <= hi) pr.bins.push_back(k);
    if (pr.bins.empty()) throw std::invalid_argument("CollisionRateFit: no bin inside the fit range");

    // Coarse scan of log(param) around the moment guess: the deviance of a truncated range can
    // be multimodal far from the optimum, and LM needs a start in the right basin.
    const double guess = moment_guess(h, model);
    double best = std::log(guess), best_d = std::numeric_limits<double>::infinity();
    for (int s = -60; s <= 60; ++s) {
        const double lp = std::log(guess) + 0.1 * s;
        const double d = total_deviance(pr, std::exp(lp));
        if (d < best_d) {
            best_d = d;
            best = lp;
        }
    }

    CollisionRateFit out;
    out.model = model;
    out.bins = static_cast<int>(pr.bins.size());
    out.dof = out.bins - 1;

    gsl_multifit_nlinear_fdf fdf{};
    fdf.f = residuals;
    fdf.df = nullptr; // forward-difference Jacobian: one parameter, cheap
    fdf.fvv = nullptr;
    fdf.n = pr.bins.size();
    fdf.p = 1;
    fdf.params = &pr;
    double lp = best;
    {
        gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
        gsl_multifit_nlinear_workspace* w =
            gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, pr.bins.size(), 1);
        gsl_vector_view x0 = gsl_vector_view_array(&best, 1);
        gsl_multifit_nlinear_init(&x0.vector, &fdf, w);
        int info = 0;
        int status = GSL_SUCCESS;
        {
            // GSL's default error handler aborts; a failed fit should be reported, not abort.
            std::lock_guard<std::mutex> lock(gsl_handler_mutex());
            gsl_error_handler_t* old = gsl_set_error_handler_off();
            status = gsl_multifit_nlinear_driver(200, 1e-10, 1e-10, 0.0, nullptr, nullptr, &info, w);
            gsl_set_error_handler(old);
        }
        lp = gsl_vector_get(gsl_multifit_nlinear_position(w), 0);
        out.converged = status == GSL_SUCCESS && std::isfinite(lp);
        gsl_multifit_nlinear_free(w);
        if (!std::isfinite(lp)) lp = best;
    }
    const double p = std::exp(lp);
    out.value = p;
    out.deviance = total_deviance(pr, p);

    // Fisher information in the natural parameter, by central differences of mu_i.
    const double hstep = 1e-5 * p;
    double info = 0.0, chi2 = 0.0;
    for (std::size_t b : pr.bins) {
        const double mu = pr.mu(b, p);
        const double dmu = (pr.mu(b, p + hstep) - pr.mu(b, p - hstep)) / (2.0 * hstep);
        info += dmu * dmu / mu;
        const double n = static_cast<double>(h.counts[b]);
        chi2 += (n - mu) * (n - mu) / mu;
    }
    out.error = info > 0.0 ? 1.0 / std::sqrt(info) : std::numeric_limits<double>::infinity();
    out.chi2_reduced = out.dof > 0 ? chi2 / out.dof : std::numeric_limits<double>::quiet_NaN();
    return out;
}

} // namespace granrepro

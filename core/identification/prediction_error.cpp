// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/prediction_error.h"

#include "core/identification/arx.h"
#include "core/identification/least_squares.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xyt {

namespace {

void requireOrder(int value, int minimum, const char* field) {
    if (value < minimum || value > 100)
        throw InvalidInput(field, makeDiagnostic("ident_between_n_100", {std::to_string(minimum)}));
}

/// The BJ structure; OE is nc = nd = 0.
struct Structure {
    std::size_t nb, nc, nd, nf, nk;
    bool boxJenkins;
    std::size_t parameters() const { return nb + nc + nd + nf; }
};

/// theta = [b, c, d, f] -> the polynomials (ascending z^-1, B with nk leading zeros).
PolynomialModel unpack(const Structure& s, const Eigen::VectorXd& theta, double ts) {
    PolynomialModel m;
    m.tsSeconds = ts;
    m.b.assign(s.nk, 0.0);
    Eigen::Index i = 0;
    for (std::size_t j = 0; j < s.nb; ++j)
        m.b.push_back(theta(i++));
    const auto monic = [&](std::size_t n) {
        std::vector<double> p{1.0};
        for (std::size_t j = 0; j < n; ++j)
            p.push_back(theta(i++));
        return p;
    };
    m.c = monic(s.nc);
    m.d = monic(s.nd);
    m.f = monic(s.nf);
    return m;
}

Eigen::VectorXd pack(const Structure& s, const PolynomialModel& m) {
    Eigen::VectorXd theta(static_cast<Eigen::Index>(s.parameters()));
    Eigen::Index i = 0;
    for (std::size_t j = 0; j < s.nb; ++j)
        theta(i++) = m.b[s.nk + j];
    for (std::size_t j = 1; j <= s.nc; ++j)
        theta(i++) = m.c[j];
    for (std::size_t j = 1; j <= s.nd; ++j)
        theta(i++) = m.d[j];
    for (std::size_t j = 1; j <= s.nf; ++j)
        theta(i++) = m.f[j];
    return theta;
}

/// The predictor and its gradient for one theta (Ljung Sec. 10.2-10.3).
class BjPredictor {
public:
    BjPredictor(const Structure& s, const IoData& data) : s_(s), data_(data), n_(data.size()) {
        w_.resize(n_);
        v_.resize(n_);
        tmp_.resize(n_);
        filtered_.resize(n_);
    }

    bool operator()(const Eigen::VectorXd& theta, Eigen::VectorXd& e, Eigen::MatrixXd* jac) {
        const PolynomialModel m = unpack(s_, theta, data_.tsSeconds);
        const double* u = data_.u.data();
        filterMonic(m.b, m.f, u, w_.data(), n_); // w = B/F u
        for (std::size_t t = 0; t < n_; ++t)
            v_[t] = data_.y[t] - w_[t];
        e.resize(static_cast<Eigen::Index>(n_));
        filterMonic(m.d, m.c, v_.data(), e.data(), n_); // e = D/C v
        if (!e.allFinite())
            return false;
        if (!jac)
            return true;
        jac->resize(static_cast<Eigen::Index>(n_), static_cast<Eigen::Index>(s_.parameters()));
        const std::vector<double> cf = polynomialProduct(m.c, m.f);
        Eigen::Index col = 0;
        // de/db_k = -q^-k D/(C F) u
        filterMonic(m.d, cf, u, filtered_.data(), n_);
        for (std::size_t j = 0; j < s_.nb; ++j)
            shiftedColumn(*jac, col++, filtered_, s_.nk + j, -1.0);
        // de/dc_k = -q^-k e / C
        if (s_.nc > 0) {
            filterMonic({1.0}, m.c, e.data(), filtered_.data(), n_);
            for (std::size_t j = 1; j <= s_.nc; ++j)
                shiftedColumn(*jac, col++, filtered_, j, -1.0);
        }
        // de/dd_k = q^-k v / C
        if (s_.nd > 0) {
            filterMonic({1.0}, m.c, v_.data(), filtered_.data(), n_);
            for (std::size_t j = 1; j <= s_.nd; ++j)
                shiftedColumn(*jac, col++, filtered_, j, 1.0);
        }
        // de/df_k = q^-k D/(C F) w
        if (s_.nf > 0) {
            filterMonic(m.d, cf, w_.data(), filtered_.data(), n_);
            for (std::size_t j = 1; j <= s_.nf; ++j)
                shiftedColumn(*jac, col++, filtered_, j, 1.0);
        }
        return true;
    }

private:
    void shiftedColumn(Eigen::MatrixXd& jac, Eigen::Index col, const std::vector<double>& x,
                       std::size_t shift, double sign) const {
        for (std::size_t t = 0; t < n_; ++t)
            jac(static_cast<Eigen::Index>(t), col) = t >= shift ? sign * x[t - shift] : 0.0;
    }

    Structure s_;
    const IoData& data_;
    std::size_t n_;
    std::vector<double> w_, v_, tmp_, filtered_;
};

double outputErrorLoss(const std::vector<double>& b, const std::vector<double>& f,
                       const IoData& data) {
    std::vector<double> yhat(data.size());
    filterMonic(b, f, data.u.data(), yhat.data(), data.size());
    double sse = 0.0;
    for (std::size_t t = 0; t < data.size(); ++t)
        sse += (data.y[t] - yhat[t]) * (data.y[t] - yhat[t]);
    return std::isfinite(sse) ? sse : std::numeric_limits<double>::infinity();
}

/**
 * B and F to start from: the ARX(nf, nb, nk) estimate, then one instrumental-variable step
 * whose instruments x = B/A u are simulated from it (reflected to stability first), Ljung
 * Eq. 7.123; whichever has the smaller OE loss. Returns false (with @p message) when the ARX
 * regressor is rank-deficient.
 */
bool initialPlant(const Structure& s, const IoData& data, PolynomialModel& model,
                  std::string& source, Diagnostic& message, std::vector<Diagnostic>& warnings) {
    const ArxResult arx = estimateArx(
        data, ArxOrders{static_cast<int>(s.nf), static_cast<int>(s.nb), static_cast<int>(s.nk)});
    if (arx.status != EstimationStatus::Converged) {
        message = arx.message;
        return false;
    }
    std::vector<double> a = arx.model.a;
    if (reflectUnstableRoots(a))
        warnings.push_back(makeDiagnostic("ident_pem_initial_reflected"));
    const std::size_t n = data.size();
    std::vector<double> x(n);
    filterMonic(arx.model.b, a, data.u.data(), x.data(), n);
    const std::size_t n0 = arx.firstRow;
    const std::size_t d = s.nf + s.nb;
    const Eigen::Index rows = static_cast<Eigen::Index>(n - n0);
    Eigen::MatrixXd phi(rows, static_cast<Eigen::Index>(d));
    Eigen::MatrixXd z(rows, static_cast<Eigen::Index>(d));
    Eigen::VectorXd y(rows);
    for (std::size_t t = n0; t < n; ++t) {
        const Eigen::Index r = static_cast<Eigen::Index>(t - n0);
        for (std::size_t i = 1; i <= s.nf; ++i) {
            phi(r, static_cast<Eigen::Index>(i - 1)) = -data.y[t - i];
            z(r, static_cast<Eigen::Index>(i - 1)) = -x[t - i];
        }
        for (std::size_t j = 0; j < s.nb; ++j) {
            phi(r, static_cast<Eigen::Index>(s.nf + j)) = data.u[t - s.nk - j];
            z(r, static_cast<Eigen::Index>(s.nf + j)) = data.u[t - s.nk - j];
        }
        y(r) = data.y[t];
    }
    model.tsSeconds = data.tsSeconds;
    model.b = arx.model.b;
    model.f = a;
    source = "ARX";
    const LinearLeastSquares iv = linearLeastSquares(z.transpose() * phi, z.transpose() * y);
    if (iv.fullRank() && iv.theta.allFinite()) {
        std::vector<double> f{1.0};
        for (std::size_t i = 0; i < s.nf; ++i)
            f.push_back(iv.theta(static_cast<Eigen::Index>(i)));
        std::vector<double> b(s.nk, 0.0);
        for (std::size_t j = 0; j < s.nb; ++j)
            b.push_back(iv.theta(static_cast<Eigen::Index>(s.nf + j)));
        reflectUnstableRoots(f);
        if (outputErrorLoss(b, f, data) <= outputErrorLoss(model.b, model.f, data)) {
            model.b = b;
            model.f = f;
            source = "instrumental variable";
        }
    }
    return true;
}

/// D from an AR(nd) least-squares fit to v = y - B/F u (reflected to stability); C = 1.
void initialNoiseModel(const Structure& s, const IoData& data, PolynomialModel& model) {
    model.c.assign(s.nc + 1, 0.0);
    model.c[0] = 1.0;
    model.d.assign(s.nd + 1, 0.0);
    model.d[0] = 1.0;
    const std::size_t n = data.size();
    if (s.nd == 0 || n <= 2 * s.nd + 1)
        return;
    std::vector<double> w(n);
    filterMonic(model.b, model.f, data.u.data(), w.data(), n);
    const Eigen::Index rows = static_cast<Eigen::Index>(n - s.nd);
    Eigen::MatrixXd phi(rows, static_cast<Eigen::Index>(s.nd));
    Eigen::VectorXd target(rows);
    for (std::size_t t = s.nd; t < n; ++t) {
        const Eigen::Index r = static_cast<Eigen::Index>(t - s.nd);
        for (std::size_t i = 1; i <= s.nd; ++i)
            phi(r, static_cast<Eigen::Index>(i - 1)) = -(data.y[t - i] - w[t - i]);
        target(r) = data.y[t] - w[t];
    }
    const LinearLeastSquares ar = linearLeastSquares(phi, target);
    if (!ar.fullRank() || !ar.theta.allFinite())
        return;
    for (std::size_t i = 1; i <= s.nd; ++i)
        model.d[i] = ar.theta(static_cast<Eigen::Index>(i - 1));
    reflectUnstableRoots(model.d);
}

void requireInitialLengths(const Structure& s, const PolynomialModel& m) {
    if (m.b.size() != s.nk + s.nb)
        throw InvalidInput("initial",
                           makeDiagnostic("ident_pem_initial_b", {std::to_string(s.nk + s.nb)}));
    if (m.f.size() != s.nf + 1 || m.f[0] != 1.0)
        throw InvalidInput("initial", makeDiagnostic("ident_pem_initial_f"));
    if (s.boxJenkins &&
        (m.c.size() != s.nc + 1 || m.d.size() != s.nd + 1 || m.c[0] != 1.0 || m.d[0] != 1.0))
        throw InvalidInput("initial", makeDiagnostic("ident_pem_initial_c_d"));
}

PemResult estimate(const Structure& s, const std::string& name, const IoData& data,
                   const PemOptions& options) {
    validateIoData(data);
    if (options.search.maxIterations < 1)
        throw InvalidInput("max_iterations", makeDiagnostic("at_least", {"1"}));
    const std::size_t n = data.size();
    const std::size_t d = s.parameters();
    const std::size_t n0 = std::max(s.nf, s.nk + s.nb - 1);
    if (n < n0 + d + 1)
        throw InvalidInput("data",
                           makeDiagnostic("ident_too_few_samples_for",
                                          {std::to_string(n), name, std::to_string(n0 + d + 1)}));
    PemResult out;
    out.structure = name;
    out.samples = n;
    for (std::size_t j = 0; j < s.nb; ++j)
        out.parameterNames.push_back("b" + std::to_string(s.nk + j));
    for (std::size_t j = 1; j <= s.nc; ++j)
        out.parameterNames.push_back("c" + std::to_string(j));
    for (std::size_t j = 1; j <= s.nd; ++j)
        out.parameterNames.push_back("d" + std::to_string(j));
    for (std::size_t j = 1; j <= s.nf; ++j)
        out.parameterNames.push_back("f" + std::to_string(j));

    PolynomialModel start;
    if (options.initial) {
        requireInitialLengths(s, *options.initial);
        start = *options.initial;
        start.tsSeconds = data.tsSeconds;
        start.a = {1.0};
        if (!s.boxJenkins) {
            start.c = {1.0};
            start.d = {1.0};
        }
        out.initialization = "given";
    } else {
        if (!initialPlant(s, data, start, out.initialization, out.message, out.warnings)) {
            out.status = EstimationStatus::NotPersistentlyExciting;
            return out;
        }
        initialNoiseModel(s, data, start);
    }
    out.initialModel = start;

    BjPredictor predictor(s, data);
    NonlinearProblem problem;
    problem.evaluate = [&](const Eigen::VectorXd& theta, Eigen::VectorXd& e, Eigen::MatrixXd* jac) {
        return predictor(theta, e, jac);
    };
    problem.project = [&](Eigen::VectorXd& theta) {
        PolynomialModel m = unpack(s, theta, data.tsSeconds);
        bool changed = reflectUnstableRoots(m.f);
        changed = reflectUnstableRoots(m.c) || changed;
        changed = reflectUnstableRoots(m.d) || changed;
        if (changed)
            theta = pack(s, m);
    };
    const SearchOutcome r =
        levenbergMarquardt(problem, pack(s, start), options.search, exactFitLoss(data.y));
    takeSearchSummary(r, out);
    if (r.status == EstimationStatus::Failed)
        return out;
    out.model = unpack(s, r.theta, data.tsSeconds);
    out.parameters.assign(r.theta.data(), r.theta.data() + r.theta.size());
    out.residuals.assign(r.residuals.data(), r.residuals.data() + r.residuals.size());
    const double sse = r.residuals.squaredNorm();
    out.loss = sse / static_cast<double>(n);
    out.noiseVariance = sse / static_cast<double>(n - d);
    parameterCovariance(r.jacobian, out.noiseVariance, out.covariance, out.standardDeviations,
                        out.warnings);
    if (maxRootMagnitude(out.model.f) >= 1.0)
        out.warnings.push_back(makeDiagnostic("ident_pem_f_unit_circle"));
    return out;
}

} // namespace

std::string OeOrders::toString() const {
    return "OE(" + std::to_string(nb) + "," + std::to_string(nf) + "," + std::to_string(nk) + ")";
}

void OeOrders::validate() const {
    requireOrder(nb, 1, "nb");
    requireOrder(nf, 0, "nf");
    requireOrder(nk, 0, "nk");
}

std::string BjOrders::toString() const {
    return "BJ(" + std::to_string(nb) + "," + std::to_string(nc) + "," + std::to_string(nd) + "," +
           std::to_string(nf) + "," + std::to_string(nk) + ")";
}

void BjOrders::validate() const {
    requireOrder(nb, 1, "nb");
    requireOrder(nc, 0, "nc");
    requireOrder(nd, 0, "nd");
    requireOrder(nf, 0, "nf");
    requireOrder(nk, 0, "nk");
}

PemResult estimateOe(const IoData& data, const OeOrders& orders, const PemOptions& options) {
    orders.validate();
    const Structure s{
        static_cast<std::size_t>(orders.nb), 0,    0, static_cast<std::size_t>(orders.nf),
        static_cast<std::size_t>(orders.nk), false};
    return estimate(s, orders.toString(), data, options);
}

PemResult estimateBj(const IoData& data, const BjOrders& orders, const PemOptions& options) {
    orders.validate();
    const Structure s{static_cast<std::size_t>(orders.nb), static_cast<std::size_t>(orders.nc),
                      static_cast<std::size_t>(orders.nd), static_cast<std::size_t>(orders.nf),
                      static_cast<std::size_t>(orders.nk), true};
    return estimate(s, orders.toString(), data, options);
}

} // namespace xyt

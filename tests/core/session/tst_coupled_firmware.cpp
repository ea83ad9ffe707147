// SPDX-License-Identifier: GPL-3.0-or-later
// The exported cross-coupled step in the loop. With the coupling on, the C export (exportCHeader)
// ends with xyt_ccc_step, which runs both axes together each period. A harness (kHarness below)
// plays the hardware of both axes, as tst_firmware_loop's does for one: it steps both plants of
// the core's sampled-data simulation (the ZOH matrices of sampledPlant, or the ARX models), reads
// them through the encoder, runs a ZPETC axis' preview steps with its own xyt_<id>_step, then
// calls xyt_ccc_step with the path's tangent and curvature of each period, passes the commands
// through the generated DAC conversion and the delay, and prints u and y of both axes with %.17g.
// Compiled with the project's C compiler and the firmware flags (tests/support/c_harness.h).
// Source of the expected values: the core's cross-coupled digital run of the same session and
// program (runDigitalProgramContour). In double the C code performs the core's operations in
// the same order, so the runs agree to the bit; asserted to 1e-12 of the signal's largest
// magnitude, as tst_firmware_loop does.
#include "core/contour/gcode_reader.h"
#include "core/session/axis_run.h"
#include "core/session/coupled_digital_run.h"
#include "core/session/export_text.h"
#include "core/session/session.h"
#include "core/session/session_evaluation.h"
#include "core/simulation/sampled_data.h"
#include "tests/support/c_harness.h"
#include "tests/support/core_checks.h"

#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <cstdio>
#include <sstream>

using namespace xyt;

namespace {

/// Both axes' hardware around xyt_ccc_step. KIND 0: continuous plants (ZOH matrices);
/// KIND 1: ARX plants (RST laws, with a ZPETC preview when PREVIEW_X / PREVIEW_Y > 0).
constexpr const char* kHarness = R"(
#define MAX_SAMPLES 200000

typedef struct {
    int n, na, nb, h, preview, head;
    double unit, rest;
    double phi[MAX_STATES * MAX_STATES], gamma[MAX_STATES], c[MAX_STATES], x[MAX_STATES];
    double a[MAX_STATES], b[MAX_STATES], y[MAX_STATES], ua[MAX_STATES];
    double line[MAX_DELAY];
    double *r; /* r(0 .. samples + preview - 1) */
} axis;

static int delay;
static double resolution;

static double delayed(axis *ax, double u) {
    double out;
    if (delay == 0)
        return u;
    out = ax->line[ax->head];
    ax->line[ax->head] = u;
    ax->head = (ax->head + 1) % delay;
    return out;
}

static void read_axis(axis *ax, int samples) {
    int i;
#if KIND == 0
    ax->unit = read_number();
    ax->n = (int)read_number();
    if (ax->n < 1 || ax->n > MAX_STATES)
        exit(2);
    for (i = 0; i < ax->n * ax->n; ++i)
        ax->phi[i] = read_number();
    for (i = 0; i < ax->n; ++i)
        ax->gamma[i] = read_number();
    for (i = 0; i < ax->n; ++i)
        ax->c[i] = read_number();
    for (i = 0; i < ax->n; ++i)
        ax->x[i] = 0.0;
    for (i = 0; i < delay; ++i)
        ax->line[i] = 0.0;
    ax->preview = 0;
#else
    double u_rest;
    ax->preview = (int)read_number();
    ax->na = (int)read_number();
    if (ax->na < 1 || ax->na > MAX_STATES)
        exit(2);
    for (i = 0; i < ax->na; ++i)
        ax->a[i] = read_number();
    ax->nb = (int)read_number();
    if (ax->nb < 1 || ax->nb > MAX_STATES)
        exit(2);
    for (i = 0; i < ax->nb; ++i)
        ax->b[i] = read_number();
    ax->rest = read_number();
    u_rest = read_number();
    ax->h = ax->na > ax->nb ? ax->na : ax->nb;
    for (i = 0; i < ax->h; ++i) {
        ax->y[i] = ax->rest;
        ax->ua[i] = u_rest;
    }
    for (i = 0; i < delay; ++i)
        ax->line[i] = u_rest;
#endif
    ax->head = 0;
    ax->r = malloc(sizeof(double) * (size_t)(samples + ax->preview));
    if (!ax->r)
        exit(2);
    for (i = 0; i < samples + ax->preview; ++i)
        ax->r[i] = read_number();
}

/* The plant's output now (mm): its own sums, as core/simulation/sampled_data.cpp. */
static double output(axis *ax) {
    int i;
#if KIND == 0
    double y = 0.0;
    for (i = 0; i < ax->n; ++i)
        y += ax->c[i] * ax->x[i];
    return y / ax->unit;
#else
    double yk = 0.0;
    for (i = ax->h - 1; i > 0; --i) {
        ax->y[i] = ax->y[i - 1];
        ax->ua[i] = ax->ua[i - 1];
    }
    for (i = 1; i < ax->nb; ++i)
        yk += ax->b[i] * ax->ua[i];
    for (i = 1; i < ax->na; ++i)
        yk -= ax->a[i] * ax->y[i];
    ax->y[0] = yk;
    return yk;
#endif
}

static void apply(axis *ax, xyt_real u) {
    const double applied = delayed(ax, dac(u));
#if KIND == 0
    double next[MAX_STATES];
    int i, j;
    for (i = 0; i < ax->n; ++i) {
        double acc = 0.0;
        for (j = 0; j < ax->n; ++j)
            acc += ax->phi[i * ax->n + j] * ax->x[j];
        acc += ax->gamma[i] * applied;
        next[i] = acc;
    }
    for (i = 0; i < ax->n; ++i)
        ax->x[i] = next[i];
#else
    ax->ua[0] = applied;
#endif
}

int main(void) {
    const int samples = (int)read_number();
    static axis ax, ay;
    double *tx, *ty, *kappa, *feed;
    int k;
    xyt_ccc_state ccc;
    STATE_X sx;
    STATE_Y sy;
    resolution = read_number();
    delay = (int)read_number();
    if (samples < 1 || samples > MAX_SAMPLES || delay < 0 || delay > MAX_DELAY)
        return 2;
    read_axis(&ax, samples);
    read_axis(&ay, samples);
    tx = malloc(sizeof(double) * (size_t)samples);
    ty = malloc(sizeof(double) * (size_t)samples);
    kappa = malloc(sizeof(double) * (size_t)samples);
    feed = malloc(sizeof(double) * (size_t)samples);
    if (!tx || !ty || !kappa || !feed)
        return 2;
    for (k = 0; k < samples; ++k) {
        tx[k] = read_number();
        ty[k] = read_number();
        kappa[k] = read_number();
        feed[k] = read_number();
    }
#if KIND == 0
    xyt_x_init(&sx);
    xyt_y_init(&sy);
#else
    int j;
    xyt_x_init(&sx, (xyt_real)ax.rest);
    xyt_y_init(&sy, (xyt_real)ay.rest);
    /* The ZPETC's preview steps before k = 0, each axis alone. */
    for (j = 0; j < ax.preview; ++j)
        apply(&ax, xyt_x_step(&sx, (xyt_real)ax.r[j], (xyt_real)encoder(output(&ax), resolution)));
    for (j = 0; j < ay.preview; ++j)
        apply(&ay, xyt_y_step(&sy, (xyt_real)ay.r[j], (xyt_real)encoder(output(&ay), resolution)));
#endif
    xyt_ccc_init(&ccc);
    for (k = 0; k < samples; ++k) {
        const double px = output(&ax), py = output(&ay);
        const double mx = encoder(px, resolution), my = encoder(py, resolution);
        xyt_real u[2];
        xyt_ccc_step(&ccc, &sx, &sy, (xyt_real)ax.r[k], (xyt_real)ay.r[k],
                     (xyt_real)ax.r[k + ax.preview], (xyt_real)ay.r[k + ay.preview], (xyt_real)mx,
                     (xyt_real)my, (xyt_real)tx[k], (xyt_real)ty[k], (xyt_real)kappa[k],
                     feed[k] != 0.0, 0, 0, 0, 0, u);
        apply(&ax, u[0]);
        apply(&ay, u[1]);
        printf("%.17g %.17g %.17g %.17g\n", (double)u[0], px, (double)u[1], py);
    }
    return 0;
}
)";

std::string numbers(const std::vector<double>& v) {
    std::string out;
    char buf[40];
    for (double x : v) {
        std::snprintf(buf, sizeof buf, "%.17g ", x);
        out += buf;
    }
    return out + "\n";
}

/// Both axes' u and y, as the harness prints them.
struct CoupledLoopRun {
    std::vector<double> ux, yx, uy, yy;
};

/// The harness' input for @p session's axes along @p program's profile (the digital run @p d).
std::string harnessInput(const Session& session, const SessionEvaluation& evaluation,
                         const GcodeProgram& program, const ContourRunOptions& options,
                         const DigitalContourRun& d) {
    const std::size_t n = d.axes[0].result.t.size();
    const ImplementationSettings& impl = session.implementation;
    const FeedProfile p =
        planFeedProfile(program.path, programFeeds(program, 1.0), options.profile);
    std::ostringstream out;
    out << n << " " << numbers({impl.encoderResolutionMm}) << impl.delaySamples << "\n";
    for (int i = 0; i < 2; ++i) {
        const AxisEvaluation& a = evaluation.axes[static_cast<std::size_t>(i)];
        const std::vector<double>& reference = i == 0 ? p.x : p.y;
        if (a.method != DesignMethod::PolePlacementZpetc) { // a continuous plant (PI, PID)
            const SampledPlant plant =
                sampledPlant(session.axes[static_cast<std::size_t>(i)].gt.plant.transferFunction(),
                             d.periodSeconds);
            out << numbers({session.axes[static_cast<std::size_t>(i)].gt.modelUnitsPerPositionUnit})
                << plant.states << "\n"
                << numbers(plant.phi) << numbers(plant.gamma) << numbers(plant.c)
                << numbers(d.axes[static_cast<std::size_t>(i)].result.r);
            continue;
        }
        const bool ff = session.axes[static_cast<std::size_t>(i)].pp.zpetcEnabled;
        const std::size_t preview = ff ? static_cast<std::size_t>(a.zpetc->previewSteps) : 0;
        // As the pole-placement axis' digital run resamples the program (programAtPeriod).
        const std::vector<double> r =
            programAtPeriod(p.t, reference, d.periodSeconds, "ts", preview);
        out << preview << "\n"
            << a.pp->a.ascending().size() << "\n"
            << numbers(a.pp->a.ascending()) << a.pp->b.ascending().size() << "\n"
            << numbers(a.pp->b.ascending()) << numbers({r[0], a.pp->a(1.0) / a.pp->b(1.0) * r[0]})
            << numbers(r);
    }
    for (std::size_t k = 0; k < n; ++k) {
        const double theta = d.directions.thetaRad[k];
        out << numbers({std::cos(theta), std::sin(theta), d.directions.curvaturePerMm[k],
                        d.directions.active[k] ? 1.0 : 0.0});
    }
    return out.str();
}

CoupledLoopRun runHarness(const std::string& header, bool pi, const std::string& input) {
    QTemporaryDir dir;
    const test::CHarnessRun run = test::runCHarness(
        dir.path(), header, QByteArray(test::kCHarnessCommon) + kHarness,
        QByteArray::fromStdString(input),
        {"-DKIND=" + QString(pi ? "0" : "1"), "-DSTATE_X=xyt_x_state", "-DSTATE_Y=xyt_y_state"});
    if (!run.ok)
        qFatal("%s", qPrintable(run.error));
    CoupledLoopRun out;
    for (const QByteArray& line : run.output.split('\n')) {
        const QList<QByteArray> parts = line.split(' ');
        if (parts.size() != 4)
            continue;
        out.ux.push_back(parts[0].toDouble());
        out.yx.push_back(parts[1].toDouble());
        out.uy.push_back(parts[2].toDouble());
        out.yy.push_back(parts[3].toDouble());
    }
    return out;
}

double largestDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double m = 0.0;
    for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
        m = std::max(m, std::abs(a[k] - b[k]));
    return m;
}

} // namespace

class TstCoupledFirmware : public QObject {
    Q_OBJECT

private slots:
    void theCoupledStepMatchesTheCore_data() {
        QTest::addColumn<int>("method");
        QTest::addColumn<QString>("program");
        QTest::addColumn<int>("delay");
        QTest::addColumn<double>("resolution");
        QTest::addColumn<int>("dacBits");
        // Braga et al.'s PIs on the paper's circle: the coupling at work (kp 0.1, ki 1).
        QTest::newRow("guillemin-truxal circle")
            << static_cast<int>(DesignMethod::GuilleminTruxal) << "F90\nG3 X0 Y0 I-25 J0\n"
            << 0 << 0.0 << 0;
        // A square with a rapid approach: the coupling off on the G0, its integral restarting
        // at each sharp corner; with a delay, an encoder and a DAC.
        QTest::newRow("guillemin-truxal square, hardware")
            << static_cast<int>(DesignMethod::GuilleminTruxal)
            << "G0 X5 Y0\nG1 X20 Y0 F600\nG1 X20 Y15\nG1 X5 Y15\nG1 X5 Y0\n"
            << 1 << 0.001 << 16;
        QTest::newRow("pid-ff circle")
            << static_cast<int>(DesignMethod::PidFeedforward) << "F90\nG3 X0 Y0 I-25 J0\n"
            << 0 << 0.0 << 0;
        QTest::newRow("pole placement + ZPETC circle")
            << static_cast<int>(DesignMethod::PolePlacementZpetc) << "F300\nG2 X0 Y0 I0 J15\n"
            << 1 << 0.0005 << 0;
    }

    void theCoupledStepMatchesTheCore() {
        QFETCH(int, method);
        QFETCH(QString, program);
        QFETCH(int, delay);
        QFETCH(double, resolution);
        QFETCH(int, dacBits);
        Session s = Session::paperDefault();
        for (AxisSettings& a : s.axes)
            a.method = static_cast<DesignMethod>(method);
        s.implementation.delaySamples = delay;
        s.implementation.encoderResolutionMm = resolution;
        s.implementation.dacBits = dacBits;
        s.crossCoupling = {0.1, 1.0, ContourEstimateKind::Circular};
        if (s.axes[0].method == DesignMethod::PolePlacementZpetc)
            s.crossCoupling = {3.0, 1.0, ContourEstimateKind::Circular};
        const GcodeProgram g = readGcode(program.toStdString());
        ContourRunOptions options;
        options.profile.maxAccelMmPerS2 = 100.0;
        options.profile.dtSeconds = 0.01;
        const DigitalContourRun d = runDigitalProgramContour(s, g, options);
        QVERIFY(!d.coupling.correction.empty());
        double largestCorrection = 0.0;
        for (double v : d.coupling.correction)
            largestCorrection = std::max(largestCorrection, std::abs(v));
        QVERIFY(largestCorrection > 0.0); // the coupling acts
        const SessionEvaluation e = evaluateSession(s);
        const std::string header = exportCHeader(s, e, ExportOptions{});
        QVERIFY(header.find("xyt_ccc_step") != std::string::npos);
        const CoupledLoopRun c =
            runHarness(header, s.axes[0].method != DesignMethod::PolePlacementZpetc,
                       harnessInput(s, e, g, options, d));
        const SimulationResult& x = d.axes[0].result;
        const SimulationResult& y = d.axes[1].result;
        QCOMPARE(c.ux.size(), x.u.size());
        QVERIFY2(largestDifference(c.ux, x.u) <= 1e-12 * test::maxAbs(x.u),
                 qPrintable(QString::number(largestDifference(c.ux, x.u))));
        QVERIFY(largestDifference(c.uy, y.u) <= 1e-12 * test::maxAbs(y.u));
        QVERIFY(largestDifference(c.yx, x.y) <= 1e-12 * test::maxAbs(x.y));
        QVERIFY(largestDifference(c.yy, y.y) <= 1e-12 * test::maxAbs(y.y));
    }

    /// The digital run with the coupling off is each axis' own digital run (the batch
    /// simulateSampled* of its method) bit for bit, and the coupled one differs.
    void theUncoupledDigitalRunIsEachAxisAlone() {
        Session s = Session::paperDefault();
        const GcodeProgram g = readGcode("F90\nG3 X0 Y0 I-25 J0\n");
        ContourRunOptions options;
        options.profile.maxAccelMmPerS2 = 100.0;
        options.profile.dtSeconds = 0.01;
        const DigitalContourRun plain = runDigitalProgramContour(s, g, options);
        QVERIFY(plain.coupling.correction.empty());
        const FeedProfile p = planFeedProfile(g.path, programFeeds(g, 1.0), options.profile);
        const DigitalPi pi = sessionDigitalPi(s, sessionGtDesign(s.axes[0].gt, 0), 0);
        const std::vector<double> r = programAtPeriod(p.t, p.x, pi.tsSeconds, "ts");
        const SampledDataRun alone =
            simulateSampledPi(s.axes[0].gt.plant.transferFunction(), pi, r,
                              sessionSampledDataOptions(s), s.axes[0].gt.modelUnitsPerPositionUnit);
        QVERIFY(plain.axes[0].result.u == alone.result.u);
        QVERIFY(plain.axes[0].result.y == alone.result.y);
        s.crossCoupling = {0.1, 1.0, ContourEstimateKind::Circular};
        const DigitalContourRun coupled = runDigitalProgramContour(s, g, options);
        QVERIFY(coupled.contour.maxAbs < 0.5 * plain.contour.maxAbs);
        qInfo("digital loops at 10 ms: contour error %.4g mm coupled, %.4g mm alone",
              coupled.contour.maxAbs, plain.contour.maxAbs);
    }
};

QTEST_GUILESS_MAIN(TstCoupledFirmware)
#include "tst_coupled_firmware.moc"

// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/identification/excitation.h"

#include "core/io/file_io.h"
#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"
#include "core/model/number_format.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace xyt {

namespace {

/// XAPP052 table 3, lengths 2..31 (index = length - 2).
const std::vector<std::vector<int>> kTaps = {
    {2, 1},        {3, 2},        {4, 3},          {5, 3},   {6, 5},           {7, 6},
    {8, 6, 5, 4},  {9, 5},        {10, 7},         {11, 9},  {12, 6, 4, 1},    {13, 4, 3, 1},
    {14, 5, 3, 1}, {15, 14},      {16, 15, 13, 4}, {17, 14}, {18, 11},         {19, 6, 2, 1},
    {20, 17},      {21, 19},      {22, 21},        {23, 18}, {24, 23, 22, 17}, {25, 22},
    {26, 6, 2, 1}, {27, 5, 2, 1}, {28, 25},        {29, 27}, {30, 6, 4, 1},    {31, 28},
};

std::size_t sampleCount(const ExcitationTiming& t) {
    requirePositive(t.tsSeconds, "ts");
    requirePositive(t.durationSeconds, "duration");
    const double x = t.durationSeconds / t.tsSeconds;
    if (!(x <= double(kMaxExcitationSamples) * (1.0 + 1e-9)))
        throw InvalidInput("duration", makeDiagnostic("ident_excite_too_many_samples",
                                                      {std::to_string(kMaxExcitationSamples)}));
    const double r = std::round(x);
    const double n = std::abs(x - r) <= 1e-9 * x ? r : std::ceil(x);
    if (n < 1.0)
        throw InvalidInput("duration", makeDiagnostic("ident_excite_shorter_than_ts"));
    return static_cast<std::size_t>(n);
}

void checkAmplitude(double amplitude, double offset, const ExcitationTiming& t) {
    requirePositive(amplitude, "amplitude");
    requireFinite(offset, "offset");
    if (t.umaxVolts) {
        requirePositive(*t.umaxVolts, "umax");
        const double peak = std::abs(offset) + amplitude;
        if (peak > *t.umaxVolts)
            throw InvalidInput("amplitude",
                               makeDiagnostic("ident_excite_exceeds_umax",
                                              {formatNumber(peak), formatNumber(*t.umaxVolts)}));
    }
}

std::string volts(double v) {
    return formatNumber(v) + " V";
}

} // namespace

std::vector<int> prbsTaps(int n) {
    if (n < 2 || n > 31)
        throw InvalidInput("register", makeDiagnostic("ident_excite_register"));
    return kTaps[static_cast<std::size_t>(n - 2)];
}

std::vector<std::uint8_t> prbsBits(int n, std::size_t count) {
    const std::vector<int> taps = prbsTaps(n);
    const std::uint32_t mask = n == 32 ? 0xFFFFFFFFu : (1u << n) - 1u;
    std::uint32_t state = mask; // all ones (all zeros would stay zero)
    std::vector<std::uint8_t> bits(count);
    for (std::size_t k = 0; k < count; ++k) {
        bits[k] = static_cast<std::uint8_t>((state >> (n - 1)) & 1u);
        std::uint32_t feedback = 0;
        for (int t : taps)
            feedback ^= (state >> (t - 1)) & 1u;
        state = ((state << 1) | feedback) & mask;
    }
    return bits;
}

ExcitationSignal squareWave(const SquareWave& w, const ExcitationTiming& t) {
    const std::size_t n = sampleCount(t);
    checkAmplitude(w.amplitudeVolts, w.offsetVolts, t);
    requirePositive(w.periodSeconds, "period");
    if (w.periodSeconds < 2.0 * t.tsSeconds)
        throw InvalidInput("period", makeDiagnostic("ident_excite_two_sample_times",
                                                    {formatNumber(2.0 * t.tsSeconds)}));
    ExcitationSignal s;
    s.tsSeconds = t.tsSeconds;
    s.u.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        // The phase counted in samples: k mod (period / Ts) is exact for whole k.
        const double perSamples = w.periodSeconds / t.tsSeconds;
        const bool high = std::fmod(double(k), perSamples) < perSamples / 2.0 - 1e-9;
        s.u[k] = w.offsetVolts + (high ? w.amplitudeVolts : -w.amplitudeVolts);
    }
    s.description = "square wave: amplitude " + volts(w.amplitudeVolts) + ", period " +
                    formatNumber(w.periodSeconds) + " s, offset " + volts(w.offsetVolts);
    return s;
}

ExcitationSignal prbs(const Prbs& p, const ExcitationTiming& t) {
    const std::size_t n = sampleCount(t);
    checkAmplitude(p.amplitudeVolts, p.offsetVolts, t);
    if (p.clockSamples < 1 || p.clockSamples > 1'000'000)
        throw InvalidInput("clock", makeDiagnostic("ident_excite_clock"));
    prbsTaps(p.registerLength);
    const std::size_t clock = static_cast<std::size_t>(p.clockSamples);
    const std::vector<std::uint8_t> bits = prbsBits(p.registerLength, (n + clock - 1) / clock);
    ExcitationSignal s;
    s.tsSeconds = t.tsSeconds;
    s.u.resize(n);
    for (std::size_t k = 0; k < n; ++k)
        s.u[k] = p.offsetVolts + (bits[k / clock] ? p.amplitudeVolts : -p.amplitudeVolts);
    const double period = (std::ldexp(1.0, p.registerLength) - 1.0) * double(clock);
    s.description = "PRBS: amplitude " + volts(p.amplitudeVolts) + ", register " +
                    std::to_string(p.registerLength) + " bits, clock " + std::to_string(clock) +
                    " samples, period " + formatNumber(period, 12) + " samples, offset " +
                    volts(p.offsetVolts);
    return s;
}

ExcitationSignal chirp(const Chirp& c, const ExcitationTiming& t) {
    const std::size_t n = sampleCount(t);
    checkAmplitude(c.amplitudeVolts, c.offsetVolts, t);
    const double nyquist = 0.5 / t.tsSeconds;
    for (const auto& [f, name] : {std::pair{c.f0Hz, "f0"}, std::pair{c.f1Hz, "f1"}}) {
        requireFinite(f, name);
        if (f < 0.0 || f > nyquist)
            throw InvalidInput(name,
                               makeDiagnostic("ident_excite_nyquist", {formatNumber(nyquist)}));
    }
    ExcitationSignal s;
    s.tsSeconds = t.tsSeconds;
    s.u.resize(n);
    const double T = t.durationSeconds;
    for (std::size_t k = 0; k < n; ++k) {
        const double time = double(k) * t.tsSeconds;
        const double phase =
            2.0 * std::numbers::pi * (c.f0Hz * time + (c.f1Hz - c.f0Hz) * time * time / (2.0 * T));
        s.u[k] = c.offsetVolts + c.amplitudeVolts * std::sin(phase);
    }
    s.description = "chirp: amplitude " + volts(c.amplitudeVolts) + ", " + formatNumber(c.f0Hz) +
                    " Hz to " + formatNumber(c.f1Hz) + " Hz over " + formatNumber(T) +
                    " s, offset " + volts(c.offsetVolts);
    return s;
}

namespace {

std::string g17(double v) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

} // namespace

std::string excitationCsvText(const ExcitationSignal& s) {
    const bool withY = s.y.size() == s.u.size() && !s.y.empty();
    std::string out = withY ? "t,u,y\n" : "t,u\n";
    out.reserve(s.u.size() * 60);
    for (std::size_t k = 0; k < s.u.size(); ++k)
        out += g17(double(k) * s.tsSeconds) + "," + g17(s.u[k]) +
               (withY ? "," + g17(s.y[k]) : std::string()) + "\n";
    return out;
}

std::string excitationLvmText(const ExcitationSignal& s) {
    const bool withY = s.y.size() == s.u.size() && !s.y.empty();
    std::string description = s.description;
    for (char& c : description)
        if (c == '\t' || c == '\n' || c == '\r')
            c = ' ';
    std::string out = "LabVIEW Measurement\t\n"
                      "Writer_Version\t2\n"
                      "Reader_Version\t2\n"
                      "Separator\tTab\n"
                      "Decimal_Separator\t.\n"
                      "Multi_Headings\tNo\n"
                      "X_Columns\tOne\n"
                      "Time_Pref\tRelative\n"
                      "Operator\tXY Tune\n"
                      "Description\t" +
                      description +
                      "\n"
                      "***End_of_Header***\t\n"
                      "\t\n"
                      "Channels\t" +
                      (withY ? "2\t\t\n" : "1\t\n") + "Samples\t" + std::to_string(s.u.size()) +
                      (withY ? "\t" + std::to_string(s.u.size()) : "") +
                      "\t\n"
                      "Y_Unit_Label\tVolts" +
                      (withY ? "\tmm" : "") +
                      "\t\n"
                      "X_Dimension\tTime" +
                      (withY ? "\tTime" : "") +
                      "\t\n"
                      "X0\t0" +
                      (withY ? "\t0" : "") +
                      "\t\n"
                      "Delta_X\t" +
                      g17(s.tsSeconds) + (withY ? "\t" + g17(s.tsSeconds) : "") +
                      "\t\n"
                      "***End_of_Header***\t\n"
                      "X_Value\tu" +
                      (withY ? "\ty" : "") + "\tComment\n";
    out.reserve(out.size() + s.u.size() * 60);
    for (std::size_t k = 0; k < s.u.size(); ++k)
        out += g17(double(k) * s.tsSeconds) + "\t" + g17(s.u[k]) +
               (withY ? "\t" + g17(s.y[k]) : std::string()) + "\n";
    return out;
}

void writeExcitation(const std::string& path, const ExcitationSignal& s) {
    auto endsWith = [&](const char* ext) {
        const std::string e(ext);
        if (path.size() < e.size())
            return false;
        std::string tail = path.substr(path.size() - e.size());
        for (char& c : tail)
            c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
        return tail == e;
    };
    if (endsWith(".csv"))
        writeFileAtomically(path, excitationCsvText(s));
    else if (endsWith(".lvm"))
        writeFileAtomically(path, excitationLvmText(s));
    else
        throw InvalidInput("output", makeDiagnostic("ident_excite_file_extension"));
}

} // namespace xyt

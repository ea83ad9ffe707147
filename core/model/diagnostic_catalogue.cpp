// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_catalogue.h"

#include "core/model/diagnostic_tables.h"

#include <stdexcept>
#include <unordered_map>

namespace xyt {

namespace {

/// The catalogue's templates by code (a later duplicate would be ignored here: the test of the
/// catalogue fails on one).
const std::unordered_map<std::string_view, const char*>& diagnosticTemplatesByCode() {
    static const std::unordered_map<std::string_view, const char*> byCode = [] {
        std::unordered_map<std::string_view, const char*> m;
        for (const DiagnosticTemplate& t : diagnosticCatalogue())
            m.emplace(t.code, t.englishTemplate);
        return m;
    }();
    return byCode;
}

} // namespace

const std::vector<DiagnosticTemplate>& diagnosticCatalogue() {
    static const std::vector<DiagnosticTemplate> catalogue = [] {
        std::vector<DiagnosticTemplate> all;
        for (const auto* table :
             {&diagnostic_tables::model(), &diagnostic_tables::io(), &diagnostic_tables::design(),
              &diagnostic_tables::analysis(), &diagnostic_tables::simulation(),
              &diagnostic_tables::identification(), &diagnostic_tables::contour(),
              &diagnostic_tables::study(), &diagnostic_tables::session()})
            all.insert(all.end(), table->begin(), table->end());
        return all;
    }();
    return catalogue;
}

const char* diagnosticTemplate(std::string_view code) {
    const auto& byCode = diagnosticTemplatesByCode();
    const auto it = byCode.find(code);
    if (it == byCode.end())
        throw std::out_of_range("no diagnostic code '" + std::string(code) + "' in the catalogue");
    return it->second;
}

std::string fillDiagnosticTemplate(std::string_view templ, const std::vector<Diagnostic>& args) {
    std::string out;
    out.reserve(templ.size());
    for (std::size_t i = 0; i < templ.size(); ++i) {
        const char c = templ[i];
        if (c == '%' && i + 1 < templ.size() && templ[i + 1] >= '1' && templ[i + 1] <= '9') {
            const auto k = static_cast<std::size_t>(templ[i + 1] - '1');
            if (k < args.size()) {
                out += args[k].text;
                ++i;
                continue;
            }
        }
        out += c;
    }
    return out;
}

Diagnostic makeDiagnostic(std::string_view code, std::vector<Diagnostic> args) {
    Diagnostic d;
    d.text = fillDiagnosticTemplate(diagnosticTemplate(code), args);
    d.code = std::string(code);
    d.args = std::move(args);
    return d;
}

Diagnostic joinDiagnostics(const std::vector<Diagnostic>& parts, std::string_view joinCode) {
    if (parts.empty())
        return Diagnostic();
    Diagnostic joined = parts.front();
    for (std::size_t i = 1; i < parts.size(); ++i)
        joined = makeDiagnostic(joinCode, {joined, parts[i]});
    return joined;
}

} // namespace xyt

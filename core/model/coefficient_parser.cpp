// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/coefficient_parser.h"

#include "core/model/diagnostic_catalogue.h"
#include "core/model/errors.h"

#include <charconv>
#include <cmath>

namespace xyt {

namespace {
bool isSeparator(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',' || c == ';';
}

std::string quoted(std::string_view token) {
    constexpr std::size_t kShown = 24;
    std::string s(token.substr(0, kShown));
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
            c = '?';
    return "'" + s + (token.size() > kShown ? "...'" : "'");
}
} // namespace

double parseNumber(std::string_view text, const std::string& field) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
        text.remove_suffix(1);
    if (text.empty())
        throw InvalidInput(field, makeDiagnostic("model_expected_number"));
    std::string_view digits = text;
    if (digits.front() == '+')
        digits.remove_prefix(1);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range)
        throw InvalidInput(field, makeDiagnostic("model_number_out_of_range", {quoted(text)}));
    if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty())
        throw InvalidInput(field, makeDiagnostic("model_not_a_number_text", {quoted(text)}));
    if (!std::isfinite(value))
        throw InvalidInput(field, makeDiagnostic("model_not_a_finite_number_text", {quoted(text)}));
    return value;
}

std::vector<double> parseCoefficientList(std::string_view text, const std::string& field) {
    std::size_t begin = 0, end = text.size();
    while (begin < end && isSeparator(text[begin]))
        ++begin;
    while (end > begin && isSeparator(text[end - 1]))
        --end;
    if (begin < end && text[begin] == '[') {
        if (text[end - 1] != ']')
            throw InvalidInput(field, makeDiagnostic("model_unclosed_bracket"));
        ++begin;
        --end;
    }
    std::vector<double> values;
    std::size_t i = begin;
    while (i < end) {
        while (i < end && isSeparator(text[i]))
            ++i;
        if (i >= end)
            break;
        std::size_t j = i;
        while (j < end && !isSeparator(text[j]))
            ++j;
        if (values.size() == kMaxCoefficients)
            throw InvalidInput(field, makeDiagnostic("model_too_many_coefficients",
                                                     {std::to_string(kMaxCoefficients)}));
        values.push_back(
            parseNumber(text.substr(i, j - i), field + "[" + std::to_string(values.size()) + "]"));
        i = j;
    }
    if (values.empty())
        throw InvalidInput(field, makeDiagnostic("model_empty_coefficient_list"));
    return values;
}

} // namespace xyt

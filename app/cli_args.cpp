// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli_args.h"

#include "core/model/coefficient_parser.h"
#include "core/model/errors.h"

namespace xyt::cli {

namespace {

/// The length of the valid UTF-8 sequence at @p p (RFC 3629: no overlong forms, no
/// surrogates, nothing above U+10FFFF), or 0 when the byte at @p p does not start one.
int validSequenceLength(const unsigned char* p) {
    const unsigned char c = p[0];
    const auto continuation = [](unsigned char b) { return b >= 0x80 && b <= 0xBF; };
    if (c < 0x80)
        return 1;
    if (c >= 0xC2 && c <= 0xDF)
        return continuation(p[1]) ? 2 : 0;
    if (c >= 0xE0 && c <= 0xEF) {
        const unsigned char lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
        return p[1] >= lo && p[1] <= hi && continuation(p[2]) ? 3 : 0;
    }
    if (c >= 0xF0 && c <= 0xF4) {
        const unsigned char lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
        return p[1] >= lo && p[1] <= hi && continuation(p[2]) && continuation(p[3]) ? 4 : 0;
    }
    return 0;
}

constexpr char16_t kEscapedByteBase = 0xDC00;

} // namespace

QString argumentText(const char* bytes) {
    QString out;
    const auto* p = reinterpret_cast<const unsigned char*>(bytes);
    while (*p) { // a NUL inside a sequence ends it as invalid, so the checks never read past it
        if (const int n = validSequenceLength(p)) {
            out += QString::fromUtf8(reinterpret_cast<const char*>(p), n);
            p += n;
        } else {
            out += QChar(static_cast<char16_t>(kEscapedByteBase + *p));
            ++p;
        }
    }
    return out;
}

std::string fileNameBytes(const QString& argument) {
    std::string out;
    qsizetype from = 0; // the start of the run of ordinary text not yet converted
    const auto flush = [&](qsizetype to) {
        out += QStringView(argument).sliced(from, to - from).toUtf8().toStdString();
    };
    for (qsizetype i = 0; i < argument.size(); ++i) {
        const char16_t u = argument[i].unicode();
        const bool escapedByte = u >= kEscapedByteBase + 0x80 && u <= kEscapedByteBase + 0xFF &&
                                 !(i > 0 && argument[i - 1].isHighSurrogate());
        if (!escapedByte)
            continue;
        flush(i);
        out += static_cast<char>(u - kEscapedByteBase);
        from = i + 1;
    }
    flush(argument.size());
    return out;
}

CliArgs CliArgs::parse(const QStringList& args, const QSet<QString>& booleanFlags,
                       const QSet<QString>& repeatable) {
    CliArgs out;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString& a = args[i];
        // "-o FILE" is the one short option.
        const bool shortOption = a == "-o";
        if (!shortOption && (!a.startsWith("--") || a.size() == 2)) {
            out.positional_ << a;
            continue;
        }
        QString name = a.mid(shortOption ? 1 : 2);
        QString value;
        bool hasInlineValue = false;
        if (const qsizetype eq = name.indexOf('='); eq >= 0) {
            value = name.mid(eq + 1);
            name = name.left(eq);
            hasInlineValue = true;
        }
        if (out.has(name) && !repeatable.contains(name))
            throw InvalidInput(field(name), "given more than once");
        out.order_ << name;
        if (booleanFlags.contains(name)) {
            if (hasInlineValue)
                throw InvalidInput(field(name), "takes no value");
            out.flags_.insert(name);
            continue;
        }
        if (!hasInlineValue) {
            if (i + 1 >= args.size())
                throw InvalidInput(field(name), "needs a value");
            value = args[++i];
        }
        out.values_.insert(name, value);
        if (repeatable.contains(name))
            out.repeated_[name] << value;
    }
    return out;
}

std::optional<QString> CliArgs::value(const QString& name) const {
    if (!values_.contains(name))
        return std::nullopt;
    return values_.value(name);
}

QString CliArgs::text(const QString& name, const QString& fallback) const {
    return values_.value(name, fallback);
}

double CliArgs::number(const QString& name, std::optional<double> fallback) const {
    const auto v = value(name);
    if (!v) {
        if (!fallback)
            throw InvalidInput(field(name), "is required");
        return *fallback;
    }
    return parseNumber(v->toStdString(), field(name));
}

int CliArgs::integer(const QString& name, int fallback, int minValue, int maxValue) const {
    const auto v = value(name);
    if (!v)
        return fallback;
    bool ok = false;
    const int n = v->toInt(&ok);
    if (!ok || n < minValue || n > maxValue)
        throw InvalidInput(field(name), "must be a whole number from " + std::to_string(minValue) +
                                            " to " + std::to_string(maxValue));
    return n;
}

void CliArgs::allowOnly(const QStringList& allowed) const {
    for (const QString& name : order_)
        if (!allowed.contains(name))
            throw InvalidInput(field(name), "is not an option of this command");
}

} // namespace xyt::cli

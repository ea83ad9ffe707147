// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli_args.h"

#include "core/model/coefficient_parser.h"
#include "core/model/errors.h"

namespace xyt::cli {

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

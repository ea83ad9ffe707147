// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QMap>
#include <QSet>
#include <QString>
#include <QStringList>

#include <optional>
#include <string>

namespace xyt::cli {

/**
 * One command-line argument as text, losslessly: valid UTF-8 is decoded as usual, and each byte
 * that is not part of a valid UTF-8 sequence becomes the lone surrogate U+DC00 + byte (as
 * Python's "surrogateescape" does). A file name is any bytes on Linux, and Qt's own decoding
 * (QCoreApplication::arguments) turns invalid ones into U+FFFD, so a name like "x_\xff.csv"
 * could neither be opened nor written under its own name. Valid UTF-8 never yields a lone
 * surrogate, so fileNameBytes() gives back exactly the bytes the shell passed.
 */
QString argumentText(const char* bytes);
/// The bytes of an argument decoded by argumentText(), for the system call (open, rename).
std::string fileNameBytes(const QString& argument);

/**
 * The arguments of one xytune-cli command: `--name value` pairs, boolean `--flag`s and
 * positional words. Every accessor that fails throws xyt::InvalidInput whose field is the
 * argument as typed ("--wn"), so main() can print one line naming it and exit with code 2.
 */
class CliArgs {
public:
    /// @param booleanFlags names (without --) that take no value.
    /// @param repeatable names that may be given more than once (read them with values()).
    /// @throws InvalidInput for an option without a value or given twice.
    static CliArgs parse(const QStringList& args, const QSet<QString>& booleanFlags = {},
                         const QSet<QString>& repeatable = {});

    bool has(const QString& name) const { return values_.contains(name) || flags_.contains(name); }
    bool flag(const QString& name) const { return flags_.contains(name); }
    std::optional<QString> value(const QString& name) const;
    /// Every value of a repeatable option, in the order given.
    QStringList values(const QString& name) const { return repeated_.value(name); }
    QString text(const QString& name, const QString& fallback) const;
    /// A finite number. Without @p fallback the argument is required.
    double number(const QString& name, std::optional<double> fallback = std::nullopt) const;
    /// A positive whole number.
    int count(const QString& name, int fallback, int maxValue) const {
        return integer(name, fallback, 1, maxValue);
    }
    /// A whole number in [minValue, maxValue].
    int integer(const QString& name, int fallback, int minValue, int maxValue) const;
    const QStringList& positional() const { return positional_; }
    /// @throws InvalidInput naming the first option not in @p allowed.
    void allowOnly(const QStringList& allowed) const;

    /// "--name" as printed in messages ("-o" for the one short option).
    static std::string field(const QString& name) {
        return ((name == "o" ? "-" : "--") + name).toStdString();
    }

private:
    QMap<QString, QString> values_;
    QMap<QString, QStringList> repeated_;
    QSet<QString> flags_;
    QStringList positional_;
    QStringList order_;
};

} // namespace xyt::cli

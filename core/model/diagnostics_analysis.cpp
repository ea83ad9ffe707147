// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The warnings and refusals of core/analysis.
const std::vector<DiagnosticTemplate>& analysis() {
    static const std::vector<DiagnosticTemplate> table = {

    };
    return table;
}

} // namespace xyt::diagnostic_tables

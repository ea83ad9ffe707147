// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The warnings and refusals of core/identification.
const std::vector<DiagnosticTemplate>& identification() {
    static const std::vector<DiagnosticTemplate> table = {

    };
    return table;
}

} // namespace xyt::diagnostic_tables

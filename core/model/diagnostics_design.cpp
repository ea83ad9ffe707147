// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/diagnostic_tables.h"

namespace xyt::diagnostic_tables {

/// The warnings and refusals of core/design.
const std::vector<DiagnosticTemplate>& design() {
    static const std::vector<DiagnosticTemplate> table = {

    };
    return table;
}

} // namespace xyt::diagnostic_tables

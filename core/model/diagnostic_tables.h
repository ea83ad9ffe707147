// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/model/diagnostic_catalogue.h"

#include <vector>

/// The catalogue's tables, one per concern of the core (diagnosticCatalogue() joins them). Each
/// lists the codes its folder's warnings and refusals use, each entry written XYT_DIAGNOSTIC(...).
namespace xyt::diagnostic_tables {

const std::vector<DiagnosticTemplate>& model();          ///< diagnostics_model.cpp
const std::vector<DiagnosticTemplate>& io();             ///< diagnostics_io.cpp
const std::vector<DiagnosticTemplate>& design();         ///< diagnostics_design.cpp
const std::vector<DiagnosticTemplate>& analysis();       ///< diagnostics_analysis.cpp
const std::vector<DiagnosticTemplate>& simulation();     ///< diagnostics_simulation.cpp
const std::vector<DiagnosticTemplate>& identification(); ///< diagnostics_identification.cpp
const std::vector<DiagnosticTemplate>& contour();        ///< diagnostics_contour.cpp
const std::vector<DiagnosticTemplate>& study();          ///< diagnostics_study.cpp
const std::vector<DiagnosticTemplate>& session();        ///< diagnostics_session.cpp

} // namespace xyt::diagnostic_tables
